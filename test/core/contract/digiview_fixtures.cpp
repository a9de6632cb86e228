#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "device_fixtures_internal.h"
#include "harness/digiview_harness.h"

namespace ptz_action_server
{
namespace
{
using Kind = ClassifiedCommand::Kind;

// ---------------------------------------------------------------- DigiView: TCP and UDP, every format

/// DigiView over \p transport in \p format, its angles in the format's documented unit (as the backend's).
DigiViewEmulatorConfig digiView(LinkKind transport, digiview::Format format)
{
  DigiViewEmulatorConfig config;
  config.transport = transport;
  config.wire = digiview::Wire(format);
  return config;
}

class DigiViewFixture : public HarnessFixture<DigiViewHarness>
{
public:
  DigiViewFixture(LinkKind transport, digiview::Format format) : HarnessFixture(digiView(transport, format))
  {
    harness_.config().session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::string linkLossWords() const override
  {
    return transportLossWords(harness_, "no state from DigiView");
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    harness_.emulator().setRefuse(true);
    goal = AxisValues{ { 0.3, 0.0, 1.0 } };
    return ": FORBIDDEN (the sender does not have permission to perform the requested action)";
  }
  AxisValues goal(double pan, double tilt) const override
  {
    return AxisValues{ { pan, tilt, 2.0 } };
  }
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    using namespace digiview;
    std::size_t targetings = 0;
    std::size_t optics_seen = 0;
    for (const ReceivedMessage& item : harness_.emulator().received().items())
    {
      if (item.message.message_type != MessageType::SET_PARAMETERS)
      {
        continue;
      }
      if (item.message.param_type == ParamType::CAM_TARGETING)
      {
        CamTargeting targeting;
        ASSERT_EQ(unpackTargeting(item.message, targeting), UnpackError::NONE);
        EXPECT_EQ(targeting.camera.stream_name, "main");
        EXPECT_EQ(targeting.targeting_mode, 0);  // directional
        EXPECT_FALSE(targeting.euler_delta);
        EXPECT_NEAR(targeting.yaw, target[PAN], 1e-3);     // clockwise, as the contract's pan
        EXPECT_NEAR(targeting.pitch, target[TILT], 1e-3);  // up positive, as the contract's tilt
        ++targetings;
      }
      else if (item.message.param_type == ParamType::CAM_OPTICS_AND_CONTROL)
      {
        CamOpticsAndControl optics;
        ASSERT_EQ(unpackOptics(item.message, optics), UnpackError::NONE);
        EXPECT_NEAR(optics.fov, harness_.config().settings.fov_wide / target[ZOOM], 1e-3);
        ++optics_seen;
      }
    }
    EXPECT_EQ(targetings, 1u) << describe(commands);
    EXPECT_EQ(optics_seen, 1u) << describe(commands);
  }
  /// A hold aims the view where it is: a SET CAM_TARGETING elsewhere than the goal's.
  std::size_t holds(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    return static_cast<std::size_t>(
        std::count_if(commands.begin(), commands.end(), [&](const ClassifiedCommand& command) {
          return command.kind == Kind::MOVE && command.aims && std::abs(command.pan - target[PAN]) > 1e-3;
        }));
  }
};

const DeviceFixtureRegistration DIGIVIEW_FIXTURES({
    { "DigiViewTcpV0_5", [] { return std::make_unique<DigiViewFixture>(LinkKind::TCP, digiview::Format::V0_5); } },
    { "DigiViewUdpV0_5", [] { return std::make_unique<DigiViewFixture>(LinkKind::UDP, digiview::Format::V0_5); } },
    { "DigiViewTcpV1_0", [] { return std::make_unique<DigiViewFixture>(LinkKind::TCP, digiview::Format::V1_0); } },
    { "DigiViewUdpV1_0", [] { return std::make_unique<DigiViewFixture>(LinkKind::UDP, digiview::Format::V1_0); } },
    { "DigiViewTcpV1_1", [] { return std::make_unique<DigiViewFixture>(LinkKind::TCP, digiview::Format::V1_1); } },
    { "DigiViewUdpV1_1", [] { return std::make_unique<DigiViewFixture>(LinkKind::UDP, digiview::Format::V1_1); } },
    { "DigiViewTcpV1_2", [] { return std::make_unique<DigiViewFixture>(LinkKind::TCP, digiview::Format::V1_2); } },
    { "DigiViewUdpV1_2", [] { return std::make_unique<DigiViewFixture>(LinkKind::UDP, digiview::Format::V1_2); } },
});
}  // namespace

}  // namespace ptz_action_server

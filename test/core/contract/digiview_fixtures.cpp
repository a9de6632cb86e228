#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "device_fixtures_internal.h"
#include "ptz_action_server/core/digiview/digiview_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/digiview_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;

// ---------------------------------------------------------------- DigiView: TCP and UDP, every format

class DigiViewFixture : public DeviceFixture
{
public:
  DigiViewFixture(LinkKind transport, digiview::Format format)
  {
    emulator_config_.transport = transport;
    emulator_config_.wire = digiview::Wire(format);  // the format's documented angle unit, as the backend's
    emulator_ = std::make_unique<DigiViewEmulator>(emulator_config_);
    emulator_config_.port = emulator_->port();
    config_.link.kind = transport;
    config_.link.port = emulator_->port();
    config_.settings.wire = digiview::Wire(format);
    config_.settings.acceleration = 4.0;  // as the emulator turns
    config_.session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    return makeDeviceBackend<DigiViewProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    using namespace digiview;
    std::vector<DeviceCommand> commands;
    for (const ReceivedMessage& item : emulator_->received().items())
    {
      const Message& message = item.message;
      Kind kind = Kind::OTHER;
      std::string text = std::string(toString(message.message_type)) + " " + toString(message.param_type);
      if (message.message_type == MessageType::GET_PARAMETERS || message.message_type == MessageType::GET_INTERVAL)
      {
        kind = Kind::QUERY;
      }
      else if (message.message_type == MessageType::SET_PARAMETERS && message.param_type == ParamType::CAM_TARGETING)
      {
        kind = Kind::MOVE;
        CamTargeting targeting;
        if (unpackTargeting(message, targeting) == UnpackError::NONE)
        {
          text += " yaw " + std::to_string(targeting.yaw) + " pitch " + std::to_string(targeting.pitch);
          commands.push_back(DeviceCommand{ item.at, kind, text, true, targeting.yaw });
          continue;
        }
      }
      commands.push_back(DeviceCommand{ item.at, kind, text });
    }
    return commands;
  }
  void clearCommands() override
  {
    emulator_->received().clear();
  }
  PtzSample deviceState() const override
  {
    PtzSample view = emulator_->view("main", 0);
    view.position[ZOOM] = config_.settings.fov_wide / view.position[ZOOM];  // the model's zoom slot is the fov
    return view;
  }
  void setSilent(bool silent) override
  {
    emulator_->setSilent(silent);
  }
  bool setFlood(unsigned copies) override
  {
    emulator_->setFlood(copies);
    return true;
  }
  bool setEndlessReplies(bool endless) override
  {
    emulator_->setEndless(endless);
    return true;
  }
  bool setFaults(const SimFaults& faults) override
  {
    emulator_->setFaults(faults);
    return true;
  }
  void breakLink() override
  {
    if (config_.link.kind == LinkKind::TCP)
    {
      emulator_->dropConnections();
    }
    else
    {
      emulator_.reset();
    }
  }
  void restoreLink() override
  {
    if (!emulator_)
    {
      emulator_ = std::make_unique<DigiViewEmulator>(emulator_config_);
    }
  }
  bool breaksAtOnce() const override
  {
    return config_.link.kind == LinkKind::TCP;
  }
  std::string linkLossWords() const override
  {
    return config_.link.kind == LinkKind::TCP ? "connection to 127.0.0.1" : "no state from DigiView";
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    emulator_->setRefuse(true);
    goal = AxisValues{ { 0.3, 0.0, 1.0 } };
    return ": FORBIDDEN (the sender does not have permission to perform the requested action)";
  }
  AxisValues goal(double pan, double tilt) const override
  {
    return AxisValues{ { pan, tilt, 2.0 } };
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    using namespace digiview;
    std::size_t targetings = 0;
    std::size_t optics_seen = 0;
    for (const ReceivedMessage& item : emulator_->received().items())
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
        EXPECT_NEAR(optics.fov, config_.settings.fov_wide / target[ZOOM], 1e-3);
        ++optics_seen;
      }
    }
    EXPECT_EQ(targetings, 1u) << describe(commands);
    EXPECT_EQ(optics_seen, 1u) << describe(commands);
  }
  /// A hold aims the view where it is: a SET CAM_TARGETING elsewhere than the goal's.
  std::size_t holds(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    return static_cast<std::size_t>(std::count_if(commands.begin(), commands.end(), [&](const DeviceCommand& command) {
      return command.kind == Kind::MOVE && command.aims && std::abs(command.pan - target[PAN]) > 1e-3;
    }));
  }

private:
  DigiViewEmulatorConfig emulator_config_;
  std::unique_ptr<DigiViewEmulator> emulator_;
  DeviceConfig<DigiViewProtocol> config_;
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

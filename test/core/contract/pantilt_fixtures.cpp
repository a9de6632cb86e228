#include <gtest/gtest.h>

#include "device_fixtures_internal.h"
#include "harness/pantilt_harness.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
// ---------------------------------------------------------------- PanTilt over UDP, and in SLIP frames on serial

/// A device controller in \p format reporting every 50 ms, over UDP or (\p serial) on a pseudo-terminal at 115200 baud.
PanTiltEmulatorConfig panTiltController(cr::pantilt::WireFormat format, bool serial)
{
  PanTiltEmulatorConfig config;
  config.format = format;
  config.state_period = 0.05;
  config.serial = serial;
  config.line.baud = 115200;
  return config;
}

class PanTiltFixture : public HarnessFixture<PanTiltHarness>
{
public:
  explicit PanTiltFixture(cr::pantilt::WireFormat format, bool serial = false)
    : HarnessFixture(panTiltController(format, serial))
  {
    harness_.config().session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::string linkLossWords() const override
  {
    return transportLossWords(harness_, "no state from a PanTilt device controller");
  }
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    using namespace cr::pantilt;
    const WireFormat format = harness_.emulatorConfig().format;
    auto set = [format](PanTiltParam id, double value) {
      std::vector<std::uint8_t> frame(SET_PARAM_SIZE);
      int size = 0;
      PanTilt::encodeSetParamCommand(frame.data(), size, id, static_cast<float>(value), format);
      return hexText(frame.data(), frame.size());
    };
    auto command = [format](PanTiltCommand id, double arg1 = 0.0, double arg2 = 0.0) {
      std::vector<std::uint8_t> frame(MAX_COMMAND_SIZE);
      int size = 0;
      PanTilt::encodeCommand(frame.data(), size, id, format, static_cast<float>(arg1), static_cast<float>(arg2));
      return hexText(frame.data(), static_cast<std::size_t>(size));
    };
    std::vector<std::string> expected = { set(PanTiltParam::PAN_MOTOR_SPEED, 100.0),
                                          set(PanTiltParam::TILT_MOTOR_SPEED, 100.0) };
    if (format == WireFormat::SEED)
    {
      expected.push_back(set(PanTiltParam::PAN_ANGLE, toDegrees(target[PAN])));
      expected.push_back(set(PanTiltParam::TILT_ANGLE, toDegrees(target[TILT])));
      expected.push_back(command(PanTiltCommand::GO_TO_PAN_TILT_ANGLE));
    }
    else
    {
      expected.push_back(
          command(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, toDegrees(target[PAN]), toDegrees(target[TILT])));
    }
    EXPECT_EQ(texts(withoutQueries(commands)), expected);
  }
};

const DeviceFixtureRegistration PANTILT_FIXTURES({
    { "PanTiltUdpSeed", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::SEED); } },
    { "PanTiltUdpV1_0", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::V1_0); } },
    { "PanTiltUdpV1_1", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::V1_1); } },
    { "PanTiltSerialSeed", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::SEED, true); } },
    { "PanTiltSerialV1_1", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::V1_1, true); } },
});
}  // namespace

}  // namespace ptz_action_server

#include <gtest/gtest.h>

#include <cmath>

#include "device_fixtures_internal.h"
#include "harness/mavlink_gimbal_harness.h"

namespace ptz_action_server
{
namespace
{
using Kind = ClassifiedCommand::Kind;
using namespace mavlink;

/// Where the gimbal is.
enum class Setup
{
  GIMBAL_INSIDE_MANAGER,  ///< the autopilot's manager drives gimbal 1 inside it (a PWM gimbal): gimbal_device_id 1
  AUTOPILOT_HOSTED,  ///< the autopilot's manager (1/1) drives the MAVLink gimbal device 1/154: gimbal_device_id 154
};

/// The gimbal manager emulator over UDP or a pseudo-terminal (at 115200 baud).
MavlinkGimbalEmulatorConfig gimbalManager(LinkKind transport, Setup setup)
{
  MavlinkGimbalEmulatorConfig config;
  if (setup == Setup::AUTOPILOT_HOSTED)
  {
    config.component_id = MAV_COMP_ID_AUTOPILOT1;
    config.gimbals.front().device_id = MAV_COMP_ID_GIMBAL;
  }
  config.transport = transport;
  config.line.baud = 115200;
  return config;
}

/// The mavlink_gimbal backend with no gimbal named (the only one found is chosen).
class MavlinkGimbalFixture : public HarnessFixture<MavlinkGimbalHarness>
{
public:
  MavlinkGimbalFixture(LinkKind transport, Setup setup) : HarnessFixture(gimbalManager(transport, setup))
  {
    harness_.config().session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::string linkLossWords() const override
  {
    return transportLossWords(harness_, "no state from");
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    // Another controller takes primary control and keeps it: our setpoints would be ignored, so the goal must end.
    harness_.emulator().giveControlTo(3, 190);
    goal = AxisValues{ { 0.3, 0.0, 1.0 } };
    return "primary control of the gimbal";
  }
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    std::size_t setpoints = 0;
    for (const ClassifiedCommand& sent : withoutQueries(commands))
    {
      ASSERT_EQ(sent.kind, Kind::MOVE) << describe(commands);
      EXPECT_FLOAT_EQ(static_cast<float>(sent.pan), static_cast<float>(target[PAN])) << describe(commands);
      ++setpoints;
    }
    EXPECT_GE(setpoints, 1u) << describe(commands);
    const MavlinkGimbalEmulatorConfig& manager = harness_.emulatorConfig();
    for (const ReceivedMavlinkFrame& item : harness_.emulator().received().items())
    {
      if (item.frame.message_id == message_id::GIMBAL_MANAGER_SET_PITCHYAW)
      {
        const auto setpoint = decode<GimbalManagerSetPitchYaw>(item.frame);
        EXPECT_FLOAT_EQ(setpoint.pitch, static_cast<float>(target[TILT]));
        EXPECT_TRUE(std::isnan(setpoint.pitch_rate) && std::isnan(setpoint.yaw_rate));
        EXPECT_EQ(setpoint.flags, 0u) << "yaw in the vehicle frame";
        EXPECT_EQ(setpoint.target_system, manager.system_id);
        EXPECT_EQ(setpoint.target_component, manager.component_id);
        EXPECT_EQ(setpoint.gimbal_device_id, manager.gimbals.front().device_id);
      }
    }
  }
  /// A stop repeats its zero rates for a moment (against loss): one run of stops is one hold.
  std::size_t holds(const std::vector<ClassifiedCommand>& commands, const AxisValues&) const override
  {
    std::size_t runs = 0;
    bool in_run = false;
    for (const ClassifiedCommand& command : withoutQueries(commands))
    {
      const bool stop = command.kind == Kind::STOP;
      runs += stop && !in_run ? 1 : 0;
      in_run = stop;
    }
    return runs;
  }
};

const DeviceFixtureRegistration MAVLINK_GIMBAL_FIXTURES({
    { "MavlinkGimbalUdp",
      [] { return std::make_unique<MavlinkGimbalFixture>(LinkKind::UDP, Setup::GIMBAL_INSIDE_MANAGER); } },
    { "MavlinkGimbalSerial",
      [] { return std::make_unique<MavlinkGimbalFixture>(LinkKind::SERIAL, Setup::GIMBAL_INSIDE_MANAGER); } },
    { "MavlinkGimbalAutopilotHostedUdp",
      [] { return std::make_unique<MavlinkGimbalFixture>(LinkKind::UDP, Setup::AUTOPILOT_HOSTED); } },
});
}  // namespace

}  // namespace ptz_action_server

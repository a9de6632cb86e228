#include <gtest/gtest.h>

#include <cmath>

#include "device_fixtures_internal.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;
using namespace mavlink;

/// Where the gimbal is.
enum class Setup
{
  GIMBAL_INSIDE_MANAGER,  ///< the autopilot's manager drives gimbal 1 inside it (a PWM gimbal): gimbal_device_id 1
  AUTOPILOT_HOSTED,  ///< the autopilot's manager (1/1) drives the MAVLink gimbal device 1/154: gimbal_device_id 154
};

/// The gimbal manager emulator over UDP or a pseudo-terminal, and the mavlink_gimbal backend configured for it (with
/// no gimbal named: the only one found is chosen).
class MavlinkGimbalFixture : public DeviceFixture
{
public:
  MavlinkGimbalFixture(LinkKind transport, Setup setup)
  {
    if (setup == Setup::AUTOPILOT_HOSTED)
    {
      emulator_config_.component_id = MAV_COMP_ID_AUTOPILOT1;
      emulator_config_.gimbals.front().device_id = MAV_COMP_ID_GIMBAL;
    }
    emulator_config_.transport = transport;
    if (transport == LinkKind::SERIAL)
    {
      emulator_config_.line.link = uniqueLink("mavlink");
      emulator_config_.line.baud = 115200;
      config_.link.kind = LinkKind::SERIAL;
      config_.link.path = emulator_config_.line.link;
      config_.link.baud = 115200;
    }
    emulator_ = std::make_unique<MavlinkGimbalEmulator>(emulator_config_);
    if (transport == LinkKind::UDP)
    {
      emulator_config_.port = emulator_->udpPort();  // a restart takes the same port
      config_.link.port = emulator_config_.port;
      config_.link.local_host = "127.0.0.1";
    }
    config_.session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    return makeDeviceBackend<MavlinkGimbalProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    std::vector<DeviceCommand> commands;
    for (const ReceivedMavlinkFrame& item : emulator_->received().items())
    {
      DeviceCommand command{ item.at, Kind::QUERY, "", false, 0.0 };
      const Frame& frame = item.frame;
      if (frame.message_id == message_id::GIMBAL_MANAGER_SET_PITCHYAW)
      {
        const auto setpoint = decode<GimbalManagerSetPitchYaw>(frame);
        if (std::isfinite(setpoint.yaw) || std::isfinite(setpoint.pitch))
        {
          command.kind = Kind::MOVE;
          command.aims = std::isfinite(setpoint.yaw);
          command.pan = setpoint.yaw;
          command.text =
              "SET_PITCHYAW pitch " + std::to_string(setpoint.pitch) + " yaw " + std::to_string(setpoint.yaw);
        }
        else
        {
          const bool stop = setpoint.yaw_rate == 0.0f && setpoint.pitch_rate == 0.0f;
          command.kind = stop ? Kind::STOP : Kind::OTHER;
          command.text = std::string(stop ? "SET_PITCHYAW stop" : "SET_PITCHYAW rates ") +
                         (stop ? "" : std::to_string(setpoint.pitch_rate) + " " + std::to_string(setpoint.yaw_rate));
        }
      }
      else if (frame.message_id == message_id::COMMAND_LONG)
      {
        const auto long_command = decode<CommandLong>(frame);
        command.kind = long_command.command == command_id::DO_GIMBAL_MANAGER_CONFIGURE ? Kind::OTHER : Kind::QUERY;
        command.text = "COMMAND_LONG " + std::to_string(long_command.command);
      }
      else
      {
        command.text = "message " + std::to_string(frame.message_id);
      }
      commands.push_back(command);
    }
    return commands;
  }
  void clearCommands() override
  {
    emulator_->received().clear();
  }
  PtzSample deviceState() const override
  {
    return emulator_->gimbal();
  }
  void setSilent(bool silent) override
  {
    emulator_->setSilent(silent);
  }
  bool setFlood(unsigned copies) override
  {
    if (emulator_config_.transport == LinkKind::SERIAL)
    {
      return false;  // a serial line carries what its baud rate allows: no flood
    }
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
    if (emulator_config_.transport == LinkKind::SERIAL)
    {
      emulator_->unplug();
    }
    else
    {
      emulator_.reset();  // the manager is gone (an autopilot rebooting)
    }
  }
  void restoreLink() override
  {
    if (emulator_config_.transport == LinkKind::SERIAL)
    {
      emulator_->replug();
    }
    else if (!emulator_)
    {
      emulator_ = std::make_unique<MavlinkGimbalEmulator>(emulator_config_);
    }
  }
  bool breaksAtOnce() const override
  {
    return emulator_config_.transport == LinkKind::SERIAL;
  }
  std::string linkLossWords() const override
  {
    return emulator_config_.transport == LinkKind::SERIAL ? config_.link.path : "no state from";
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    // Another controller takes primary control and keeps it: our setpoints would be ignored, so the goal must end.
    emulator_->giveControlTo(3, 190);
    goal = AxisValues{ { 0.3, 0.0, 1.0 } };
    return "primary control of the gimbal";
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    std::size_t setpoints = 0;
    for (const DeviceCommand& sent : withoutQueries(commands))
    {
      ASSERT_EQ(sent.kind, Kind::MOVE) << describe(commands);
      EXPECT_FLOAT_EQ(static_cast<float>(sent.pan), static_cast<float>(target[PAN])) << describe(commands);
      ++setpoints;
    }
    EXPECT_GE(setpoints, 1u) << describe(commands);
    for (const ReceivedMavlinkFrame& item : emulator_->received().items())
    {
      if (item.frame.message_id == message_id::GIMBAL_MANAGER_SET_PITCHYAW)
      {
        const auto setpoint = decode<GimbalManagerSetPitchYaw>(item.frame);
        EXPECT_FLOAT_EQ(setpoint.pitch, static_cast<float>(target[TILT]));
        EXPECT_TRUE(std::isnan(setpoint.pitch_rate) && std::isnan(setpoint.yaw_rate));
        EXPECT_EQ(setpoint.flags, 0u) << "yaw in the vehicle frame";
        EXPECT_EQ(setpoint.target_system, emulator_config_.system_id);
        EXPECT_EQ(setpoint.target_component, emulator_config_.component_id);
        EXPECT_EQ(setpoint.gimbal_device_id, emulator_config_.gimbals.front().device_id);
      }
    }
  }
  /// A stop repeats its zero rates for a moment (against loss): one run of stops is one hold.
  std::size_t holds(const std::vector<DeviceCommand>& commands, const AxisValues&) const override
  {
    std::size_t runs = 0;
    bool in_run = false;
    for (const DeviceCommand& command : withoutQueries(commands))
    {
      const bool stop = command.kind == Kind::STOP;
      runs += stop && !in_run ? 1 : 0;
      in_run = stop;
    }
    return runs;
  }

private:
  MavlinkGimbalEmulatorConfig emulator_config_;
  std::unique_ptr<MavlinkGimbalEmulator> emulator_;
  DeviceConfig<MavlinkGimbalProtocol> config_;
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

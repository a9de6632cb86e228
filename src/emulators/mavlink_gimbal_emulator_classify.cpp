#include <cmath>

#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> MavlinkGimbalEmulator::classify() const
{
  namespace mav = mavlink;
  using Kind = ClassifiedCommand::Kind;
  return received_.classified([](const ReceivedMavlinkFrame& item) {
    // Heartbeats, requests and intervals are what a controller asks to hear: queries.
    ClassifiedCommand command{ item.at, Kind::QUERY, "" };
    const mav::Frame& frame = item.frame;
    if (frame.message_id == mav::message_id::GIMBAL_MANAGER_SET_PITCHYAW)
    {
      const auto setpoint = mav::decode<mav::GimbalManagerSetPitchYaw>(frame);
      if (std::isfinite(setpoint.yaw) || std::isfinite(setpoint.pitch))
      {
        command.kind = Kind::MOVE;
        command.aims = std::isfinite(setpoint.yaw);
        command.pan = setpoint.yaw;
        command.text = "SET_PITCHYAW pitch " + std::to_string(setpoint.pitch) + " yaw " + std::to_string(setpoint.yaw);
      }
      else
      {
        const bool stop = setpoint.yaw_rate == 0.0f && setpoint.pitch_rate == 0.0f;
        command.kind = stop ? Kind::STOP : Kind::OTHER;  // rates: a velocity goal's
        command.text = std::string(stop ? "SET_PITCHYAW stop" : "SET_PITCHYAW rates ") +
                       (stop ? "" : std::to_string(setpoint.pitch_rate) + " " + std::to_string(setpoint.yaw_rate));
      }
    }
    else if (frame.message_id == mav::message_id::COMMAND_LONG)
    {
      const auto long_command = mav::decode<mav::CommandLong>(frame);
      command.kind = long_command.command == mav::command_id::DO_GIMBAL_MANAGER_CONFIGURE ? Kind::OTHER : Kind::QUERY;
      command.text = "COMMAND_LONG " + std::to_string(long_command.command);
    }
    else
    {
      command.text = "message " + std::to_string(frame.message_id);
    }
    return command;
  });
}

}  // namespace ptz_action_server

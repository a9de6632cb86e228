/**
 * \file
 * \brief MavlinkGimbalEmulator: what the managers do with the commands and setpoints they receive. What they send
 * is in mavlink_gimbal_emulator_reports.cpp, the link in mavlink_gimbal_emulator.cpp.
 */
#include <cmath>

#include "mavlink_gimbal_emulator_internal.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
using namespace mavlink_emulator;

void MavlinkGimbalEmulator::handleCommand(std::uint8_t component, const Frame& frame, const CommandLong& command,
                                          TimePoint now)
{
  CommandAck ack;
  ack.command = command.command;
  ack.target_system = frame.header.system_id;
  ack.target_component = frame.header.component_id;
  ack.result = Result::ACCEPTED;
  const std::vector<Gimbal*> managed = addressed(component, 0);
  const bool manager = !managed.empty() && !config_.gimbal_v1;  // a v1 autopilot manages no gimbal
  std::vector<const Gimbal*> informed, reported;                // answered with their information, their status
  switch (command.command)
  {
    case command_id::REQUEST_MESSAGE:
      if (manager && command.params[0] == static_cast<float>(message_id::GIMBAL_MANAGER_INFORMATION))
      {
        informed.assign(managed.begin(), managed.end());
      }
      else if (manager && command.params[0] == static_cast<float>(message_id::GIMBAL_MANAGER_STATUS))
      {
        reported.assign(managed.begin(), managed.end());
      }
      else
      {
        ack.result = Result::UNSUPPORTED;  // a gimbal device is no manager; other messages are not modelled
      }
      break;
    case command_id::SET_MESSAGE_INTERVAL: {
      ack.result = Result::UNSUPPORTED;
      if (command.params[0] != static_cast<float>(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS))
      {
        break;
      }
      const float interval_us = command.params[1];
      for (const auto& gimbal : gimbals_)
      {
        if (gimbal->attitudeComponent() == component)  // the attitudes this component sends
        {
          gimbal->attitude_interval = interval_us < 0.0f  ? 0.0 :
                                      interval_us == 0.0f ? config_.attitude_interval :
                                                            interval_us / 1e6;
          ack.result = Result::ACCEPTED;
        }
      }
      break;
    }
    case command_id::DO_GIMBAL_MANAGER_CONFIGURE: {
      if (!manager)
      {
        ack.result = Result::UNSUPPORTED;
        break;
      }
      const std::vector<Gimbal*> targets = addressed(component, static_cast<std::uint8_t>(command.params[6]));
      ack.result = targets.empty() ? Result::DENIED : Result::ACCEPTED;  // no such gimbal here
      for (Gimbal* gimbal : targets)
      {
        if (configure(*gimbal, frame, command) != Result::ACCEPTED)
        {
          ack.result = Result::DENIED;
        }
        reported.push_back(gimbal);
      }
      break;
    }
    case command_id::DO_GIMBAL_MANAGER_PITCHYAW: {
      if (!manager)
      {
        ack.result = Result::UNSUPPORTED;
        break;
      }
      const std::vector<Gimbal*> targets = addressed(component, static_cast<std::uint8_t>(command.params[6]));
      ack.result = targets.empty() ? Result::DENIED : Result::ACCEPTED;
      for (Gimbal* gimbal : targets)
      {
        if (refuse_ || !fromPrimary(*gimbal, frame))
        {
          ack.result = Result::DENIED;
          continue;
        }
        // The command's degrees as the message's radians.
        execute(*gimbal, static_cast<std::uint32_t>(command.params[4]),
                static_cast<float>(toRadians(command.params[0])), static_cast<float>(toRadians(command.params[1])),
                static_cast<float>(toRadians(command.params[2])), static_cast<float>(toRadians(command.params[3])),
                now);
      }
      break;
    }
    default:
      ack.result = Result::UNSUPPORTED;
  }
  if (ack.result == Result::DENIED)
  {
    ++counters_.commands_denied;
  }
  send(component, ack);
  for (const Gimbal* gimbal : informed)
  {
    sendInformation(*gimbal);
  }
  for (const Gimbal* gimbal : reported)
  {
    sendStatus(*gimbal);
  }
}

Result MavlinkGimbalEmulator::configure(Gimbal& gimbal, const Frame& frame, const CommandLong& command)
{
  if (refuse_)
  {
    return Result::DENIED;
  }
  const float system = command.params[0];
  const float component = command.params[1];
  if (system == UNCHANGED)
  {
    return Result::ACCEPTED;
  }
  const bool held = gimbal.primary_system != 0 || gimbal.primary_component != 0;
  if (gimbal.control_kept && held && !fromPrimary(gimbal, frame))
  {
    return Result::DENIED;
  }
  if (system == RELEASE)
  {
    if (fromPrimary(gimbal, frame))  // "remove control if currently in control"
    {
      gimbal.primary_system = gimbal.primary_component = 0;
    }
    return Result::ACCEPTED;
  }
  if (system == MANAGER_ITSELF)
  {
    gimbal.primary_system = config_.system_id;
    gimbal.primary_component = gimbal.manager;
  }
  else if (system >= 0.0f && system <= 255.0f && component >= 0.0f && component <= 255.0f)
  {
    gimbal.primary_system = static_cast<std::uint8_t>(system);
    gimbal.primary_component = static_cast<std::uint8_t>(component);
  }
  else
  {
    return Result::DENIED;
  }
  gimbal.control_kept = false;
  return Result::ACCEPTED;
}

void MavlinkGimbalEmulator::setpoint(Gimbal& gimbal, const Frame& frame, std::uint32_t flags, float pitch, float yaw,
                                     float pitch_rate, float yaw_rate, TimePoint now)
{
  if (!fromPrimary(gimbal, frame))
  {
    ++counters_.setpoints_ignored;  // as PX4 does: no answer to a message from a non-primary sender
    return;
  }
  execute(gimbal, flags, pitch, yaw, pitch_rate, yaw_rate, now);
}

void MavlinkGimbalEmulator::execute(Gimbal& gimbal, std::uint32_t flags, float pitch, float yaw, float pitch_rate,
                                    float yaw_rate, TimePoint now)
{
  ++counters_.setpoints_executed;
  for (std::size_t index = 0; index < gimbals_.size(); ++index)
  {
    if (gimbals_[index].get() == &gimbal)
    {
      ++counters_.executed_per_gimbal[index];
    }
  }
  if ((flags & gimbal_flags::RETRACT) != 0)
  {
    return;  // no retracted position (no HAS_RETRACT): stays where it is
  }
  if ((flags & gimbal_flags::NEUTRAL) != 0)
  {
    gimbal.rates_active = false;
    gimbal.model.goToAxis(PAN, 0.0, now);
    gimbal.model.goToAxis(TILT, 0.0, now);
    return;
  }
  if (config_.earth_frame_flag_dropped)
  {
    flags &= ~gimbal_flags::YAW_IN_EARTH_FRAME;  // as PX4 loses it (issue 26569): YAW_LOCK alone says North
  }
  // A yaw relative to North: the model turns in the vehicle frame.
  const double yaw_offset = yawInEarthFrame(flags) ? -config_.vehicle_yaw : 0.0;
  if (std::isfinite(pitch) || std::isfinite(yaw))
  {
    gimbal.rates_active = false;
    if (std::isfinite(yaw))
    {
      gimbal.model.goToAxis(PAN, std::remainder(yaw + yaw_offset, 2.0 * M_PI), now);
    }
    if (std::isfinite(pitch))
    {
      gimbal.model.goToAxis(TILT, pitch, now);
    }
    return;
  }
  if (std::isfinite(yaw_rate) || std::isfinite(pitch_rate))
  {
    gimbal.model.moveAxisAtVelocity(PAN, std::isfinite(yaw_rate) ? yaw_rate : 0.0, now);
    gimbal.model.moveAxisAtVelocity(TILT, std::isfinite(pitch_rate) ? pitch_rate : 0.0, now);
    gimbal.rates_active = true;
    gimbal.rates_until = now + toDuration(config_.rate_timeout);
  }
}

}  // namespace ptz_action_server

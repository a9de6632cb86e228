/**
 * \file
 * \brief MavlinkGimbalProtocol: what the gimbal manager sends (discovery, information, status, acknowledgements,
 * attitude). What goes out is in mavlink_gimbal_protocol.cpp.
 */
#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
using namespace mavlink;

bool finite(float value)
{
  return std::isfinite(value);
}

double wrapAngle(double angle)
{
  return std::remainder(angle, 2.0 * M_PI);
}

/// \p axis narrowed to [\p min, \p max] when the manager gave a usable range.
void narrow(AxisCapability& axis, float min, float max)
{
  if (finite(min) && finite(max) && min < max)
  {
    axis.range.min = std::max(axis.range.min, static_cast<double>(min));
    axis.range.max = std::min(axis.range.max, static_cast<double>(max));
    axis.range.max = std::max(axis.range.max, axis.range.min);
  }
}

const char* commandName(std::uint16_t command)
{
  switch (command)
  {
    case command_id::SET_MESSAGE_INTERVAL:
      return "SET_MESSAGE_INTERVAL";
    case command_id::REQUEST_MESSAGE:
      return "REQUEST_MESSAGE";
    case command_id::DO_GIMBAL_MANAGER_PITCHYAW:
      return "DO_GIMBAL_MANAGER_PITCHYAW";
    case command_id::DO_GIMBAL_MANAGER_CONFIGURE:
      return "DO_GIMBAL_MANAGER_CONFIGURE";
  }
  return "a command";
}
}  // namespace

// ---------------------------------------------------------------- what arrives

void MavlinkGimbalProtocol::handle(const Frame& frame)
{
  if (frame.header.system_id == settings_.system_id && frame.header.component_id == settings_.component_id)
  {
    return;  // our own frame, echoed by a router or a serial loop
  }
  switch (frame.message_id)
  {
    case message_id::HEARTBEAT:
      handleHeartbeat(frame);
      return;
    case message_id::GIMBAL_MANAGER_STATUS:
      if (!manager_known_ && settings_.target_system == 0)
      {
        chooseManager(frame.header.system_id, frame.header.component_id);
      }
      if (fromManager(frame))
      {
        handleStatus(decode<GimbalManagerStatus>(frame));
        return;
      }
      break;
    case message_id::GIMBAL_MANAGER_INFORMATION:
      if (!manager_known_ && (settings_.target_system == 0 || settings_.target_system == frame.header.system_id))
      {
        chooseManager(frame.header.system_id, frame.header.component_id);
      }
      if (fromManager(frame))
      {
        handleInformation(decode<GimbalManagerInformation>(frame));
        return;
      }
      break;
    case message_id::COMMAND_ACK:
      if (fromManager(frame))
      {
        handleAck(decode<CommandAck>(frame));
        return;
      }
      break;
    case message_id::GIMBAL_DEVICE_ATTITUDE_STATUS:
      // From the manager's system: the manager itself, or a MAVLink gimbal device beside it.
      if (manager_known_ && frame.header.system_id == manager_system_)
      {
        handleAttitude(decode<GimbalDeviceAttitudeStatus>(frame));
        return;
      }
      break;
    default:
      return;  // known, but nothing the client side needs
  }
  ++counters_.foreign_frames;
}

void MavlinkGimbalProtocol::handleHeartbeat(const Frame& frame)
{
  if (manager_known_ || !due(information_asked_at_, settings_.resend_period * 0.5))
  {
    return;
  }
  if (settings_.target_system != 0 && frame.header.system_id != settings_.target_system)
  {
    return;
  }
  // A candidate manager: an autopilot, or a gimbal that may manage itself. Whoever answers with its information
  // is the manager (a gimbal device beside an autopilot does not).
  const Heartbeat heartbeat = decode<Heartbeat>(frame);
  const bool autopilot = heartbeat.autopilot != MAV_AUTOPILOT_INVALID && heartbeat.type != MAV_TYPE_GCS;
  if (autopilot || frame.header.component_id == MAV_COMP_ID_GIMBAL)
  {
    requestInformation(frame.header.system_id, frame.header.component_id);
  }
}

bool MavlinkGimbalProtocol::fromManager(const Frame& frame) const
{
  return manager_known_ && frame.header.system_id == manager_system_ && frame.header.component_id == manager_component_;
}

void MavlinkGimbalProtocol::chooseManager(std::uint8_t system_id, std::uint8_t component_id)
{
  {
    std::lock_guard<std::mutex> lock(names_mutex_);
    manager_system_ = system_id;
    manager_component_ = component_id;
  }
  manager_known_ = true;
  requestInformation();
}

void MavlinkGimbalProtocol::handleInformation(const GimbalManagerInformation& information)
{
  if (settings_.gimbal_device_id != 0 && information.gimbal_device_id != settings_.gimbal_device_id)
  {
    ++counters_.foreign_frames;  // a manager sends one per gimbal: another gimbal's
    return;
  }
  gimbal_device_id_ = information.gimbal_device_id;
  Capabilities capabilities = this->capabilities();
  narrow(capabilities.axes[PAN], information.yaw_min, information.yaw_max);
  narrow(capabilities.axes[TILT], information.pitch_min, information.pitch_max);
  session_.setCapabilities(capabilities);
  if (!informed_)
  {
    informed_ = true;
    startIfReady();
    if (!in_control_)
    {
      takeControl();
    }
    requestAttitude();
  }
}

void MavlinkGimbalProtocol::startIfReady()
{
  if (informed_ && in_control_ && !ready_)
  {
    ready_ = true;
    ever_ready_ = true;
    session_.ready();
  }
}

void MavlinkGimbalProtocol::handleStatus(const GimbalManagerStatus& status)
{
  if (gimbal_device_id_ != 0 && status.gimbal_device_id != 0 && status.gimbal_device_id != gimbal_device_id_)
  {
    ++counters_.foreign_frames;
    return;
  }
  session_.reportAlive();
  holder_system_ = status.primary_control_sysid;
  holder_component_ = status.primary_control_compid;
  if (!startup_refusal_.empty())
  {
    session_.failStartup(startup_refusal_ + (holder_system_ != 0 || holder_component_ != 0 ? heldBy() : ""));
    startup_refusal_.clear();
    return;
  }
  const bool ours = holder_system_ == settings_.system_id && holder_component_ == settings_.component_id;
  if (ours && !in_control_)
  {
    in_control_ = true;
    startIfReady();
    if (setpoint_ != Setpoint::NONE && setpoint_ != Setpoint::STOP)
    {
      sendSetpoint();  // control came back: what the node last asked for, which a non-primary sender could not
    }
  }
  else if (!ours && in_control_)
  {
    in_control_ = false;
    ++counters_.control_lost;
    if (holder_system_ != 0 || holder_component_ != 0)
    {
      session_.reportFault(formatText("%s gave primary control of the gimbal to %s", deviceName().c_str(),
                                      controllerName(holder_system_, holder_component_).c_str()),
                           session_.currentCommand());
    }
  }
}

void MavlinkGimbalProtocol::handleAck(const CommandAck& ack)
{
  if ((ack.target_system != 0 && ack.target_system != settings_.system_id) ||
      (ack.target_component != 0 && ack.target_component != settings_.component_id))
  {
    return;  // another client's
  }
  const auto pending = pending_.find(ack.command);
  if (pending == pending_.end() || ack.result == Result::IN_PROGRESS)
  {
    return;
  }
  const std::uint64_t goal_command = pending->second.goal_command;
  pending_.erase(pending);
  session_.reportAlive();
  if (ack.result == Result::ACCEPTED)
  {
    if (ack.command == command_id::SET_MESSAGE_INTERVAL)
    {
      attitude_requested_ = true;
    }
    return;
  }
  ++counters_.acks_refused;
  std::string text =
      formatText("%s refused %s: %s", deviceName().c_str(), commandName(ack.command), toString(ack.result).c_str());
  if (ack.command == command_id::SET_MESSAGE_INTERVAL)
  {
    attitude_requested_ = true;  // the attitude comes at the manager's own rate; the state timeout judges it
    return;
  }
  if (ack.command == command_id::DO_GIMBAL_MANAGER_CONFIGURE)
  {
    if (holder_system_ != 0 || holder_component_ != 0)
    {
      text += heldBy();
    }
    else if (!ever_ready_)
    {
      // Who holds control comes with the manager's next status (5 Hz): say it, rather than fail without it.
      startup_refusal_ = text;
      refused_at_ = session_.now();
      return;
    }
  }
  if (!ever_ready_)
  {
    session_.failStartup(text);
  }
  else
  {
    session_.reportFault(text, goal_command);
  }
}

void MavlinkGimbalProtocol::handleAttitude(const GimbalDeviceAttitudeStatus& attitude)
{
  const std::uint8_t gimbal = gimbal_device_id_;
  if (gimbal != 0 && attitude.gimbal_device_id != 0 && attitude.gimbal_device_id != gimbal)
  {
    ++counters_.foreign_frames;
    return;
  }
  const PanTilt angles = panTiltFromQuaternion(attitude.q);
  // The frame the device reports its yaw in: the flags say, or (before those flags existed) YAW_LOCK means North.
  bool earth = (attitude.flags & gimbal_flags::YAW_IN_EARTH_FRAME) != 0;
  if ((attitude.flags & (gimbal_flags::YAW_IN_EARTH_FRAME | gimbal_flags::YAW_IN_VEHICLE_FRAME)) == 0)
  {
    earth = (attitude.flags & gimbal_flags::YAW_LOCK) != 0;
  }
  double pan = angles.pan;
  if (earth != settings_.yaw_lock)
  {
    if (!finite(attitude.delta_yaw))
    {
      ++counters_.unusable_attitudes;  // no delta_yaw to relate the frames: the state stays the last one
      return;
    }
    pan += earth ? -attitude.delta_yaw : attitude.delta_yaw;
  }
  ++counters_.attitudes;
  session_.reportState(AxisValues{ { wrapAngle(pan), angles.tilt, 1.0 } });
}

}  // namespace ptz_action_server

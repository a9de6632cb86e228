/**
 * \file
 * \brief MavlinkGimbalProtocol: what the gimbal manager sends (information, status, acknowledgements). Discovery is in
 * mavlink_gimbal_discovery.cpp, the attitude in mavlink_gimbal_attitude.cpp, what goes out in
 * mavlink_gimbal_protocol.cpp.
 */
#include <algorithm>
#include <cmath>

#include "mavlink_gimbal_internal.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/core/mavlink/mavlink_vehicle_messages.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
using namespace mavlink;
using namespace mavlink_gimbal_detail;

bool finite(float value)
{
  return std::isfinite(value);
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
      handleStatus(frame, decode<GimbalManagerStatus>(frame));
      return;
    case message_id::GIMBAL_MANAGER_INFORMATION:
      handleInformation(frame, decode<GimbalManagerInformation>(frame));
      return;
    case message_id::COMMAND_ACK:
      handleAck(frame, decode<CommandAck>(frame));
      return;
    case message_id::GIMBAL_DEVICE_ATTITUDE_STATUS:
      noteHeard(frame);
      handleAttitude(frame, decode<GimbalDeviceAttitudeStatus>(frame));
      return;
    case message_id::ATTITUDE:
      handleVehicleAttitude(frame);
      return;
    case message_id::MOUNT_ORIENTATION:
    case message_id::MOUNT_STATUS:
      noteHeard(frame);  // gimbal protocol v1: said at start-up when no manager answers
      return;
    default:
      return;  // known, but nothing the client side needs
  }
}

// ---------------------------------------------------------------- manager messages

bool MavlinkGimbalProtocol::fromManager(const Frame& frame) const
{
  return chosen_ && frame.header.system_id == gimbal_.system_id &&
         frame.header.component_id == gimbal_.manager_component;
}

bool MavlinkGimbalProtocol::namesOurGimbal(std::uint8_t gimbal_device_id) const
{
  // 0 names no gimbal: ours only when its manager has no other (a manager from before the ids were required).
  return gimbal_device_id == gimbal_.device_id || (gimbal_device_id == 0 && manager_gimbals_.size() <= 1);
}

void MavlinkGimbalProtocol::handleInformation(const Frame& frame, const GimbalManagerInformation& information)
{
  const MavlinkGimbalAddress address{ frame.header.system_id, frame.header.component_id, information.gimbal_device_id };
  if (!chosen_)
  {
    // A manager answers with one message per gimbal it manages.
    asked_[componentKey(address.system_id, address.manager_component)].answered = true;
    const auto known = std::find_if(found_.begin(), found_.end(),
                                    [&address](const FoundGimbal& found) { return found.address == address; });
    if (known != found_.end())
    {
      known->information = information;
      return;
    }
    found_.push_back(FoundGimbal{ address, information });
    std::vector<const FoundGimbal*> all;
    for (const FoundGimbal& found : found_)
    {
      all.push_back(&found);
    }
    std::lock_guard<std::mutex> lock(names_mutex_);
    found_names_ = foundList(all);
    return;
  }
  if (!fromManager(frame))
  {
    ++counters_.foreign_frames;
    return;
  }
  manager_gimbals_.insert(information.gimbal_device_id);
  if (!namesOurGimbal(information.gimbal_device_id))
  {
    ++counters_.foreign_frames;  // the manager's other gimbal
    return;
  }
  applyInformation(information);
}

void MavlinkGimbalProtocol::applyInformation(const GimbalManagerInformation& information)
{
  Capabilities capabilities = this->capabilities();
  narrow(capabilities.axes[PAN], information.yaw_min, information.yaw_max);
  narrow(capabilities.axes[TILT], information.pitch_min, information.pitch_max);
  session_.setCapabilities(capabilities);
  if (!informed_)
  {
    informed_ = true;
    startIfReady();
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

void MavlinkGimbalProtocol::handleStatus(const Frame& frame, const GimbalManagerStatus& status)
{
  if (!chosen_)
  {
    // A manager: ask it for its gimbals, and keep who controls each for the choice.
    askCandidate(frame.header.system_id, frame.header.component_id);
    statuses_[gimbalKey(
        MavlinkGimbalAddress{ frame.header.system_id, frame.header.component_id, status.gimbal_device_id })] = status;
    return;
  }
  if (!fromManager(frame))
  {
    ++counters_.foreign_frames;
    return;
  }
  if (status.gimbal_device_id != 0)
  {
    manager_gimbals_.insert(status.gimbal_device_id);
  }
  if (!namesOurGimbal(status.gimbal_device_id))
  {
    ++counters_.foreign_frames;  // the manager's other gimbal
    return;
  }
  session_.reportAlive();
  status_seen_ = true;
  holder_system_ = status.primary_control_sysid;
  holder_component_ = status.primary_control_compid;
  if (!startup_refusal_.empty())
  {
    session_.failStartup(startup_refusal_ + (holder_system_ != 0 || holder_component_ != 0 ? heldBy() : ""));
    startup_refusal_.clear();
    return;
  }
  const bool ours = holder_system_ == settings_.system_id && holder_component_ == settings_.component_id;
  if (!ours && !in_control_ && control_requested_ && !ever_ready_ && (holder_system_ != 0 || holder_component_ != 0))
  {
    warnPreviousController(holder_system_, holder_component_);  // its status crossed our request
  }
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

void MavlinkGimbalProtocol::handleAck(const Frame& frame, const CommandAck& ack)
{
  if ((ack.target_system != 0 && ack.target_system != settings_.system_id) ||
      (ack.target_component != 0 && ack.target_component != settings_.component_id))
  {
    return;  // another client's
  }
  const std::uint32_t key = static_cast<std::uint32_t>(ack.command) << 16 |
                            static_cast<std::uint32_t>(frame.header.system_id) << 8 | frame.header.component_id;
  const auto pending = pending_.find(key);
  if (pending == pending_.end() || ack.result == Result::IN_PROGRESS)
  {
    return;
  }
  const std::uint64_t goal_command = pending->second.goal_command;
  pending_.erase(pending);
  if (ack.command == command_id::REQUEST_MESSAGE && !fromManager(frame))
  {
    if (ack.result != Result::ACCEPTED)
    {
      // Asked during discovery, and no gimbal manager (a gimbal device beside its manager, a plain autopilot).
      asked_[componentKey(frame.header.system_id, frame.header.component_id)].answered = true;
    }
    return;
  }
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
    attitude_requested_ = true;  // the attitude comes at the device's own rate; the state timeout judges it
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

}  // namespace ptz_action_server

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

double wrapGimbalAngle(double angle)
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

/// An index of a component.
std::uint16_t componentKey(std::uint8_t system_id, std::uint8_t component_id)
{
  return static_cast<std::uint16_t>(system_id << 8 | component_id);
}

std::uint32_t gimbalKey(const MavlinkGimbalAddress& address)
{
  return static_cast<std::uint32_t>(address.system_id) << 16 |
         static_cast<std::uint32_t>(address.manager_component) << 8 | address.device_id;
}

/// A component whose heartbeat says it may host a gimbal manager: an autopilot (PX4 and ArduPilot manage the gimbals
/// attached to them), or a gimbal (which may manage itself).
bool mayManageGimbals(const Heartbeat& heartbeat, std::uint8_t component_id)
{
  const bool autopilot = heartbeat.autopilot != MAV_AUTOPILOT_INVALID && heartbeat.type != MAV_TYPE_GCS;
  const bool gimbal_id = component_id == MAV_COMP_ID_GIMBAL ||
                         (component_id >= MAV_COMP_ID_GIMBAL2 && component_id <= MAV_COMP_ID_GIMBAL6);
  return autopilot || heartbeat.type == MAV_TYPE_GIMBAL || gimbal_id;
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
      handleAttitude(frame, decode<GimbalDeviceAttitudeStatus>(frame));
      return;
    default:
      return;  // known, but nothing the client side needs
  }
}

void MavlinkGimbalProtocol::handleHeartbeat(const Frame& frame)
{
  if (!chosen_ && mayManageGimbals(decode<Heartbeat>(frame), frame.header.component_id))
  {
    askCandidate(frame.header.system_id, frame.header.component_id);
  }
}

// ---------------------------------------------------------------- discovery

bool MavlinkGimbalProtocol::managerAllowed(std::uint8_t system_id, std::uint8_t component_id) const
{
  return (settings_.target_system == 0 || settings_.target_system == system_id) &&
         (settings_.target_component == 0 || settings_.target_component == component_id);
}

bool MavlinkGimbalProtocol::gimbalAllowed(const MavlinkGimbalAddress& address) const
{
  return managerAllowed(address.system_id, address.manager_component) &&
         (settings_.gimbal_device_id == 0 || settings_.gimbal_device_id == address.device_id);
}

void MavlinkGimbalProtocol::askCandidate(std::uint8_t system_id, std::uint8_t component_id)
{
  if (!managerAllowed(system_id, component_id))
  {
    return;
  }
  Asked& asked = asked_[componentKey(system_id, component_id)];
  if (asked.answered || asked.times >= 3 || (asked.times > 0 && !due(asked.last_at, settings_.resend_period)))
  {
    return;
  }
  const TimePoint now = session_.now();
  if (asked.times == 0)
  {
    asked.first_at = now;
  }
  asked.last_at = now;
  ++asked.times;
  requestInformation(system_id, component_id);
}

void MavlinkGimbalProtocol::discover()
{
  if (discovery_failed_)
  {
    return;
  }
  // Ask again whoever has not answered (a lost datagram).
  for (auto& entry : asked_)
  {
    if (!entry.second.answered)
    {
      askCandidate(static_cast<std::uint8_t>(entry.first >> 8), static_cast<std::uint8_t>(entry.first & 0xFF));
    }
  }
  std::vector<const FoundGimbal*> matching;
  for (const FoundGimbal& found : found_)
  {
    if (gimbalAllowed(found.address))
    {
      matching.push_back(&found);
    }
  }
  const bool named_in_full =
      settings_.target_system != 0 && settings_.target_component != 0 && settings_.gimbal_device_id != 0;
  if (named_in_full && matching.size() == 1)
  {
    choose(*matching.front());
    return;
  }
  if (!due(listening_since_, settings_.discovery_time))
  {
    return;
  }
  for (const auto& entry : asked_)
  {
    if (!entry.second.answered && !due(entry.second.first_at, settings_.resend_period))
    {
      return;  // a possible manager asked a moment ago: its gimbals may be on their way
    }
  }
  if (matching.size() == 1)
  {
    choose(*matching.front());
    return;
  }
  if (matching.empty() && found_.empty())
  {
    return;  // nothing yet: the start-up timeout says so
  }
  std::vector<const FoundGimbal*> all;
  for (const FoundGimbal& found : found_)
  {
    all.push_back(&found);
  }
  discovery_failed_ = true;
  if (matching.empty())
  {
    session_.failStartup(formatText("no gimbal found matches target_system %u, target_component %u, "
                                    "gimbal_device_id %u (0: any); found: %s",
                                    settings_.target_system, settings_.target_component, settings_.gimbal_device_id,
                                    foundList(all).c_str()));
    return;
  }
  // Several: say which setting tells them apart.
  bool same_manager = true;
  for (const FoundGimbal* found : matching)
  {
    same_manager = same_manager && found->address.system_id == matching.front()->address.system_id &&
                   found->address.manager_component == matching.front()->address.manager_component;
  }
  session_.failStartup(formatText("several gimbals found and none chosen: %s; choose one with %s",
                                  foundList(matching).c_str(),
                                  same_manager ? "gimbal_device_id (its id in the list)" :
                                                 "target_system and target_component (its manager) and, if that "
                                                 "manager has several, "
                                                 "gimbal_device_id"));
}

std::string MavlinkGimbalProtocol::foundList(const std::vector<const FoundGimbal*>& gimbals) const
{
  std::string list;
  for (const FoundGimbal* found : gimbals)
  {
    list += (list.empty() ? "" : ", ") + found->address.describe();
  }
  return list;
}

void MavlinkGimbalProtocol::choose(const FoundGimbal& found)
{
  {
    std::lock_guard<std::mutex> lock(names_mutex_);
    chosen_ = true;
    gimbal_ = found.address;
  }
  chosen_at_ = session_.now();
  manager_gimbals_.clear();
  for (const FoundGimbal& other : found_)
  {
    if (other.address.system_id == gimbal_.system_id && other.address.manager_component == gimbal_.manager_component)
    {
      manager_gimbals_.insert(other.address.device_id);
    }
  }
  const auto status = statuses_.find(gimbalKey(gimbal_));
  if (status != statuses_.end())
  {
    status_seen_ = true;
    holder_system_ = status->second.primary_control_sysid;
    holder_component_ = status->second.primary_control_compid;
  }
  statuses_.clear();
  asked_.clear();
  applyInformation(found.information);
  requestAttitude();
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

// ---------------------------------------------------------------- the attitude

bool MavlinkGimbalProtocol::isOurAttitude(const Frame& frame, const GimbalDeviceAttitudeStatus& attitude) const
{
  if (!chosen_ || frame.header.system_id != gimbal_.system_id)
  {
    return false;
  }
  const std::uint8_t sender = frame.header.component_id;
  const std::uint8_t id = attitude.gimbal_device_id;
  if (gimbal_.device_id == 0 || isInternalGimbalId(gimbal_.device_id))
  {
    // A gimbal inside its manager: the manager's component sends its attitude with its id.
    return sender == gimbal_.manager_component && namesOurGimbal(id);
  }
  // A MAVLink gimbal device sends its own, with 0 (the protocol's value; its own id is taken too); a manager that
  // relays it names it.
  return (sender == gimbal_.device_id && (id == 0 || id == gimbal_.device_id)) ||
         (sender == gimbal_.manager_component && id == gimbal_.device_id);
}

void MavlinkGimbalProtocol::handleAttitude(const Frame& frame, const GimbalDeviceAttitudeStatus& attitude)
{
  if (!chosen_)
  {
    return;  // no gimbal of ours yet
  }
  if (!isOurAttitude(frame, attitude))
  {
    ++counters_.other_attitudes;
    return;
  }
  const PanTilt angles = panTiltFromQuaternion(attitude.q);
  // The frame the device reports its yaw in: the flags say, or (before those flags existed) YAW_LOCK means North.
  const bool earth = yawInEarthFrame(attitude.flags);
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
  session_.reportState(AxisValues{ { wrapGimbalAngle(pan), angles.tilt, 1.0 } });
}

}  // namespace ptz_action_server

/**
 * \file
 * \brief MavlinkGimbalProtocol: discovery, from the first HEARTBEAT to the gimbal chosen, and what the start says when
 * the vehicle has no gimbal manager.
 */
#include <algorithm>

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

/// A component whose heartbeat says it may host a gimbal manager: an autopilot (PX4 and ArduPilot manage the gimbals
/// attached to them), or a gimbal (which may manage itself).
bool mayManageGimbals(const Heartbeat& heartbeat, std::uint8_t component_id)
{
  const bool autopilot = heartbeat.autopilot != MAV_AUTOPILOT_INVALID && heartbeat.type != MAV_TYPE_GCS;
  const bool gimbal_id = component_id == MAV_COMP_ID_GIMBAL ||
                         (component_id >= MAV_COMP_ID_GIMBAL2 && component_id <= MAV_COMP_ID_GIMBAL6);
  return autopilot || heartbeat.type == MAV_TYPE_GIMBAL || gimbal_id;
}

const char* autopilotName(std::uint8_t autopilot)
{
  switch (autopilot)
  {
    case MAV_AUTOPILOT_PX4:
      return " (PX4)";
    case MAV_AUTOPILOT_ARDUPILOTMEGA:
      return " (ArduPilot)";
    default:
      return "";
  }
}
}  // namespace

void MavlinkGimbalProtocol::handleHeartbeat(const Frame& frame)
{
  const Heartbeat heartbeat = decode<Heartbeat>(frame);
  Heard& heard = heard_[componentKey(frame.header.system_id, frame.header.component_id)];
  heard.autopilot = heartbeat.autopilot;  // kept after the choice too: the yaw frame of PX4's own gimbal output
  heard.type = heartbeat.type;
  if (!chosen_ && mayManageGimbals(heartbeat, frame.header.component_id))
  {
    askCandidate(frame.header.system_id, frame.header.component_id);
  }
}

void MavlinkGimbalProtocol::noteHeard(const Frame& frame)
{
  if (chosen_)
  {
    return;
  }
  Heard& heard = heard_[componentKey(frame.header.system_id, frame.header.component_id)];
  heard.mount_orientation = heard.mount_orientation || frame.message_id == message_id::MOUNT_ORIENTATION;
  heard.mount_status = heard.mount_status || frame.message_id == message_id::MOUNT_STATUS;
  heard.device_attitude = heard.device_attitude || frame.message_id == message_id::GIMBAL_DEVICE_ATTITUDE_STATUS;
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
    failWithoutManager();  // when no one is left to ask: what the vehicle speaks instead (else the start-up timeout)
    return;
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

bool MavlinkGimbalProtocol::failWithoutManager()
{
  if (asked_.empty())
  {
    return false;  // no one to ask yet: nothing heard at all ends in the start-up timeout
  }
  for (const auto& entry : asked_)
  {
    const Asked& asked = entry.second;
    if (!asked.answered && (asked.times < 3 || !due(asked.last_at, settings_.resend_period)))
    {
      return false;  // still asking, or an answer may be on its way
    }
  }
  // Every possible manager refused REQUEST_MESSAGE GIMBAL_MANAGER_INFORMATION or never answered it: say what was heard.
  std::string heard_text;
  bool v1 = false;
  bool px4 = false;
  bool ardupilot = false;
  for (const auto& entry : heard_)
  {
    const Heard& heard = entry.second;
    const std::string who =
        controllerName(static_cast<std::uint8_t>(entry.first >> 8), static_cast<std::uint8_t>(entry.first & 0xFF));
    px4 = px4 || heard.autopilot == MAV_AUTOPILOT_PX4;
    ardupilot = ardupilot || heard.autopilot == MAV_AUTOPILOT_ARDUPILOTMEGA;
    std::string said;
    if (heard.mount_orientation || heard.mount_status)
    {
      v1 = true;
      said = std::string("speaks gimbal protocol v1 (it sends ") +
             (heard.mount_orientation && heard.mount_status ? "MOUNT_ORIENTATION and MOUNT_STATUS" :
              heard.mount_orientation                       ? "MOUNT_ORIENTATION" :
                                                              "MOUNT_STATUS") +
             ")";
    }
    else if (heard.device_attitude)
    {
      said = "is a gimbal device (it sends GIMBAL_DEVICE_ATTITUDE_STATUS) with no gimbal manager";
    }
    else if (heard.autopilot != MAV_AUTOPILOT_INVALID && heard.type != MAV_TYPE_GCS)
    {
      said = "sends HEARTBEATs but no gimbal message at all";
    }
    else
    {
      continue;
    }
    const char* kind = heard.autopilot != MAV_AUTOPILOT_INVALID ? "the autopilot " : "the component ";
    heard_text += (heard_text.empty() ? "" : "; ") + (kind + who) + autopilotName(heard.autopilot) + " " + said;
  }
  if (heard_text.empty())
  {
    return false;  // only others' frames: the start-up timeout says so
  }
  std::string remedy = "a gimbal manager (MAVLink Gimbal Protocol v2) is needed: ";
  if (px4 || !ardupilot)
  {
    remedy += "on PX4 (1.13 or later) set MNT_MODE_IN to 4 (MAVLink gimbal protocol v2) and MNT_MODE_OUT to 0 "
              "(AUX) or 2 (MAVLink gimbal protocol v2), then reboot";
  }
  if (ardupilot || !px4)
  {
    remedy += std::string(px4 || !ardupilot ? "; " : "") + "on ArduPilot (4.3 or later; 4.4 for "
                                                           "GIMBAL_MANAGER_INFORMATION) set MNT1_TYPE to the mount's "
                                                           "driver";
  }
  discovery_failed_ = true;
  session_.failStartup(formatText("no gimbal manager answered REQUEST_MESSAGE GIMBAL_MANAGER_INFORMATION: %s%s; %s",
                                  heard_text.c_str(), v1 ? " (the old protocol: this node speaks only v2)" : "",
                                  remedy.c_str()));
  return true;
}

}  // namespace ptz_action_server

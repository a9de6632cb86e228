#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using namespace mavlink;

/// DO_GIMBAL_MANAGER_CONFIGURE's "leave unchanged" and "release" values.
constexpr float UNCHANGED = -1.0f;
constexpr float RELEASE = -3.0f;
/// s a stop keeps repeating its zero rates (against a lost datagram).
constexpr double STOP_REPEAT = 0.5;

}  // namespace

std::string MavlinkGimbalAddress::describe() const
{
  const std::string manager =
      " of the gimbal manager " + std::to_string(system_id) + "/" + std::to_string(manager_component);
  if (device_id == 0)
  {
    return "the gimbal (gimbal_device_id 0)" + manager;
  }
  if (isInternalGimbalId(device_id))
  {
    return "gimbal_device_id " + std::to_string(device_id) + manager;
  }
  return "gimbal_device_id " + std::to_string(device_id) + " (the gimbal device " + std::to_string(system_id) + "/" +
         std::to_string(device_id) + ")" + manager;
}

MavlinkGimbalProtocol::MavlinkGimbalProtocol(const MavlinkGimbalSettings& settings, DeviceSession& session)
  : settings_(settings), session_(session)
{
}

std::string MavlinkGimbalProtocol::deviceName() const
{
  std::lock_guard<std::mutex> lock(names_mutex_);
  if (!chosen_)
  {
    return "the MAVLink gimbal manager";
  }
  // "the MAVLink gimbal manager 1/1 (gimbal_device_id 154, the gimbal device 1/154)"
  std::string text = "the MAVLink gimbal manager " + controllerName(gimbal_.system_id, gimbal_.manager_component) +
                     " (gimbal_device_id " + std::to_string(gimbal_.device_id);
  if (gimbal_.device_id != 0 && !isInternalGimbalId(gimbal_.device_id))
  {
    text += ", the gimbal device " + controllerName(gimbal_.system_id, gimbal_.device_id);
  }
  return text + ")";
}

MavlinkGimbalAddress MavlinkGimbalProtocol::gimbal() const
{
  std::lock_guard<std::mutex> lock(names_mutex_);
  return chosen_ ? gimbal_ : MavlinkGimbalAddress{};
}

std::string MavlinkGimbalProtocol::heldBy() const
{
  return " (primary control of the gimbal is held by " + controllerName(holder_system_, holder_component_) + ")";
}

std::string MavlinkGimbalProtocol::controllerName(std::uint8_t system_id, std::uint8_t component_id) const
{
  return std::to_string(system_id) + "/" + std::to_string(component_id);
}

Capabilities MavlinkGimbalProtocol::capabilities() const
{
  Capabilities capabilities;
  capabilities.axes[PAN] = settings_.pan;
  capabilities.axes[TILT] = settings_.tilt;
  for (Axis axis : { PAN, TILT })
  {
    // GIMBAL_MANAGER_SET_PITCHYAW takes angles and rates; GIMBAL_DEVICE_ATTITUDE_STATUS reports the attitude.
    capabilities.axes[axis].present = true;
    capabilities.axes[axis].absolute = true;
    capabilities.axes[axis].velocity = true;
    capabilities.axes[axis].feedback = true;
  }
  capabilities.axes[ZOOM] = absentAxis("a MAVLink gimbal has no zoom (a camera's zoom is not part of Gimbal Protocol "
                                       "v2)");
  return capabilities;
}

// ---------------------------------------------------------------- the link

void MavlinkGimbalProtocol::onConnected()
{
  parser_.reset();
  pending_.clear();
  in_control_ = false;
  informed_ = false;
  ready_ = false;
  status_seen_ = false;
  control_requested_ = false;
  attitude_requested_ = false;
  attitude_asks_ = 0;
  holder_system_ = holder_component_ = 0;
  const TimePoint now = session_.now();
  heartbeat_at_ = now;
  listening_since_ = now;
  chosen_at_ = now;
  send(Heartbeat{});
  if (chosen_)
  {
    requestInformation(gimbal_.system_id, gimbal_.manager_component);  // the manager may have restarted: its limits
  }
  else
  {
    asked_.clear();
    if (settings_.target_system != 0 && settings_.target_component != 0)
    {
      askCandidate(settings_.target_system, settings_.target_component);
    }
  }
}

void MavlinkGimbalProtocol::onDisconnected()
{
  in_control_ = false;
  parser_.reset();
}

void MavlinkGimbalProtocol::onReceived(const std::uint8_t* data, std::size_t size)
{
  parser_.feed(data, size, [this](const Frame& frame) { handle(frame); });
  const ParserCounts& counts = parser_.counts();
  counters_.frames.set(counts.frames);
  for (std::size_t index = 0; index < FRAME_ERROR_COUNT; ++index)
  {
    counters_.bad[index].set(counts.errors[index]);
  }
  session_.reportDropped(counts.noise_bytes - dropped_reported_);
  dropped_reported_ = counts.noise_bytes;
}

void MavlinkGimbalProtocol::poll()
{
  const TimePoint now = session_.now();
  if (!startup_refusal_.empty() && due(refused_at_, settings_.resend_period))
  {
    session_.failStartup(startup_refusal_);  // no status came to say who holds control
    startup_refusal_.clear();
  }
  if (due(heartbeat_at_, settings_.heartbeat_period))
  {
    heartbeat_at_ = now;
    send(Heartbeat{});
  }
  if (!chosen_)
  {
    discover();
  }
  else
  {
    if (!informed_ && due(information_asked_at_, settings_.resend_period))
    {
      requestInformation(gimbal_.system_id, gimbal_.manager_component);
    }
    // Take control at start-up, and back when it comes free; never from another controller unasked. Look at the
    // gimbal's status first (who holds control), waiting for it no longer than resend_period.
    const bool control_free = holder_system_ == 0 && holder_component_ == 0;
    const bool status_known = status_seen_ || due(chosen_at_, settings_.resend_period);
    if (informed_ && !in_control_ && status_known && (control_free || !ever_ready_) &&
        due(control_asked_at_, settings_.resend_period))
    {
      takeControl();
    }
    if (!attitude_requested_ && due(attitude_asked_at_, settings_.resend_period))
    {
      requestAttitude();
    }
  }
  switch (setpoint_)
  {
    case Setpoint::POSITION:
      if (due(setpoint_sent_at_, settings_.resend_period))
      {
        sendSetpoint();
      }
      break;
    case Setpoint::RATES:
      if (due(setpoint_sent_at_, settings_.rate_period))
      {
        sendSetpoint();
      }
      break;
    case Setpoint::STOP:
      if (now < stop_until_ && due(setpoint_sent_at_, settings_.rate_period))
      {
        sendSetpoint();
      }
      break;
    case Setpoint::NONE:
      break;
  }
}

// ---------------------------------------------------------------- what goes out

template <class Message>
void MavlinkGimbalProtocol::send(const Message& message)
{
  const EncodedFrame frame = encode(FrameHeader{ sequence_++, settings_.system_id, settings_.component_id }, message);
  session_.write(frame.data(), frame.size);
}

void MavlinkGimbalProtocol::sendCommand(std::uint16_t command, const std::array<float, 7>& params)
{
  sendCommandTo(gimbal_.system_id, gimbal_.manager_component, command, params);
}

void MavlinkGimbalProtocol::sendCommandTo(std::uint8_t system_id, std::uint8_t component_id, std::uint16_t command,
                                          const std::array<float, 7>& params)
{
  CommandLong message;
  message.params = params;
  message.command = command;
  message.target_system = system_id;
  message.target_component = component_id;
  const std::uint32_t key =
      static_cast<std::uint32_t>(command) << 16 | static_cast<std::uint32_t>(system_id) << 8 | component_id;
  pending_[key] = PendingCommand{ session_.currentCommand(), session_.now() };
  send(message);
}

void MavlinkGimbalProtocol::requestInformation(std::uint8_t system_id, std::uint8_t component_id)
{
  information_asked_at_ = session_.now();
  sendCommandTo(system_id, component_id, command_id::REQUEST_MESSAGE,
                { static_cast<float>(message_id::GIMBAL_MANAGER_INFORMATION), 0, 0, 0, 0, 0, 0 });
}

void MavlinkGimbalProtocol::takeControl()
{
  if (!ever_ready_ && (holder_system_ != 0 || holder_component_ != 0) &&
      !(holder_system_ == settings_.system_id && holder_component_ == settings_.component_id))
  {
    warnPreviousController(holder_system_, holder_component_);
  }
  control_asked_at_ = session_.now();
  control_requested_ = true;
  // param7: this gimbal only (0 would configure every gimbal of the manager's component).
  sendCommand(command_id::DO_GIMBAL_MANAGER_CONFIGURE,
              { static_cast<float>(settings_.system_id), static_cast<float>(settings_.component_id), UNCHANGED,
                UNCHANGED, 0, 0, static_cast<float>(gimbal_.device_id) });
}

void MavlinkGimbalProtocol::warnPreviousController(std::uint8_t system_id, std::uint8_t component_id)
{
  if (warned_)
  {
    return;
  }
  warned_ = true;
  {
    std::lock_guard<std::mutex> lock(names_mutex_);
    previous_controller_ = controllerName(system_id, component_id);
  }
  session_.warn(formatText("taking primary control of %s from %s, which held it (GIMBAL_MANAGER_STATUS); it may have "
                           "been driving the gimbal (a mission, a ground station, a tracker)",
                           gimbal_.describe().c_str(), controllerName(system_id, component_id).c_str()));
}

void MavlinkGimbalProtocol::requestAttitude()
{
  // Asked of the component that sends the attitude; one that never answers is asked three times, then left to its
  // own rate (the state timeout judges it).
  attitude_asked_at_ = session_.now();
  if (++attitude_asks_ >= 3)
  {
    attitude_requested_ = true;
  }
  sendCommandTo(gimbal_.system_id, gimbal_.attitudeComponent(), command_id::SET_MESSAGE_INTERVAL,
                { static_cast<float>(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS),
                  static_cast<float>(settings_.attitude_interval * 1e6), 0, 0, 0, 0, 0 });
}

std::uint32_t MavlinkGimbalProtocol::setpointFlags() const
{
  // Without YAW_LOCK the yaw is the vehicle's (PX4 dropped YAW_IN_EARTH_FRAME; YAW_LOCK is what every manager takes).
  return settings_.yaw_lock ? gimbal_flags::YAW_LOCK : 0;
}

void MavlinkGimbalProtocol::sendSetpoint()
{
  GimbalManagerSetPitchYaw message;
  message.flags = setpointFlags();
  switch (setpoint_)
  {
    case Setpoint::POSITION:
      message.pitch = static_cast<float>(setpoint_values_[TILT]);
      message.yaw = static_cast<float>(setpoint_values_[PAN]);
      break;
    case Setpoint::RATES:
      message.pitch_rate = static_cast<float>(setpoint_values_[TILT]);
      message.yaw_rate = static_cast<float>(setpoint_values_[PAN]);
      break;
    case Setpoint::STOP:
      message.pitch_rate = 0.0f;
      message.yaw_rate = 0.0f;
      break;
    case Setpoint::NONE:
      return;
  }
  if (!chosen_)
  {
    return;  // sent once there is a gimbal to send it to
  }
  message.target_system = gimbal_.system_id;
  message.target_component = gimbal_.manager_component;
  message.gimbal_device_id = gimbal_.device_id;
  setpoint_sent_at_ = session_.now();
  ++counters_.setpoints;
  send(message);
}

// ---------------------------------------------------------------- the node's commands

void MavlinkGimbalProtocol::goTo(const AxisValues& position)
{
  setpoint_ = Setpoint::POSITION;
  setpoint_values_ = position;
  if (!in_control_ && informed_)
  {
    takeControl();  // refused: the goal aborts with the manager's result
  }
  sendSetpoint();
}

void MavlinkGimbalProtocol::moveAtVelocity(const AxisValues& velocity)
{
  if (velocity[PAN] == 0.0 && velocity[TILT] == 0.0)
  {
    stop();
    return;
  }
  setpoint_ = Setpoint::RATES;
  setpoint_values_ = velocity;
  if (!in_control_ && informed_)
  {
    takeControl();
  }
  sendSetpoint();
}

void MavlinkGimbalProtocol::stop()
{
  setpoint_ = Setpoint::STOP;
  stop_until_ = session_.now() + toDuration(STOP_REPEAT);
  sendSetpoint();
}

void MavlinkGimbalProtocol::shutdown()
{
  // Release what we asked for (control may have been granted without its status having come yet), of our gimbal
  // only: -3 releases it if it is ours, and leaves it to another controller that took it since.
  if (!chosen_ || !session_.connected() || !(in_control_ || control_requested_))
  {
    return;
  }
  stop();
  sendCommand(command_id::DO_GIMBAL_MANAGER_CONFIGURE,
              { RELEASE, RELEASE, UNCHANGED, UNCHANGED, 0, 0, static_cast<float>(gimbal_.device_id) });
}

void MavlinkGimbalProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  {
    std::lock_guard<std::mutex> lock(names_mutex_);
    values.emplace_back("gimbal manager",
                        chosen_ ? controllerName(gimbal_.system_id, gimbal_.manager_component) : "not chosen yet");
    values.emplace_back("gimbal", chosen_ ? gimbal_.describe() : "not chosen yet");
    values.emplace_back("gimbals found", found_names_.empty() ? "none yet" : found_names_);
    values.emplace_back("previous controller", previous_controller_.empty() ? "none" : previous_controller_);
  }
  values.emplace_back("primary control", in_control_ ? "ours" : "not ours");
  values.emplace_back("yaw frame", settings_.yaw_lock ? "North (YAW_LOCK)" : "vehicle");
  static const char* const FRAMES[] = { "auto", "flags", "vehicle", "North" };
  const int seen = attitude_frame_;
  values.emplace_back("attitude yaw frame", std::string(FRAMES[static_cast<int>(settings_.attitude_yaw_frame)]) + ": " +
                                                (seen < 0  ? "no attitude yet" :
                                                 seen == 1 ? "read as North" :
                                                             "read as the vehicle's"));
  addCounts(values, { { "frames", counters_.frames },
                      { "attitudes", counters_.attitudes },
                      { "attitudes of other gimbals", counters_.other_attitudes },
                      { "setpoints sent", counters_.setpoints },
                      { "commands refused", counters_.acks_refused },
                      { "control lost", counters_.control_lost },
                      { "attitudes without delta_yaw", counters_.unusable_attitudes },
                      { "frames for others", counters_.foreign_frames } });
  for (std::size_t index = 0; index < counters_.bad.size(); ++index)
  {
    values.emplace_back(std::string("dropped: ") + toString(static_cast<FrameError>(index)),
                        std::to_string(counters_.bad[index]));
  }
}

}  // namespace ptz_action_server

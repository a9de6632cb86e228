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

MavlinkGimbalProtocol::MavlinkGimbalProtocol(const MavlinkGimbalSettings& settings, DeviceSession& session)
  : settings_(settings), session_(session)
{
  gimbal_device_id_ = settings_.gimbal_device_id;
}

std::string MavlinkGimbalProtocol::deviceName() const
{
  return "the MAVLink gimbal manager" + managerName();
}

std::string MavlinkGimbalProtocol::managerName() const
{
  std::lock_guard<std::mutex> lock(names_mutex_);
  if (manager_system_ == 0 && manager_component_ == 0)
  {
    return "";
  }
  return " " + controllerName(manager_system_, manager_component_);
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
  capabilities.axes[ZOOM] = absentAxis("a MAVLink gimbal has no zoom");
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
  attitude_requested_ = false;
  holder_system_ = holder_component_ = 0;
  const TimePoint now = session_.now();
  heartbeat_at_ = now;
  send(Heartbeat{});
  if (settings_.target_system != 0 && settings_.target_component != 0)
  {
    chooseManager(settings_.target_system, settings_.target_component);
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
  if (manager_known_)
  {
    if (!informed_ && due(information_asked_at_, settings_.resend_period))
    {
      requestInformation();
    }
    // Take control at start-up, and back when it comes free; never from another controller unasked.
    const bool control_free = holder_system_ == 0 && holder_component_ == 0;
    if (informed_ && !in_control_ && (control_free || !ever_ready_) && due(control_asked_at_, settings_.resend_period))
    {
      takeControl();
    }
    if (informed_ && !attitude_requested_ && due(attitude_asked_at_, settings_.resend_period))
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
  sendCommandTo(manager_system_, manager_component_, command, params);
}

void MavlinkGimbalProtocol::sendCommandTo(std::uint8_t system_id, std::uint8_t component_id, std::uint16_t command,
                                          const std::array<float, 7>& params)
{
  CommandLong message;
  message.params = params;
  message.command = command;
  message.target_system = system_id;
  message.target_component = component_id;
  pending_[command] = PendingCommand{ session_.currentCommand(), session_.now() };
  send(message);
}

void MavlinkGimbalProtocol::requestInformation()
{
  requestInformation(manager_system_, manager_component_);
}

void MavlinkGimbalProtocol::requestInformation(std::uint8_t system_id, std::uint8_t component_id)
{
  information_asked_at_ = session_.now();
  sendCommandTo(system_id, component_id, command_id::REQUEST_MESSAGE,
                { static_cast<float>(message_id::GIMBAL_MANAGER_INFORMATION), 0, 0, 0, 0, 0, 0 });
}

void MavlinkGimbalProtocol::takeControl()
{
  control_asked_at_ = session_.now();
  sendCommand(command_id::DO_GIMBAL_MANAGER_CONFIGURE,
              { static_cast<float>(settings_.system_id), static_cast<float>(settings_.component_id), UNCHANGED,
                UNCHANGED, 0, 0, static_cast<float>(gimbal_device_id_.load()) });
}

void MavlinkGimbalProtocol::requestAttitude()
{
  attitude_asked_at_ = session_.now();
  sendCommand(command_id::SET_MESSAGE_INTERVAL,
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
  message.target_system = manager_system_;
  message.target_component = manager_component_;
  message.gimbal_device_id = gimbal_device_id_;
  setpoint_sent_at_ = session_.now();
  ++counters_.setpoints;
  send(message);
}

// ---------------------------------------------------------------- the node's commands

void MavlinkGimbalProtocol::goTo(const AxisValues& position)
{
  setpoint_ = Setpoint::POSITION;
  setpoint_values_ = position;
  if (!in_control_ && manager_known_)
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
  if (!in_control_ && manager_known_)
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
  if (!in_control_ || !session_.connected())
  {
    return;
  }
  stop();
  sendCommand(command_id::DO_GIMBAL_MANAGER_CONFIGURE,
              { RELEASE, RELEASE, UNCHANGED, UNCHANGED, 0, 0, static_cast<float>(gimbal_device_id_.load()) });
}

void MavlinkGimbalProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("gimbal manager", managerName().empty() ? "not found yet" : managerName().substr(1));
  values.emplace_back("gimbal device id", std::to_string(gimbal_device_id_.load()));
  values.emplace_back("primary control", in_control_ ? "ours" : "not ours");
  values.emplace_back("yaw frame", settings_.yaw_lock ? "North (YAW_LOCK)" : "vehicle");
  addCounts(values, { { "frames", counters_.frames },
                      { "attitudes", counters_.attitudes },
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

std::unique_ptr<DeviceBackend> makeMavlinkGimbalBackend(const MavlinkGimbalConfig& config,
                                                        std::shared_ptr<const Clock> clock)
{
  return makeDeviceBackend<MavlinkGimbalProtocol>(config.link, config.session, config.gimbal, std::move(clock));
}

}  // namespace ptz_action_server

#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using namespace mavlink;

constexpr std::size_t MAX_DATAGRAM = 2048;
constexpr double UDP_TICK = 0.01;  ///< s: the longest the UDP thread waits before looking at the clock again
constexpr float UNCHANGED = -1.0f;
constexpr float MANAGER_ITSELF = -2.0f;
constexpr float RELEASE = -3.0f;
/// GIMBAL_MANAGER_CAP_FLAGS of a two-axis gimbal: HAS_PITCH_AXIS | HAS_PITCH_FOLLOW | HAS_PITCH_LOCK |
/// HAS_YAW_AXIS | HAS_YAW_FOLLOW | HAS_YAW_LOCK.
constexpr std::uint32_t CAPABILITIES = 0x10 | 0x20 | 0x40 | 0x80 | 0x100 | 0x200;
}  // namespace

SimDeviceConfig MavlinkGimbalEmulatorConfig::defaultDevice()
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  device.axes[TILT].range = AxisRange{ -M_PI / 2.0, M_PI / 4.0 };
  device.axes[TILT].resolution = 0.0;
  device.axes[PAN].resolution = 0.0;
  device.axes[ZOOM].present = false;
  device.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  return device;
}

MavlinkGimbalEmulator::MavlinkGimbalEmulator(const MavlinkGimbalEmulatorConfig& config,
                                             std::shared_ptr<const Clock> clock)
  : config_(config)
  , clock_(std::move(clock))
  , model_(config.device, clock_->now())
  , attitude_interval_(config.attitude_interval)
{
  if (config_.transport == LinkKind::UDP)
  {
    udp_.bind(config_.host, config_.port);
    thread_ = std::thread(&MavlinkGimbalEmulator::runUdp, this);
    return;
  }
  DevicePortConfig line = config_.line;
  line.tick_period = 0.01;
  DevicePort::Handlers handlers;
  handlers.on_bytes = [this](const std::uint8_t* data, std::size_t size, TimePoint) { receive(data, size); };
  handlers.on_tick = [this] { tick(); };
  line_ = DevicePort::create(line, handlers);
  line_->start();
}

MavlinkGimbalEmulator::~MavlinkGimbalEmulator()
{
  running_ = false;
  if (thread_.joinable())
  {
    udp_.interrupt();
    thread_.join();
  }
  line_.reset();
}

std::string MavlinkGimbalEmulator::address() const
{
  return line_ ? line_->path() : udp_.localEndpoint().toString();
}

std::uint16_t MavlinkGimbalEmulator::udpPort() const
{
  return line_ ? 0 : udp_.localEndpoint().port();
}

std::string MavlinkGimbalEmulator::path() const
{
  return line_ ? line_->path() : std::string();
}

void MavlinkGimbalEmulator::setSilent(bool silent)
{
  silent_ = silent;
  if (line_)
  {
    line_->setSilent(silent);
  }
}

void MavlinkGimbalEmulator::setRefuse(bool refuse)
{
  refuse_ = refuse;
}

void MavlinkGimbalEmulator::setFaults(const SimFaults& faults)
{
  std::lock_guard<std::mutex> lock(mutex_);
  model_.setFaults(faults, clock_->now());
}

void MavlinkGimbalEmulator::giveControlTo(std::uint8_t system_id, std::uint8_t component_id)
{
  std::lock_guard<std::mutex> lock(mutex_);
  primary_system_ = system_id;
  primary_component_ = component_id;
  control_kept_ = true;
  sendStatus();
}

void MavlinkGimbalEmulator::releaseControl()
{
  std::lock_guard<std::mutex> lock(mutex_);
  primary_system_ = primary_component_ = 0;
  control_kept_ = false;
  sendStatus();
}

void MavlinkGimbalEmulator::unplug()
{
  if (line_)
  {
    line_->unplug();
  }
}

void MavlinkGimbalEmulator::replug()
{
  if (line_)
  {
    line_->replug();
  }
}

std::pair<std::uint8_t, std::uint8_t> MavlinkGimbalEmulator::primaryController() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return { primary_system_, primary_component_ };
}

PtzSample MavlinkGimbalEmulator::gimbal() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return model_.sample(clock_->now());
}

MavlinkGimbalEmulatorCounters MavlinkGimbalEmulator::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  MavlinkGimbalEmulatorCounters counters = counters_;
  counters.dropped = parser_.counts().errors;
  return counters;
}

// ---------------------------------------------------------------- transports

void MavlinkGimbalEmulator::runUdp()
{
  std::array<std::uint8_t, MAX_DATAGRAM> buffer{};
  while (running_)
  {
    std::size_t size = 0;
    UdpEndpoint from;
    const ReceiveStatus status =
        udp_.receive(buffer.data(), buffer.size(), size, from, static_cast<int>(UDP_TICK * 1000.0));
    if (!running_)
    {
      break;
    }
    if (status == ReceiveStatus::DATAGRAM && !silent_)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        has_peer_ = true;  // the controller: replies and streams go where it sends from
        peer_ = from;
      }
      receive(buffer.data(), size);
    }
    tick();
  }
}

void MavlinkGimbalEmulator::receive(const std::uint8_t* data, std::size_t size)
{
  if (silent_)
  {
    return;
  }
  const TimePoint now = clock_->now();
  std::lock_guard<std::mutex> lock(mutex_);
  parser_.feed(data, size, [&](const Frame& frame) {
    received_.add(ReceivedMavlinkFrame{ now, frame });
    handle(frame, now);
  });
}

template <class Message>
void MavlinkGimbalEmulator::send(const Message& message)
{
  // With mutex_ held.
  if (silent_)
  {
    return;
  }
  const EncodedFrame frame = encode(FrameHeader{ sequence_++, config_.system_id, config_.component_id }, message);
  if (line_)
  {
    line_->send(frame.data(), frame.size);
  }
  else if (has_peer_)
  {
    udp_.sendTo(peer_, frame.data(), frame.size);
  }
}

void MavlinkGimbalEmulator::tick()
{
  const TimePoint now = clock_->now();
  std::lock_guard<std::mutex> lock(mutex_);
  if (rates_active_ && now >= rates_until_)
  {
    rates_active_ = false;
    ++counters_.rate_timeouts;
    model_.stop(now);
  }
  if (secondsBetween(heartbeat_at_, now) >= config_.heartbeat_period)
  {
    heartbeat_at_ = now;
    Heartbeat heartbeat;
    const bool autopilot = config_.component_id == MAV_COMP_ID_AUTOPILOT1;
    heartbeat.type = autopilot ? 2 : MAV_TYPE_GIMBAL;              // 2: a quadrotor
    heartbeat.autopilot = autopilot ? 12 : MAV_AUTOPILOT_INVALID;  // 12: PX4
    send(heartbeat);
  }
  if (secondsBetween(status_at_, now) >= config_.status_period)
  {
    sendStatus();
  }
  if (attitude_interval_ > 0.0 && secondsBetween(attitude_at_, now) >= attitude_interval_)
  {
    sendAttitude(now);
  }
}

// ---------------------------------------------------------------- what the manager sends

void MavlinkGimbalEmulator::sendStatus()
{
  status_at_ = clock_->now();
  GimbalManagerStatus status;
  status.time_boot_ms = static_cast<std::uint32_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(status_at_.time_since_epoch()).count());
  status.gimbal_device_id = config_.gimbal_device_id;
  status.primary_control_sysid = primary_system_;
  status.primary_control_compid = primary_component_;
  send(status);
}

void MavlinkGimbalEmulator::sendInformation()
{
  GimbalManagerInformation information;
  information.cap_flags = CAPABILITIES;
  information.pitch_min = static_cast<float>(config_.device.axes[TILT].range.min);
  information.pitch_max = static_cast<float>(config_.device.axes[TILT].range.max);
  information.yaw_min = static_cast<float>(config_.device.axes[PAN].range.min);
  information.yaw_max = static_cast<float>(config_.device.axes[PAN].range.max);
  information.gimbal_device_id = config_.gimbal_device_id;
  send(information);
}

void MavlinkGimbalEmulator::sendAttitude(TimePoint now)
{
  attitude_at_ = now;
  const PtzSample state = model_.sample(now);
  GimbalDeviceAttitudeStatus attitude;
  const double yaw = state.position[PAN] + (config_.report_earth_frame ? config_.vehicle_yaw : 0.0);
  attitude.q = quaternionFromPanTilt(yaw, state.position[TILT]);
  attitude.angular_velocity_x = 0.0f;
  attitude.angular_velocity_y = static_cast<float>(state.velocity[TILT]);
  attitude.angular_velocity_z = static_cast<float>(state.velocity[PAN]);
  attitude.flags = static_cast<std::uint16_t>(config_.report_earth_frame ? gimbal_flags::YAW_IN_EARTH_FRAME :
                                                                           gimbal_flags::YAW_IN_VEHICLE_FRAME);
  attitude.delta_yaw = static_cast<float>(config_.vehicle_yaw);
  attitude.gimbal_device_id = config_.gimbal_device_id;
  send(attitude);
}

// ---------------------------------------------------------------- what the manager receives

bool MavlinkGimbalEmulator::fromPrimary(const Frame& frame) const
{
  return frame.header.system_id == primary_system_ && frame.header.component_id == primary_component_;
}

void MavlinkGimbalEmulator::handle(const Frame& frame, TimePoint now)
{
  if (frame.message_id == message_id::COMMAND_LONG)
  {
    const CommandLong command = decode<CommandLong>(frame);
    if ((command.target_system == config_.system_id || command.target_system == 0) &&
        (command.target_component == config_.component_id || command.target_component == 0))
    {
      handleCommand(frame, command, now);
    }
  }
  else if (frame.message_id == message_id::GIMBAL_MANAGER_SET_PITCHYAW)
  {
    const GimbalManagerSetPitchYaw setpoint = decode<GimbalManagerSetPitchYaw>(frame);
    if (setpoint.target_system != config_.system_id || setpoint.target_component != config_.component_id ||
        (setpoint.gimbal_device_id != 0 && setpoint.gimbal_device_id != config_.gimbal_device_id))
    {
      return;
    }
    if (!fromPrimary(frame))
    {
      ++counters_.setpoints_ignored;  // as PX4 does: no answer to a message from a non-primary sender
      return;
    }
    setPitchYaw(setpoint, now);
  }
}

void MavlinkGimbalEmulator::handleCommand(const Frame& frame, const CommandLong& command, TimePoint now)
{
  CommandAck ack;
  ack.command = command.command;
  ack.target_system = frame.header.system_id;
  ack.target_component = frame.header.component_id;
  ack.result = Result::ACCEPTED;
  bool answer_information = false;
  bool answer_status = false;
  switch (command.command)
  {
    case command_id::REQUEST_MESSAGE:
      answer_information = command.params[0] == static_cast<float>(message_id::GIMBAL_MANAGER_INFORMATION);
      answer_status = command.params[0] == static_cast<float>(message_id::GIMBAL_MANAGER_STATUS);
      ack.result = answer_information || answer_status ? Result::ACCEPTED : Result::UNSUPPORTED;
      break;
    case command_id::SET_MESSAGE_INTERVAL:
      if (command.params[0] == static_cast<float>(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS))
      {
        const float interval_us = command.params[1];
        attitude_interval_ = interval_us < 0.0f  ? 0.0 :
                             interval_us == 0.0f ? config_.attitude_interval :
                                                   interval_us / 1e6;
      }
      else
      {
        ack.result = Result::UNSUPPORTED;
      }
      break;
    case command_id::DO_GIMBAL_MANAGER_CONFIGURE:
      ack.result = configure(frame, command);
      answer_status = ack.result == Result::ACCEPTED;
      break;
    case command_id::DO_GIMBAL_MANAGER_PITCHYAW:
      if (refuse_ || !fromPrimary(frame))
      {
        ack.result = Result::DENIED;
      }
      else
      {
        GimbalManagerSetPitchYaw setpoint;  // the command's degrees as the message's radians
        setpoint.flags = static_cast<std::uint32_t>(command.params[4]);
        setpoint.pitch = static_cast<float>(toRadians(command.params[0]));
        setpoint.yaw = static_cast<float>(toRadians(command.params[1]));
        setpoint.pitch_rate = static_cast<float>(toRadians(command.params[2]));
        setpoint.yaw_rate = static_cast<float>(toRadians(command.params[3]));
        setPitchYaw(setpoint, now);
      }
      break;
    default:
      ack.result = Result::UNSUPPORTED;
  }
  if (ack.result == Result::DENIED)
  {
    ++counters_.commands_denied;
  }
  send(ack);
  if (answer_information)
  {
    sendInformation();
  }
  if (answer_status)
  {
    sendStatus();
  }
}

Result MavlinkGimbalEmulator::configure(const Frame& frame, const CommandLong& command)
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
  const bool holder_keeps = control_kept_ && !fromPrimary(frame) && (primary_system_ != 0 || primary_component_ != 0);
  if (holder_keeps)
  {
    return Result::DENIED;
  }
  if (system == RELEASE)
  {
    primary_system_ = primary_component_ = 0;
  }
  else if (system == MANAGER_ITSELF)
  {
    primary_system_ = config_.system_id;
    primary_component_ = config_.component_id;
  }
  else if (system >= 0.0f && system <= 255.0f && component >= 0.0f && component <= 255.0f)
  {
    primary_system_ = static_cast<std::uint8_t>(system);
    primary_component_ = static_cast<std::uint8_t>(component);
  }
  else
  {
    return Result::DENIED;
  }
  control_kept_ = false;
  return Result::ACCEPTED;
}

void MavlinkGimbalEmulator::setPitchYaw(const GimbalManagerSetPitchYaw& setpoint, TimePoint now)
{
  ++counters_.setpoints_executed;
  // YAW_LOCK: the yaw is relative to North; the model turns in the vehicle frame.
  const double yaw_offset = (setpoint.flags & gimbal_flags::YAW_LOCK) != 0 ? -config_.vehicle_yaw : 0.0;
  const bool angles = std::isfinite(setpoint.pitch) || std::isfinite(setpoint.yaw);
  if (angles)
  {
    rates_active_ = false;
    if (std::isfinite(setpoint.yaw))
    {
      model_.goToAxis(PAN, std::remainder(setpoint.yaw + yaw_offset, 2.0 * M_PI), now);
    }
    if (std::isfinite(setpoint.pitch))
    {
      model_.goToAxis(TILT, setpoint.pitch, now);
    }
    return;
  }
  if (std::isfinite(setpoint.yaw_rate) || std::isfinite(setpoint.pitch_rate))
  {
    model_.moveAxisAtVelocity(PAN, std::isfinite(setpoint.yaw_rate) ? setpoint.yaw_rate : 0.0, now);
    model_.moveAxisAtVelocity(TILT, std::isfinite(setpoint.pitch_rate) ? setpoint.pitch_rate : 0.0, now);
    rates_active_ = true;
    rates_until_ = now + toDuration(config_.rate_timeout);
  }
}

}  // namespace ptz_action_server

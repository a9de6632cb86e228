#include "ptz_action_server/core/pantilt/pantilt_udp_backend.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
using cr::pantilt::PanTilt;
using cr::pantilt::PanTiltCommand;
using cr::pantilt::PanTiltParam;
using cr::pantilt::WireVersion;

constexpr std::size_t MAX_DATAGRAM = 512;

double degrees(double radians)
{
  return radians * 180.0 / M_PI;
}

double radians(double degrees)
{
  return degrees * M_PI / 180.0;
}
}  // namespace

PanTiltUdpBackend::PanTiltUdpBackend(const PanTiltUdpConfig& config, std::shared_ptr<const Clock> clock)
  : config_(config), clock_(std::move(clock)), motion_(config.settle_window)
{
}

PanTiltUdpBackend::~PanTiltUdpBackend()
{
  if (running_)
  {
    running_ = false;
    socket_.interrupt();
    thread_.join();
  }
}

Capabilities PanTiltUdpBackend::capabilities() const
{
  Capabilities capabilities;
  const double speed_share[] = { config_.pan_speed / 100.0, config_.tilt_speed / 100.0 };
  for (Axis axis : { PAN, TILT })
  {
    capabilities.axes[axis] = config_.axes[axis];
    capabilities.axes[axis].max_speed *= speed_share[axis];
  }
  capabilities.axes[ZOOM].present = false;
  capabilities.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  return capabilities;
}

void PanTiltUdpBackend::start()
{
  device_ = UdpEndpoint::resolve(config_.device_host, config_.device_port);
  socket_.bind(config_.local_host, config_.local_port);
  running_ = true;
  thread_ = std::thread(&PanTiltUdpBackend::run, this);
  sendStateRequest();
  sendSpeeds();
}

void PanTiltUdpBackend::goTo(const AxisValues& position)
{
  std::lock_guard<std::mutex> lock(send_mutex_);
  sendSpeeds();
  if (config_.version == WireVersion::V1_1)
  {
    sendCommand(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, degrees(position[PAN]), degrees(position[TILT]));
    return;
  }
  sendSetParam(PanTiltParam::PAN_ANGLE, degrees(position[PAN]));
  sendSetParam(PanTiltParam::TILT_ANGLE, degrees(position[TILT]));
  sendCommand(PanTiltCommand::GO_TO_PAN_TILT_ANGLE);
}

void PanTiltUdpBackend::moveAtVelocity(const AxisValues& velocity)
{
  std::lock_guard<std::mutex> lock(send_mutex_);
  const double percent[] = { 100.0 * velocity[PAN] / config_.axes[PAN].max_speed,
                             100.0 * velocity[TILT] / config_.axes[TILT].max_speed };
  if (config_.version == WireVersion::V1_1)
  {
    sendCommand(PanTiltCommand::MOVE_PAN_TILT, percent[PAN], percent[TILT]);
    return;
  }
  // 1.0 has no velocity command: move towards the limit at that speed. An axis at 0 holds where it is.
  const PtzSample current = sample();
  const PanTiltParam speed_param[] = { PanTiltParam::PAN_MOTOR_SPEED, PanTiltParam::TILT_MOTOR_SPEED };
  const PanTiltParam angle_param[] = { PanTiltParam::PAN_ANGLE, PanTiltParam::TILT_ANGLE };
  const double configured_speed[] = { config_.pan_speed, config_.tilt_speed };
  for (Axis axis : { PAN, TILT })
  {
    const AxisRange& range = config_.axes[axis].range;
    const bool holds = velocity[axis] == 0.0;
    const double target = holds ? current.position[axis] : (velocity[axis] > 0.0 ? range.max : range.min);
    sendSetParam(speed_param[axis], holds ? configured_speed[axis] : std::min(100.0, std::abs(percent[axis])));
    sendSetParam(angle_param[axis], degrees(target));
  }
  sendCommand(PanTiltCommand::GO_TO_PAN_TILT_ANGLE);
}

void PanTiltUdpBackend::stop()
{
  std::lock_guard<std::mutex> lock(send_mutex_);
  sendCommand(PanTiltCommand::STOP);
}

PtzSample PanTiltUdpBackend::sample() const
{
  std::lock_guard<std::mutex> lock(state_mutex_);
  PtzSample sample;
  const TimePoint now = clock_->now();
  sample.stamp = now;
  sample.link_up = linkUp(now);
  sample.position[ZOOM] = 1.0;
  motion_.fill(sample);
  return sample;
}

std::string PanTiltUdpBackend::lastFault() const
{
  return {};  // the PanTilt protocol has no error replies
}

void PanTiltUdpBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  const PanTiltUdpCounters counters = this->counters();
  values.emplace_back("device", device_.toString());
  values.emplace_back("local", socket_.localEndpoint().toString());
  values.emplace_back("wire version", cr::pantilt::toString(config_.version));
  values.emplace_back("frames ok", std::to_string(counters.frames_ok));
  values.emplace_back("dropped: foreign sender", std::to_string(counters.foreign_sender));
  values.emplace_back("dropped: bad size", std::to_string(counters.bad_size));
  values.emplace_back("dropped: bad header", std::to_string(counters.bad_header));
  values.emplace_back("dropped: bad version", std::to_string(counters.bad_version));
  values.emplace_back("dropped: bad mask", std::to_string(counters.bad_mask));
  values.emplace_back("datagrams sent", std::to_string(counters.datagrams_sent));
  values.emplace_back("send failures", std::to_string(counters.send_failures));
  values.emplace_back("link losses", std::to_string(counters.link_losses));
}

PanTiltUdpCounters PanTiltUdpBackend::counters() const
{
  std::lock_guard<std::mutex> lock(state_mutex_);
  return counters_;
}

UdpEndpoint PanTiltUdpBackend::localEndpoint() const
{
  return socket_.localEndpoint();
}

void PanTiltUdpBackend::run()
{
  std::array<std::uint8_t, MAX_DATAGRAM> buffer{};
  while (running_)
  {
    // Wake for the next state request or link deadline; frames wake us anyway.
    const int timeout_ms =
        static_cast<int>(std::ceil(std::min(config_.state_request_period, config_.state_timeout) * 1e3));
    std::size_t size = 0;
    bool truncated = false;
    UdpEndpoint from;
    const ReceiveStatus status = socket_.receive(buffer.data(), buffer.size(), size, from, timeout_ms, &truncated);
    if (!running_)
    {
      break;
    }
    if (status == ReceiveStatus::DATAGRAM)
    {
      handleDatagram(buffer.data(), size, truncated, from);
    }
    superviseLink(clock_->now());
  }
}

void PanTiltUdpBackend::handleDatagram(const std::uint8_t* data, std::size_t size, bool truncated,
                                       const UdpEndpoint& from)
{
  const TimePoint now = clock_->now();
  cr::pantilt::DecodeError error = cr::pantilt::DecodeError::NONE;
  cr::pantilt::PanTiltParams params;
  const bool foreign = from != device_;
  const bool valid = !foreign && !truncated && params.decode(data, static_cast<int>(size), config_.version, &error);
  bool recovered = false;
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (foreign)
    {
      ++counters_.foreign_sender;
      return;
    }
    if (!valid)
    {
      switch (truncated ? cr::pantilt::DecodeError::BAD_SIZE : error)
      {
        case cr::pantilt::DecodeError::BAD_HEADER:
          ++counters_.bad_header;
          break;
        case cr::pantilt::DecodeError::BAD_VERSION:
          ++counters_.bad_version;
          break;
        case cr::pantilt::DecodeError::BAD_MASK:
          ++counters_.bad_mask;
          break;
        default:
          ++counters_.bad_size;
          break;
      }
      return;
    }
    ++counters_.frames_ok;
    recovered = ever_received_ && !linkUp(now);
    motion_.add(now, AxisValues{ { radians(params.panAngle), radians(params.tiltAngle), 1.0 } });
    last_frame_at_ = now;
    ever_received_ = true;
    link_was_up_ = true;
  }
  if (recovered)
  {
    // The device is back: whatever it was doing belongs to a goal that has ended.
    std::lock_guard<std::mutex> lock(send_mutex_);
    sendCommand(PanTiltCommand::STOP);
    sendSpeeds();
  }
}

void PanTiltUdpBackend::superviseLink(TimePoint now)
{
  bool request = false;
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (link_was_up_ && !linkUp(now))
    {
      link_was_up_ = false;
      ++counters_.link_losses;
    }
    // Ask for state while the device is quiet (at start, or silent): its periodic frames make this unnecessary.
    const bool quiet = !ever_received_ || secondsBetween(last_frame_at_, now) >= config_.state_request_period;
    request = quiet && secondsBetween(last_request_at_, now) >= config_.state_request_period;
  }
  if (request)
  {
    sendStateRequest();
  }
}

bool PanTiltUdpBackend::linkUp(TimePoint now) const
{
  return ever_received_ && secondsBetween(last_frame_at_, now) <= config_.state_timeout;
}

void PanTiltUdpBackend::sendSetParam(PanTiltParam id, double value)
{
  std::uint8_t frame[cr::pantilt::SET_PARAM_SIZE];
  int size = 0;
  if (PanTilt::encodeSetParamCommand(frame, size, id, static_cast<float>(value), config_.version))
  {
    send(frame, size);
  }
}

void PanTiltUdpBackend::sendCommand(PanTiltCommand id, double arg1, double arg2)
{
  std::uint8_t frame[cr::pantilt::COMMAND_SIZE_V1_1];
  int size = 0;
  if (PanTilt::encodeCommand(frame, size, id, config_.version, static_cast<float>(arg1), static_cast<float>(arg2)))
  {
    send(frame, size);
  }
}

void PanTiltUdpBackend::sendSpeeds()
{
  sendSetParam(PanTiltParam::PAN_MOTOR_SPEED, config_.pan_speed);
  sendSetParam(PanTiltParam::TILT_MOTOR_SPEED, config_.tilt_speed);
}

void PanTiltUdpBackend::sendStateRequest()
{
  // A params frame with an empty mask asks for the device's params and changes nothing.
  const cr::pantilt::PanTiltParamsMask empty = cr::pantilt::PanTiltParamsMask::none();
  std::uint8_t frame[cr::pantilt::PARAMS_HEADER_SIZE];
  int size = 0;
  cr::pantilt::PanTiltParams().encode(frame, sizeof(frame), size, &empty, config_.version);
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    last_request_at_ = clock_->now();
  }
  send(frame, size);
}

void PanTiltUdpBackend::send(const std::uint8_t* data, int size)
{
  const bool sent = socket_.sendTo(device_, data, static_cast<std::size_t>(size));
  std::lock_guard<std::mutex> lock(state_mutex_);
  ++(sent ? counters_.datagrams_sent : counters_.send_failures);
}

}  // namespace ptz_action_server

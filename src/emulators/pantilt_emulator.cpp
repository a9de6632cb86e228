#include "ptz_action_server/emulators/pantilt_emulator.h"

#include <algorithm>
#include <cmath>

namespace ptz_action_server
{
namespace
{
using namespace cr::pantilt;

}  // namespace

SimDeviceConfig PanTiltEmulatorConfig::defaultDevice()
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  device.axes[ZOOM].present = false;
  device.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  return device;
}

PanTiltEmulator::PanTiltEmulator(const PanTiltEmulatorConfig& config, std::shared_ptr<const Clock> clock)
  : config_(config), clock_(std::move(clock)), pan_tilt_(config.device, clock_, config.format)
{
  DevicePortConfig port = config_.line;  // serial: SLIP frames on a pseudo-terminal
  if (!config_.serial)
  {
    port.kind = DevicePortConfig::Kind::UDP;  // a frame per datagram
    port.host = config_.host;
    port.port = config_.port;
  }
  port.tick_period = 0.01;
  DevicePort::Handlers handlers;
  if (config_.serial)
  {
    handlers.on_bytes = [this](const std::uint8_t* data, std::size_t size, TimePoint) {
      slip_.feed(data, size,
                 [this](const std::uint8_t* frame, std::size_t length) { handleDatagram(frame, length, ""); });
    };
  }
  else
  {
    handlers.on_bytes = [this](const std::uint8_t* data, std::size_t size, TimePoint) {
      handleDatagram(data, size, port_->sender());
    };
  }
  handlers.on_tick = [this] { sendDueReplies(clock_->now()); };
  port_ = DevicePort::create(port, handlers);
  port_->start();
}

PanTiltEmulator::~PanTiltEmulator()
{
  destroyPort(port_);  // first: its thread calls back into this
}

std::uint16_t PanTiltEmulator::udpPort() const
{
  return port_->udpPort();
}

std::string PanTiltEmulator::address() const
{
  return config_.serial ? std::string() : port_->path();
}

std::string PanTiltEmulator::path() const
{
  return config_.serial ? port_->path() : std::string();
}

void PanTiltEmulator::unplug()
{
  if (config_.serial)
  {
    port_->unplug();
  }
}

void PanTiltEmulator::replug()
{
  if (config_.serial)
  {
    port_->replug();
  }
}

void PanTiltEmulator::setEndless(bool endless)
{
  port_->setEndless(endless);  // a datagram of noise; on the line, a frame that never ends
}

void PanTiltEmulator::setDropRatio(double ratio)
{
  drop_ratio_ = std::clamp(ratio, 0.0, 1.0);
}

void PanTiltEmulator::setReplyDelay(double seconds)
{
  reply_delay_ = std::max(0.0, seconds);
}

void PanTiltEmulator::sendRaw(const std::string& to, const std::uint8_t* data, std::size_t size)
{
  port_->sendTo(to, data, size);
}

bool PanTiltEmulator::faultDrop(bool on)
{
  setDropRatio(on ? FAULT_DROP_RATIO : 0.0);
  return true;
}

void PanTiltEmulator::setModelFaults(const SimFaults& faults)
{
  pan_tilt_.setFaults(faults);
}

PanTiltEmulatorCounters PanTiltEmulator::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

void PanTiltEmulator::sendDueReplies(TimePoint now)
{
  while (!pending_replies_.empty() && pending_replies_.front().send_at <= now)
  {
    sendState(pending_replies_.front().to);
    pending_replies_.pop_front();
  }
  if (has_client_ && config_.state_period > 0.0 && now >= next_state_at_)
  {
    // On the period's beat, not a tick late each time (the tick is 10 ms), unless the device fell a period behind.
    next_state_at_ = addSeconds(next_state_at_, config_.state_period);
    if (next_state_at_ < now)
    {
      next_state_at_ = addSeconds(now, config_.state_period);
    }
    if (!silent())
    {
      sendState(last_client_);
    }
  }
}

void PanTiltEmulator::handleDatagram(const std::uint8_t* data, std::size_t size, const std::string& from)
{
  const TimePoint now = clock_->now();
  received_.add(ReceivedDatagram{ now, std::vector<std::uint8_t>(data, data + size) });
  if (silent())
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++counters_.dropped_by_fault;
    return;
  }

  // Only a frame of the configured format is executed (or answered): one of another format is dropped.
  const int length = static_cast<int>(size);
  DecodeError error = DecodeError::NONE;
  bool valid = false;
  bool executed = false;
  bool state_request = false;
  if (size > 0 && data[0] == PARAMS_HEADER)
  {
    PanTiltParams ignored;
    valid = state_request = ignored.decode(data, length, config_.format, &error);
  }
  else
  {
    PanTiltParam param{};
    PanTiltCommand command{};
    float value = 0.0f;
    float second = 0.0f;
    switch (PanTilt::decodeCommand(data, length, param, command, value, config_.format, &second, &error))
    {
      case 0:
        valid = true;
        executed = pan_tilt_.executeCommand(command, value, second);
        break;
      case 1:
        valid = true;
        executed = pan_tilt_.setParam(param, value);
        break;
      default:
        break;
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!valid)
    {
      ++counters_.invalid[static_cast<std::size_t>(error)];
      return;
    }
    if (state_request)
    {
      ++counters_.state_requests;
    }
    else if (executed)
    {
      ++counters_.commands_executed;
    }
    else
    {
      ++counters_.commands_refused;
    }
  }
  if (!has_client_ || from != last_client_)
  {
    next_state_at_ = addSeconds(now, config_.state_period);
  }
  has_client_ = true;
  last_client_ = from;
  reply(from, now);
}

void PanTiltEmulator::reply(const std::string& to, TimePoint now)
{
  if (std::uniform_real_distribution<double>(0.0, 1.0)(random_) < drop_ratio_)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++counters_.dropped_by_fault;
    return;
  }
  const double delay = reply_delay_;
  if (delay > 0.0)
  {
    pending_replies_.push_back(PendingReply{ addSeconds(now, delay), to });
    return;
  }
  sendState(to);
}

void PanTiltEmulator::sendState(const std::string& to)
{
  PanTiltParams params;
  pan_tilt_.getParams(params);
  std::uint8_t frame[MAX_PARAMS_FRAME_SIZE];
  int size = 0;
  params.encode(frame, sizeof(frame), size, nullptr, config_.format);
  const std::uint8_t* bytes = frame;
  std::size_t length = static_cast<std::size_t>(size);
  if (config_.serial)
  {
    framed_.clear();
    slip::encode(frame, length, framed_);
    bytes = framed_.data();
    length = framed_.size();
  }
  for (unsigned copy = 0; copy < floodCopies(); ++copy)
  {
    port_->sendTo(to, bytes, length);
    std::lock_guard<std::mutex> lock(mutex_);
    ++counters_.replies_sent;
  }
}

}  // namespace ptz_action_server

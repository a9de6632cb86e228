#include "ptz_action_server/emulators/pantilt_emulator.h"

#include <algorithm>
#include <cmath>

namespace ptz_action_server
{
namespace
{
using namespace cr::pantilt;

constexpr std::size_t MAX_DATAGRAM = 2048;
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
  if (!config_.serial)
  {
    socket_.bind(config.host, config.port);
    thread_ = std::thread(&PanTiltEmulator::run, this);
    return;
  }
  // A serial line: SLIP frames on a pseudo-terminal, whose I/O thread runs both handlers.
  DevicePortConfig line = config_.line;
  line.tick_period = 0.01;
  DevicePort::Handlers handlers;
  handlers.on_bytes = [this](const std::uint8_t* data, std::size_t size, TimePoint) {
    slip_.feed(data, size,
               [this](const std::uint8_t* frame, std::size_t length) { handleDatagram(frame, length, UdpEndpoint{}); });
  };
  handlers.on_tick = [this] { sendDueReplies(clock_->now()); };
  line_ = DevicePort::create(line, handlers);
  line_->start();
}

PanTiltEmulator::~PanTiltEmulator()
{
  running_ = false;
  if (thread_.joinable())
  {
    socket_.interrupt();
    thread_.join();
  }
  line_.reset();
}

UdpEndpoint PanTiltEmulator::endpoint() const
{
  return socket_.localEndpoint();
}

std::string PanTiltEmulator::path() const
{
  return line_ ? line_->path() : std::string();
}

void PanTiltEmulator::unplug()
{
  if (line_)
  {
    line_->unplug();
  }
}

void PanTiltEmulator::replug()
{
  if (line_)
  {
    line_->replug();
  }
}

void PanTiltEmulator::setSilent(bool silent)
{
  silent_ = silent;
}

void PanTiltEmulator::setEndless(bool endless)
{
  endless_ = endless;
  if (line_)
  {
    line_->setEndless(endless);
  }
}

void PanTiltEmulator::setDropRatio(double ratio)
{
  drop_ratio_ = std::clamp(ratio, 0.0, 1.0);
}

void PanTiltEmulator::setReplyDelay(double seconds)
{
  reply_delay_ = std::max(0.0, seconds);
}

void PanTiltEmulator::sendRaw(const UdpEndpoint& to, const std::uint8_t* data, std::size_t size)
{
  socket_.sendTo(to, data, size);
}

PanTiltEmulatorCounters PanTiltEmulator::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

void PanTiltEmulator::run()
{
  std::array<std::uint8_t, MAX_DATAGRAM> buffer{};
  while (running_)
  {
    std::size_t size = 0;
    UdpEndpoint from;
    const ReceiveStatus status =
        socket_.receive(buffer.data(), buffer.size(), size, from, millisecondsToNextEvent(clock_->now()));
    if (!running_)
    {
      break;
    }
    if (status == ReceiveStatus::DATAGRAM)
    {
      handleDatagram(buffer.data(), size, from);
    }
    sendDueReplies(clock_->now());
  }
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
    next_state_at_ = addSeconds(now, config_.state_period);
    if (!silent_)
    {
      sendState(last_client_);
    }
  }
}

int PanTiltEmulator::millisecondsToNextEvent(TimePoint now) const
{
  double wait = -1.0;  // no deadline: only a datagram or interrupt() wakes the thread
  if (has_client_ && config_.state_period > 0.0)
  {
    wait = std::max(0.0, secondsBetween(now, next_state_at_));
  }
  if (!pending_replies_.empty())
  {
    const double until_reply = std::max(0.0, secondsBetween(now, pending_replies_.front().send_at));
    wait = wait < 0.0 ? until_reply : std::min(wait, until_reply);
  }
  return wait < 0.0 ? -1 : static_cast<int>(std::ceil(wait * 1000.0));
}

void PanTiltEmulator::handleDatagram(const std::uint8_t* data, std::size_t size, const UdpEndpoint& from)
{
  const TimePoint now = clock_->now();
  received_.add(ReceivedDatagram{ now, std::vector<std::uint8_t>(data, data + size) });
  if (silent_)
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

void PanTiltEmulator::reply(const UdpEndpoint& to, TimePoint now)
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

void PanTiltEmulator::sendState(const UdpEndpoint& to)
{
  PanTiltParams params;
  pan_tilt_.getParams(params);
  std::uint8_t frame[MAX_PARAMS_FRAME_SIZE];
  int size = 0;
  params.encode(frame, sizeof(frame), size, nullptr, config_.format);
  if (!line_ && endless_)
  {
    std::fill(frame, frame + size, 'A');  // a datagram of noise (on the line, the port fills)
  }
  if (line_)
  {
    framed_.clear();
    slip::encode(frame, static_cast<std::size_t>(size), framed_);
    line_->send(framed_.data(), framed_.size());
    std::lock_guard<std::mutex> lock(mutex_);
    ++counters_.replies_sent;
  }
  else
  {
    for (unsigned copy = 0; copy < flood_; ++copy)
    {
      if (socket_.sendTo(to, frame, static_cast<std::size_t>(size)))
      {
        std::lock_guard<std::mutex> lock(mutex_);
        ++counters_.replies_sent;
      }
    }
  }
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/serial/pelco_backend.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// A query and its reply: two frames.
constexpr std::size_t EXCHANGE_BYTES = 2 * pelco::FRAME_SIZE;

std::chrono::steady_clock::duration seconds(double value)
{
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(value));
}

double degrees(double radians)
{
  return radians * 180.0 / M_PI;
}

double radians(double degrees)
{
  return degrees * M_PI / 180.0;
}

/// A speed (rad/s, X/s) as a Pelco speed byte 1..0x3F, signed; 0 stays 0.
int speedByte(double speed, double max_speed)
{
  if (speed == 0.0 || !(max_speed > 0.0))
  {
    return 0;
  }
  const int magnitude = std::clamp(static_cast<int>(std::lround(std::abs(speed) / max_speed * pelco::MAX_SPEED)), 1,
                                   static_cast<int>(pelco::MAX_SPEED));
  return speed > 0.0 ? magnitude : -magnitude;
}
}  // namespace

PelcoBackend::PelcoBackend(const PelcoConfig& config, std::shared_ptr<const Clock> clock)
  : config_(config)
  , clock_(std::move(clock))
  , link_(config.serial.link, *this)
  , channel_(link_, config.serial.replyTimeoutFor(EXCHANGE_BYTES),
             [this](const TransactionChannel::Request& lost) {
               parser_.reset();
               if (lost.tag != COMMAND)
               {
                 polls_pending_ = 0;
               }
               std::lock_guard<std::mutex> lock(mutex_);
               ++counters_.timeouts;
             })
  , parser_(config.address, config.general_reply)
  , poll_timer_(link_.context())
  , motion_(config.serial.settle_window)
{
}

PelcoBackend::~PelcoBackend()
{
  link_.stop();
}

Capabilities PelcoBackend::capabilities() const
{
  Capabilities capabilities;
  capabilities.axes = config_.axes;
  if (!capabilities.axes[ZOOM].present)
  {
    capabilities.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  }
  return capabilities;
}

std::uint16_t PelcoBackend::zoomToPosition(double zoom) const
{
  const AxisRange& range = config_.axes[ZOOM].range;
  const double share =
      range.max > range.min ? (std::clamp(zoom, range.min, range.max) - range.min) / (range.max - range.min) : 0.0;
  return static_cast<std::uint16_t>(std::lround(share * config_.zoom_position_max));
}

double PelcoBackend::positionToZoom(std::uint16_t position) const
{
  const AxisRange& range = config_.axes[ZOOM].range;
  const double share =
      config_.zoom_position_max > 0 ? std::min(1.0, double(position) / config_.zoom_position_max) : 0.0;
  return range.min + share * (range.max - range.min);
}

void PelcoBackend::start()
{
  link_.start();
  std::unique_lock<std::mutex> lock(mutex_);
  if (!answered_.wait_for(lock, seconds(config_.serial.startup_timeout), [this] { return ever_answered_; }))
  {
    const std::string reason = link_.lastError();
    lock.unlock();
    link_.stop();
    throw BackendError(formatText("no answer from a Pelco-D device (address %u) on %s at %u baud within %.1f s%s%s",
                                  config_.address, config_.serial.link.path.c_str(), config_.serial.link.baud,
                                  config_.serial.startup_timeout, reason.empty() ? "" : ": ", reason.c_str()));
  }
}

void PelcoBackend::goTo(const AxisValues& position)
{
  link_.post([this, position] {
    if (!link_.connected())
    {
      return;
    }
    channel_.clearQueue();
    polls_pending_ = 0;
    queueFrame(pelco::withValue(config_.address, pelco::SET_PAN, pelco::encodePan(degrees(position[PAN]))), COMMAND);
    queueFrame(pelco::withValue(config_.address, pelco::SET_TILT,
                                pelco::encodeTilt(degrees(position[TILT]), config_.tilt_encoding)),
               COMMAND);
    if (config_.axes[ZOOM].present)
    {
      queueFrame(pelco::withValue(config_.address, pelco::SET_ZOOM, zoomToPosition(position[ZOOM])), COMMAND);
    }
  });
}

void PelcoBackend::moveAtVelocity(const AxisValues& velocity)
{
  link_.post([this, velocity] {
    if (!link_.connected())
    {
      return;
    }
    channel_.clearQueue();
    polls_pending_ = 0;
    const int zoom = config_.axes[ZOOM].present ? (velocity[ZOOM] > 0.0 ? 1 : (velocity[ZOOM] < 0.0 ? -1 : 0)) : 0;
    queueFrame(pelco::move(config_.address, speedByte(velocity[PAN], config_.axes[PAN].max_speed),
                           speedByte(velocity[TILT], config_.axes[TILT].max_speed), zoom),
               COMMAND);
  });
}

void PelcoBackend::stop()
{
  link_.post([this] {
    if (!link_.connected())
    {
      return;
    }
    channel_.clearQueue();
    polls_pending_ = 0;
    sendUrgent(pelco::stop(config_.address));
  });
}

PtzSample PelcoBackend::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  PtzSample sample;
  const TimePoint now = clock_->now();
  sample.stamp = now;
  sample.link_up = linkUpLocked(now);
  sample.position[ZOOM] = 1.0;
  motion_.fill(sample);
  return sample;
}

std::string PelcoBackend::lastFault() const
{
  return {};  // Pelco-D has no error replies
}

PelcoCounters PelcoBackend::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

void PelcoBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  const PelcoCounters counters = this->counters();
  values.emplace_back("protocol", "pelco_d");
  values.emplace_back("address", std::to_string(config_.address));
  link_.diagnostics(values);
  values.emplace_back("frames", std::to_string(counters.parser.frames));
  values.emplace_back("dropped: bad checksum or partial", std::to_string(counters.parser.bad_checksum));
  values.emplace_back("dropped: bytes outside frames", std::to_string(counters.parser.skipped_bytes));
  values.emplace_back("dropped: other address", std::to_string(counters.parser.wrong_address));
  values.emplace_back("unexpected frames", std::to_string(counters.unexpected_frames));
  values.emplace_back("reply timeouts", std::to_string(counters.timeouts));
  values.emplace_back("late replies dropped", std::to_string(counters.late_replies));
  values.emplace_back("link losses", std::to_string(counters.link_losses));
}

void PelcoBackend::onConnected()
{
  channel_.reset();
  parser_.reset();
  polls_pending_ = 0;
  bool reconnection = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    connected_ = true;
    reconnection = was_connected_;
    was_connected_ = true;
    motion_.clear();
  }
  if (reconnection)
  {
    sendUrgent(pelco::stop(config_.address));  // an aborted goal must not go on
  }
  schedulePoll();
}

void PelcoBackend::onDisconnected(const std::string&)
{
  channel_.reset();
  poll_timer_.cancel();
  polls_pending_ = 0;
  std::lock_guard<std::mutex> lock(mutex_);
  connected_ = false;
  if (link_was_up_)
  {
    link_was_up_ = false;
    ++counters_.link_losses;
  }
}

void PelcoBackend::schedulePoll()
{
  poll_timer_.expires_after(seconds(config_.serial.poll_period));
  poll_timer_.async_wait([this](const boost::system::error_code& error) {
    if (error || !link_.connected())
    {
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const bool up = linkUpLocked(clock_->now());
      if (link_was_up_ && !up)
      {
        ++counters_.link_losses;
      }
      link_was_up_ = up;
    }
    if (polls_pending_ == 0 && channel_.queued() == 0)
    {
      queueFrame(pelco::withValue(config_.address, pelco::QUERY_PAN, 0), QUERY_PAN);
      queueFrame(pelco::withValue(config_.address, pelco::QUERY_TILT, 0), QUERY_TILT);
      polls_pending_ = 2;
      if (config_.axes[ZOOM].present)
      {
        queueFrame(pelco::withValue(config_.address, pelco::QUERY_ZOOM, 0), QUERY_ZOOM);
        ++polls_pending_;
      }
    }
    schedulePoll();
  });
}

void PelcoBackend::queueFrame(const pelco::Frame& frame, Tag tag)
{
  const pelco::Bytes bytes = pelco::encode(frame);
  const bool expects_reply = tag != COMMAND || config_.general_reply;
  channel_.queue(TransactionChannel::Request{ std::string(bytes.begin(), bytes.end()), tag, expects_reply });
}

void PelcoBackend::sendUrgent(const pelco::Frame& frame)
{
  const pelco::Bytes bytes = pelco::encode(frame);
  channel_.sendUrgent(
      TransactionChannel::Request{ std::string(bytes.begin(), bytes.end()), COMMAND, config_.general_reply });
}

void PelcoBackend::onBytes(const std::uint8_t* data, std::size_t size)
{
  std::vector<pelco::FrameParser::Event> events;
  parser_.feed(data, size, events);
  const TimePoint now = clock_->now();
  bool recovered = false;
  for (const pelco::FrameParser::Event& event : events)
  {
    const bool query_reply = !event.general_reply &&
                             (event.frame.command2 == pelco::PAN_REPLY || event.frame.command2 == pelco::TILT_REPLY ||
                              event.frame.command2 == pelco::ZOOM_REPLY);
    if (!event.general_reply && !query_reply)
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++counters_.unexpected_frames;
      continue;
    }
    const std::optional<TransactionChannel::Request> answered = channel_.complete(now);
    std::lock_guard<std::mutex> lock(mutex_);
    counters_.parser = parser_.counters();
    if (!answered)
    {
      counters_.late_replies = channel_.lateReplies();
      continue;
    }
    const int expected_reply = answered->tag == QUERY_PAN  ? pelco::PAN_REPLY :
                               answered->tag == QUERY_TILT ? pelco::TILT_REPLY :
                               answered->tag == QUERY_ZOOM ? pelco::ZOOM_REPLY :
                                                             -1;
    if ((event.general_reply && answered->tag != COMMAND) ||
        (!event.general_reply && event.frame.command2 != expected_reply))
    {
      ++counters_.unexpected_frames;
      continue;
    }
    if (ever_answered_ && !linkUpLocked(now))
    {
      recovered = true;
    }
    last_reply_at_ = now;
    if (!ever_answered_)
    {
      ever_answered_ = true;
      link_was_up_ = true;
      answered_.notify_all();
    }
    if (event.general_reply)
    {
      continue;
    }
    const std::uint16_t value = event.frame.value();
    switch (answered->tag)
    {
      case QUERY_PAN:
        polled_[PAN] = radians(pelco::decodePan(value));
        break;
      case QUERY_TILT:
        polled_[TILT] = radians(pelco::decodeTilt(value, config_.tilt_encoding));
        break;
      case QUERY_ZOOM:
        polled_[ZOOM] = positionToZoom(value);
        break;
      default:
        break;
    }
    if (--polls_pending_ <= 0)
    {
      polls_pending_ = 0;
      motion_.add(now, polled_);
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    counters_.parser = parser_.counters();
  }
  if (recovered)
  {
    // The device answers again after a silence: it may still run an aborted goal. Stop it.
    sendUrgent(pelco::stop(config_.address));
  }
}

bool PelcoBackend::linkUpLocked(TimePoint now) const
{
  return connected_ && ever_answered_ && secondsBetween(last_reply_at_, now) <= config_.serial.transaction_deadline;
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/serial/flir_backend.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// Longest exchange: a command like "PP-12345 " and a verbose reply.
constexpr std::size_t EXCHANGE_BYTES = 48;

double arcSecondsToRadians(double arc_seconds)
{
  return arc_seconds / 3600.0 * M_PI / 180.0;
}

std::chrono::steady_clock::duration seconds(double value)
{
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(value));
}
}  // namespace

FlirBackend::FlirBackend(const FlirConfig& config, std::shared_ptr<const Clock> clock)
  : config_(config)
  , clock_(std::move(clock))
  , link_(config.serial.link, *this)
  , channel_(link_, config.serial.replyTimeoutFor(EXCHANGE_BYTES),
             [this](const TransactionChannel::Request& lost) {
               parser_.reset();
               poll_pending_ = false;
               {
                 std::lock_guard<std::mutex> lock(mutex_);
                 ++counters_.timeouts;
               }
               if (lost.tag != COMMAND && lost.tag != PAN_POSITION && lost.tag != TILT_POSITION)
               {
                 // A setup answer went missing: start the setup again once the line is quiet.
                 channel_.clearQueue();
                 queueSetup();
               }
             })
  , poll_timer_(link_.context())
  , motion_(config.serial.settle_window)
{
}

FlirBackend::~FlirBackend()
{
  link_.stop();
}

Capabilities FlirBackend::capabilities() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  Capabilities capabilities;
  AxisCapability& pan = capabilities.axes[PAN];
  // The unit's positive pan is counter-clockwise: its minimum is the contract's maximum.
  pan.range = AxisRange{ -limits_[1] * pan_resolution_, -limits_[0] * pan_resolution_ };
  pan.max_speed = std::min(config_.pan_speed, speed_max_[0] * pan_resolution_);
  pan.acceleration = config_.acceleration;
  AxisCapability& tilt = capabilities.axes[TILT];
  tilt.range = AxisRange{ limits_[2] * tilt_resolution_, limits_[3] * tilt_resolution_ };
  tilt.max_speed = std::min(config_.tilt_speed, speed_max_[1] * tilt_resolution_);
  tilt.acceleration = config_.acceleration;
  capabilities.axes[ZOOM].present = false;
  capabilities.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  return capabilities;
}

void FlirBackend::start()
{
  link_.start();
  std::unique_lock<std::mutex> lock(mutex_);
  if (!ready_changed_.wait_for(lock, seconds(config_.serial.startup_timeout), [this] { return ready_; }))
  {
    const std::string reason = link_.lastError();
    lock.unlock();
    link_.stop();
    throw BackendError(formatText("no answer from a FLIR PTU on %s at %u baud within %.1f s%s%s",
                                  config_.serial.link.path.c_str(), config_.serial.link.baud,
                                  config_.serial.startup_timeout, reason.empty() ? "" : ": ", reason.c_str()));
  }
}

void FlirBackend::goTo(const AxisValues& position)
{
  link_.post([this, position] {
    if (!link_.connected())
    {
      return;
    }
    // A new goal replaces whatever of the last one has not gone out yet.
    channel_.clearQueue();
    poll_pending_ = false;
    sendMode(false);
    const Capabilities limits = capabilities();
    request(flir::command("PS", std::lround(limits.axes[PAN].max_speed / panResolution())), COMMAND);
    request(flir::command("TS", std::lround(limits.axes[TILT].max_speed / tiltResolution())), COMMAND);
    request(flir::command("PP", std::lround(-position[PAN] / panResolution())), COMMAND);
    request(flir::command("TP", std::lround(position[TILT] / tiltResolution())), COMMAND);
  });
}

void FlirBackend::moveAtVelocity(const AxisValues& velocity)
{
  link_.post([this, velocity] {
    if (!link_.connected())
    {
      return;
    }
    channel_.clearQueue();
    poll_pending_ = false;
    sendMode(true);
    request(flir::command("PS", std::lround(-velocity[PAN] / panResolution())), COMMAND);
    request(flir::command("TS", std::lround(velocity[TILT] / tiltResolution())), COMMAND);
  });
}

void FlirBackend::stop()
{
  link_.post([this] {
    if (!link_.connected())
    {
      return;
    }
    // The halt goes out at once, ahead of anything queued; the unit decelerates to rest.
    channel_.clearQueue();
    poll_pending_ = false;
    channel_.sendUrgent(TransactionChannel::Request{ flir::command("H"), COMMAND, true });
  });
}

PtzSample FlirBackend::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  PtzSample sample;
  const TimePoint now = clock_->now();
  sample.stamp = now;
  sample.link_up = linkUpLocked(now);
  sample.position[ZOOM] = 1.0;
  motion_.fill(sample);
  sample.fault_count = fault_count_;
  return sample;
}

std::string FlirBackend::lastFault() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return last_fault_;
}

FlirCounters FlirBackend::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

void FlirBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  const FlirCounters counters = this->counters();
  values.emplace_back("protocol", "flir");
  link_.diagnostics(values);
  values.emplace_back("replies", std::to_string(counters.replies));
  values.emplace_back("device errors", std::to_string(counters.errors));
  values.emplace_back("limit hits", std::to_string(counters.limit_hits));
  values.emplace_back("unexpected text lines", std::to_string(counters.unexpected_text));
  values.emplace_back("reply timeouts", std::to_string(counters.timeouts));
  values.emplace_back("late replies dropped", std::to_string(counters.late_replies));
  values.emplace_back("link losses", std::to_string(counters.link_losses));
}

void FlirBackend::onConnected()
{
  channel_.reset();
  parser_.reset();
  poll_pending_ = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    connected_ = true;
    ready_ = false;
    motion_.clear();
  }
  queueSetup();
  schedulePoll();
}

void FlirBackend::onDisconnected(const std::string&)
{
  channel_.reset();
  poll_timer_.cancel();
  poll_pending_ = false;
  std::lock_guard<std::mutex> lock(mutex_);
  connected_ = false;
  if (link_was_up_)
  {
    link_was_up_ = false;
    ++counters_.link_losses;
  }
}

void FlirBackend::queueSetup()
{
  // Terse replies, no echo, position mode; then what the unit is: resolution, limits, top speeds.
  request(flir::command("FT"), SETUP);
  request(flir::command("ED"), SETUP);
  request(flir::command("CI"), SETUP);
  request(flir::command("PR"), PAN_RESOLUTION);
  request(flir::command("TR"), TILT_RESOLUTION);
  request(flir::command("PN"), PAN_MIN);
  request(flir::command("PX"), PAN_MAX);
  request(flir::command("TN"), TILT_MIN);
  request(flir::command("TX"), TILT_MAX);
  request(flir::command("PU"), PAN_SPEED_MAX);
  request(flir::command("TU"), TILT_SPEED_MAX);
}

void FlirBackend::schedulePoll()
{
  poll_timer_.expires_after(seconds(config_.serial.poll_period));
  poll_timer_.async_wait([this](const boost::system::error_code& error) {
    if (error || !link_.connected())
    {
      return;
    }
    bool ready = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ready = ready_;
      const bool up = linkUpLocked(clock_->now());
      if (link_was_up_ && !up)
      {
        ++counters_.link_losses;
      }
      link_was_up_ = up;
    }
    // Goal commands go first; the position is asked for whenever the line is otherwise free.
    if (ready && !poll_pending_ && channel_.queued() == 0)
    {
      request(flir::command("PP"), PAN_POSITION);
      request(flir::command("TP"), TILT_POSITION);
      poll_pending_ = true;
    }
    schedulePoll();
  });
}

void FlirBackend::request(const std::string& text, Tag tag)
{
  channel_.queue(TransactionChannel::Request{ text, tag, true });
}

void FlirBackend::sendMode(bool velocity)
{
  // Every goal states its mode: a mode switch queued for an earlier goal may have been dropped with the queue.
  request(flir::command(velocity ? "CV" : "CI"), COMMAND);
}

void FlirBackend::onBytes(const std::uint8_t* data, std::size_t size)
{
  std::vector<flir::Reply> replies;
  parser_.feed(data, size, replies);
  for (const flir::Reply& reply : replies)
  {
    handleReply(reply);
  }
}

void FlirBackend::handleReply(const flir::Reply& reply)
{
  if (reply.kind == flir::Reply::Kind::TEXT || reply.kind == flir::Reply::Kind::LIMIT)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++(reply.kind == flir::Reply::Kind::TEXT ? counters_.unexpected_text : counters_.limit_hits);
    return;
  }
  const TimePoint now = clock_->now();
  const std::optional<TransactionChannel::Request> answered = channel_.complete(now);
  if (!answered)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    counters_.late_replies = channel_.lateReplies();
    return;
  }
  bool recovered = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    recovered = ready_ && was_ready_ && !linkUpLocked(now);
    last_reply_at_ = now;
    ++counters_.replies;
  }
  handleAnswer(*answered, reply);
  if (recovered)
  {
    // The unit answers again after a silence: it may still run an aborted goal. Halt it.
    channel_.sendUrgent(TransactionChannel::Request{ flir::command("H"), COMMAND, true });
  }
}

void FlirBackend::handleAnswer(const TransactionChannel::Request& request, const flir::Reply& reply)
{
  const Tag tag = static_cast<Tag>(request.tag);
  if (tag == TILT_POSITION)
  {
    poll_pending_ = false;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (reply.kind == flir::Reply::Kind::ERROR)
  {
    ++counters_.errors;
    if (tag == COMMAND)
    {
      ++fault_count_;
      std::string sent = request.bytes;
      sent.erase(sent.find_last_not_of(' ') + 1);
      last_fault_ = "the FLIR PTU refused '" + sent + "': " + reply.text;
    }
    return;
  }
  const double value = reply.value;
  switch (tag)
  {
    case PAN_RESOLUTION:
      pan_resolution_ = arcSecondsToRadians(value);
      break;
    case TILT_RESOLUTION:
      tilt_resolution_ = arcSecondsToRadians(value);
      break;
    case PAN_MIN:
    case PAN_MAX:
    case TILT_MIN:
    case TILT_MAX:
      limits_[tag - PAN_MIN] = std::lround(value);
      break;
    case PAN_SPEED_MAX:
      speed_max_[0] = std::lround(value);
      break;
    case TILT_SPEED_MAX:
      speed_max_[1] = std::lround(value);
      if (pan_resolution_ > 0.0 && tilt_resolution_ > 0.0)
      {
        if (was_ready_)
        {
          // After a reconnection: an aborted goal must not go on.
          channel_.sendUrgent(TransactionChannel::Request{ flir::command("H"), COMMAND, true });
        }
        ready_ = true;
        was_ready_ = true;
        link_was_up_ = true;
        ready_changed_.notify_all();
      }
      break;
    case PAN_POSITION:
      polled_pan_ = -value * pan_resolution_;
      break;
    case TILT_POSITION:
      motion_.add(clock_->now(), AxisValues{ { polled_pan_, value * tilt_resolution_, 1.0 } });
      break;
    case SETUP:
    case COMMAND:
      break;
  }
}

bool FlirBackend::linkUpLocked(TimePoint now) const
{
  return connected_ && ready_ && secondsBetween(last_reply_at_, now) <= config_.serial.transaction_deadline;
}

double FlirBackend::panResolution() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return pan_resolution_;
}

double FlirBackend::tiltResolution() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return tilt_resolution_;
}

}  // namespace ptz_action_server

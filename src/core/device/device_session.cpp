#include "ptz_action_server/core/device/device_session.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <boost/asio/post.hpp>

#include "ptz_action_server/core/device/device_protocol.h"
#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
DeviceSession::DeviceSession(const LinkConfig& link, const DeviceSessionConfig& config,
                             std::shared_ptr<const Clock> clock, DeviceIoPool& pool)
  : config_(config)
  , clock_(std::move(clock))
  // A link whose calls block (HTTP) would stall every session on a shared thread: it gets a thread of its own.
  , io_(pool.acquire(link.kind == LinkKind::HTTP))
  , link_(Link::create(io_.context(), link, *this))
  , tick_timer_(io_.context())
  , grace_timer_(io_.context())
  , supervisor_(config.state_timeout, clock_)
  , motion_(config.settle_window)
{
  const std::string link_warning = HttpLink::configWarning(link);  // TLS without verification, once
  if (!link_warning.empty())
  {
    warn(link_warning);
  }
}

DeviceSession::~DeviceSession()
{
  stop();
}

HttpChannel& DeviceSession::http()
{
  HttpChannel* http = link_->http();
  if (http == nullptr)
  {
    throw std::logic_error(protocol_->name() + " needs an HTTP link, not " + link_->config().describe());
  }
  return *http;
}

ByteLink& DeviceSession::bytes()
{
  ByteLink* bytes = link_->bytes();
  if (bytes == nullptr)
  {
    throw std::logic_error(protocol_->name() + " writes bytes to " + link_->config().describe() +
                           ", which carries none");
  }
  return *bytes;
}

const HttpCounters* DeviceSession::httpCounters() const
{
  const HttpChannel* http = link_->http();
  return http == nullptr ? nullptr : &http->httpCounters();
}

void DeviceSession::attach(DeviceProtocol& protocol)
{
  protocol_ = &protocol;
  std::lock_guard<std::mutex> lock(mutex_);
  capabilities_ = protocol.capabilities();
  supervisor_.name("state from " + protocol.deviceName(), "states from " + protocol.deviceName());
}

void DeviceSession::start()
{
  {
    std::lock_guard<std::mutex> lock(post_mutex_);
    if (started_ || stop_begun_)
    {
      return;
    }
    started_ = true;
    boost::asio::post(context(), [this] {
      link_->open();
      tick();
    });
  }
  std::unique_lock<std::mutex> lock(mutex_);
  if (supervisor_.waitForStartup(lock, config_.startup_timeout))
  {
    return;
  }
  const std::string problem = supervisor_.startupProblem();
  const std::string impossible = supervisor_.impossibleReason();
  lock.unlock();
  const std::string device = protocol_->deviceName() + " on " + link_->config().describe();
  const std::string link_error = link_->lastError();
  stop();
  if (!problem.empty())
  {
    throw BackendError(device + ": " + problem);
  }
  if (!impossible.empty())
  {
    throw BackendError(formatText("only impossible states from %s within %.1f s: %s", device.c_str(),
                                  config_.startup_timeout, impossible.c_str()));
  }
  // What was noticed meanwhile may say why (answers too late for the reply deadline, a link without verification).
  std::string noticed;
  for (const std::string& warning : takeWarnings())
  {
    noticed += "; " + warning;
  }
  throw BackendError(formatText("no answer from %s within %.1f s%s%s%s", device.c_str(), config_.startup_timeout,
                                link_error.empty() ? "" : ": ", link_error.c_str(), noticed.c_str()));
}

void DeviceSession::stop()
{
  if (DeviceIoPool::onIoThread())
  {
    throw std::logic_error("a device session (" + link_->config().describe() +
                           ") stopped or destroyed on a device I/O thread: it would wait for its own thread's work");
  }
  auto stopped = std::make_shared<std::promise<void>>();
  std::future<void> done = stopped->get_future();
  {
    std::lock_guard<std::mutex> lock(post_mutex_);
    if (stop_begun_)
    {
      return;
    }
    stop_begun_ = true;  // command() queues nothing from now on: every handler queued so far runs before the fence
    if (started_)
    {
      boost::asio::post(context(), [this, stopped] { beginStop(stopped); });
    }
    else
    {
      // Never started: only commands may be queued; a fence behind them is enough.
      boost::asio::post(context(), [stopped] { stopped->set_value(); });
    }
  }
  done.wait();
}

void DeviceSession::beginStop(std::shared_ptr<std::promise<void>> stopped)
{
  stopped_ = std::move(stopped);
  stopping_ = true;
  tick_timer_.cancel();
  if (link_->isOpen())
  {
    protocol_->shutdown();
  }
  // Close once the last words are out, or after the grace time if the device does not take them.
  link_->whenWritten([this] { finishStop(); });
  if (closing_)
  {
    return;  // nothing was left to write: closed already, and no timer may be armed now
  }
  grace_timer_.expires_after(toDuration(config_.shutdown_grace));
  grace_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error)
    {
      finishStop();
    }
  });
}

void DeviceSession::finishStop()
{
  if (closing_)
  {
    return;  // link_->close() below runs the whenWritten callback too
  }
  closing_ = true;
  grace_timer_.cancel();
  tick_timer_.cancel();
  link_->close();
  if (protocol_ != nullptr)
  {
    protocol_->onClosing();
  }
  // Everything cancelled above has queued its aborted handler by now, and the context runs on one thread, first in
  // first out: once this fence runs, none of them is left, and (closing_) none has started anything new.
  boost::asio::post(context(), [stopped = std::move(stopped_)] { stopped->set_value(); });
}

void DeviceSession::command(std::function<void()> work)
{
  std::lock_guard<std::mutex> lock(post_mutex_);
  if (stop_begun_)
  {
    return;
  }
  boost::asio::post(context(), [this, work = std::move(work)] {
    ++command_serial_;
    work();
  });
}

PtzSample DeviceSession::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const TimePoint now = clock_->now();
  checkLinkLocked();
  PtzSample sample;
  sample.stamp = now;
  sample.position = last_position_;
  motion_.fill(sample);
  sample.link_up = supervisor_.up();
  sample.fault_count = fault_count_;
  sample.link_losses = supervisor_.losses();
  return sample;
}

PtzSample DeviceSession::estimate() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  PtzSample sample;
  sample.stamp = clock_->now();
  sample.position = last_position_;
  motion_.fill(sample);
  return sample;
}

Capabilities DeviceSession::capabilities() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return capabilities_;
}

std::string DeviceSession::lastFault() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return last_fault_;
}

std::vector<std::string> DeviceSession::takeWarnings()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (warnings_taken_ == warnings_given_.size())
  {
    return {};
  }
  std::vector<std::string> fresh(warnings_given_.begin() + static_cast<std::ptrdiff_t>(warnings_taken_),
                                 warnings_given_.end());
  warnings_taken_ = warnings_given_.size();
  return fresh;
}

void DeviceSession::warn(const std::string& text)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (std::find(warnings_given_.begin(), warnings_given_.end(), text) == warnings_given_.end())
  {
    warnings_given_.push_back(text);
  }
}

std::string DeviceSession::lastLinkLoss() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  checkLinkLocked();
  return supervisor_.lastLoss();
}

void DeviceSession::diagnostics(std::vector<DiagnosticValue>& values) const
{
  link_->diagnostics(values);
  addCounts(values, { { "state reports", counters_.state_reports },
                      { "link losses", supervisor_.losses() },
                      { "recoveries (device held after a loss)", counters_.recoveries },
                      { "faults of replaced commands (ignored)", counters_.stale_faults },
                      { "impossible states dropped", counters_.impossible_states },
                      { "received bytes dropped (unframed, too long)", counters_.dropped_bytes } });
  values.emplace_back("state deadline (s)", formatText("%.3f", stateDeadline()));
  values.emplace_back("last link loss", lastLinkLoss());
}

double DeviceSession::stateDeadline() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return supervisor_.stateTimeout();
}

void DeviceSession::replyDeadlineChanged(double reply_deadline)
{
  std::lock_guard<std::mutex> lock(mutex_);
  supervisor_.setStateTimeout(std::max(config_.state_timeout, 3.0 * reply_deadline + config_.poll_period));
}

void DeviceSession::setCapabilities(const Capabilities& capabilities)
{
  std::lock_guard<std::mutex> lock(mutex_);
  capabilities_ = capabilities;
}

void DeviceSession::reportState(const AxisValues& position)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const TimePoint now = clock_->now();
    checkLinkLocked();  // a report after a silence ends that silence as a loss first
    std::string impossible = plausibility_.judge(position, now, capabilities_);
    if (!impossible.empty())
    {
      ++counters_.impossible_states;
      supervisor_.impossibleReported(impossible);
      return;
    }
    ++counters_.state_reports;
    supervisor_.stateReported();
    last_position_ = position;
    motion_.add(now, position);
  }
  refreshLink();
  if (state_listener_)
  {
    state_listener_();
  }
}

void DeviceSession::reportAlive()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    checkLinkLocked();
    supervisor_.aliveReported();
  }
  refreshLink();
}

void DeviceSession::reportFault(const std::string& text, std::uint64_t command)
{
  if (command != command_serial_)
  {
    ++counters_.stale_faults;
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  ++fault_count_;
  last_fault_ = text;
}

void DeviceSession::ready()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_.ready();
  }
  refreshLink();
}

void DeviceSession::failStartup(const std::string& reason)
{
  std::lock_guard<std::mutex> lock(mutex_);
  supervisor_.failStartup(reason);
}

void DeviceSession::onLinkUp()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_.connected();
    motion_.clear();  // old positions say nothing about the device behind a new connection
    plausibility_.forget();
  }
  protocol_->onConnected();
}

void DeviceSession::onLinkBytes(const std::uint8_t* data, std::size_t size)
{
  protocol_->onReceived(data, size);
}

void DeviceSession::onLinkDown(const std::string& reason)
{
  // A loss that repeats on every retry (a refused certificate) before the device was ever up ends start-up now, with
  // that reason, instead of at startup_timeout.
  const bool refused_for_good = link_->refusedForGood();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_.disconnected(reason);
    if (refused_for_good && !supervisor_.everUp() && supervisor_.startupProblem().empty())
    {
      // "https://host:port: GET ...: TLS refused: ..." without the address start() names already.
      const std::string address = link_->config().describe() + ": ";
      supervisor_.failStartup(reason.rfind(address, 0) == 0 ? reason.substr(address.size()) : reason);
    }
  }
  protocol_->onDisconnected();
  if (state_listener_)
  {
    state_listener_();
  }
}

void DeviceSession::tick()
{
  // Ticks keep their rate from one start to the next: a poll that blocks (an HTTP request to a slow camera) is
  // followed by the next at once, not a poll_period later, so a reply at 90 % of state_timeout still keeps the link.
  const auto started = std::chrono::steady_clock::now();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    checkLinkLocked();
  }
  if (link_->isOpen())
  {
    protocol_->poll();
  }
  tick_timer_.expires_at(started + toDuration(config_.poll_period));
  tick_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error && !stopping_)  // a tick already due when stop() began: no poll after the last words
    {
      tick();
    }
  });
}

void DeviceSession::checkLinkLocked() const
{
  if (supervisor_.check() == LinkSupervisor::Loss::IMPOSSIBLE)
  {
    // A device that goes on reporting the same new place is believed from its next report on (it may have been
    // moved by hand, or re-homed): the loss has ended the goal that relied on the old one.
    plausibility_.forget();
  }
}

void DeviceSession::refreshLink()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (supervisor_.refresh() != LinkSupervisor::Rise::RECOVERED)
    {
      return;
    }
  }
  // Same handler as the report that brought the link up: no command the node sends on seeing it up can come first.
  ++counters_.recoveries;
  protocol_->hold();
}

}  // namespace ptz_action_server

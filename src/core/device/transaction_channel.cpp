#include "ptz_action_server/core/device/transaction_channel.h"

#include <algorithm>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// s a device (and this process, on a busy machine) may take to answer beyond the exchange's wire time.
constexpr double REPLY_SLACK = 0.1;
}  // namespace

double replyTimeout(const LinkConfig& link, double configured, std::size_t exchange_bytes)
{
  return configured > 0.0 ? configured : link.wireTime(exchange_bytes) + REPLY_SLACK;
}

TransactionChannel::TransactionChannel(boost::asio::io_context& context, const Clock& clock, Writer write,
                                       double reply_timeout, std::function<void(const Request&)> on_timeout)
  : clock_(clock)
  , write_(std::move(write))
  , reply_timeout_(reply_timeout)
  , on_timeout_(std::move(on_timeout))
  , timer_(context)
{
}

void TransactionChannel::queue(Request request)
{
  if (!request.expects_reply && queue_.empty())
  {
    // Nothing to wait for and nothing ahead of it: a request without reply cannot confuse the matching.
    send(request);
    return;
  }
  queue_.push_back(std::move(request));
  pump();
}

void TransactionChannel::sendUrgent(Request request)
{
  send(request);
}

void TransactionChannel::retry(Request request)
{
  queue_.push_front(std::move(request));
  pump();
}

bool TransactionChannel::polling() const
{
  const auto is_poll = [](const Request& request) { return request.poll; };
  return !queue_.empty() || std::any_of(outstanding_.begin(), outstanding_.end(), is_poll);
}

void TransactionChannel::diagnostics(std::vector<DiagnosticValue>& values) const
{
  addCounts(values, { { "reply timeouts", timeouts_ }, { "late replies dropped", late_replies_ } });
}

void TransactionChannel::clearQueue()
{
  queue_.clear();
}

void TransactionChannel::reset()
{
  queue_.clear();
  outstanding_.clear();
  timer_.cancel();
  drain_until_ = TimePoint{};
}

void TransactionChannel::close()
{
  closed_ = true;
  reset();
}

std::optional<TransactionChannel::Request> TransactionChannel::complete()
{
  return complete([](const Request&) { return true; });
}

std::optional<TransactionChannel::Request>
TransactionChannel::complete(const std::function<bool(const Request&)>& answers)
{
  if (clock_.now() < drain_until_ || outstanding_.empty() || !answers(outstanding_.front()))
  {
    ++late_replies_;
    return std::nullopt;
  }
  Request answered = std::move(outstanding_.front());
  outstanding_.pop_front();
  armTimer();
  pump();
  return answered;
}

void TransactionChannel::pump()
{
  while (outstanding_.empty() && !queue_.empty() && clock_.now() >= drain_until_)
  {
    Request next = std::move(queue_.front());
    queue_.pop_front();
    send(next);
  }
}

void TransactionChannel::send(const Request& request)
{
  if (closed_)
  {
    return;
  }
  write_(request.bytes);
  if (request.expects_reply)
  {
    outstanding_.push_back(request);
    if (outstanding_.size() == 1)
    {
      armTimer();
    }
  }
}

void TransactionChannel::armTimer()
{
  timer_.cancel();
  if (outstanding_.empty())
  {
    return;
  }
  // The oldest request's reply is due reply_timeout from now: it went out now, or the one before it just answered
  // (the device answers in order).
  timer_.expires_after(toDuration(reply_timeout_));
  timer_.async_wait([this](const boost::system::error_code& error) {
    if (error || closed_ || outstanding_.empty())
    {
      return;
    }
    const Request lost = outstanding_.front();
    // Whatever is still on the wire may answer late: drop it all and ignore replies for a while.
    outstanding_.clear();
    drain_until_ = addSeconds(clock_.now(), reply_timeout_);
    ++timeouts_;
    on_timeout_(lost);
    // Resume once the drain time has passed.
    timer_.expires_after(toDuration(reply_timeout_));
    timer_.async_wait([this](const boost::system::error_code& drained) {
      if (!drained && !closed_)
      {
        pump();
      }
    });
  });
}

}  // namespace ptz_action_server

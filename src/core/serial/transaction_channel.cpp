#include "ptz_action_server/core/serial/transaction_channel.h"

namespace ptz_action_server
{
TransactionChannel::TransactionChannel(SerialLink& link, double reply_timeout,
                                       std::function<void(const Request&)> on_timeout)
  : link_(link), reply_timeout_(reply_timeout), on_timeout_(std::move(on_timeout)), timer_(link.context())
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

std::optional<TransactionChannel::Request> TransactionChannel::complete(TimePoint now)
{
  if (now < drain_until_ || outstanding_.empty())
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
  const TimePoint now = SteadyClock::now();
  while (outstanding_.empty() && !queue_.empty() && now >= drain_until_)
  {
    Request next = std::move(queue_.front());
    queue_.pop_front();
    send(next);
  }
}

void TransactionChannel::send(const Request& request)
{
  link_.write(request.bytes);
  if (request.expects_reply && link_.connected())
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
  timer_.expires_at(addSeconds(SteadyClock::now(), reply_timeout_));
  timer_.async_wait([this](const boost::system::error_code& error) {
    if (error || outstanding_.empty())
    {
      return;
    }
    const Request lost = outstanding_.front();
    // Whatever is still on the wire may answer late: drop it all and ignore replies for a while.
    outstanding_.clear();
    drain_until_ = addSeconds(SteadyClock::now(), reply_timeout_);
    on_timeout_(lost);
    // Resume once the drain time has passed.
    timer_.expires_at(drain_until_);
    timer_.async_wait([this](const boost::system::error_code& drained) {
      if (!drained)
      {
        pump();
      }
    });
  });
}

}  // namespace ptz_action_server

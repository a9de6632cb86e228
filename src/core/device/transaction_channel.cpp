#include "ptz_action_server/core/device/transaction_channel.h"

#include <algorithm>

#include "ptz_action_server/core/device/device_session.h"
#include "ptz_action_server/core/text.h"
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
  : clock_(clock), write_(std::move(write)), timing_(reply_timeout), on_timeout_(std::move(on_timeout)), timer_(context)
{
}

TransactionChannel::TransactionChannel(DeviceSession& session, Writer write, double reply_timeout,
                                       std::function<void(const Request&)> on_timeout)
  : TransactionChannel(session.context(), session.clock(), std::move(write), reply_timeout, std::move(on_timeout))
{
  on_deadline_ = [&session](double deadline) { session.replyDeadlineChanged(deadline); };
  on_too_late_ = [&session](const std::string& text) { session.warn(text); };
  on_deadline_(timing_.deadline());
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
  return !queue_.empty() || std::any_of(outstanding_.begin(), outstanding_.end(), is_poll) ||
         std::any_of(overdue_.begin(), overdue_.end(), is_poll);
}

void TransactionChannel::diagnostics(std::vector<DiagnosticValue>& values) const
{
  timing_.diagnostics(values);
  addCounts(values, { { "reply timeouts", timeouts_ },
                      { "late replies taken", late_taken_ },
                      { "late replies dropped", late_replies_ } });
}

void TransactionChannel::clearQueue()
{
  queue_.clear();
}

void TransactionChannel::reset()
{
  queue_.clear();
  outstanding_.clear();
  overdue_.clear();
  timer_.cancel();
  drain_until_ = TimePoint{};
  busy_until_ = TimePoint{};
  front_guessed_ = false;
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
  const TimePoint now = clock_.now();
  if (!overdue_.empty() && now < drain_until_)
  {
    // Draining, and nothing has gone out since the timeout: the overdue request's answer, if it can be and it came
    // within the ceiling. Later than that, the device answers too slowly to be used.
    const bool too_late = secondsBetween(front_since_, now) > timing_.ceiling();
    if (too_late && on_too_late_)
    {
      on_too_late_(formatText("answers come later than %.3f s, the most the reply deadline learns (twice "
                              "reply_timeout, whose 0 means 100 ms and the wire time): they are dropped; if the "
                              "device is that slow, raise reply_timeout",
                              timing_.ceiling()));
    }
    if (too_late || !answers(overdue_.front()))
    {
      ++late_replies_;
      return std::nullopt;
    }
    Request answered = std::move(overdue_.front());
    overdue_.pop_front();
    ++late_taken_;
    learn(now);
    front_since_ = now;  // the next overdue one's deadline: the device answers in order
    front_guessed_ = false;
    if (overdue_.empty())
    {
      // Everything that was on the wire is answered: nothing late can follow, the drain is over.
      drain_until_ = now;
      timer_.cancel();
      pump();
    }
    return answered;
  }
  if (now < drain_until_ || outstanding_.empty() || !answers(outstanding_.front()))
  {
    ++late_replies_;
    return std::nullopt;
  }
  Request answered = std::move(outstanding_.front());
  outstanding_.pop_front();
  learn(now);
  armTimer();
  pump();
  return answered;
}

void TransactionChannel::learn(TimePoint now)
{
  if (front_guessed_)
  {
    return;  // when the device could start on it was a guess: its time says little
  }
  if (timing_.answered(secondsBetween(front_since_, now)) && on_deadline_)
  {
    on_deadline_(timing_.deadline());
  }
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
  const TimePoint now = clock_.now();
  if (!request.expects_reply)
  {
    // The device reads it before whatever follows, and may take as long over it as over a request it answers: the
    // next request's deadline begins after that (within a ceiling, however many such requests go out).
    busy_until_ =
        std::min(addSeconds(std::max(now, busy_until_), timing_.typical()), addSeconds(now, timing_.ceiling()));
    return;
  }
  overdue_.clear();  // a reply may be this request's from now on: the overdue ones are no longer awaited
  outstanding_.push_back(request);
  if (outstanding_.size() == 1)
  {
    armTimer();
  }
}

void TransactionChannel::armTimer()
{
  timer_.cancel();
  if (outstanding_.empty())
  {
    return;
  }
  // The first request's deadline begins now (it went out now, or the one before it just answered: the device answers
  // in order), or once the device is done with the requests without reply written before it.
  const TimePoint now = clock_.now();
  front_guessed_ = busy_until_ > now;
  front_since_ = front_guessed_ ? busy_until_ : now;
  timer_.expires_after(toDuration(secondsBetween(now, front_since_) + timing_.deadline()));
  timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error && !closed_ && !outstanding_.empty())
    {
      onTimeout();
    }
  });
}

void TransactionChannel::onTimeout()
{
  const Request lost = outstanding_.front();
  // Whatever is on the wire may still answer: it is awaited while draining, and nothing new goes out meanwhile, so a
  // late reply is never taken for the next request's.
  overdue_ = std::move(outstanding_);
  outstanding_.clear();
  const TimePoint now = clock_.now();
  const double deadline = timing_.deadline();
  drain_until_ = addSeconds(std::max(now, addSeconds(front_since_, deadline)), deadline);
  ++timeouts_;
  timer_.expires_after(toDuration(secondsBetween(now, drain_until_)));
  timer_.async_wait([this](const boost::system::error_code& error) {
    if (error || closed_)
    {
      return;
    }
    if (clock_.now() >= drain_until_)
    {
      overdue_.clear();
    }
    pump();
  });
  on_timeout_(lost);
}

}  // namespace ptz_action_server

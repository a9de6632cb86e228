/**
 * \file
 * \brief Request/reply bookkeeping for protocols that answer requests in order (FLIR, Pelco-D, VISCA).
 */
#pragma once

#include <deque>
#include <functional>
#include <optional>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/counter.h"
#include "ptz_action_server/core/device/reply_timing.h"
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
class DeviceSession;

/// The floor of the reply deadline of an exchange of \p exchange_bytes (request and reply): \p configured if > 0,
/// else the exchange's time on the wire plus 100 ms. The deadline learns from the device up to twice that
/// (ReplyTiming).
double replyTimeout(const LinkConfig& link, double configured, std::size_t exchange_bytes);

/**
 * \brief One request on the wire at a time, so a reply never needs guessing which request it answers.
 *
 * Requests wait in a queue; an urgent request (a halt) goes out at once and is answered after the one already on
 * the wire. Everything runs on the I/O thread of \p context; time is \p clock's, so tests can drive it.
 *
 * Each request has a reply deadline, learnt from the device's answers (ReplyTiming): it begins when the device can
 * start on the request (it went out, the request before it was answered, or the requests without reply written before
 * it have had their typical answer time) and lasts the learnt deadline. A request without a reply in time is overdue:
 * on_timeout runs, and the channel drains for one more deadline before it sends anything else. An answer that comes
 * meanwhile, before the next request went out, that can answer the overdue request (complete(answers) says so) and
 * came within the deadline's ceiling, is that request's answer: taken, counted, and it teaches the deadline. Any other
 * reply while draining is dropped, so a late reply is never taken for the next request's.
 */
class TransactionChannel
{
public:
  struct Request
  {
    std::string bytes;
    int tag = 0;                ///< what the protocol asked, to interpret the reply
    bool expects_reply = true;  ///< false: written and forgotten
    std::uint64_t command = 0;  ///< the node command it serves (DeviceSession::currentCommand()), for its faults
    bool poll = false;          ///< a state poll: asked for only while no goal command waits (see polling())
  };
  using Writer = std::function<void(const std::string& bytes)>;

  /// \p write sends bytes; \p on_timeout runs (I/O thread) for a request overdue; the reply deadline starts at
  /// \p reply_timeout s (see replyTimeout()) and learns up to twice that.
  TransactionChannel(boost::asio::io_context& context, const Clock& clock, Writer write, double reply_timeout,
                     std::function<void(const Request&)> on_timeout);
  /// The same on \p session's I/O thread and clock; the session's state deadline follows the reply deadline learnt
  /// (DeviceSession::replyDeadlineChanged()), and an answer later than the ceiling is a warning
  /// (DeviceSession::warn()).
  TransactionChannel(DeviceSession& session, Writer write, double reply_timeout,
                     std::function<void(const Request&)> on_timeout);

  /// Queues a request (sent when the wire is free). A request without reply, with nothing queued ahead of it, goes
  /// out at once.
  void queue(Request request);
  /// Sends now, ahead of the queue.
  void sendUrgent(Request request);
  /// Queues \p request first in line (a request that timed out, asked again once the drain is over).
  void retry(Request request);
  /// Drops the queued (not yet sent) requests: what a new command replaces.
  void clearQueue();
  /// Forgets everything but the deadline learnt (after a reconnect).
  void reset();
  /// For good (the session closes): cancels the timer; nothing is sent or timed from now on.
  void close();

  /// A reply arrived: the request it answers (the one on the wire, or the overdue one while draining), or nothing.
  std::optional<Request> complete();
  /// A reply that \p answers tells apart arrived: the request on the wire (or overdue) if it answers it. Otherwise it
  /// is the late reply of a request before it (counted, dropped) and the request on the wire still waits for its own:
  /// a device that once answered later than the drain is not answered one request behind from then on.
  std::optional<Request> complete(const std::function<bool(const Request&)>& answers);
  std::size_t queued() const
  {
    return queue_.size();
  }
  /// True while a poll waits or is on the wire, or anything else waits: then no new poll should be queued, so goal
  /// commands go first and the line is never flooded.
  bool polling() const;
  /// The reply deadline learnt so far (s). Any thread.
  double replyDeadline() const
  {
    return timing_.deadline();
  }
  const ReplyTiming& timing() const
  {
    return timing_;
  }
  std::uint64_t timeouts() const
  {
    return timeouts_;
  }
  std::uint64_t lateReplies() const
  {
    return late_replies_;
  }
  std::uint64_t lateRepliesTaken() const
  {
    return late_taken_;
  }
  /// The reply deadline, the answer times, reply timeouts and late replies, for diagnostics. Any thread.
  void diagnostics(std::vector<DiagnosticValue>& values) const;

private:
  void pump();
  void send(const Request& request);
  /// Starts the deadline of the request on the wire first (none: stops the timer).
  void armTimer();
  void onTimeout();
  /// The request now answered took from front_since_ to now: learnt (unless its start was a guess).
  void learn(TimePoint now);

  const Clock& clock_;
  Writer write_;
  ReplyTiming timing_;
  std::function<void(double)> on_deadline_;              ///< told each new deadline (the session), or empty
  std::function<void(const std::string&)> on_too_late_;  ///< told of answers later than the ceiling, or empty
  std::function<void(const Request&)> on_timeout_;
  boost::asio::steady_timer timer_;
  std::deque<Request> queue_;
  std::deque<Request> outstanding_;  ///< on the wire, oldest first
  std::deque<Request> overdue_;      ///< on the wire when the first of them timed out; awaited while draining
  TimePoint front_since_{};          ///< when the deadline of the first on the wire (or overdue) began
  bool front_guessed_ = false;       ///< front_since_ is a guess: requests without reply went out before it
  TimePoint busy_until_{};           ///< when the device should be done with the requests without reply written
  TimePoint drain_until_{};
  bool closed_ = false;
  Counter timeouts_;
  Counter late_replies_;
  Counter late_taken_;
};

}  // namespace ptz_action_server

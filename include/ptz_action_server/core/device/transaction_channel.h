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
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// The reply deadline of an exchange of \p exchange_bytes (request and reply): \p configured if > 0, else the
/// exchange's time on the wire plus 100 ms.
double replyTimeout(const LinkConfig& link, double configured, std::size_t exchange_bytes);

/**
 * \brief One request on the wire at a time, so a reply never needs guessing which request it answers.
 *
 * Requests wait in a queue; an urgent request (a halt) goes out at once and is answered after the one already on
 * the wire. A request without a reply in time is dropped (on_timeout runs), and replies are then ignored for a drain
 * time, so a late reply cannot be taken for the next request's. Everything runs on the I/O thread of \p context;
 * time is \p clock's, so tests can drive it.
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

  /// \p write sends bytes; \p on_timeout runs (I/O thread) for a request without a reply within \p reply_timeout s.
  TransactionChannel(boost::asio::io_context& context, const Clock& clock, Writer write, double reply_timeout,
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
  /// Forgets everything (after a reconnect).
  void reset();
  /// For good (the session closes): cancels the timer; nothing is sent or timed from now on.
  void close();

  /// A reply arrived: the request it answers, or nothing (none outstanding, or draining after a timeout).
  std::optional<Request> complete();
  /// A reply that \p answers tells apart arrived: the request on the wire if it answers it. Otherwise it is the late
  /// reply of a request that timed out (counted, dropped) and the request on the wire still waits for its own: a
  /// device that once answered later than the drain is not answered one request behind from then on.
  std::optional<Request> complete(const std::function<bool(const Request&)>& answers);
  std::size_t queued() const
  {
    return queue_.size();
  }
  /// True while a poll waits or is on the wire, or anything else waits: then no new poll should be queued, so goal
  /// commands go first and the line is never flooded.
  bool polling() const;
  std::uint64_t timeouts() const
  {
    return timeouts_;
  }
  std::uint64_t lateReplies() const
  {
    return late_replies_;
  }
  /// Reply timeouts and late replies, for diagnostics. Any thread.
  void diagnostics(std::vector<DiagnosticValue>& values) const;

private:
  void pump();
  void send(const Request& request);
  void armTimer();

  const Clock& clock_;
  Writer write_;
  const double reply_timeout_;
  std::function<void(const Request&)> on_timeout_;
  boost::asio::steady_timer timer_;
  std::deque<Request> queue_;
  std::deque<Request> outstanding_;  ///< on the wire, oldest first
  TimePoint drain_until_{};
  bool closed_ = false;
  Counter timeouts_;
  Counter late_replies_;
};

}  // namespace ptz_action_server

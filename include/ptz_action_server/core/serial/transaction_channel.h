/**
 * \file
 * \brief Request/reply bookkeeping over a SerialLink, shared by the serial protocols.
 */
#pragma once

#include <deque>
#include <functional>
#include <optional>
#include <string>

#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/core/transport/serial_link.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief One request on the wire at a time, so replies never need guessing which request they answer.
 *
 * Requests wait in a queue; an urgent request (a halt) goes out at once and is answered after the one already on
 * the wire. A request without reply in time is dropped with a counter, and replies are then ignored for a drain
 * time, so a late reply cannot be taken for the next request's. Everything runs on the link's I/O thread.
 */
class TransactionChannel
{
public:
  struct Request
  {
    std::string bytes;
    int tag = 0;                ///< what the protocol asked, to interpret the reply
    bool expects_reply = true;  ///< false: written and forgotten
  };

  /// \p on_timeout runs (I/O thread) for a request that got no reply within \p reply_timeout.
  TransactionChannel(SerialLink& link, double reply_timeout, std::function<void(const Request&)> on_timeout);

  /// Queues a request (sent when the wire is free). A request without reply, with nothing queued ahead of it, goes
  /// out at once.
  void queue(Request request);
  /// Sends now, ahead of the queue.
  void sendUrgent(Request request);
  /// Drops the queued (not yet sent) requests.
  void clearQueue();
  /// Forgets everything (after a reconnect).
  void reset();

  /// A reply arrived: the request it answers, or nothing (none outstanding, or draining after a timeout).
  std::optional<Request> complete(TimePoint now);
  std::size_t queued() const
  {
    return queue_.size();
  }

  std::uint64_t lateReplies() const
  {
    return late_replies_;
  }

private:
  void pump();
  void send(const Request& request);
  void armTimer();

  SerialLink& link_;
  const double reply_timeout_;
  std::function<void(const Request&)> on_timeout_;
  boost::asio::steady_timer timer_;
  std::deque<Request> queue_;
  std::deque<Request> outstanding_;  ///< on the wire, oldest first
  TimePoint drain_until_{};
  std::uint64_t late_replies_ = 0;
};

}  // namespace ptz_action_server

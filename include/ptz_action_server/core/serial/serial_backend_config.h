/**
 * \file
 * \brief Settings every serial backend shares.
 */
#pragma once

#include "ptz_action_server/core/transport/serial_link.h"

namespace ptz_action_server
{
struct SerialBackendConfig
{
  SerialLinkConfig link;               ///< device path, baud, reconnect backoff
  double transaction_deadline = 0.25;  ///< s without a valid reply (while one is due) before the link is down
  double reply_timeout = 0.0;          ///< s for one reply; 0: the exchange's wire time plus 50 ms
  double poll_period = 0.05;           ///< s between state polls
  double startup_timeout = 10.0;       ///< s start() waits for the device to answer
  double settle_window = 0.1;          ///< s a still position must last to count as settled

  /// Seconds \p bytes take on the wire at the configured baud (8N1: 10 bits a byte).
  double wireTime(std::size_t bytes) const
  {
    return bytes * 10.0 / link.baud;
  }
  /// The reply timeout for an exchange of \p bytes in total.
  double replyTimeoutFor(std::size_t bytes) const
  {
    return reply_timeout > 0.0 ? reply_timeout : wireTime(bytes) + 0.05;
  }
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief What protocols over HTTP (VAPIX, ONVIF) see of their transport: requests and answers, not bytes.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/counter.h"

namespace ptz_action_server
{
/// One request. GET when body is empty, POST otherwise.
struct HttpRequest
{
  std::string path;          ///< from the first '/', with the query: "/axis-cgi/com/ptz.cgi?query=position"
  std::string body;          ///< POST body
  std::string content_type;  ///< POST content type
};

/// What came back.
struct HttpReply
{
  bool delivered = false;  ///< an HTTP answer arrived; false: the link was lost (the reason is its lastError())
  long status = 0;         ///< HTTP status code
  std::string body;
};

/// What an HTTP channel counts beyond LinkCounters.
struct HttpCounters
{
  Counter requests;           ///< requests made
  Counter connections;        ///< TCP (or TLS) connections curl had to open: 1 while the camera keeps its connection
  Counter error_statuses;     ///< answers with a status >= 400
  Counter timeouts;           ///< requests that hit request_timeout
  Counter transport_errors;   ///< refused, reset, unresolvable, TLS failures
  Counter tls_refusals;       ///< TLS connections refused: the camera's certificate was untrusted or not the pinned one
  Counter oversized_answers;  ///< answers past HttpLink::MAX_ANSWER (a body or envelope without end): dropped
  Counter dropped_bytes;      ///< bytes of those answers received before they were cut
};

/**
 * \brief Requests and their answers to one HTTP server, one at a time, on the session's I/O thread.
 *
 * The link behind it (HttpLink) keeps the connection and its supervision: a request that gets no answer loses the
 * link with its reason before request() returns, and the session hears of it as of any link's loss. A DeviceSession
 * over HTTP hands it to its protocol (DeviceSession::http()).
 */
class HttpChannel
{
public:
  virtual ~HttpChannel() = default;

  /// Makes one request (I/O thread, link open) and returns its answer, valid until the next request. Blocks for at
  /// most request_timeout. Without an answer the reply says !delivered and the link is lost.
  virtual const HttpReply& request(const HttpRequest& request) = 0;
  /// Any thread.
  virtual const HttpCounters& httpCounters() const = 0;

  /// "GET /axis-cgi/com/ptz.cgi?query=position", for messages.
  static std::string describe(const HttpRequest& request)
  {
    return (request.body.empty() ? "GET " : "POST ") + request.path;
  }
};

}  // namespace ptz_action_server

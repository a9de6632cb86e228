/**
 * \file
 * \brief HTTP under the device layer: a Link (kind HTTP) whose traffic is requests and answers (HttpChannel), made
 * with libcurl on the session's I/O thread over one keep-alive connection.
 *
 * Decision (doc/device-layer.md, "HTTP on the device layer"): HTTP is a link like the others, so reconnection with
 * backoff, the loss reasons, the counters and the session's supervision stay in one place. A request runs to completion
 * on the I/O thread (curl's easy interface, one handle reused for every request, so one connection and one digest nonce
 * serve them all); its deadline (request_timeout) bounds how long the thread can be held. Commands queued meanwhile
 * run after it, in order, as on a serial line with one request on the wire.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/transport/http_channel.h"
#include "ptz_action_server/core/transport/link.h"

struct curl_slist;  // libcurl's, kept out of this header

namespace ptz_action_server
{
/// "AB:CD:..." (any case, with or without colons, spaces allowed around) as 64 lower-case hex digits; "" if \p text is
/// not a SHA-256 fingerprint.
std::string parseCertificateFingerprint(const std::string& text);
/// 64 hex digits as "AB:CD:...", the form browsers and `openssl x509 -fingerprint -sha256` print.
std::string formatCertificateFingerprint(const std::string& hex);

/// A pinned certificate: what the check wants and what the camera last presented.
struct CertificatePin
{
  std::string expected;   ///< 64 lower-case hex digits ("" = no pin)
  std::string presented;  ///< the SHA-256 of the certificate the last handshake saw, if it did not match
};

/**
 * \brief The HTTP link: requests on the I/O thread, one connection kept alive, Digest or Basic authentication.
 *
 * "Open" means ready to send: the connection itself is curl's to make on the first request and to keep. A request
 * that gets no answer (refused, reset, timed out) loses the link with its reason, and it reopens after the backoff;
 * the backoff starts afresh only once an answer came (provenAlive()). It carries no bytes (bytes() is nullptr):
 * protocols reach it as an HttpChannel (http()). A refused certificate is a loss for good (refusedForGood()): start-up
 * ends.
 *
 * request() blocks its thread for up to request_timeout, so a session over HTTP does not share the pool's I/O threads
 * (DeviceIoPool): it gets a thread of its own, until HTTP is asynchronous.
 */
class HttpLink : public Link, public HttpChannel
{
public:
  /// Bytes an answer's body (a VAPIX reply, a SOAP envelope) may have. Past it the answer is cut and dropped, counted
  /// (HttpCounters::oversized_answers, dropped_bytes), and the link is lost: it reopens on a fresh connection.
  static constexpr std::size_t MAX_ANSWER = 256 * 1024;

  HttpLink(boost::asio::io_context& context, const LinkConfig& config, Listener& listener);
  ~HttpLink() override;

  /// Makes one request (I/O thread, link open). Blocks for at most request_timeout. On a failure without an answer
  /// the link is lost (the listener hears onLinkDown() before this returns) and the reply says !delivered.
  const HttpReply& request(const HttpRequest& request) override;

  const HttpCounters& httpCounters() const override
  {
    return http_counters_;
  }
  HttpChannel* http() override
  {
    return this;
  }
  void diagnostics(std::vector<DiagnosticValue>& values) const override;
  /// The last request failed because its certificate was refused (untrusted, or not the pinned one): retrying the
  /// same camera will not change that. I/O thread.
  bool refusedForGood() const override
  {
    return certificate_refused_;
  }

  /// The warning a session gives once for \p config: TLS with verification off; "" for none.
  static std::string configWarning(const LinkConfig& config);

protected:
  void startOpen() override;
  void closeHandle() override;

private:
  void configureHandle();
  void configureTls();
  /// Why curl's TLS failure \p result happened, in the user's terms (which certificate, which parameter).
  std::string tlsFailure(int result) const;
  /// curl_easy_perform with the authentication this request may carry (a CURLcode).
  int performOnce(const HttpRequest& request);

  void* curl_ = nullptr;      ///< CURL*: one easy handle for every request (its connection and nonce)
  curl_slist* post_headers_;  ///< Content-Type and "Expect:" of POSTs (rebuilt when the type changes)
  std::string post_content_type_;
  const std::string base_url_;
  HttpReply reply_;  ///< reused: no allocation per poll once its body has grown
  char error_buffer_[256] = {};
  long auth_;                ///< CURLAUTH_* bits to offer (AUTO narrows them to what the camera asked for)
  bool challenged_ = false;  ///< the camera has answered 401 once: it wants HTTP authentication
  CertificatePin pin_;       ///< the pin and what the camera presented (OpenSSL's verify callback fills it, I/O thread)
  HttpCounters http_counters_;
  bool certificate_refused_ = false;  ///< the last request's certificate was refused (I/O thread)
};

}  // namespace ptz_action_server

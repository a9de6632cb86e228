/**
 * \file
 * \brief The HTTP end of the emulated IP cameras: a Boost.Beast server on 127.0.0.1 with keep-alive connections,
 * HTTP Digest (RFC 7616, MD5, qop=auth, nonces that go stale) or Basic authentication, faults to switch on, and TLS
 * (Asio over OpenSSL) with a certificate of its own.
 */
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl/context.hpp>

#include "ptz_action_server/core/counter.h"
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/core/types.h"
#include "ptz_action_server/emulators/ports/received_log.h"

namespace ptz_action_server
{
/// Where and how the camera's web server answers.
struct HttpCameraServerConfig
{
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;            ///< 0 = any free port
  HttpAuth auth = HttpAuth::DIGEST;  ///< DIGEST, BASIC or NONE (AUTO is a client's choice: taken as DIGEST)
  std::string realm = "AXIS_ACCC8E000000";
  std::string username = "root";
  std::string password = "pass";
  unsigned nonce_uses = 0;  ///< a nonce goes stale after this many requests (0: never), as some firmware does
  /// https: TLS with a self-signed certificate generated at start (an EC P-256 key; names 127.0.0.1, localhost
  /// and host). A plain-HTTP request on the port is answered 400 and counted, never served.
  bool tls = false;
  /// "" = none: the file the server appends every credential-derived value it meets to, one a line (the Digest
  /// nonces it hands out, each request's Digest response and cnonce, a Basic token; the ONVIF camera adds the
  /// WS-Security Nonce and PasswordDigest), so a test can check that a client never prints one.
  std::string secrets_file;
};

/// A request as the server read it.
struct HttpExchange
{
  TimePoint at;  ///< when it was read
  std::string method;
  std::string target;  ///< path and query
  std::string body;
  unsigned status = 0;  ///< what it was answered (0: not answered)
};

/// What a camera answers to an authenticated request.
struct HttpAnswer
{
  unsigned status = 200;
  std::string content_type = "text/plain";
  std::string body;
  /// A WWW-Authenticate the handler sends with a 401 of its own (a camera whose service asks for credentials its web
  /// server does not check: Axis's ONVIF service); "" for none. (Initialised here: answers brace-initialise the
  /// fields above only.)
  std::string challenge{};
};

/// What the server counts. Any thread.
struct HttpServerCounters
{
  Counter connections;          ///< TCP connections accepted
  Counter requests;             ///< requests read
  Counter challenges;           ///< 401 answers (a request without valid credentials, or a stale nonce)
  Counter refused_credentials;  ///< a wrong user or password (or digest response)
  Counter tls_handshakes;       ///< tls: handshakes completed
  Counter tls_failures;         ///< tls: handshakes that failed (the client refused the certificate, or spoke no TLS)
  Counter plain_requests;       ///< tls: plain-HTTP requests sent to the TLS port (answered 400, never served)
};

/// RFC 7616 (qop=auth, MD5): the `response` of a Digest Authorization.
std::string httpDigestResponse(const std::string& username, const std::string& realm, const std::string& password,
                               const std::string& method, const std::string& uri, const std::string& nonce,
                               const std::string& nc, const std::string& cnonce);

class SocketServer;
class TcpListener;

/**
 * \brief A camera's web server. Requests that pass authentication go to the handler (on the server's thread, one at
 * a time); which requests need none is the handler's to say.
 */
class HttpCameraServer
{
public:
  /// Answers one authenticated request: method, target (path and query), body.
  using Handler =
      std::function<HttpAnswer(const std::string& method, const std::string& target, const std::string& body)>;
  /// True for a request served without HTTP authentication (ONVIF: WS-Security is in the body).
  using Open = std::function<bool(const std::string& target)>;

  HttpCameraServer(const HttpCameraServerConfig& config, Handler handler, Open open = nullptr);
  ~HttpCameraServer();
  HttpCameraServer(const HttpCameraServer&) = delete;
  HttpCameraServer& operator=(const HttpCameraServer&) = delete;

  std::uint16_t port() const;
  /// "https://127.0.0.1:PORT" or "http://...".
  std::string url() const;
  /// tls: the SHA-256 of the certificate, "AB:CD:..." (what a client pins); "" without tls.
  std::string fingerprint() const;
  /// tls: the certificate, PEM (what a client may trust as its CA file); "" without tls.
  std::string certificatePem() const;
  /// Writes certificatePem() to \p path. Throws std::runtime_error if it cannot.
  void writeCertificate(const std::string& path) const;
  /// tls: makes a new key and certificate (a camera reset to factory, or someone else on its address) and drops every
  /// connection: the next ones meet the new certificate.
  void renewCertificate();
  /// Reads requests and never answers them.
  void setSilent(bool silent);
  /// Endless: every answer's body is cut half-way and followed by ENDLESS_BODY filler bytes ('A'), more than any
  /// client should keep: a body or SOAP envelope that never ends. Off again, the answers are whole.
  void setEndless(bool endless);
  static constexpr std::size_t ENDLESS_BODY = 512 * 1024;
  /// Waits \p seconds before each answer.
  void setDelay(double seconds);
  /// Answers every request with \p status (e.g. 500) and a short body; 0 = normally.
  void setErrorStatus(unsigned status);
  /// Closes every open connection (a reboot, a network cut); keeps listening unless setListening(false).
  void dropConnections();
  /// Stops or resumes listening on the same port (stopped: connections are refused).
  void setListening(bool listening);
  /// Makes every outstanding nonce stale (the next request is challenged with stale=true).
  void renewNonce();
  /// The Cookie header of the request being handled ("" without one): for the handler, on its thread, during its call.
  const std::string& requestCookie() const
  {
    return request_cookie_;
  }
  /// For the handler, during its call: its answer carries `Set-Cookie: value`.
  void setAnswerCookie(const std::string& value)
  {
    answer_cookie_ = value;
  }
  /// Appends \p values (the empty ones skipped) to config's secrets_file, one a line; nothing without one. Any thread.
  void recordSecrets(const std::vector<std::string>& values);

  ReceivedLog<HttpExchange>& received()
  {
    return received_;
  }
  const HttpServerCounters& counters() const
  {
    return counters_;
  }

private:
  class Connection;
  friend class Connection;

  void accept();
  /// Closes every open connection (server thread).
  void closeConnections();
  /// The answer to one request; \p challenge set for a 401.
  HttpAnswer answer(const std::string& method, const std::string& target, const std::string& body,
                    const std::string& authorization, std::string& challenge);
  bool authorised(const std::string& method, const std::string& target, const std::string& authorization, bool& stale);
  std::string newNonce();

  const HttpCameraServerConfig config_;
  std::string request_cookie_;  ///< see requestCookie()
  std::string answer_cookie_;   ///< see setAnswerCookie()
  const Handler handler_;
  const Open open_;
  void makeCertificate();

  std::string certificate_pem_;                             ///< tls only; guarded by mutex_
  std::string fingerprint_;                                 ///< tls only; guarded by mutex_
  std::shared_ptr<boost::asio::ssl::context> ssl_context_;  ///< that of new connections (each keeps its own)
  std::unique_ptr<SocketServer> socket_server_;  ///< the context and its thread (what the emulators' ports serve on
                                                 ///< too)
  std::unique_ptr<TcpListener> listener_;        ///< after socket_server_, whose context it uses
  ReceivedLog<HttpExchange> received_;
  HttpServerCounters counters_;

  std::mutex secrets_mutex_;  ///< guards appends to secrets_file
  mutable std::mutex mutex_;  ///< guards the fault switches and the certificate's texts
  bool silent_ = false;
  bool endless_ = false;
  double delay_ = 0.0;
  unsigned error_status_ = 0;

  // Server thread only.
  std::set<std::shared_ptr<Connection>> connections_;
  std::string nonce_;
  unsigned nonce_used_ = 0;
  std::uint64_t nonce_serial_ = 0;
};

}  // namespace ptz_action_server

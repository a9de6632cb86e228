/**
 * \file
 * \brief The HTTP link on libcurl's easy interface: one handle, so one keep-alive connection and one digest nonce
 * for every request.
 */
#include "ptz_action_server/core/transport/http_link.h"

#include <curl/curl.h>
#include <openssl/evp.h>
#include <openssl/ssl.h>
#include <openssl/x509.h>
#include <openssl/x509_vfy.h>

#include <cctype>
#include <fstream>
#include <mutex>
#include <stdexcept>

#include <boost/asio/post.hpp>

#include "links.h"
#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
std::size_t appendBody(char* data, std::size_t size, std::size_t count, void* body)
{
  std::string& kept = *static_cast<std::string*>(body);
  if (kept.size() + size * count > HttpLink::MAX_ANSWER)
  {
    return 0;  // an answer that never ends: curl aborts it (CURLE_WRITE_ERROR)
  }
  kept.append(data, size * count);
  return size * count;
}

long curlAuth(HttpAuth auth)
{
  switch (auth)
  {
    case HttpAuth::DIGEST:
      return CURLAUTH_DIGEST;
    case HttpAuth::BASIC:
      return CURLAUTH_BASIC;
    case HttpAuth::AUTO:
      return CURLAUTH_DIGEST | CURLAUTH_BASIC;
    case HttpAuth::NONE:
      return CURLAUTH_NONE;
  }
  return CURLAUTH_NONE;
}

/// OpenSSL's whole certificate check while a pin is set (SSL_CTX_set_cert_verify_callback): the chain need not be
/// trusted, the camera's own certificate must have the pinned SHA-256.
int checkPinnedCertificate(X509_STORE_CTX* store, void* pin_pointer)
{
  auto& pin = *static_cast<CertificatePin*>(pin_pointer);
  X509* certificate = X509_STORE_CTX_get0_cert(store);
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (certificate == nullptr || X509_digest(certificate, EVP_sha256(), digest, &length) != 1)
  {
    X509_STORE_CTX_set_error(store, X509_V_ERR_UNSPECIFIED);
    return 0;
  }
  const std::string presented = hexDigits(digest, length);
  if (presented == pin.expected)
  {
    pin.presented.clear();
    X509_STORE_CTX_set_error(store, X509_V_OK);
    return 1;
  }
  pin.presented = presented;
  X509_STORE_CTX_set_error(store, X509_V_ERR_CERT_REJECTED);
  return 0;
}

/// CURLOPT_SSL_CTX_FUNCTION: installs the pin check on the connection's OpenSSL context (before its handshake).
CURLcode onSslContext(CURL*, void* ssl_context, void* pin)
{
  SSL_CTX_set_cert_verify_callback(static_cast<SSL_CTX*>(ssl_context), checkPinnedCertificate, pin);
  return CURLE_OK;
}
}  // namespace

std::string parseCertificateFingerprint(const std::string& text)
{
  std::string hex;
  for (char c : text)
  {
    if (std::isxdigit(static_cast<unsigned char>(c)) != 0)
    {
      hex += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    else if (c != ':' && c != ' ' && c != '\t')
    {
      return "";
    }
  }
  return hex.size() == 64 ? hex : "";
}

std::string formatCertificateFingerprint(const std::string& hex)
{
  std::string text;
  for (std::size_t i = 0; i < hex.size(); i += 2)
  {
    text += (i == 0 ? "" : ":") + hex.substr(i, 2);
  }
  for (char& c : text)
  {
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return text;
}

std::string HttpLink::configWarning(const LinkConfig& config)
{
  if (config.kind != LinkKind::HTTP || !config.http.tls || config.http.verify_peer)
  {
    return "";
  }
  return "TLS certificate verification is off (tls_verify: false) for " + config.describe() +
         ": anyone on the network path can pose as the camera and read what is sent to it; pin its certificate "
         "instead (tls_fingerprint, the SHA-256 its web page or `openssl s_client` shows)";
}

HttpLink::HttpLink(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
  : Link(context, config, listener)
  , post_headers_(nullptr)
  , base_url_(config.describe())
  , auth_(curlAuth(config.http.auth))
{
  static std::once_flag global_init;
  std::call_once(global_init, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
  curl_ = curl_easy_init();
  if (curl_ == nullptr)
  {
    throw ConfigError("libcurl could not make a handle for " + base_url_);
  }
  configureHandle();
}

HttpLink::~HttpLink()
{
  curl_easy_cleanup(curl_);
  curl_slist_free_all(post_headers_);
}

void HttpLink::configureHandle()
{
  const HttpLinkConfig& http = config_.http;
  curl_easy_setopt(curl_, CURLOPT_NOSIGNAL, 1L);  // other threads run: no SIGALRM for timeouts
  curl_easy_setopt(curl_, CURLOPT_ERRORBUFFER, error_buffer_);
  curl_easy_setopt(curl_, CURLOPT_WRITEFUNCTION, appendBody);
  curl_easy_setopt(curl_, CURLOPT_WRITEDATA, &reply_.body);
  curl_easy_setopt(curl_, CURLOPT_TIMEOUT_MS, static_cast<long>(http.request_timeout * 1000.0));
  curl_easy_setopt(curl_, CURLOPT_CONNECTTIMEOUT_MS,
                   static_cast<long>(std::min(config_.connect_timeout, http.request_timeout) * 1000.0));
  curl_easy_setopt(curl_, CURLOPT_TCP_NODELAY, 1L);
  curl_easy_setopt(curl_, CURLOPT_TCP_KEEPALIVE, 1L);
  curl_easy_setopt(curl_, CURLOPT_MAXCONNECTS, 1L);  // one camera, one connection
  // Keep the cookies the camera sets and send them back: an Axis camera with its PTZ control queue on tells its
  // clients apart by a cookie (VAPIX Queuing API), and control is the cookie's.
  curl_easy_setopt(curl_, CURLOPT_COOKIEFILE, "");
  configureTls();
  if (http.auth != HttpAuth::NONE)
  {
    curl_easy_setopt(curl_, CURLOPT_HTTPAUTH, curlAuth(http.auth));
    curl_easy_setopt(curl_, CURLOPT_USERNAME, http.username.c_str());
    curl_easy_setopt(curl_, CURLOPT_PASSWORD, http.password.c_str());
  }
}

void HttpLink::configureTls()
{
  const HttpLinkConfig& http = config_.http;
  // The scheme is the only one this handle speaks: an https camera is never asked over http, whatever happens.
  if (curl_easy_setopt(curl_, CURLOPT_PROTOCOLS_STR, http.tls ? "https" : "http") != CURLE_OK)
  {
    throw ConfigError("this libcurl cannot restrict " + base_url_ + " to its scheme (CURLOPT_PROTOCOLS_STR)");
  }
  if (!http.tls)
  {
    return;
  }
  if (!http.verify_peer && (!http.fingerprint.empty() || !http.ca_file.empty()))
  {
    throw ConfigError("TLS verification is off for " + base_url_ + " but a certificate to check is given");
  }
  if (!http.fingerprint.empty() && !http.ca_file.empty())
  {
    throw ConfigError("both a pinned fingerprint and a ca_file for " + base_url_ + ": give one");
  }
  if (!http.verify_peer)
  {
    curl_easy_setopt(curl_, CURLOPT_SSL_VERIFYPEER, 0L);
    curl_easy_setopt(curl_, CURLOPT_SSL_VERIFYHOST, 0L);
    return;
  }
  curl_easy_setopt(curl_, CURLOPT_SSL_VERIFYPEER, 1L);
  if (!http.fingerprint.empty())
  {
    // The pin is the identity: the certificate (self-signed, any name) must be that one, chain and name aside.
    pin_.expected = parseCertificateFingerprint(http.fingerprint);
    if (pin_.expected.empty())
    {
      throw ConfigError("the pinned fingerprint for " + base_url_ + " is not a SHA-256 (64 hex digits, AB:CD:...)");
    }
    curl_easy_setopt(curl_, CURLOPT_SSL_VERIFYHOST, 0L);
    if (curl_easy_setopt(curl_, CURLOPT_SSL_CTX_FUNCTION, onSslContext) != CURLE_OK ||
        curl_easy_setopt(curl_, CURLOPT_SSL_CTX_DATA, &pin_) != CURLE_OK)
    {
      throw ConfigError("this libcurl cannot check a pinned certificate (it is not built on OpenSSL): " + base_url_);
    }
    return;
  }
  curl_easy_setopt(curl_, CURLOPT_SSL_VERIFYHOST, 2L);
  if (!http.ca_file.empty())
  {
    if (!std::ifstream(http.ca_file))
    {
      throw ConfigError("cannot read the ca_file " + http.ca_file + " for " + base_url_);
    }
    curl_easy_setopt(curl_, CURLOPT_CAINFO, http.ca_file.c_str());
  }
}

std::string HttpLink::tlsFailure(int code) const
{
  const auto result = static_cast<CURLcode>(code);
  const std::string curl_text = error_buffer_[0] != '\0' ? error_buffer_ : curl_easy_strerror(result);
  if (!pin_.expected.empty() && !pin_.presented.empty())
  {
    return "TLS refused: the camera's certificate has SHA-256 " + formatCertificateFingerprint(pin_.presented) +
           ", not the pinned tls_fingerprint " + formatCertificateFingerprint(pin_.expected) +
           " (another camera, a new certificate, or someone in between)";
  }
  if (result == CURLE_PEER_FAILED_VERIFICATION)
  {
    const std::string& ca_file = config_.http.ca_file;
    return "TLS refused: the camera's certificate is not trusted" +
           (ca_file.empty() ? std::string(" by the system's CAs") : " by ca_file " + ca_file) + " (" + curl_text + ")" +
           (ca_file.empty() ? "; give its CA in ca_file, or pin its SHA-256 in tls_fingerprint" : "");
  }
  if (result == CURLE_SSL_CACERT_BADFILE)
  {
    return "TLS: cannot use ca_file " + config_.http.ca_file + " (" + curl_text + ")";
  }
  return "TLS handshake failed (" + curl_text + ")";
}

int HttpLink::performOnce(const HttpRequest& request)
{
  reply_.body.clear();
  // curl opens a multi-pass authentication (Digest) of a POST with a probe that carries no body; a camera that
  // authenticates in the message (ONVIF's WS-Security) would answer that empty request. So POSTs go without HTTP
  // authentication until the camera has asked for it once.
  const bool unauthenticated_post = !request.body.empty() && !challenged_ && config_.http.auth != HttpAuth::NONE;
  curl_easy_setopt(curl_, CURLOPT_HTTPAUTH, unauthenticated_post ? CURLAUTH_NONE : auth_);
  const CURLcode result = curl_easy_perform(curl_);
  long status = 0;
  curl_easy_getinfo(curl_, CURLINFO_RESPONSE_CODE, &status);
  if (result == CURLE_OK && status == 401 && !challenged_)
  {
    challenged_ = true;
    if (unauthenticated_post)
    {
      return performOnce(request);  // once more, authenticated
    }
  }
  return result;
}

void HttpLink::startOpen()
{
  // Nothing to connect yet: curl connects on the first request. Open from a handler of its own, as the other links do.
  boost::asio::post(context_, [this, connection = connection()] {
    if (connection == this->connection())
    {
      opened(false);
    }
  });
}

void HttpLink::closeHandle()
{
  // The next request starts on a fresh connection (the old one leaves curl's one-connection cache); the handle and
  // its digest state stay.
  curl_easy_setopt(curl_, CURLOPT_FRESH_CONNECT, 1L);
}

const HttpReply& HttpLink::request(const HttpRequest& request)
{
  reply_.delivered = false;
  reply_.status = 0;
  error_buffer_[0] = '\0';
  pin_.presented.clear();
  certificate_refused_ = false;
  if (!isOpen())
  {
    ++counters_.writes_dropped;
    return reply_;
  }
  ++http_counters_.requests;
  const std::string url = base_url_ + request.path;
  curl_easy_setopt(curl_, CURLOPT_URL, url.c_str());
  if (request.body.empty())
  {
    curl_easy_setopt(curl_, CURLOPT_HTTPGET, 1L);
  }
  else
  {
    if (post_headers_ == nullptr || post_content_type_ != request.content_type)
    {
      curl_slist_free_all(post_headers_);
      post_headers_ = curl_slist_append(nullptr, ("Content-Type: " + request.content_type).c_str());
      post_headers_ = curl_slist_append(post_headers_, "Expect:");  // no 100-continue round trip
      post_content_type_ = request.content_type;
    }
    curl_easy_setopt(curl_, CURLOPT_HTTPHEADER, post_headers_);
    curl_easy_setopt(curl_, CURLOPT_POSTFIELDS, request.body.data());
    curl_easy_setopt(curl_, CURLOPT_POSTFIELDSIZE, static_cast<long>(request.body.size()));
  }
  const auto result = static_cast<CURLcode>(performOnce(request));
  curl_easy_setopt(curl_, CURLOPT_FRESH_CONNECT, 0L);
  if (!request.body.empty())
  {
    curl_easy_setopt(curl_, CURLOPT_HTTPHEADER, nullptr);
  }

  long connects = 0;
  curl_easy_getinfo(curl_, CURLINFO_NUM_CONNECTS, &connects);
  http_counters_.connections += static_cast<std::uint64_t>(connects);
  curl_off_t uploaded = 0;
  curl_easy_getinfo(curl_, CURLINFO_SIZE_UPLOAD_T, &uploaded);
  counters_.bytes_out += static_cast<std::uint64_t>(uploaded) + request.path.size();
  counters_.bytes_in += reply_.body.size();

  if (result != CURLE_OK)
  {
    const bool timed_out = result == CURLE_OPERATION_TIMEDOUT;
    const bool oversized = result == CURLE_WRITE_ERROR;  // only appendBody() fails a write
    const bool tls_failed =
        config_.http.tls && (result == CURLE_SSL_CONNECT_ERROR || result == CURLE_PEER_FAILED_VERIFICATION ||
                             result == CURLE_SSL_CACERT_BADFILE || !pin_.presented.empty());
    if (oversized)
    {
      ++http_counters_.oversized_answers;
      http_counters_.dropped_bytes += reply_.body.size();
      reply_.body.clear();
    }
    else
    {
      ++(timed_out ? http_counters_.timeouts : http_counters_.transport_errors);
    }
    if (tls_failed && (result == CURLE_PEER_FAILED_VERIFICATION || !pin_.presented.empty()))
    {
      ++http_counters_.tls_refusals;
      certificate_refused_ = true;
    }
    const std::string detail =
        oversized  ? formatText("an answer longer than %zu bytes: dropped", MAX_ANSWER) :
        timed_out  ? formatText("no answer within %.2f s", config_.http.request_timeout) :
        tls_failed ? tlsFailure(result) :
                     std::string(error_buffer_[0] != '\0' ? error_buffer_ : curl_easy_strerror(result));
    lost(base_url_ + ": " + describe(request) + ": " + detail);
    return reply_;
  }
  provenAlive();
  reply_.delivered = true;
  curl_easy_getinfo(curl_, CURLINFO_RESPONSE_CODE, &reply_.status);
  if (reply_.status >= 400)
  {
    ++http_counters_.error_statuses;
  }
  if (config_.http.auth == HttpAuth::AUTO && reply_.status != 401)
  {
    // The camera has said what it takes: only that from now on, so the nonce is reused and no request is probed.
    long offered = 0;
    curl_easy_getinfo(curl_, CURLINFO_HTTPAUTH_AVAIL, &offered);
    if (offered != 0)
    {
      auth_ = (offered & CURLAUTH_DIGEST) != 0 ? CURLAUTH_DIGEST : CURLAUTH_BASIC;
    }
  }
  return reply_;
}

void HttpLink::diagnostics(std::vector<DiagnosticValue>& values) const
{
  Link::diagnostics(values);
  addCounts(values, { { "http requests", http_counters_.requests },
                      { "http connections opened", http_counters_.connections },
                      { "http error answers (>= 400)", http_counters_.error_statuses },
                      { "http timeouts", http_counters_.timeouts },
                      { "http transport errors", http_counters_.transport_errors },
                      { "tls refused certificates", http_counters_.tls_refusals },
                      { "http answers too long (dropped)", http_counters_.oversized_answers },
                      { "http answer bytes dropped", http_counters_.dropped_bytes } });
}

std::unique_ptr<Link> makeHttpLink(boost::asio::io_context& context, const LinkConfig& config, Link::Listener& listener)
{
  return std::make_unique<HttpLink>(context, config, listener);
}

}  // namespace ptz_action_server

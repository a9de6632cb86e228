/**
 * \file
 * \brief The HTTP link on libcurl's easy interface: one handle, so one keep-alive connection and one digest nonce
 * for every request.
 */
#include "ptz_action_server/core/transport/http_link.h"

#include <curl/curl.h>

#include <mutex>
#include <stdexcept>

#include <boost/asio/post.hpp>

#include "links.h"
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
}  // namespace

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
  curl_easy_setopt(curl_, CURLOPT_SSL_VERIFYPEER, http.verify_peer ? 1L : 0L);
  curl_easy_setopt(curl_, CURLOPT_SSL_VERIFYHOST, http.verify_peer ? 2L : 0L);
  if (http.auth != HttpAuth::NONE)
  {
    curl_easy_setopt(curl_, CURLOPT_HTTPAUTH, curlAuth(http.auth));
    curl_easy_setopt(curl_, CURLOPT_USERNAME, http.username.c_str());
    curl_easy_setopt(curl_, CURLOPT_PASSWORD, http.password.c_str());
  }
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

void HttpLink::startWrite(const std::vector<std::uint8_t>&)
{
  throw std::logic_error("bytes written to the HTTP link " + base_url_ + ": protocols call perform()");
}

std::string HttpLink::describe(const HttpRequest& request)
{
  return (request.body.empty() ? "GET " : "POST ") + request.path;
}

const HttpReply& HttpLink::perform(const HttpRequest& request)
{
  reply_.delivered = false;
  reply_.status = 0;
  error_buffer_[0] = '\0';
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
    const std::string detail =
        oversized ? formatText("an answer longer than %zu bytes: dropped", MAX_ANSWER) :
        timed_out ? formatText("no answer within %.2f s", config_.http.request_timeout) :
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
                      { "http answers too long (dropped)", http_counters_.oversized_answers },
                      { "http answer bytes dropped", http_counters_.dropped_bytes } });
}

std::unique_ptr<Link> makeHttpLink(boost::asio::io_context& context, const LinkConfig& config, Link::Listener& listener)
{
  return std::make_unique<HttpLink>(context, config, listener);
}

}  // namespace ptz_action_server

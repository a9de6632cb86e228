/**
 * \file
 * \brief HttpCameraServer: its listener, its keep-alive connections (a request read, answered after the delay or not
 * at all, the next read; a TLS handshake or plain HTTP on the TLS port told apart) and its fault switches. The
 * authentication is http_camera_auth.cpp's, the certificate http_camera_tls.cpp's.
 */
#include "ptz_action_server/emulators/http_camera_server.h"

#include <future>

#include <boost/asio/post.hpp>
#include <boost/asio/ssl/stream.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>

#include "ptz_action_server/core/units.h"
#include "ports/socket_server.h"

namespace ptz_action_server
{
namespace http = boost::beast::http;
using boost::asio::ip::tcp;

namespace
{
const char* reasonOf(unsigned status)
{
  return http::obsolete_reason(static_cast<http::status>(status)).data();
}
}  // namespace

/// One keep-alive connection: read a request, answer it (after the delay), read the next.
class HttpCameraServer::Connection : public std::enable_shared_from_this<Connection>
{
public:
  Connection(HttpCameraServer& server, tcp::socket socket)
    : server_(server)
    , ssl_context_(server.ssl_context_)
    , stream_(std::move(socket), *ssl_context_)
    , delay_timer_(server.socket_server_->context())
  {
  }

  /// Plain HTTP: reads at once. TLS: looks at the first byte; a TLS record starts the handshake, anything else is
  /// plain HTTP sent to the TLS port (read, answered 400, counted).
  void start()
  {
    if (!server_.config_.tls)
    {
      read();
      return;
    }
    socket().async_wait(tcp::socket::wait_read, [self = shared_from_this()](const boost::system::error_code& error) {
      std::uint8_t first = 0;
      boost::system::error_code peek_error;
      const std::size_t peeked =
          error ? 0 : self->socket().receive(boost::asio::buffer(&first, 1), tcp::socket::message_peek, peek_error);
      if (error || peek_error || peeked == 0)
      {
        self->close();
        return;
      }
      if (first != 0x16)  // a TLS handshake record
      {
        self->plain_on_tls_ = true;
        self->read();
        return;
      }
      self->stream_.async_handshake(boost::asio::ssl::stream_base::server,
                                    [self](const boost::system::error_code& handshake_error) {
                                      if (handshake_error)
                                      {
                                        ++self->server_.counters_.tls_failures;
                                        self->close();
                                        return;
                                      }
                                      ++self->server_.counters_.tls_handshakes;
                                      self->tls_ = true;
                                      self->read();
                                    });
    });
  }

  void read()
  {
    request_ = {};
    auto done = [self = shared_from_this()](const boost::system::error_code& error, std::size_t) {
      if (error)
      {
        self->close();
        return;
      }
      self->handle();
    };
    if (tls_)
    {
      http::async_read(stream_, buffer_, request_, std::move(done));
    }
    else
    {
      http::async_read(socket(), buffer_, request_, std::move(done));
    }
  }

  void close()
  {
    boost::system::error_code ignored;
    delay_timer_.cancel();
    socket().shutdown(tcp::socket::shutdown_both, ignored);
    socket().close(ignored);
    server_.connections_.erase(shared_from_this());
  }

private:
  tcp::socket& socket()
  {
    return stream_.next_layer();
  }

  void handle()
  {
    if (plain_on_tls_)
    {
      ++server_.counters_.plain_requests;  // never served, never logged as the camera's traffic
      respond(HttpAnswer{ 400, "text/plain", "The plain HTTP request was sent to HTTPS port\r\n" }, "", false, 0.0,
              false);
      return;
    }
    HttpExchange exchange{ SteadyClock::now(), std::string(request_.method_string()), std::string(request_.target()),
                           request_.body(), 0 };
    ++server_.counters_.requests;
    bool silent = false;
    bool endless = false;
    double delay = 0.0;
    unsigned error_status = 0;
    {
      std::lock_guard<std::mutex> lock(server_.mutex_);
      silent = server_.silent_;
      endless = server_.endless_;
      delay = server_.delay_;
      error_status = server_.error_status_;
    }
    if (silent)
    {
      server_.received_.add(exchange);
      return;  // never answered; the connection stays open until the client gives up
    }
    std::string challenge;
    HttpAnswer answer;
    if (error_status != 0)
    {
      answer = HttpAnswer{ error_status, "text/plain", std::string(reasonOf(error_status)) + "\r\n" };
    }
    else
    {
      const auto authorization = request_.find(http::field::authorization);
      const auto cookie = request_.find(http::field::cookie);
      server_.request_cookie_ = cookie == request_.end() ? std::string() : std::string(cookie->value());
      server_.answer_cookie_.clear();
      answer = server_.answer(exchange.method, exchange.target, exchange.body,
                              authorization == request_.end() ? std::string() : std::string(authorization->value()),
                              challenge);
    }
    exchange.status = answer.status;
    server_.received_.add(exchange);
    set_cookie_ = error_status != 0 ? std::string() : server_.answer_cookie_;
    respond(answer, challenge, request_.keep_alive(), delay, endless);
  }

  /// Sends \p answer after \p delay s; an \p endless one is cut at half its body and followed by filler.
  void respond(const HttpAnswer& answer, const std::string& challenge, bool keep_alive, double delay, bool endless)
  {
    response_ = {};
    response_.version(request_.version());
    response_.result(answer.status);
    response_.set(http::field::server, "ptz_action_server emulated camera");
    if (!challenge.empty())
    {
      response_.set(http::field::www_authenticate, challenge);
    }
    if (!set_cookie_.empty())
    {
      response_.set(http::field::set_cookie, set_cookie_);
    }
    if (answer.status != 204)
    {
      response_.set(http::field::content_type, answer.content_type);
      response_.body() = answer.body;
      if (endless)
      {
        response_.body().resize(answer.body.size() / 2);
        response_.body().append(ENDLESS_BODY, 'A');
      }
    }
    response_.keep_alive(keep_alive);
    response_.prepare_payload();
    if (delay > 0.0)
    {
      delay_timer_.expires_after(toDuration(delay));
      delay_timer_.async_wait([self = shared_from_this()](const boost::system::error_code& error) {
        if (!error)
        {
          self->write();
        }
      });
      return;
    }
    write();
  }

  void write()
  {
    auto done = [self = shared_from_this()](const boost::system::error_code& error, std::size_t) {
      if (error || !self->response_.keep_alive())
      {
        self->close();
        return;
      }
      self->read();
    };
    if (tls_)
    {
      http::async_write(stream_, response_, std::move(done));
    }
    else
    {
      http::async_write(socket(), response_, std::move(done));
    }
  }

  HttpCameraServer& server_;
  const std::shared_ptr<boost::asio::ssl::context> ssl_context_;  ///< before stream_, which uses it
  boost::asio::ssl::stream<tcp::socket> stream_;                  ///< its next layer is the socket; TLS only once tls_
  bool tls_ = false;           ///< the handshake is done: requests go through stream_
  bool plain_on_tls_ = false;  ///< plain HTTP on the TLS port
  boost::asio::steady_timer delay_timer_;
  boost::beast::flat_buffer buffer_;
  http::request<http::string_body> request_;
  http::response<http::string_body> response_;
  std::string set_cookie_;  ///< the Set-Cookie of the answer being sent ("" none)
};

HttpCameraServer::HttpCameraServer(const HttpCameraServerConfig& config, Handler handler, Open open)
  : config_(config)
  , handler_(std::move(handler))
  , open_(std::move(open))
  , ssl_context_(std::make_shared<boost::asio::ssl::context>(boost::asio::ssl::context::tls_server))
  , socket_server_(std::make_unique<SocketServer>())
{
  if (config.tls)
  {
    makeCertificate();
  }
  listener_ = std::make_unique<TcpListener>(socket_server_->context(), config.host, config.port);
  accept();
  nonce_ = newNonce();
  socket_server_->start();
}

HttpCameraServer::~HttpCameraServer()
{
  socket_server_->stop([this] {
    listener_->close();
    closeConnections();
  });
}

std::uint16_t HttpCameraServer::port() const
{
  return listener_->port();
}

void HttpCameraServer::accept()
{
  listener_->accept([this](tcp::socket socket) {
    ++counters_.connections;
    auto connection = std::make_shared<Connection>(*this, std::move(socket));
    connections_.insert(connection);
    connection->start();
  });
}

std::string HttpCameraServer::url() const
{
  return (config_.tls ? "https://" : "http://") + config_.host + ":" + std::to_string(port());
}

void HttpCameraServer::setSilent(bool silent)
{
  std::lock_guard<std::mutex> lock(mutex_);
  silent_ = silent;
}

void HttpCameraServer::setEndless(bool endless)
{
  std::lock_guard<std::mutex> lock(mutex_);
  endless_ = endless;
}

void HttpCameraServer::setDelay(double seconds)
{
  std::lock_guard<std::mutex> lock(mutex_);
  delay_ = seconds;
}

void HttpCameraServer::setErrorStatus(unsigned status)
{
  std::lock_guard<std::mutex> lock(mutex_);
  error_status_ = status;
}

void HttpCameraServer::dropConnections()
{
  socket_server_->run([this] { closeConnections(); });
}

void HttpCameraServer::closeConnections()
{
  while (!connections_.empty())
  {
    (*connections_.begin())->close();  // it leaves connections_
  }
}

void HttpCameraServer::setListening(bool listening)
{
  socket_server_->run([this, listening] {
    if (listening == listener_->isOpen())
    {
      return;
    }
    if (listening)
    {
      listener_->open();
      accept();
    }
    else
    {
      listener_->close();
    }
  });
}

}  // namespace ptz_action_server

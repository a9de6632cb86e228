#include "ptz_action_server/emulators/http_camera_server.h"

#include <future>
#include <map>
#include <random>

#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>

#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace http = boost::beast::http;
using boost::asio::ip::tcp;

namespace
{
/// The `key=value` / `key="value"` pairs of a Digest Authorization header (after "Digest ").
std::map<std::string, std::string> digestFields(const std::string& text)
{
  std::map<std::string, std::string> fields;
  std::size_t index = 0;
  while (index < text.size())
  {
    while (index < text.size() && (text[index] == ' ' || text[index] == ','))
    {
      ++index;
    }
    const std::size_t equals = text.find('=', index);
    if (equals == std::string::npos)
    {
      break;
    }
    const std::string key = text.substr(index, equals - index);
    std::string value;
    index = equals + 1;
    if (index < text.size() && text[index] == '"')
    {
      const std::size_t close = text.find('"', index + 1);
      value = text.substr(index + 1, close == std::string::npos ? std::string::npos : close - index - 1);
      index = close == std::string::npos ? text.size() : close + 1;
    }
    else
    {
      const std::size_t comma = text.find(',', index);
      value = text.substr(index, comma == std::string::npos ? std::string::npos : comma - index);
      index = comma == std::string::npos ? text.size() : comma;
    }
    fields[key] = value;
  }
  return fields;
}

const char* reasonOf(unsigned status)
{
  return http::obsolete_reason(static_cast<http::status>(status)).data();
}
}  // namespace

std::string httpDigestResponse(const std::string& username, const std::string& realm, const std::string& password,
                               const std::string& method, const std::string& uri, const std::string& nonce,
                               const std::string& nc, const std::string& cnonce)
{
  const std::string ha1 = md5Hex(username + ":" + realm + ":" + password);
  const std::string ha2 = md5Hex(method + ":" + uri);
  return md5Hex(ha1 + ":" + nonce + ":" + nc + ":" + cnonce + ":auth:" + ha2);
}

/// One keep-alive connection: read a request, answer it (after the delay), read the next.
class HttpCameraServer::Connection : public std::enable_shared_from_this<Connection>
{
public:
  Connection(HttpCameraServer& server, tcp::socket socket)
    : server_(server), socket_(std::move(socket)), delay_timer_(server.context_)
  {
  }

  void read()
  {
    request_ = {};
    http::async_read(socket_, buffer_, request_,
                     [self = shared_from_this()](const boost::system::error_code& error, std::size_t) {
                       if (error)
                       {
                         self->close();
                         return;
                       }
                       self->handle();
                     });
  }

  void close()
  {
    boost::system::error_code ignored;
    delay_timer_.cancel();
    socket_.shutdown(tcp::socket::shutdown_both, ignored);
    socket_.close(ignored);
    server_.connections_.erase(shared_from_this());
  }

private:
  void handle()
  {
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
      answer = server_.answer(exchange.method, exchange.target, exchange.body,
                              authorization == request_.end() ? std::string() : std::string(authorization->value()),
                              challenge);
    }
    exchange.status = answer.status;
    server_.received_.add(exchange);
    response_ = {};
    response_.version(request_.version());
    response_.result(answer.status);
    response_.set(http::field::server, "ptz_action_server emulated camera");
    if (!challenge.empty())
    {
      response_.set(http::field::www_authenticate, challenge);
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
    response_.keep_alive(request_.keep_alive());
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
    http::async_write(socket_, response_,
                      [self = shared_from_this()](const boost::system::error_code& error, std::size_t) {
                        if (error || !self->response_.keep_alive())
                        {
                          self->close();
                          return;
                        }
                        self->read();
                      });
  }

  HttpCameraServer& server_;
  tcp::socket socket_;
  boost::asio::steady_timer delay_timer_;
  boost::beast::flat_buffer buffer_;
  http::request<http::string_body> request_;
  http::response<http::string_body> response_;
};

HttpCameraServer::HttpCameraServer(const HttpCameraServerConfig& config, Handler handler, Open open)
  : config_(config), handler_(std::move(handler)), open_(std::move(open)), acceptor_(context_)
{
  port_ = config.port;
  listen();
  nonce_ = newNonce();
  thread_ = std::thread([this] {
    auto work = boost::asio::make_work_guard(context_);
    context_.run();
  });
}

HttpCameraServer::~HttpCameraServer()
{
  runOnServerThread([this] {
    boost::system::error_code ignored;
    acceptor_.close(ignored);
    while (!connections_.empty())
    {
      (*connections_.begin())->close();
    }
  });
  context_.stop();
  thread_.join();
}

void HttpCameraServer::listen()
{
  const tcp::endpoint endpoint(boost::asio::ip::make_address(config_.host), port_);
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
  port_ = acceptor_.local_endpoint().port();  // a restart takes the same port
  accept();
}

void HttpCameraServer::accept()
{
  acceptor_.async_accept([this](const boost::system::error_code& error, tcp::socket socket) {
    if (error)
    {
      return;  // closed
    }
    ++counters_.connections;
    socket.set_option(tcp::no_delay(true));
    auto connection = std::make_shared<Connection>(*this, std::move(socket));
    connections_.insert(connection);
    connection->read();
    accept();
  });
}

void HttpCameraServer::runOnServerThread(const std::function<void()>& work)
{
  if (std::this_thread::get_id() == thread_.get_id())
  {
    work();
    return;
  }
  std::promise<void> done;
  boost::asio::post(context_, [&] {
    work();
    done.set_value();
  });
  done.get_future().wait();
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
  runOnServerThread([this] {
    while (!connections_.empty())
    {
      (*connections_.begin())->close();
    }
  });
}

void HttpCameraServer::setListening(bool listening)
{
  runOnServerThread([this, listening] {
    if (listening == acceptor_.is_open())
    {
      return;
    }
    if (listening)
    {
      listen();
    }
    else
    {
      boost::system::error_code ignored;
      acceptor_.close(ignored);
    }
  });
}

void HttpCameraServer::renewNonce()
{
  runOnServerThread([this] { nonce_ = newNonce(); });
}

std::string HttpCameraServer::newNonce()
{
  static thread_local std::mt19937_64 random(std::random_device{}());
  nonce_used_ = 0;
  return base64Encode(formatText("%016llx:%llu", static_cast<unsigned long long>(random()),
                                 static_cast<unsigned long long>(++nonce_serial_)));
}

bool HttpCameraServer::authorised(const std::string& method, const std::string& target,
                                  const std::string& authorization, bool& stale)
{
  stale = false;
  if (config_.auth == HttpAuth::BASIC)
  {
    return authorization == "Basic " + base64Encode(config_.username + ":" + config_.password);
  }
  if (authorization.rfind("Digest ", 0) != 0)
  {
    return false;
  }
  std::map<std::string, std::string> fields = digestFields(authorization.substr(7));
  if (fields["nonce"] != nonce_)
  {
    stale = !fields["nonce"].empty();
    return false;
  }
  const bool valid = fields["username"] == config_.username && fields["realm"] == config_.realm &&
                     fields["uri"] == target && fields["qop"] == "auth" &&
                     fields["response"] == httpDigestResponse(config_.username, config_.realm, config_.password, method,
                                                              target, nonce_, fields["nc"], fields["cnonce"]);
  if (valid && config_.nonce_uses > 0 && ++nonce_used_ >= config_.nonce_uses)
  {
    nonce_ = newNonce();  // this request passes; the next one meets a stale nonce
  }
  return valid;
}

HttpAnswer HttpCameraServer::answer(const std::string& method, const std::string& target, const std::string& body,
                                    const std::string& authorization, std::string& challenge)
{
  if (config_.auth == HttpAuth::NONE || (open_ && open_(target)))
  {
    return handler_(method, target, body);
  }
  bool stale = false;
  if (authorised(method, target, authorization, stale))
  {
    return handler_(method, target, body);
  }
  ++counters_.challenges;
  if (!authorization.empty() && !stale)
  {
    ++counters_.refused_credentials;
  }
  challenge = config_.auth == HttpAuth::BASIC ? "Basic realm=\"" + config_.realm + "\"" :
                                                "Digest realm=\"" + config_.realm + "\", nonce=\"" + nonce_ +
                                                    "\", algorithm=MD5, qop=\"auth\"" + (stale ? ", stale=true" : "");
  return HttpAnswer{ 401, "text/html", "<HTML><HEAD><TITLE>401 Unauthorized</TITLE></HEAD></HTML>\r\n" };
}

}  // namespace ptz_action_server

#include "ptz_action_server/emulators/http_camera_server.h"

#include <openssl/bio.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/x509.h>
#include <openssl/x509v3.h>

#include <fstream>
#include <future>
#include <map>
#include <random>
#include <stdexcept>

#include <boost/asio/post.hpp>
#include <boost/asio/ssl/stream.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>

#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"
#include "ports/socket_server.h"

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

/// A key and a self-signed certificate made at start, as PEM, with the certificate's SHA-256.
struct Credentials
{
  std::string certificate_pem;
  std::string key_pem;
  std::string fingerprint;  ///< "AB:CD:..."
};

template <typename T, void (*Free)(T*)>
struct OpenSslFree
{
  void operator()(T* pointer) const
  {
    Free(pointer);
  }
};
using KeyPointer = std::unique_ptr<EVP_PKEY, OpenSslFree<EVP_PKEY, EVP_PKEY_free>>;
using CertificatePointer = std::unique_ptr<X509, OpenSslFree<X509, X509_free>>;
using BioPointer = std::unique_ptr<BIO, OpenSslFree<BIO, BIO_free_all>>;
using ExtensionPointer = std::unique_ptr<X509_EXTENSION, OpenSslFree<X509_EXTENSION, X509_EXTENSION_free>>;

void check(bool ok, const char* what)
{
  if (!ok)
  {
    throw std::runtime_error(std::string("the emulated camera cannot make its TLS certificate: ") + what);
  }
}

std::string pemOf(const std::function<int(BIO*)>& write)
{
  BioPointer bio(BIO_new(BIO_s_mem()));
  check(bio != nullptr && write(bio.get()) == 1, "PEM");
  char* data = nullptr;
  const long size = BIO_get_mem_data(bio.get(), &data);
  return std::string(data, static_cast<std::size_t>(size));
}

/// An EC P-256 key and a self-signed X.509 v3 certificate for 127.0.0.1, localhost and \p host, valid for a year.
Credentials makeCredentials(const std::string& host)
{
  KeyPointer key(EVP_EC_gen("P-256"));
  check(key != nullptr, "EC key");
  CertificatePointer certificate(X509_new());
  check(certificate != nullptr, "X509_new");
  X509* cert = certificate.get();
  X509_set_version(cert, 2);
  std::random_device random;
  ASN1_INTEGER_set(X509_get_serialNumber(cert), static_cast<long>(random() & 0x7fffffff));
  X509_gmtime_adj(X509_getm_notBefore(cert), -3600);
  X509_gmtime_adj(X509_getm_notAfter(cert), 365L * 24 * 3600);
  check(X509_set_pubkey(cert, key.get()) == 1, "public key");
  X509_NAME* name = X509_get_subject_name(cert);
  X509_NAME_add_entry_by_txt(name, "O", MBSTRING_ASC,
                             reinterpret_cast<const unsigned char*>("ptz_action_server emulated camera"), -1, -1, 0);
  X509_NAME_add_entry_by_txt(name, "CN", MBSTRING_ASC, reinterpret_cast<const unsigned char*>("127.0.0.1"), -1, -1, 0);
  X509_set_issuer_name(cert, name);
  std::string names = "IP:127.0.0.1,DNS:localhost";
  boost::system::error_code not_an_address;
  const auto address = boost::asio::ip::make_address(host, not_an_address);
  if (!not_an_address && !address.is_unspecified() && host != "127.0.0.1")
  {
    names += ",IP:" + host;
  }
  X509V3_CTX context;
  X509V3_set_ctx_nodb(&context);
  X509V3_set_ctx(&context, cert, cert, nullptr, nullptr, 0);
  for (const auto& extension : { std::make_pair(NID_basic_constraints, std::string("critical,CA:TRUE")),
                                 std::make_pair(NID_subject_alt_name, names) })
  {
    ExtensionPointer made(X509V3_EXT_conf_nid(nullptr, &context, extension.first, extension.second.c_str()));
    check(made != nullptr && X509_add_ext(cert, made.get(), -1) == 1, "extension");
  }
  check(X509_sign(cert, key.get(), EVP_sha256()) > 0, "signature");

  Credentials credentials;
  credentials.certificate_pem = pemOf([cert](BIO* bio) { return PEM_write_bio_X509(bio, cert); });
  credentials.key_pem = pemOf(
      [&key](BIO* bio) { return PEM_write_bio_PrivateKey(bio, key.get(), nullptr, nullptr, 0, nullptr, nullptr); });
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  check(X509_digest(cert, EVP_sha256(), digest, &length) == 1, "digest");
  credentials.fingerprint = formatCertificateFingerprint(hexDigits(digest, length));
  return credentials;
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

void HttpCameraServer::makeCertificate()
{
  namespace ssl = boost::asio::ssl;
  const Credentials credentials = makeCredentials(config_.host);
  auto context = std::make_shared<ssl::context>(ssl::context::tls_server);
  context->set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 | ssl::context::no_sslv3 |
                       ssl::context::no_tlsv1 | ssl::context::no_tlsv1_1);
  context->use_certificate(boost::asio::buffer(credentials.certificate_pem), ssl::context::pem);
  context->use_private_key(boost::asio::buffer(credentials.key_pem), ssl::context::pem);
  ssl_context_ = context;
  std::lock_guard<std::mutex> lock(mutex_);
  certificate_pem_ = credentials.certificate_pem;
  fingerprint_ = credentials.fingerprint;
}

void HttpCameraServer::renewCertificate()
{
  socket_server_->run([this] {
    makeCertificate();
    closeConnections();
  });
}

std::string HttpCameraServer::fingerprint() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return fingerprint_;
}

std::string HttpCameraServer::certificatePem() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return certificate_pem_;
}

std::string HttpCameraServer::url() const
{
  return (config_.tls ? "https://" : "http://") + config_.host + ":" + std::to_string(port());
}

void HttpCameraServer::writeCertificate(const std::string& path) const
{
  std::ofstream file(path);
  file << certificatePem();
  file.close();
  if (!file)
  {
    throw std::runtime_error("cannot write the certificate to " + path);
  }
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

void HttpCameraServer::recordSecrets(const std::vector<std::string>& values)
{
  if (config_.secrets_file.empty())
  {
    return;
  }
  std::lock_guard<std::mutex> lock(secrets_mutex_);
  std::ofstream file(config_.secrets_file, std::ios::app);
  for (const std::string& value : values)
  {
    if (!value.empty())
    {
      file << value << '\n';
    }
  }
}

void HttpCameraServer::renewNonce()
{
  socket_server_->run([this] { nonce_ = newNonce(); });
}

std::string HttpCameraServer::newNonce()
{
  static thread_local std::mt19937_64 random(std::random_device{}());
  nonce_used_ = 0;
  const std::string nonce = base64Encode(formatText("%016llx:%llu", static_cast<unsigned long long>(random()),
                                                    static_cast<unsigned long long>(++nonce_serial_)));
  recordSecrets({ nonce });
  return nonce;
}

bool HttpCameraServer::authorised(const std::string& method, const std::string& target,
                                  const std::string& authorization, bool& stale)
{
  stale = false;
  if (config_.auth == HttpAuth::BASIC)
  {
    recordSecrets({ authorization.rfind("Basic ", 0) == 0 ? authorization.substr(6) : std::string() });
    return authorization == "Basic " + base64Encode(config_.username + ":" + config_.password);
  }
  if (authorization.rfind("Digest ", 0) != 0)
  {
    return false;
  }
  std::map<std::string, std::string> fields = digestFields(authorization.substr(7));
  recordSecrets({ fields["response"], fields["nonce"], fields["cnonce"] });
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
    HttpAnswer answered = handler_(method, target, body);
    challenge = answered.challenge;
    return answered;
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

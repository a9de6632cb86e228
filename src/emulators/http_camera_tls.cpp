/**
 * \file
 * \brief HttpCameraServer's TLS: the EC P-256 key and self-signed certificate it makes at start (or renews), and what
 * it tells of it (the PEM, the SHA-256 fingerprint). The connections that use it are http_camera_server.cpp's.
 */
#include <openssl/bio.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/x509.h>
#include <openssl/x509v3.h>

#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include <boost/asio/buffer.hpp>
#include <boost/asio/ip/address.hpp>
#include <boost/asio/ssl/context.hpp>

#include "ports/socket_server.h"
#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
namespace
{
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

void checkCertificateStep(bool ok, const char* what)
{
  if (!ok)
  {
    throw std::runtime_error(std::string("the emulated camera cannot make its TLS certificate: ") + what);
  }
}

std::string pemOf(const std::function<int(BIO*)>& write)
{
  BioPointer bio(BIO_new(BIO_s_mem()));
  checkCertificateStep(bio != nullptr && write(bio.get()) == 1, "PEM");
  char* data = nullptr;
  const long size = BIO_get_mem_data(bio.get(), &data);
  return std::string(data, static_cast<std::size_t>(size));
}

/// An EC P-256 key and a self-signed X.509 v3 certificate for 127.0.0.1, localhost and \p host, valid for a year.
Credentials makeCredentials(const std::string& host)
{
  KeyPointer key(EVP_EC_gen("P-256"));
  checkCertificateStep(key != nullptr, "EC key");
  CertificatePointer certificate(X509_new());
  checkCertificateStep(certificate != nullptr, "X509_new");
  X509* cert = certificate.get();
  X509_set_version(cert, 2);
  std::random_device random;
  ASN1_INTEGER_set(X509_get_serialNumber(cert), static_cast<long>(random() & 0x7fffffff));
  X509_gmtime_adj(X509_getm_notBefore(cert), -3600);
  X509_gmtime_adj(X509_getm_notAfter(cert), 365L * 24 * 3600);
  checkCertificateStep(X509_set_pubkey(cert, key.get()) == 1, "public key");
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
    checkCertificateStep(made != nullptr && X509_add_ext(cert, made.get(), -1) == 1, "extension");
  }
  checkCertificateStep(X509_sign(cert, key.get(), EVP_sha256()) > 0, "signature");

  Credentials credentials;
  credentials.certificate_pem = pemOf([cert](BIO* bio) { return PEM_write_bio_X509(bio, cert); });
  credentials.key_pem = pemOf(
      [&key](BIO* bio) { return PEM_write_bio_PrivateKey(bio, key.get(), nullptr, nullptr, 0, nullptr, nullptr); });
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  checkCertificateStep(X509_digest(cert, EVP_sha256(), digest, &length) == 1, "digest");
  credentials.fingerprint = formatCertificateFingerprint(hexDigits(digest, length));
  return credentials;
}
}  // namespace

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

}  // namespace ptz_action_server

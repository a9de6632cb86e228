/**
 * \file
 * \brief HttpCameraServer's authentication: HTTP Digest (RFC 7616, MD5, qop=auth, nonces that go stale) or Basic, the
 * handler's own challenge, and the credential-derived values it records for the leak tests.
 */
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "ports/socket_server.h"
#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
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
}  // namespace

std::string httpDigestResponse(const std::string& username, const std::string& realm, const std::string& password,
                               const std::string& method, const std::string& uri, const std::string& nonce,
                               const std::string& nc, const std::string& cnonce)
{
  const std::string ha1 = md5Hex(username + ":" + realm + ":" + password);
  const std::string ha2 = md5Hex(method + ":" + uri);
  return md5Hex(ha1 + ":" + nonce + ":" + nc + ":" + cnonce + ":auth:" + ha2);
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

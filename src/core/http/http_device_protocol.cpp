#include "ptz_action_server/core/http/http_device_protocol.h"

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
LinkConfig HttpDeviceProtocol::defaultLink()
{
  LinkConfig link;
  link.kind = LinkKind::HTTP;
  link.port = 80;
  link.reconnect_min = 0.1;
  return link;
}

HttpDeviceProtocol::HttpDeviceProtocol(DeviceSession& session) : session_(session), http_(session.http())
{
}

void HttpDeviceProtocol::requireHttp(const LinkConfig& link, const std::string& device)
{
  if (link.kind != LinkKind::HTTP)
  {
    throw ConfigError(device + " is reached over HTTP");
  }
}

const HttpReply* HttpDeviceProtocol::send(const HttpRequest& request)
{
  const HttpReply& reply = http_.request(request);
  return reply.delivered ? &reply : nullptr;
}

std::string HttpDeviceProtocol::statusProblem(long status, const std::string& what, const std::string& where) const
{
  if (status == 401)
  {
    return "HTTP 401 Unauthorized: the camera refused the credentials of user '" + httpUser() + "' for " + what;
  }
  return where.empty() ? formatText("HTTP %ld answering %s", status, what.c_str()) :
                         formatText("HTTP %ld answering %s at %s", status, what.c_str(), where.c_str());
}

void HttpDeviceProtocol::setupFailed(const std::string& problem)
{
  if (problem.empty())
  {
    return;  // the link was lost: it reopens and the set-up runs again
  }
  session_.failStartup(problem);
  session_.disconnect(problem);
}

void HttpDeviceProtocol::commandResult(bool done, const std::string& problem, std::uint64_t serial)
{
  if (!done && !problem.empty())
  {
    session_.reportFault(problem, serial);
  }
  if (done || !problem.empty())
  {
    session_.reportAlive();
  }
}

const std::string& HttpDeviceProtocol::httpUser() const
{
  return session_.linkConfig().http.username;
}

}  // namespace ptz_action_server

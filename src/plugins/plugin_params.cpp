#include "plugin_params.h"

#include <algorithm>
#include <fstream>
#include <string>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/transport/http_link.h"

namespace ptz_action_server
{
namespace
{
/// `username: NAME` and `password: SECRET` lines of \p path into \p http. Errors name the file, never its content.
void readCredentialsFile(const std::string& path, HttpLinkConfig& http)
{
  std::ifstream file(path);
  if (!file)
  {
    throw ConfigError("cannot read the credentials file " + path);
  }
  bool has_username = false;
  bool has_password = false;
  std::string line;
  while (std::getline(file, line))
  {
    const std::size_t colon = line.find(':');
    if (trimmed(line).empty() || trimmed(line)[0] == '#' || colon == std::string::npos)
    {
      continue;
    }
    const std::string key = trimmed(line.substr(0, colon));
    std::string value = trimmed(line.substr(colon + 1));
    if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') && value.back() == value.front())
    {
      value = value.substr(1, value.size() - 2);
    }
    if (key == "username")
    {
      http.username = value;
      has_username = true;
    }
    else if (key == "password")
    {
      http.password = value;
      has_password = true;
    }
  }
  if (!has_username || !has_password)
  {
    throw ConfigError("the credentials file " + path + " needs a 'username:' and a 'password:' line");
  }
}

LinkKind linkKind(const std::string& transport)
{
  return transport == "serial" ? LinkKind::SERIAL :
         transport == "tcp"    ? LinkKind::TCP :
         transport == "udp"    ? LinkKind::UDP :
                                 LinkKind::HTTP;
}

bool standardBaud(int baud)
{
  for (int rate : { 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600 })
  {
    if (rate == baud)
    {
      return true;
    }
  }
  return false;
}
}  // namespace

std::string transportName(LinkKind kind)
{
  return kind == LinkKind::HTTP ? "http" : toString(kind);
}

/// The http and https transports: host (an http:// or https:// prefix sets tls), port (0: 80, or 443 with tls), tls,
/// tls_verify, ca_file, tls_fingerprint, auth, username, password (never printed), credentials_file, request_timeout.
void readHttpLink(const ParamReader& params, bool https, LinkConfig& link)
{
  link.kind = LinkKind::HTTP;
  HttpLinkConfig& http = link.http;
  link.host = params.text("host", link.host);
  http.tls = params.flag("tls", http.tls) || https;  // transport: https is tls: true
  // "https://camera" turns tls on (whatever `tls` says: config/*.yaml set it false); "http://camera" with tls on is
  // an error, never a quiet downgrade.
  for (const bool secure : { true, false })
  {
    const std::string scheme = secure ? "https://" : "http://";
    if (link.host.rfind(scheme, 0) == 0)
    {
      if (!secure && http.tls)
      {
        throw ConfigError("parameter " + params.resolve("host") + " = '" + link.host + "' contradicts " +
                          params.resolve("tls") + " = " + (http.tls ? "true" : "false"));
      }
      http.tls = secure;
      link.host = link.host.substr(scheme.size());
      link.host = link.host.substr(0, link.host.find('/'));
      if (link.host.find(':') != std::string::npos)
      {
        throw ConfigError("parameter " + params.resolve("host") + " = '" + scheme + link.host + "': give the port in " +
                          params.resolve("port"));
      }
    }
  }
  const int port = params.integer("port", 0, 0, 65535);
  link.port = static_cast<std::uint16_t>(port != 0 ? port : (http.tls ? 443 : 80));
  http.verify_peer = params.flag("tls_verify", http.verify_peer);
  http.ca_file = params.text("ca_file", "");
  const std::string fingerprint = params.text("tls_fingerprint", "");
  if (!fingerprint.empty())
  {
    http.fingerprint = parseCertificateFingerprint(fingerprint);
    if (http.fingerprint.empty())
    {
      throw ConfigError("parameter " + params.resolve("tls_fingerprint") + " = '" + fingerprint +
                        "' is not a SHA-256 fingerprint (64 hex digits, AB:CD:... or abcd...)");
    }
  }
  const std::string tls_words = params.resolve("tls") + " (or an https:// host)";
  if (!http.tls && (!http.ca_file.empty() || !http.fingerprint.empty()))
  {
    throw ConfigError("parameter " + params.resolve(http.ca_file.empty() ? "tls_fingerprint" : "ca_file") +
                      " asks for a checked certificate, but " + tls_words +
                      " is off: the camera would be asked over plain http");
  }
  if (!http.ca_file.empty() && !http.fingerprint.empty())
  {
    throw ConfigError("parameters " + params.resolve("ca_file") + " and " + params.resolve("tls_fingerprint") +
                      " are both set: set one (the CA that signed the camera's certificate, or the certificate's "
                      "own SHA-256)");
  }
  if (!http.verify_peer && (!http.ca_file.empty() || !http.fingerprint.empty()))
  {
    throw ConfigError("parameter " + params.resolve("tls_verify") + " = false turns off the check that " +
                      params.resolve(http.ca_file.empty() ? "tls_fingerprint" : "ca_file") + " asks for: set one");
  }
  if (!http.ca_file.empty() && !std::ifstream(http.ca_file))
  {
    throw ConfigError("parameter " + params.resolve("ca_file") + ": cannot read " + http.ca_file);
  }
  const std::string auth = params.choice("auth", "digest", { "digest", "basic", "auto", "none" });
  http.auth = auth == "digest" ? HttpAuth::DIGEST :
              auth == "basic"  ? HttpAuth::BASIC :
              auth == "auto"   ? HttpAuth::AUTO :
                                 HttpAuth::NONE;
  http.username = params.text("username", http.username);
  http.password = params.text("password", http.password);
  // A file wins over parameters: roslaunch prints parameter values, never a file's content.
  const std::string credentials_file = params.text("credentials_file", "");
  if (!credentials_file.empty())
  {
    readCredentialsFile(credentials_file, http);
  }
  http.request_timeout = params.number("request_timeout", http.request_timeout, 0.05, 60.0);
}

void readLink(const ParamReader& params, const LinkChoices& choices, LinkConfig& link)
{
  std::vector<std::string> allowed;
  for (const TransportChoice& choice : choices.transports)
  {
    allowed.push_back(transportName(choice.kind));
    if (choice.kind == LinkKind::HTTP)
    {
      allowed.push_back("https");
    }
  }
  const std::string transport = params.choice("transport", allowed.front(), allowed);
  link.kind = linkKind(transport);
  std::uint16_t default_port = link.port;
  for (const TransportChoice& choice : choices.transports)
  {
    if (choice.kind == link.kind && choice.default_port != 0)
    {
      default_port = choice.default_port;
    }
  }
  if (link.kind == LinkKind::SERIAL)
  {
    // port is the device path here
    link.path = params.text("port", link.path.empty() ? "/dev/ttyUSB0" : link.path);
    const int baud = params.integer("baud", static_cast<int>(link.baud), 1200, 921600);
    if (!standardBaud(baud))
    {
      throw ConfigError("parameter " + params.resolve("baud") + " = " + std::to_string(baud) +
                        " is not a standard rate (1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400, "
                        "460800, 921600)");
    }
    link.baud = static_cast<unsigned>(baud);
  }
  else if (link.kind == LinkKind::HTTP)
  {
    readHttpLink(params, transport == "https", link);
  }
  else
  {
    link.host = params.text("host", link.host);
    // port is the port number here
    link.port = static_cast<std::uint16_t>(params.integer("port", default_port, 1, 65535));
    if (link.kind == LinkKind::UDP)
    {
      link.local_host = params.text("local_host", link.local_host);
      link.local_port = static_cast<std::uint16_t>(params.integer("local_port", link.local_port, 0, 65535));
    }
  }
  if (link.kind == LinkKind::TCP || link.kind == LinkKind::HTTP)
  {
    link.connect_timeout = params.number("connect_timeout", link.connect_timeout, 0.05, 60.0);
  }
  link.reconnect_min = params.number("reconnect_min", link.reconnect_min, 0.01, 10.0);
  link.reconnect_max = params.number("reconnect_max", link.reconnect_max, link.reconnect_min, 60.0);
}

void readSession(const ParamReader& params, const LinkChoices& choices, DeviceSessionConfig& session)
{
  session.state_timeout = params.number("state_timeout", session.state_timeout, choices.state_timeout_min, 60.0);
  session.poll_period = params.number("poll_period", session.poll_period, choices.poll_period_min, 1.0);
  session.startup_timeout = params.number("startup_timeout", session.startup_timeout, 0.1, 600.0);
  session.settle_window = params.number("settle_window", session.settle_window, 0.0, 5.0);
}

void readAxis(const ParamReader& params, const AxisRange& urdf, double bound, AxisCapability& axis)
{
  axis.range.min = params.number("min", std::max(urdf.min, -bound), -bound, bound);
  axis.range.max = params.number("max", std::min(urdf.max, bound), axis.range.min, bound);
  axis.max_speed = params.number("max_speed", axis.max_speed, 1e-3, 100.0);
  axis.acceleration = params.number("acceleration", axis.acceleration, 0.0, 1e4);
}

}  // namespace ptz_action_server

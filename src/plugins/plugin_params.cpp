#include "plugin_params.h"

#include <algorithm>
#include <string>

namespace ptz_action_server
{
namespace
{
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

void readReconnect(const ParamReader& params, LinkConfig& link)
{
  link.reconnect_min = params.number("reconnect_min", link.reconnect_min, 0.01, 10.0);
  link.reconnect_max = params.number("reconnect_max", link.reconnect_max, link.reconnect_min, 60.0);
}

void readHttpLink(const ParamReader& params, LinkConfig& link)
{
  link.kind = LinkKind::HTTP;
  HttpLinkConfig& http = link.http;
  link.host = params.text("host", link.host);
  http.tls = params.flag("tls", http.tls);
  const int port = params.integer("port", 0, 0, 65535);
  link.port = static_cast<std::uint16_t>(port != 0 ? port : (http.tls ? 443 : 80));
  http.verify_peer = params.flag("verify_peer", http.verify_peer);
  const std::string auth = params.choice("auth", "digest", { "digest", "basic", "auto", "none" });
  http.auth = auth == "digest" ? HttpAuth::DIGEST :
              auth == "basic"  ? HttpAuth::BASIC :
              auth == "auto"   ? HttpAuth::AUTO :
                                 HttpAuth::NONE;
  http.username = params.text("username", http.username);
  http.password = params.text("password", http.password);
  http.request_timeout = params.number("request_timeout", http.request_timeout, 0.05, 60.0);
  link.connect_timeout = params.number("connect_timeout", link.connect_timeout, 0.05, 60.0);
  readReconnect(params, link);
}

void readSerialLink(const ParamReader& params, const char* path_name, LinkConfig& link)
{
  link.kind = LinkKind::SERIAL;
  link.path = params.text(path_name, "/dev/ttyUSB0");
  const int baud = params.integer("baud", 9600, 1200, 921600);
  if (!standardBaud(baud))
  {
    throw ConfigError("parameter " + params.resolve("baud") + " = " + std::to_string(baud) +
                      " is not a standard rate (1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400, "
                      "460800, 921600)");
  }
  link.baud = static_cast<unsigned>(baud);
  readReconnect(params, link);
}

void readSessionTiming(const ParamReader& params, DeviceSessionConfig& session)
{
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

#include "ptz_action_server/core/onvif/onvif_codec.h"

#include <cmath>
#include <cstdio>
#include <ctime>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace onvif
{
namespace
{
bool number(const std::string& text, double& value)
{
  return vapix::parseNumber(text, value);
}

bool number(const char* text, double& value)
{
  return text != nullptr && number(std::string(text), value);
}

std::string readRange(const Element* range, Range& out)
{
  Range read;
  if (!number(text(child(range, ns::SCHEMA, "Min")), read.min) ||
      !number(text(child(range, ns::SCHEMA, "Max")), read.max) || read.min > read.max)
  {
    return "a range without Min <= Max";
  }
  out = read;
  return {};
}
}  // namespace

std::string passwordDigest(const std::string& nonce, const std::string& created, const std::string& password)
{
  return base64Encode(sha1(nonce + created + password));
}

std::string isoTime(double utc_seconds)
{
  const std::time_t whole = static_cast<std::time_t>(std::floor(utc_seconds));
  const int millis = std::min(999, static_cast<int>((utc_seconds - static_cast<double>(whole)) * 1000.0));
  std::tm parts{};
  gmtime_r(&whole, &parts);
  return formatText("%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", parts.tm_year + 1900, parts.tm_mon + 1, parts.tm_mday,
                    parts.tm_hour, parts.tm_min, parts.tm_sec, millis);
}

bool parseIsoTime(const std::string& text, double& utc_seconds)
{
  std::tm parts{};
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d%n", &parts.tm_year, &parts.tm_mon, &parts.tm_mday,
                  &parts.tm_hour, &parts.tm_min, &parts.tm_sec, &consumed) != 6 ||
      consumed != 19)
  {
    return false;
  }
  double fraction = 0.0;
  std::string rest = text.substr(19);
  if (!rest.empty() && rest[0] == '.')
  {
    const std::size_t end = rest.find_first_not_of("0123456789", 1);
    if (end == 1 || end == std::string::npos || !number("0" + rest.substr(0, end), fraction))
    {
      return false;
    }
    rest = rest.substr(end);
  }
  if (rest != "Z" || parts.tm_mon < 1 || parts.tm_mon > 12 || parts.tm_mday < 1 || parts.tm_mday > 31 ||
      parts.tm_hour > 23 || parts.tm_min > 59 || parts.tm_sec > 60)
  {
    return false;
  }
  parts.tm_year -= 1900;
  parts.tm_mon -= 1;
  utc_seconds = static_cast<double>(timegm(&parts)) + fraction;
  return true;
}

std::string envelope(const std::string& body, const UsernameToken* token, const std::string& password)
{
  std::string xml = std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<s:Envelope xmlns:s=\"") + ns::SOAP +
                    "\" xmlns:tds=\"" + ns::DEVICE + "\" xmlns:trt=\"" + ns::MEDIA + "\" xmlns:tptz=\"" + ns::PTZ +
                    "\" xmlns:tt=\"" + ns::SCHEMA + "\">";
  if (token != nullptr)
  {
    xml += std::string("<s:Header><wsse:Security s:mustUnderstand=\"1\" xmlns:wsse=\"") + ns::WSSE + "\" xmlns:wsu=\"" +
           ns::WSU + "\"><wsse:UsernameToken><wsse:Username>" + escaped(token->username) +
           "</wsse:Username><wsse:Password Type=\"http://docs.oasis-open.org/wss/2004/01/"
           "oasis-200401-wss-username-token-profile-1.0#PasswordDigest\">" +
           passwordDigest(token->nonce, token->created, password) +
           "</wsse:Password><wsse:Nonce EncodingType=\"http://docs.oasis-open.org/wss/2004/01/"
           "oasis-200401-wss-soap-message-security-1.0#Base64Binary\">" +
           base64Encode(token->nonce) + "</wsse:Nonce><wsu:Created>" + token->created +
           "</wsu:Created></wsse:UsernameToken></wsse:Security></s:Header>";
  }
  return xml + "<s:Body>" + body + "</s:Body></s:Envelope>";
}

std::string getSystemDateAndTime()
{
  return "<tds:GetSystemDateAndTime/>";
}

std::string getCapabilities()
{
  return "<tds:GetCapabilities><tds:Category>All</tds:Category></tds:GetCapabilities>";
}

std::string getProfiles()
{
  return "<trt:GetProfiles/>";
}

std::string getNodes()
{
  return "<tptz:GetNodes/>";
}

std::string getConfigurationOptions(const std::string& configuration_token)
{
  return "<tptz:GetConfigurationOptions><tptz:ConfigurationToken>" + escaped(configuration_token) +
         "</tptz:ConfigurationToken></tptz:GetConfigurationOptions>";
}

std::string getStatus(const std::string& profile)
{
  return "<tptz:GetStatus><tptz:ProfileToken>" + escaped(profile) + "</tptz:ProfileToken></tptz:GetStatus>";
}

std::string absoluteMove(const std::string& profile, double x, double y, const char* space, bool with_zoom, double zoom)
{
  std::string body =
      "<tptz:AbsoluteMove><tptz:ProfileToken>" + escaped(profile) +
      formatText("</tptz:ProfileToken><tptz:Position><tt:PanTilt x=\"%.6f\" y=\"%.6f\" space=\"%s\"/>", x, y, space);
  if (with_zoom)
  {
    body += formatText("<tt:Zoom x=\"%.6f\" space=\"%s\"/>", zoom, GENERIC_ZOOM_SPACE);
  }
  return body + "</tptz:Position></tptz:AbsoluteMove>";
}

std::string continuousMove(const std::string& profile, double x, double y, bool with_zoom, double zoom,
                           int timeout_seconds)
{
  std::string body = "<tptz:ContinuousMove><tptz:ProfileToken>" + escaped(profile) +
                     formatText("</tptz:ProfileToken><tptz:Velocity><tt:PanTilt x=\"%.6f\" y=\"%.6f\" space=\"%s\"/>",
                                x, y, GENERIC_PAN_TILT_VELOCITY);
  if (with_zoom)
  {
    body += formatText("<tt:Zoom x=\"%.6f\" space=\"%s\"/>", zoom, GENERIC_ZOOM_VELOCITY);
  }
  return body + formatText("</tptz:Velocity><tptz:Timeout>PT%dS</tptz:Timeout></tptz:ContinuousMove>", timeout_seconds);
}

std::string stop(const std::string& profile)
{
  return "<tptz:Stop><tptz:ProfileToken>" + escaped(profile) +
         "</tptz:ProfileToken><tptz:PanTilt>true</tptz:PanTilt><tptz:Zoom>true</tptz:Zoom></tptz:Stop>";
}

std::string readSystemTime(const Element* response, double& utc_seconds)
{
  const Element* utc = path(response, ns::DEVICE, { "SystemDateAndTime" });
  utc = child(utc, ns::SCHEMA, "UTCDateTime");
  const Element* date = child(utc, ns::SCHEMA, "Date");
  const Element* time = child(utc, ns::SCHEMA, "Time");
  double values[6];
  const std::pair<const Element*, const char*> fields[6] = { { date, "Year" }, { date, "Month" },  { date, "Day" },
                                                             { time, "Hour" }, { time, "Minute" }, { time, "Second" } };
  for (int index = 0; index < 6; ++index)
  {
    if (!number(text(child(fields[index].first, ns::SCHEMA, fields[index].second)), values[index]) ||
        values[index] < 0.0 || values[index] > 9999.0)
    {
      return std::string("no UTCDateTime ") + fields[index].second + " (a whole number 0..9999)";
    }
  }
  const std::string iso =
      formatText("%04d-%02d-%02dT%02d:%02d:%02dZ", static_cast<int>(values[0]), static_cast<int>(values[1]),
                 static_cast<int>(values[2]), static_cast<int>(values[3]), static_cast<int>(values[4]),
                 static_cast<int>(values[5]));
  return parseIsoTime(iso, utc_seconds) ? "" : "a UTCDateTime that is no date: " + iso;
}

std::string readCapabilities(const Element* response, ServicePaths& paths)
{
  const Element* capabilities = child(response, ns::DEVICE, "Capabilities");
  ServicePaths read;
  for (auto service : { std::make_pair("Media", &read.media), std::make_pair("PTZ", &read.ptz) })
  {
    const std::string address = text(path(child(capabilities, ns::SCHEMA, service.first), ns::SCHEMA, { "XAddr" }));
    const std::size_t scheme = address.find("://");
    const std::size_t slash = address.find('/', scheme == std::string::npos ? 0 : scheme + 3);
    if (address.empty() || slash == std::string::npos)
    {
      return std::string("no ") + service.first + " XAddr";
    }
    *service.second = address.substr(slash);
  }
  paths = read;
  return {};
}

std::string readProfiles(const Element* response, const std::string& wanted, Profile& profile)
{
  std::string tokens;
  for (const Element* item : children(response, ns::MEDIA, "Profiles"))
  {
    const char* token = attribute(item, "token");
    const Element* configuration = child(item, ns::SCHEMA, "PTZConfiguration");
    tokens += std::string(tokens.empty() ? "" : ", ") + (token == nullptr ? "?" : token);
    if (token == nullptr || configuration == nullptr || (!wanted.empty() && wanted != token))
    {
      continue;
    }
    const char* configuration_token = attribute(configuration, "token");
    profile.token = token;
    profile.ptz_configuration = configuration_token == nullptr ? "" : configuration_token;
    profile.node = text(child(configuration, ns::SCHEMA, "NodeToken"));
    return {};
  }
  return wanted.empty() ? "no profile with a PTZConfiguration (profiles: " + tokens + ")" :
                          "no profile '" + wanted + "' with a PTZConfiguration (profiles: " + tokens + ")";
}

std::string readNode(const Element* response, const std::string& token, Node& node)
{
  for (const Element* item : children(response, ns::PTZ, "PTZNode"))
  {
    const char* item_token = attribute(item, "token");
    if (!token.empty() && (item_token == nullptr || token != item_token))
    {
      continue;
    }
    Node read;
    const Element* spaces = child(item, ns::SCHEMA, "SupportedPTZSpaces");
    for (const Element* space : children(spaces, ns::SCHEMA, "AbsolutePanTiltPositionSpace"))
    {
      const std::string uri = text(child(space, ns::SCHEMA, "URI"));
      if (uri == DEGREE_SPACE)
      {
        const std::string problem = readRange(child(space, ns::SCHEMA, "XRange"), read.degree_pan) +
                                    readRange(child(space, ns::SCHEMA, "YRange"), read.degree_tilt);
        if (!problem.empty())
        {
          return "SphericalPositionSpaceDegrees: " + problem;
        }
        read.degree_space = true;
      }
      read.generic_space = read.generic_space || uri == GENERIC_PAN_TILT_SPACE;
    }
    for (const Element* space : children(spaces, ns::SCHEMA, "AbsoluteZoomPositionSpace"))
    {
      read.zoom = read.zoom || text(child(space, ns::SCHEMA, "URI")) == GENERIC_ZOOM_SPACE;
    }
    if (!read.degree_space && !read.generic_space)
    {
      return "PTZ node '" + token + "' lists no absolute pan-tilt space this backend knows";
    }
    node = read;
    return {};
  }
  return "no PTZ node '" + token + "'";
}

std::string readTimeoutRange(const Element* response, double& min_s, double& max_s)
{
  const Element* timeout = path(child(response, ns::PTZ, "PTZConfigurationOptions"), ns::SCHEMA, { "PTZTimeout" });
  if (timeout == nullptr)
  {
    return {};
  }
  double low = 0.0;
  double high = 0.0;
  if (!parseDuration(text(child(timeout, ns::SCHEMA, "Min")), low) ||
      !parseDuration(text(child(timeout, ns::SCHEMA, "Max")), high) || low > high)
  {
    return "a PTZTimeout without Min <= Max durations";
  }
  min_s = low;
  max_s = high;
  return {};
}

std::string readStatus(const Element* response, Status& status)
{
  const Element* ptz_status = child(response, ns::PTZ, "PTZStatus");
  const Element* position = child(ptz_status, ns::SCHEMA, "Position");
  const Element* pan_tilt = child(position, ns::SCHEMA, "PanTilt");
  Status read;
  if (!number(attribute(pan_tilt, "x"), read.x) || !number(attribute(pan_tilt, "y"), read.y))
  {
    return "no Position/PanTilt x and y";
  }
  const char* space = attribute(pan_tilt, "space");
  read.space = space == nullptr ? "" : space;
  const Element* zoom = child(position, ns::SCHEMA, "Zoom");
  read.has_zoom = zoom != nullptr;
  if (read.has_zoom && !number(attribute(zoom, "x"), read.zoom))
  {
    return "a Position/Zoom without x";
  }
  const Element* move_status = child(child(ptz_status, ns::SCHEMA, "MoveStatus"), ns::SCHEMA, "PanTilt");
  read.move_status = text(move_status);
  status = read;
  return {};
}

bool parseDuration(const std::string& text, double& seconds)
{
  if (text.size() < 4 || text.compare(0, 2, "PT") != 0)
  {
    return false;
  }
  const char unit = text.back();
  double value = 0.0;
  if (!number(text.substr(2, text.size() - 3), value) || value < 0.0)
  {
    return false;
  }
  switch (unit)
  {
    case 'S':
      seconds = value;
      return true;
    case 'M':
      seconds = 60.0 * value;
      return true;
    case 'H':
      seconds = 3600.0 * value;
      return true;
  }
  return false;
}

}  // namespace onvif
}  // namespace ptz_action_server

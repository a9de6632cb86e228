/**
 * \file
 * \brief The ONVIF replies: the readers of each response (the clock, the services, profiles, nodes and their spaces,
 * the timeout range, the status, the presets) and the durations they carry. The requests are onvif_requests.cpp's.
 */
#include "ptz_action_server/core/onvif/onvif_codec.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace onvif
{
namespace
{
bool number(const std::string& text, double& value)
{
  return parseNumber(text, value);
}

bool number(const char* text, double& value)
{
  return text != nullptr && number(std::string(text), value);
}

/// A range bound: a number, or INF / -INF (xs:float), as the specification writes an unbounded range.
bool bound(const std::string& text, double& value)
{
  if (text == "INF" || text == "+INF")
  {
    value = std::numeric_limits<double>::infinity();
    return true;
  }
  if (text == "-INF")
  {
    value = -std::numeric_limits<double>::infinity();
    return true;
  }
  return number(text, value);
}

std::string readRange(const Element* range, Range& out)
{
  Range read;
  if (!bound(text(child(range, ns::SCHEMA, "Min")), read.min) ||
      !bound(text(child(range, ns::SCHEMA, "Max")), read.max) || !(read.min <= read.max))
  {
    return "a range without Min <= Max";
  }
  out = read;
  return {};
}

/// Every \p kind space of \p spaces (a SupportedPTZSpaces), with its XRange (and YRange for pan-tilt).
std::string readSpaces(const Element* spaces, const char* kind, bool pan_tilt, std::vector<Space>& out)
{
  for (const Element* item : children(spaces, ns::SCHEMA, kind))
  {
    Space space;
    space.uri = text(child(item, ns::SCHEMA, "URI"));
    std::string problem = readRange(child(item, ns::SCHEMA, "XRange"), space.x);
    if (problem.empty() && pan_tilt)
    {
      problem = readRange(child(item, ns::SCHEMA, "YRange"), space.y);
    }
    if (space.uri.empty() || !problem.empty())
    {
      return std::string(kind) + " '" + spaceName(space.uri) + "': " + (problem.empty() ? "no URI" : problem);
    }
    out.push_back(space);
  }
  return {};
}

/// A PTZVector (Position, PTZPosition) read into a Status' position.
std::string readVector(const Element* vector, Status& status)
{
  const Element* pan_tilt = child(vector, ns::SCHEMA, "PanTilt");
  if (pan_tilt != nullptr)
  {
    if (!number(attribute(pan_tilt, "x"), status.x) || !number(attribute(pan_tilt, "y"), status.y))
    {
      return "a PanTilt without numbers x and y";
    }
    status.has_pan_tilt = true;
    const char* space = attribute(pan_tilt, "space");
    status.space = space == nullptr ? "" : space;
  }
  const Element* zoom = child(vector, ns::SCHEMA, "Zoom");
  if (zoom != nullptr)
  {
    if (!number(attribute(zoom, "x"), status.zoom))
    {
      return "a Zoom without a number x";
    }
    status.has_zoom = true;
    const char* space = attribute(zoom, "space");
    status.zoom_space = space == nullptr ? "" : space;
  }
  return {};
}

std::string servicePath(const std::string& address)
{
  const std::size_t scheme = address.find("://");
  const std::size_t slash = address.find('/', scheme == std::string::npos ? 0 : scheme + 3);
  return address.empty() || slash == std::string::npos ? "" : address.substr(slash);
}
}  // namespace

std::string spaceName(const std::string& uri)
{
  const std::size_t slash = uri.rfind('/');
  return slash == std::string::npos || slash + 1 == uri.size() ? uri : uri.substr(slash + 1);
}

const Space* findSpace(const std::vector<Space>& spaces, const std::string& uri)
{
  for (const Space& space : spaces)
  {
    if (space.uri == uri)
    {
      return &space;
    }
  }
  return nullptr;
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
    *service.second = servicePath(text(path(child(capabilities, ns::SCHEMA, service.first), ns::SCHEMA, { "XAddr" })));
    if (service.second->empty())
    {
      return std::string("no ") + service.first + " XAddr";
    }
  }
  read.imaging = servicePath(text(path(child(capabilities, ns::SCHEMA, "Imaging"), ns::SCHEMA, { "XAddr" })));
  paths = read;
  return {};
}

std::string readServices(const Element* response, ServicePaths& paths)
{
  ServicePaths read;
  for (const Element* service : children(response, ns::DEVICE, "Service"))
  {
    const std::string name = text(child(service, ns::DEVICE, "Namespace"));
    const std::string address = servicePath(text(child(service, ns::DEVICE, "XAddr")));
    if (name == ns::MEDIA)
    {
      read.media = address;
    }
    else if (name == ns::PTZ)
    {
      read.ptz = address;
    }
    else if (name == ns::IMAGING)
    {
      read.imaging = address;
    }
  }
  if (read.media.empty() || read.ptz.empty())
  {
    return read.media.empty() ? "no media service (ver10/media/wsdl) with an XAddr" :
                                "no PTZ service (ver20/ptz/wsdl) with an XAddr";
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
    Profile read;
    read.token = token;
    read.ptz_configuration = configuration_token == nullptr ? "" : configuration_token;
    read.node = text(child(configuration, ns::SCHEMA, "NodeToken"));
    read.default_pan_tilt_space = text(child(configuration, ns::SCHEMA, "DefaultAbsolutePantTiltPositionSpace"));
    read.default_zoom_space = text(child(configuration, ns::SCHEMA, "DefaultAbsoluteZoomPositionSpace"));
    read.video_source = text(path(item, ns::SCHEMA, { "VideoSourceConfiguration", "SourceToken" }));
    profile = read;
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
    read.token = item_token == nullptr ? "" : item_token;
    const Element* spaces = child(item, ns::SCHEMA, "SupportedPTZSpaces");
    const std::string problem = readSpaces(spaces, "AbsolutePanTiltPositionSpace", true, read.absolute_pan_tilt) +
                                readSpaces(spaces, "AbsoluteZoomPositionSpace", false, read.absolute_zoom) +
                                readSpaces(spaces, "RelativePanTiltTranslationSpace", true, read.relative_pan_tilt) +
                                readSpaces(spaces, "RelativeZoomTranslationSpace", false, read.relative_zoom) +
                                readSpaces(spaces, "ContinuousPanTiltVelocitySpace", true, read.continuous_pan_tilt) +
                                readSpaces(spaces, "ContinuousZoomVelocitySpace", false, read.continuous_zoom) +
                                readSpaces(spaces, "PanTiltSpeedSpace", false, read.pan_tilt_speed) +
                                readSpaces(spaces, "ZoomSpeedSpace", false, read.zoom_speed);
    if (!problem.empty())
    {
      return "PTZ node '" + read.token + "': " + problem;
    }
    // xs:int in the schema; read as a number and kept within what any camera stores (a count cast out of range is UB).
    double presets = 0.0;
    const std::string presets_text = text(child(item, ns::SCHEMA, "MaximumNumberOfPresets"));
    if (!presets_text.empty() && number(presets_text, presets))
    {
      read.max_presets = static_cast<int>(std::clamp(std::floor(presets), 0.0, 1e6));
    }
    const std::string home = text(child(item, ns::SCHEMA, "HomeSupported"));
    read.home_supported = home == "true" || home == "1";
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

std::string readOptionSpaces(const Element* response, Node& spaces)
{
  const Element* listed = path(child(response, ns::PTZ, "PTZConfigurationOptions"), ns::SCHEMA, { "Spaces" });
  Node read;
  const std::string problem = readSpaces(listed, "RelativePanTiltTranslationSpace", true, read.relative_pan_tilt) +
                              readSpaces(listed, "RelativeZoomTranslationSpace", false, read.relative_zoom);
  if (!problem.empty())
  {
    return "PTZ configuration options: " + problem;
  }
  spaces.relative_pan_tilt = read.relative_pan_tilt;
  spaces.relative_zoom = read.relative_zoom;
  return {};
}

std::string readStatus(const Element* response, Status& status)
{
  const Element* ptz_status = child(response, ns::PTZ, "PTZStatus");
  if (ptz_status == nullptr)
  {
    return "no PTZStatus";
  }
  Status read;
  const std::string problem = readVector(child(ptz_status, ns::SCHEMA, "Position"), read);
  if (!problem.empty())
  {
    return "a Position with " + problem;
  }
  const Element* move_status = child(ptz_status, ns::SCHEMA, "MoveStatus");
  read.move_status = text(child(move_status, ns::SCHEMA, "PanTilt"));
  read.zoom_move_status = text(child(move_status, ns::SCHEMA, "Zoom"));
  read.error = text(child(ptz_status, ns::SCHEMA, "Error"));
  status = read;
  return {};
}

std::string readPresets(const Element* response, std::vector<Preset>& presets)
{
  if (response == nullptr || !is(*response, ns::PTZ, "GetPresetsResponse"))
  {
    return "no GetPresetsResponse";
  }
  std::vector<Preset> read;
  for (const Element* item : children(response, ns::PTZ, "Preset"))
  {
    Preset preset;
    const char* token = attribute(item, "token");
    if (token == nullptr || *token == '\0')
    {
      return "a Preset without a token";
    }
    preset.token = token;
    preset.name = text(child(item, ns::SCHEMA, "Name"));
    const std::string problem = readVector(child(item, ns::SCHEMA, "PTZPosition"), preset.position);
    if (!problem.empty())
    {
      return "preset '" + preset.token + "': a PTZPosition with " + problem;
    }
    read.push_back(preset);
  }
  presets = read;
  return {};
}

std::string readPresetToken(const Element* response, std::string& token)
{
  const std::string read = text(child(response, ns::PTZ, "PresetToken"));
  if (read.empty())
  {
    return "no PresetToken";
  }
  token = read;
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

#include "ptz_action_server/emulators/axis_camera_emulator.h"

#include <cmath>
#include <map>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
int hexDigit(char c)
{
  if (c >= '0' && c <= '9')
  {
    return c - '0';
  }
  if (c >= 'a' && c <= 'f')
  {
    return c - 'a' + 10;
  }
  if (c >= 'A' && c <= 'F')
  {
    return c - 'A' + 10;
  }
  return -1;
}

std::string percentDecoded(const std::string& text)
{
  std::string decoded;
  for (std::size_t index = 0; index < text.size(); ++index)
  {
    if (text[index] == '%' && index + 2 < text.size() && hexDigit(text[index + 1]) >= 0 &&
        hexDigit(text[index + 2]) >= 0)
    {
      decoded += static_cast<char>(hexDigit(text[index + 1]) * 16 + hexDigit(text[index + 2]));
      index += 2;
    }
    else
    {
      decoded += text[index] == '+' ? ' ' : text[index];
    }
  }
  return decoded;
}

/// `a=1&b=2` into an ordered list (later arguments of the same name win, as in the camera's CGI).
std::vector<std::pair<std::string, std::string>> formArguments(const std::string& form)
{
  std::vector<std::pair<std::string, std::string>> arguments;
  std::size_t start = 0;
  while (start < form.size())
  {
    std::size_t end = form.find('&', start);
    end = end == std::string::npos ? form.size() : end;
    const std::string pair = form.substr(start, end - start);
    start = end + 1;
    if (pair.empty())
    {
      continue;
    }
    const std::size_t equals = pair.find('=');
    arguments.emplace_back(percentDecoded(pair.substr(0, equals)),
                           equals == std::string::npos ? std::string() : percentDecoded(pair.substr(equals + 1)));
  }
  return arguments;
}

HttpAnswer errorBody(const std::string& words)
{
  return HttpAnswer{ 200, "text/plain", "Error:\r\n" + words + "\r\n" };
}

/// The emulated device with its zoom range taken from the lens (\p table empty: no zoom, range 1..1).
SimDeviceConfig withLens(SimDeviceConfig device, const vapix::ZoomTable& table)
{
  device.axes[ZOOM].range = table.empty() ? AxisRange{ 1.0, 1.0 } : AxisRange{ table.minFactor(), table.maxFactor() };
  return device;
}

vapix::ZoomTable lensOf(const std::string& text)
{
  vapix::ZoomTable table;
  if (!text.empty())
  {
    const std::string problem = vapix::ZoomTable::parse(text, table);
    if (!problem.empty())
    {
      throw ConfigError("zoom table: " + problem);
    }
  }
  return table;
}
}  // namespace

std::string AxisCameraEmulatorConfig::linearZoomTable(double max_optical)
{
  const vapix::ZoomTable table = vapix::ZoomTable::linear(max_optical);
  if (table.empty())
  {
    throw ConfigError(formatText("an optical zoom of %g X: must be above 1", max_optical));
  }
  return table.toText();
}

SimDeviceConfig AxisCameraEmulatorConfig::defaultDevice()
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  device.axes[PAN].range = { toRadians(-170.0), toRadians(170.0) };
  device.axes[TILT].range = { toRadians(-20.0), toRadians(90.0) };
  device.axes[PAN].resolution = 0.0;
  device.axes[TILT].resolution = 0.0;
  return device;
}

AxisCameraEmulator::AxisCameraEmulator(const AxisCameraEmulatorConfig& config, std::shared_ptr<const Clock> clock)
  : HttpCameraEmulator(withLens(config.device, lensOf(config.zoom_table)), std::move(clock))
  , config_(config)
  , zoom_table_(lensOf(config.zoom_table))
  , optics_(FieldOfViewModel::fromWideEnd(config.field_of_view))
  , lens_(config.lens, clock_->now())
{
  if (config_.model.empty() || config_.model.find_first_of("\r\n") != std::string::npos)
  {
    throw ConfigError("model: a product number, one line");
  }
  server_ = std::make_unique<HttpCameraServer>(
      config_.http, [this](const std::string& method, const std::string& target, const std::string& body) {
        return handle(method, target, body);
      });
}

HttpAnswer AxisCameraEmulator::handle(const std::string& method, const std::string& target, const std::string& body)
{
  const std::size_t question = target.find('?');
  const std::string path = target.substr(0, question);
  if (path != vapix::PTZ_PATH && path != vapix::PARAM_PATH && path != vapix::QUEUE_PATH)
  {
    return HttpAnswer{ 404, "text/html", "<HTML><HEAD><TITLE>404 Not Found</TITLE></HEAD></HTML>\r\n" };
  }
  const auto arguments =
      formArguments(method == "POST" ? body : (question == std::string::npos ? "" : target.substr(question + 1)));
  std::map<std::string, std::string> values(arguments.begin(), arguments.end());
  for (const auto& argument : arguments)
  {
    values[argument.first] = argument.second;
  }
  if (path == vapix::PARAM_PATH)
  {
    return parameters(values["action"], values["group"]);
  }

  std::lock_guard<std::mutex> lock(mutex_);
  const TimePoint now = clock_->now();
  std::string set_cookie;
  const std::string client = clientOf(server_->requestCookie(), set_cookie);
  if (!set_cookie.empty())
  {
    server_->setAnswerCookie(set_cookie);
  }
  return command(path, values, client, now);
}

HttpAnswer AxisCameraEmulator::command(const std::string& path, std::map<std::string, std::string>& values,
                                       const std::string& client, TimePoint now)
{
  double camera = 1.0;
  if (values.count("camera") && (!parseNumber(values["camera"], camera) || camera < 1 || camera > config_.cameras ||
                                 camera != std::floor(camera)))
  {
    return errorBody("camera: invalid camera: " + values["camera"]);
  }
  if (path == vapix::QUEUE_PATH)
  {
    return queueAnswer(values["control"], client, now);
  }
  if (values.count("info"))
  {
    return info();
  }
  if (values.count("query"))
  {
    return query(values["query"], values.count("group") ? values["group"] : "", now);
  }
  if (std::optional<HttpAnswer> lens = lensCommand(values, client, now))
  {
    return *lens;
  }
  // Check every argument before acting on any, as the CGI does.
  struct Move
  {
    double value = 0.0;
    bool given = false;
  };
  std::map<std::string, Move> numbers;
  for (const char* name : { "pan", "tilt", "zoom", "speed", "rpan", "rtilt", "rzoom", "continuouszoommove" })
  {
    if (values.count(name))
    {
      Move& move = numbers[name];
      move.given = parseNumber(values[name], move.value);
      if (!move.given)
      {
        return errorBody(std::string(name) + ": bad value: " + values[name]);
      }
    }
  }
  double pan_percent = 0.0;
  double tilt_percent = 0.0;
  const bool continuous = values.count("continuouspantiltmove") > 0;
  if (continuous)
  {
    const std::string& text = values["continuouspantiltmove"];
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos || !parseNumber(text.substr(0, comma), pan_percent) ||
        !parseNumber(text.substr(comma + 1), tilt_percent) || std::abs(pan_percent) > 100 ||
        std::abs(tilt_percent) > 100)
    {
      return errorBody("continuouspantiltmove: bad value: " + text);
    }
  }
  for (const auto& value : values)
  {
    static const char* const KNOWN[] = { "camera",
                                         "pan",
                                         "tilt",
                                         "zoom",
                                         "speed",
                                         "rpan",
                                         "rtilt",
                                         "rzoom",
                                         "continuouspantiltmove",
                                         "continuouszoommove",
                                         "move",
                                         "imagerotation" };
    static const char* const PICTURE[] = { "center", "areazoom", "imagewidth", "imageheight" };
    const auto named = [&](const char* name) { return value.first == name; };
    if (std::find_if(std::begin(KNOWN), std::end(KNOWN), named) == std::end(KNOWN) &&
        !(config_.area_zoom && std::find_if(std::begin(PICTURE), std::end(PICTURE), named) != std::end(PICTURE)))
    {
      return errorBody(value.first + ": unknown argument");
    }
  }
  const std::string picture = aimInPicture(values, false, now);
  if (!picture.empty())
  {
    return errorBody(picture);
  }
  if (values.count("move") && values["move"] != "stop" && values["move"] != "home")
  {
    return errorBody("move: unknown value: " + values["move"]);
  }
  if (refusing())
  {
    return errorBody(REFUSAL);
  }
  if (!mayMove(client, now))
  {
    return HttpAnswer{ 204, "text/plain", "" };  // taken, and nothing moves
  }

  if (numbers["speed"].given)
  {
    speed_ = static_cast<int>(std::clamp(numbers["speed"].value, 1.0, 100.0));
  }
  for (Axis axis : { PAN, TILT })
  {
    model_.setCruiseSpeed(axis, config_.device.axes[axis].motion.max_speed * speed_ / 100.0, now);
  }
  const PtzSample state = model_.sample(now);
  auto go = [&](Axis axis, const char* absolute, const char* relative) {
    if (numbers[absolute].given)
    {
      model_.goToAxis(axis, toRadians(numbers[absolute].value), now);
    }
    else if (numbers[relative].given)
    {
      model_.goToAxis(axis, state.position[axis] + toRadians(numbers[relative].value), now);
    }
  };
  go(PAN, "pan", "rpan");
  go(TILT, "tilt", "rtilt");
  if (!zoom_table_.empty() && numbers["zoom"].given)
  {
    model_.goToAxis(ZOOM, zoom_table_.toFactor(numbers["zoom"].value), now);
  }
  if (!zoom_table_.empty() && numbers["rzoom"].given)
  {
    model_.goToAxis(ZOOM, zoom_table_.toFactor(zoom_table_.toValue(state.position[ZOOM]) + numbers["rzoom"].value),
                    now);
  }
  if (continuous)
  {
    model_.moveAxisAtVelocity(PAN, config_.device.axes[PAN].motion.max_speed * pan_percent / 100.0, now);
    model_.moveAxisAtVelocity(TILT, config_.device.axes[TILT].motion.max_speed * tilt_percent / 100.0, now);
  }
  if (!zoom_table_.empty() && numbers["continuouszoommove"].given)
  {
    model_.moveAxisAtVelocity(
        ZOOM, config_.device.axes[ZOOM].motion.max_speed * numbers["continuouszoommove"].value / 100.0, now);
  }
  aimInPicture(values, true, now);
  if (values["move"] == "stop")
  {
    model_.stop(now);
  }
  else if (values["move"] == "home")
  {
    model_.goTo({ 0.0, 0.0, zoom_table_.empty() ? 1.0 : zoom_table_.minFactor() }, now);
  }
  return HttpAnswer{ 204, "text/plain", "" };
}

HttpAnswer AxisCameraEmulator::query(const std::string& what, const std::string& group, TimePoint now)
{
  const SimDeviceConfig& device = config_.device;
  if (what == "position")
  {
    const PtzSample state = model_.sample(now);
    std::string body =
        formatText("pan=%.4f\r\ntilt=%.4f\r\n", toDegrees(state.position[PAN]), toDegrees(state.position[TILT]));
    if (!zoom_table_.empty())
    {
      body += formatText("zoom=%.0f\r\n", std::round(zoom_table_.toValue(state.position[ZOOM])));
    }
    return HttpAnswer{ 200, "text/plain", body + lensLines(now) };
  }
  if (what == "limits")
  {
    std::string body = formatText("MinPan=%g\r\nMaxPan=%g\r\nMinTilt=%g\r\nMaxTilt=%g\r\n",
                                  toDegrees(device.axes[PAN].range.min), toDegrees(device.axes[PAN].range.max),
                                  toDegrees(device.axes[TILT].range.min), toDegrees(device.axes[TILT].range.max));
    if (!zoom_table_.empty())
    {
      body += formatText("MinZoom=%g\r\nMaxZoom=%g\r\n", zoom_table_.minValue(), zoom_table_.maxValue());
    }
    return HttpAnswer{ 200, "text/plain",
                       body + "MinIris=1\r\nMaxIris=9999\r\nMinFocus=1\r\nMaxFocus=9999\r\nMinFieldAngle=22\r\n"
                              "MaxFieldAngle=623\r\n" };
  }
  if (what == "speed")
  {
    return HttpAnswer{ 200, "text/plain", formatText("speed=%d\r\n", speed_) };
  }
  if (what == "presetposcam" || what == "presetposall")
  {
    return HttpAnswer{ 200, "text/plain", "Preset Positions for camera 1\r\npresetposno1=Home\r\n" };
  }
  if (what == "attributes" && config_.attributes)
  {
    // The documented plain-text form: a section per channel; array entries split by ',', their pairs by '|'.
    std::string body = "Attributes for camera 1\r\n";
    if (!zoom_table_.empty() && (group.empty() || group == "zoom"))
    {
      const double optical = zoom_table_.toFactor(vapix::ZOOM_VALUE_OPTICAL_MAX);
      body += formatText("maxOpticalZoomMag=%g\r\n", optical);
      if (zoom_table_.maxValue() > vapix::ZOOM_VALUE_OPTICAL_MAX)
      {
        body += formatText("maxDigitalZoomMag=%g\r\n", zoom_table_.maxFactor() / optical);
      }
      body += "zoomSteps=";
      for (std::size_t index = 0; index < zoom_table_.size(); ++index)
      {
        const auto& point = zoom_table_.points()[index];
        body += formatText("%svalue=%g | zoom=%g", index == 0 ? "" : ",", point.first, point.second);
      }
      body += "\r\n";
    }
    else if (group != "zoom" && !group.empty() && group != "focus" && group != "speed" && group != "speeddry")
    {
      return errorBody("group: unknown value: " + group);
    }
    return HttpAnswer{ 200, "text/plain", body };
  }
  return errorBody("query: unknown value: " + what);
}

HttpAnswer AxisCameraEmulator::info() const
{
  const bool zoom = !zoom_table_.empty();
  std::string body = "Available commands:\r\n{camera=[n]}\r\nmove={ home | stop }\r\npan=[abspos]\r\ntilt=[abspos]\r\n";
  body += zoom ? "zoom=[n]\r\n" : "";
  if (config_.area_zoom)  // as the VAPIX documentation's example lists them
  {
    body += "center=[x],[y]\r\n  imagewidth=[n]\r\n  imageheight=[n]\r\n";
    body += zoom ? "areazoom=[x],[y],[z]\r\n  imagewidth=[n]\r\n  imageheight=[n]\r\n" : "";
  }
  body += "rpan=[offset]\r\nrtilt=[offset]\r\n";
  body += zoom ? "rzoom=[offset]\r\n" : "";
  body += "continuouspantiltmove=[x-speed],[y-speed]\r\n";
  body += zoom ? "continuouszoommove=[speed]\r\n" : "";
  body += lens_.present(LensFunction::FOCUS) ? "autofocus={ on | off "
                                               "}\r\nfocus=[n]\r\ncontinuousfocusmove=[speed]\r\n" :
                                               "";
  body +=
      lens_.present(LensFunction::IRIS) ? "autoiris={ on | off }\r\niris=[n]\r\ncontinuousirismove=[speed]\r\n" : "";
  body += "speed=[n]\r\nimagerotation=[n]\r\nquery={ speed | position | limits | presetposcam | presetposall";
  body += config_.attributes ? " | attributes }\r\n" : " }\r\n";
  return HttpAnswer{ 200, "text/plain", body };
}

HttpAnswer AxisCameraEmulator::parameters(const std::string& action, const std::string& group) const
{
  if (action == "list" && group.rfind("root.PTZ", 0) == 0)
  {
    return HttpAnswer{ 200, "text/plain", queueParameters(group) };
  }
  if (action == "list" && (group == "root.Brand" || group == "Brand"))
  {
    return HttpAnswer{ 200, "text/plain",
                       "root.Brand.Brand=AXIS\r\nroot.Brand.ProdFullName=AXIS " + config_.model +
                           " PTZ Network Camera\r\nroot.Brand.ProdNbr=" + config_.model +
                           "\r\nroot.Brand.ProdShortName=AXIS " + config_.model +
                           "\r\nroot.Brand.ProdType=PTZ Network Camera\r\nroot.Brand.ProdVariant=\r\n"
                           "root.Brand.WebURL=http://www.axis.com\r\n" };
  }
  return HttpAnswer{ 200, "text/plain", "# Error: Error -1 getting param in group '" + group + "'\r\n" };
}

}  // namespace ptz_action_server

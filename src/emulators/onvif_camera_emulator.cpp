#include "ptz_action_server/emulators/onvif_camera_emulator.h"

#include <chrono>
#include <cmath>

#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif;

constexpr const char* DEVICE_PATH = "/onvif/device_service";
constexpr const char* MEDIA_PATH = "/onvif/media_service";
constexpr const char* PTZ_PATH = "/onvif/ptz_service";
constexpr const char* CONTENT_TYPE = "application/soap+xml; charset=utf-8";

/// An answer in the camera's own prefixes: env for SOAP, a default namespace for the response's service.
HttpAnswer respond(const char* service, const std::string& content)
{
  return HttpAnswer{ 200, CONTENT_TYPE,
                     std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<env:Envelope xmlns:env=\"") + ns::SOAP +
                         "\" xmlns:sch=\"" + ns::SCHEMA + "\"><env:Body><" + content.substr(0, content.find('>')) +
                         " xmlns=\"" + service + "\"" + content.substr(content.find('>')) +
                         "</env:Body></env:Envelope>" };
}

HttpAnswer fault(bool sender, const char* subcode, const std::string& reason)
{
  return HttpAnswer{ sender ? 400u : 500u, CONTENT_TYPE,
                     std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<env:Envelope xmlns:env=\"") + ns::SOAP +
                         "\" "
                         "xmlns:ter=\"http://www.onvif.org/ver10/error\"><env:Body><env:Fault><env:Code><env:Value>" +
                         (sender ? "env:Sender" : "env:Receiver") + "</env:Value><env:Subcode><env:Value>" + subcode +
                         "</env:Value></env:Subcode></env:Code><env:Reason><env:Text xml:lang=\"en\">" +
                         escaped(reason) + "</env:Text></env:Reason></env:Fault></env:Body></env:Envelope>" };
}

std::string range(const char* name, double min, double max)
{
  return formatText("<sch:%s><sch:Min>%g</sch:Min><sch:Max>%g</sch:Max></sch:%s>", name, min, max, name);
}

std::string space(const char* kind, const char* uri, bool pan_tilt, double min, double max, double y_min = 0.0,
                  double y_max = 0.0)
{
  return std::string("<sch:") + kind + "><sch:URI>" + uri + "</sch:URI>" + range("XRange", min, max) +
         (pan_tilt ? range("YRange", y_min, y_max) : "") + "</sch:" + kind + ">";
}

bool number(const char* text, double& value)
{
  char* end = nullptr;
  if (text == nullptr)
  {
    return false;
  }
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}
}  // namespace

SimDeviceConfig OnvifCameraEmulatorConfig::defaultDevice()
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  device.axes[ZOOM].range = { 1.0, 18.0 };
  device.axes[PAN].resolution = 0.0;
  device.axes[TILT].resolution = 0.0;
  return device;
}

OnvifCameraEmulator::OnvifCameraEmulator(const OnvifCameraEmulatorConfig& config, std::shared_ptr<const Clock> clock)
  : config_(config), clock_(std::move(clock)), model_(config.device, clock_->now())
{
  server_ = std::make_unique<HttpCameraServer>(
      config_.http,
      [this](const std::string&, const std::string& target, const std::string& body) { return handle(target, body); });
}

OnvifCameraEmulator::~OnvifCameraEmulator() = default;

PtzSample OnvifCameraEmulator::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const TimePoint now = clock_->now();
  expireVelocity(now);
  return model_.sample(now);
}

void OnvifCameraEmulator::setRefuse(bool refuse)
{
  std::lock_guard<std::mutex> lock(mutex_);
  refuse_ = refuse;
}

void OnvifCameraEmulator::setFaults(const SimFaults& faults)
{
  std::lock_guard<std::mutex> lock(mutex_);
  model_.setFaults(faults, clock_->now());
}

std::uint64_t OnvifCameraEmulator::refusedTokens() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return refused_tokens_;
}

double OnvifCameraEmulator::cameraUtc() const
{
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count() +
         config_.clock_offset;
}

void OnvifCameraEmulator::expireVelocity(TimePoint now) const
{
  if (velocity_active_ && now >= velocity_until_)
  {
    velocity_active_ = false;
    model_.stop(velocity_until_);  // the ContinuousMove's Timeout ran out
  }
}

std::string OnvifCameraEmulator::checkToken(const SoapMessage& message) const
{
  const Element* token = path(child(message.header, ns::WSSE, "Security"), ns::WSSE, { "UsernameToken" });
  if (token == nullptr)
  {
    return "no UsernameToken";
  }
  const std::string username = text(child(token, ns::WSSE, "Username"));
  const std::string password = text(child(token, ns::WSSE, "Password"));
  const std::string created = text(child(token, ns::WSU, "Created"));
  std::string nonce;
  double created_utc = 0.0;
  if (!base64Decode(text(child(token, ns::WSSE, "Nonce")), nonce) || !parseIsoTime(created, created_utc))
  {
    return "a UsernameToken without a Base64 Nonce or a UTC Created";
  }
  if (std::abs(created_utc - cameraUtc()) > config_.max_token_age)
  {
    return "a UsernameToken created at " + created + ", far from the camera's clock";
  }
  if (username != config_.username || password != passwordDigest(nonce, created, config_.password))
  {
    return "a wrong username or password";
  }
  return {};
}

HttpAnswer OnvifCameraEmulator::handle(const std::string& target, const std::string& body)
{
  if (target != DEVICE_PATH && target != MEDIA_PATH && target != PTZ_PATH)
  {
    return HttpAnswer{ 404, "text/html", "<html><body>404 Not Found</body></html>" };
  }
  SoapMessage message;
  if (!parseSoap(body, message).empty() || message.fault)
  {
    return fault(true, "ter:WellFormed", "the request is not a SOAP 1.2 envelope");
  }
  const std::string operation = localName(*message.content);
  const std::string service = namespaceOf(*message.content);
  const char* expected = target == DEVICE_PATH ? ns::DEVICE : target == MEDIA_PATH ? ns::MEDIA : ns::PTZ;
  if (service != expected)
  {
    return fault(false, "ter:ActionNotSupported", operation + " is not an operation of " + target);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (operation != "GetSystemDateAndTime")
  {
    const std::string refused = checkToken(message);
    if (!refused.empty())
    {
      ++refused_tokens_;
      return fault(true, "ter:NotAuthorized", "Sender not Authorized: " + refused);
    }
  }
  const TimePoint now = clock_->now();
  expireVelocity(now);
  return operate(operation, message, now);
}

HttpAnswer OnvifCameraEmulator::operate(const std::string& operation, const SoapMessage& message, TimePoint now)
{
  const std::string host = "http://" + config_.advertised_host;
  const Element* request = message.content;
  if (operation == "GetSystemDateAndTime")
  {
    const std::string iso = isoTime(cameraUtc());
    int year, month, day, hour, minute, second;
    std::sscanf(iso.c_str(), "%d-%d-%dT%d:%d:%d", &year, &month, &day, &hour, &minute, &second);
    return respond(ns::DEVICE, formatText("GetSystemDateAndTimeResponse><SystemDateAndTime><sch:DateTimeType>NTP</"
                                          "sch:DateTimeType>"
                                          "<sch:DaylightSavings>false</"
                                          "sch:DaylightSavings><sch:UTCDateTime><sch:Time><sch:Hour>%d"
                                          "</sch:Hour><sch:Minute>%d</sch:Minute><sch:Second>%d</sch:Second></"
                                          "sch:Time><sch:Date>"
                                          "<sch:Year>%d</sch:Year><sch:Month>%d</sch:Month><sch:Day>%d</sch:Day></"
                                          "sch:Date>"
                                          "</sch:UTCDateTime></SystemDateAndTime></GetSystemDateAndTimeResponse>",
                                          hour, minute, second, year, month, day));
  }
  if (operation == "GetCapabilities")
  {
    return respond(ns::DEVICE, "GetCapabilitiesResponse><Capabilities><sch:Device><sch:XAddr>" + host + DEVICE_PATH +
                                   "</sch:XAddr></sch:Device><sch:Media><sch:XAddr>" + host + MEDIA_PATH +
                                   "</sch:XAddr></sch:Media><sch:PTZ><sch:XAddr>" + host + PTZ_PATH +
                                   "</sch:XAddr></sch:PTZ></Capabilities></GetCapabilitiesResponse>");
  }
  if (operation == "GetProfiles")
  {
    return respond(ns::MEDIA, "GetProfilesResponse><Profiles token=\"profile_0\" fixed=\"true\"><sch:Name>sub"
                              "</sch:Name></Profiles><Profiles token=\"profile_1\" fixed=\"true\"><sch:Name>main"
                              "</sch:Name><sch:PTZConfiguration token=\"ptz0\"><sch:Name>ptz</sch:Name><sch:NodeToken>"
                              "node0</sch:NodeToken><sch:DefaultPTZTimeout>PT5S</sch:DefaultPTZTimeout>"
                              "</sch:PTZConfiguration></Profiles></GetProfilesResponse>");
  }
  const std::string spaces =
      (config_.degree_space ? space("AbsolutePanTiltPositionSpace", DEGREE_SPACE, true, -180, 180, -90, 90) : "") +
      space("AbsolutePanTiltPositionSpace", GENERIC_PAN_TILT_SPACE, true, -1, 1, -1, 1) +
      space("AbsoluteZoomPositionSpace", GENERIC_ZOOM_SPACE, false, 0, 1) +
      space("ContinuousPanTiltVelocitySpace", GENERIC_PAN_TILT_VELOCITY, true, -1, 1, -1, 1) +
      space("ContinuousZoomVelocitySpace", GENERIC_ZOOM_VELOCITY, false, -1, 1);
  if (operation == "GetNodes")
  {
    return respond(ns::PTZ, "GetNodesResponse><PTZNode "
                            "token=\"node0\"><sch:Name>node</sch:Name><sch:SupportedPTZSpaces>" +
                                spaces +
                                "</sch:SupportedPTZSpaces><sch:MaximumNumberOfPresets>64"
                                "</sch:MaximumNumberOfPresets><sch:HomeSupported>true</sch:HomeSupported>"
                                "</PTZNode></GetNodesResponse>");
  }
  if (operation == "GetConfigurationOptions")
  {
    return respond(ns::PTZ, "GetConfigurationOptionsResponse><PTZConfigurationOptions><sch:Spaces>" + spaces +
                                "</sch:Spaces><sch:PTZTimeout><sch:Min>PT1S</sch:Min><sch:Max>PT60S</sch:Max>"
                                "</sch:PTZTimeout></PTZConfigurationOptions></GetConfigurationOptionsResponse>");
  }
  const bool moves = operation == "AbsoluteMove" || operation == "ContinuousMove";
  if (child(request, ns::PTZ, "ProfileToken") == nullptr || text(child(request, ns::PTZ, "ProfileToken")) != "profile_"
                                                                                                             "1")
  {
    if (moves || operation == "Stop" || operation == "GetStatus")
    {
      return fault(true, "ter:NoProfile", "The requested profile token does not exist");
    }
  }
  if (moves && refuse_)
  {
    return fault(true, "ter:InvalidArgVal", OnvifCameraEmulator::REFUSAL);
  }
  const SimDeviceConfig& device = config_.device;
  if (operation == "AbsoluteMove")
  {
    const Element* position = child(request, ns::PTZ, "Position");
    const Element* pan_tilt = child(position, ns::SCHEMA, "PanTilt");
    const Element* zoom = child(position, ns::SCHEMA, "Zoom");
    const char* space_uri = attribute(pan_tilt, "space");
    const bool degrees = space_uri != nullptr && std::string(space_uri) == DEGREE_SPACE;
    double x = 0.0, y = 0.0, z = 0.0;
    if (pan_tilt != nullptr && (!number(attribute(pan_tilt, "x"), x) || !number(attribute(pan_tilt, "y"), y) ||
                                (degrees && !config_.degree_space)))
    {
      return fault(true, "ter:InvalidArgVal", "The requested position is not valid in its space");
    }
    const double limit_x = degrees ? 180.0 : 1.0;
    const double limit_y = degrees ? 90.0 : 1.0;
    if (std::abs(x) > limit_x || std::abs(y) > limit_y ||
        (zoom != nullptr && (!number(attribute(zoom, "x"), z) || z < 0.0 || z > 1.0)))
    {
      return fault(true, "ter:InvalidArgVal", "The requested position is out of bounds");
    }
    velocity_active_ = false;
    if (pan_tilt != nullptr)
    {
      model_.goToAxis(PAN, degrees ? toRadians(x) : x * M_PI, now);
      model_.goToAxis(TILT, degrees ? toRadians(y) : y * M_PI / 2.0, now);
    }
    if (zoom != nullptr)
    {
      model_.goToAxis(ZOOM, std::pow(device.axes[ZOOM].range.max, z), now);
    }
    return respond(ns::PTZ, "AbsoluteMoveResponse></AbsoluteMoveResponse>");
  }
  if (operation == "ContinuousMove")
  {
    const Element* velocity = child(request, ns::PTZ, "Velocity");
    const Element* pan_tilt = child(velocity, ns::SCHEMA, "PanTilt");
    const Element* zoom = child(velocity, ns::SCHEMA, "Zoom");
    double x = 0.0, y = 0.0, z = 0.0, timeout = 5.0;
    const Element* timeout_element = child(request, ns::PTZ, "Timeout");
    if ((pan_tilt != nullptr && (!number(attribute(pan_tilt, "x"), x) || !number(attribute(pan_tilt, "y"), y))) ||
        (zoom != nullptr && !number(attribute(zoom, "x"), z)) || std::abs(x) > 1 || std::abs(y) > 1 ||
        std::abs(z) > 1 || (timeout_element != nullptr && !parseDuration(text(timeout_element), timeout)))
    {
      return fault(true, "ter:InvalidArgVal", "The requested velocity or timeout is not valid");
    }
    model_.moveAxisAtVelocity(PAN, x * device.axes[PAN].motion.max_speed, now);
    model_.moveAxisAtVelocity(TILT, y * device.axes[TILT].motion.max_speed, now);
    model_.moveAxisAtVelocity(ZOOM, z * device.axes[ZOOM].motion.max_speed, now);
    velocity_active_ = true;
    velocity_until_ = addSeconds(now, timeout);
    return respond(ns::PTZ, "ContinuousMoveResponse></ContinuousMoveResponse>");
  }
  if (operation == "Stop")
  {
    velocity_active_ = false;
    model_.stop(now);
    return respond(ns::PTZ, "StopResponse></StopResponse>");
  }
  if (operation == "GetStatus")
  {
    const PtzSample state = model_.sample(now);
    const double x = config_.degree_space ? toDegrees(state.position[PAN]) : state.position[PAN] / M_PI;
    const double y = config_.degree_space ? toDegrees(state.position[TILT]) : state.position[TILT] / (M_PI / 2.0);
    const double z = std::log(state.position[ZOOM]) / std::log(device.axes[ZOOM].range.max);
    const char* moving = state.moving ? "MOVING" : "IDLE";
    return respond(ns::PTZ, formatText("GetStatusResponse><PTZStatus><sch:Position><sch:PanTilt x=\"%.6f\" y=\"%.6f\" "
                                       "space=\"%s\"/><sch:Zoom x=\"%.6f\" "
                                       "space=\"%s\"/></sch:Position><sch:MoveStatus>"
                                       "<sch:PanTilt>%s</sch:PanTilt><sch:Zoom>%s</sch:Zoom></"
                                       "sch:MoveStatus><sch:UtcTime>%s"
                                       "</sch:UtcTime></PTZStatus></GetStatusResponse>",
                                       x, y, config_.degree_space ? DEGREE_SPACE : GENERIC_PAN_TILT_SPACE, z,
                                       GENERIC_ZOOM_SPACE, moving, moving, isoTime(cameraUtc()).c_str()));
  }
  return fault(false, "ter:ActionNotSupported", "The operation " + operation + " is not supported");
}

}  // namespace ptz_action_server

#include "ptz_action_server/emulators/onvif_camera_emulator.h"

#include <chrono>
#include <cmath>
#include <initializer_list>

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
constexpr const char* PROFILE = "profile_1";  ///< the profile with PTZ
constexpr const char* PROFILE_WITHOUT_PTZ = "profile_0";
constexpr const char* CONFIGURATION = "ptz0";
constexpr const char* NODE = "node0";
constexpr const char* VIDEO_SOURCE = "video_source_0";
constexpr double MIN_TIMEOUT = 1.0;   ///< s, the PTZTimeout range GetConfigurationOptions lists
constexpr double MAX_TIMEOUT = 60.0;  ///< s
constexpr double MOVING = 1e-6;       ///< rad/s (X/s) an axis moves faster than when MoveStatus says MOVING

/// An answer in the camera's own prefixes: env for SOAP, a default namespace for the response's service.
HttpAnswer respond(const char* service, const std::string& content)
{
  return HttpAnswer{ 200, CONTENT_TYPE,
                     std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<env:Envelope xmlns:env=\"") + ns::SOAP +
                         "\" xmlns:sch=\"" + ns::SCHEMA + "\"><env:Body><" + content.substr(0, content.find('>')) +
                         " xmlns=\"" + service + "\"" + content.substr(content.find('>')) +
                         "</env:Body></env:Envelope>" };
}

/// A SOAP fault: env:Sender (HTTP 400) or env:Receiver (HTTP 500), then the subcodes, outermost first.
HttpAnswer fault(bool sender, std::initializer_list<const char*> subcodes, const std::string& reason)
{
  std::string code = std::string("<env:Code><env:Value>") + (sender ? "env:Sender" : "env:Receiver") + "</env:Value>";
  std::string closing = "</env:Code>";
  for (const char* subcode : subcodes)
  {
    code += std::string("<env:Subcode><env:Value>") + subcode + "</env:Value>";
    closing = "</env:Subcode>" + closing;
  }
  return HttpAnswer{ sender ? 400u : 500u, CONTENT_TYPE,
                     std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<env:Envelope xmlns:env=\"") + ns::SOAP +
                         "\" xmlns:ter=\"http://www.onvif.org/ver10/error\"><env:Body><env:Fault>" + code + closing +
                         "<env:Reason><env:Text xml:lang=\"en\">" + escaped(reason) +
                         "</env:Text></env:Reason></env:Fault></env:Body></env:Envelope>" };
}

/// env:Sender / ter:InvalidArgVal / ter:\p what, as the PTZ service's argument faults are.
HttpAnswer invalid(const char* what, const std::string& reason)
{
  return fault(true, { "ter:InvalidArgVal", what }, reason);
}

HttpAnswer notSupported(const std::string& operation)
{
  return fault(false, { "ter:ActionNotSupported" }, "The operation " + operation + " is not supported");
}

std::string range(const char* name, double min, double max)
{
  return formatText("<sch:%s><sch:Min>%g</sch:Min><sch:Max>%g</sch:Max></sch:%s>", name, min, max, name);
}

std::string space(const char* kind, const char* uri, double min, double max)
{
  return std::string("<sch:") + kind + "><sch:URI>" + uri + "</sch:URI>" + range("XRange", min, max) + "</sch:" + kind +
         ">";
}

std::string space(const char* kind, const char* uri, double x_min, double x_max, double y_min, double y_max)
{
  return std::string("<sch:") + kind + "><sch:URI>" + uri + "</sch:URI>" + range("XRange", x_min, x_max) +
         range("YRange", y_min, y_max) + "</sch:" + kind + ">";
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

std::string videoSourceConfiguration()
{
  return std::string("<sch:VideoSourceConfiguration token=\"video_source_configuration_0\"><sch:Name>video</sch:Name>"
                     "<sch:UseCount>2</sch:UseCount><sch:SourceToken>") +
         VIDEO_SOURCE +
         "</sch:SourceToken><sch:Bounds x=\"0\" y=\"0\" width=\"1920\" "
         "height=\"1080\"/></sch:VideoSourceConfiguration>";
}

/// The pan-tilt part of a position vector read: x, y in \p space_uri ("" for none given).
struct PanTiltArgument
{
  bool given = false;
  double x = 0.0, y = 0.0;
  std::string space;
  bool numbers = true;
};

PanTiltArgument panTiltOf(const Element* vector)
{
  PanTiltArgument argument;
  const Element* pan_tilt = child(vector, ns::SCHEMA, "PanTilt");
  if (pan_tilt == nullptr)
  {
    return argument;
  }
  argument.given = true;
  argument.numbers = number(attribute(pan_tilt, "x"), argument.x) && number(attribute(pan_tilt, "y"), argument.y);
  const char* uri = attribute(pan_tilt, "space");
  argument.space = uri == nullptr ? "" : uri;
  return argument;
}

struct ZoomArgument
{
  bool given = false;
  double x = 0.0;
  std::string space;
  bool number = true;
};

ZoomArgument zoomOf(const Element* vector)
{
  ZoomArgument argument;
  const Element* zoom = child(vector, ns::SCHEMA, "Zoom");
  if (zoom == nullptr)
  {
    return argument;
  }
  argument.given = true;
  argument.number = number(attribute(zoom, "x"), argument.x);
  const char* uri = attribute(zoom, "space");
  argument.space = uri == nullptr ? "" : uri;
  return argument;
}
}  // namespace

const char* const OnvifCameraEmulatorConfig::MODES = "standard, generic-status, continuous-only, refuse-absolute-move, "
                                                     "no-position, no-presets, wrong-generic-range, no-relative, "
                                                     "generic-only";

SimDeviceConfig OnvifCameraEmulatorConfig::defaultDevice()
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  device.axes[ZOOM].range = { 1.0, 18.0 };
  device.axes[PAN].resolution = 0.0;
  device.axes[TILT].resolution = 0.0;
  return device;
}

bool OnvifCameraEmulatorConfig::applyMode(const std::string& mode)
{
  if (mode == "generic-status")
  {
    degree_space = true;
    degrees_default = false;
  }
  else if (mode == "continuous-only")
  {
    absolute = false;
  }
  else if (mode == "refuse-absolute-move")
  {
    refuse_absolute_move = true;
  }
  else if (mode == "no-position")
  {
    status_position = false;
  }
  else if (mode == "no-presets")
  {
    presets = false;
  }
  else if (mode == "wrong-generic-range")
  {
    degree_space = true;  // the camera of the field report: degrees listed, its status in the generic space
    degrees_default = false;
    listed_generic_pan_min = 0.0;
    listed_generic_pan_max = 1.0;
    device.axes[PAN].initial_position = -0.864666 * M_PI;
  }
  else if (mode == "no-relative")
  {
    relative = false;
  }
  else if (mode == "generic-only")
  {
    degree_space = false;
  }
  else if (mode != "standard")
  {
    return false;
  }
  return true;
}

OnvifCameraEmulator::OnvifCameraEmulator(const OnvifCameraEmulatorConfig& config, std::shared_ptr<const Clock> clock)
  : config_(config), clock_(std::move(clock)), model_(config.device, clock_->now())
{
  home_ = { { config.device.axes[PAN].initial_position, config.device.axes[TILT].initial_position,
              config.device.axes[ZOOM].initial_position } };
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
  {
    std::lock_guard<std::mutex> lock(mutex_);
    model_.setFaults(faults, clock_->now());
  }
  server_->setDelay(faults.reply_delay);  // a slow camera: every answer waits
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
  if (now < velocity_until_)
  {
    return;
  }
  for (Axis axis : ALL_AXES)
  {
    if (velocity_axes_[axis])
    {
      velocity_axes_[axis] = false;
      model_.moveAxisAtVelocity(axis, 0.0, velocity_until_);  // the ContinuousMove's Timeout ran out
    }
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

const char* OnvifCameraEmulator::defaultSpace() const
{
  // A continuous-only camera lists no position space, and reports its status in the generic one (as those do).
  return config_.absolute && config_.degree_space && config_.degrees_default ? DEGREE_SPACE : GENERIC_PAN_TILT_SPACE;
}

std::string OnvifCameraEmulator::supportedSpaces() const
{
  std::string spaces;
  if (config_.absolute)
  {
    spaces += (config_.degree_space ? space("AbsolutePanTiltPositionSpace", DEGREE_SPACE, -180, 180, -90, 90) : "") +
              space("AbsolutePanTiltPositionSpace", GENERIC_PAN_TILT_SPACE, config_.listed_generic_pan_min,
                    config_.listed_generic_pan_max, -1, 1) +
              space("AbsoluteZoomPositionSpace", GENERIC_ZOOM_SPACE, 0, 1);
    if (config_.relative)
    {
      spaces +=
          (config_.degree_space ? space("RelativePanTiltTranslationSpace", DEGREE_TRANSLATION, -360, 360, -180, 180) :
                                  "") +
          space("RelativePanTiltTranslationSpace", GENERIC_PAN_TILT_TRANSLATION, -1, 1, -1, 1) +
          space("RelativeZoomTranslationSpace", GENERIC_ZOOM_TRANSLATION, -1, 1);
    }
  }
  spaces += space("ContinuousPanTiltVelocitySpace", GENERIC_PAN_TILT_VELOCITY, -1, 1, -1, 1) +
            space("ContinuousZoomVelocitySpace", GENERIC_ZOOM_VELOCITY, -1, 1);
  if (config_.absolute)
  {
    spaces +=
        space("PanTiltSpeedSpace", GENERIC_PAN_TILT_SPEED, 0, 1) + space("ZoomSpeedSpace", GENERIC_ZOOM_SPEED, 0, 1);
  }
  return spaces;
}

std::string OnvifCameraEmulator::ptzConfiguration(const char* element) const
{
  std::string defaults;
  if (config_.absolute)
  {
    defaults += std::string("<sch:DefaultAbsolutePantTiltPositionSpace>") + defaultSpace() +
                "</sch:DefaultAbsolutePantTiltPositionSpace><sch:DefaultAbsoluteZoomPositionSpace>" +
                GENERIC_ZOOM_SPACE + "</sch:DefaultAbsoluteZoomPositionSpace>";
    if (config_.relative)
    {
      defaults += std::string("<sch:DefaultRelativePanTiltTranslationSpace>") + GENERIC_PAN_TILT_TRANSLATION +
                  "</sch:DefaultRelativePanTiltTranslationSpace><sch:DefaultRelativeZoomTranslationSpace>" +
                  GENERIC_ZOOM_TRANSLATION + "</sch:DefaultRelativeZoomTranslationSpace>";
    }
  }
  defaults += std::string("<sch:DefaultContinuousPanTiltVelocitySpace>") + GENERIC_PAN_TILT_VELOCITY +
              "</sch:DefaultContinuousPanTiltVelocitySpace><sch:DefaultContinuousZoomVelocitySpace>" +
              GENERIC_ZOOM_VELOCITY + "</sch:DefaultContinuousZoomVelocitySpace>";
  if (config_.absolute)
  {
    defaults += std::string("<sch:DefaultPTZSpeed><sch:PanTilt x=\"1\" y=\"1\" space=\"") + GENERIC_PAN_TILT_SPEED +
                "\"/><sch:Zoom x=\"1\" space=\"" + GENERIC_ZOOM_SPEED + "\"/></sch:DefaultPTZSpeed>";
  }
  return std::string("<") + element + " token=\"" + CONFIGURATION + "\"><sch:Name>ptz</sch:Name><sch:UseCount>1" +
         "</sch:UseCount><sch:NodeToken>" + NODE + "</sch:NodeToken>" + defaults +
         "<sch:DefaultPTZTimeout>PT5S</sch:DefaultPTZTimeout></" + element + ">";
}

std::string OnvifCameraEmulator::positionVector(const char* element, const AxisValues& position) const
{
  const bool degrees = std::string(defaultSpace()) == DEGREE_SPACE;
  const double x = degrees ? toDegrees(position[PAN]) : position[PAN] / M_PI;
  const double y = degrees ? toDegrees(position[TILT]) : position[TILT] / (M_PI / 2.0);
  const double z = std::log(position[ZOOM]) / std::log(config_.device.axes[ZOOM].range.max);
  return formatText("<sch:%s><sch:PanTilt x=\"%.6f\" y=\"%.6f\" space=\"%s\"/><sch:Zoom x=\"%.6f\" "
                    "space=\"%s\"/></sch:%s>",
                    element, x, y, defaultSpace(), z, GENERIC_ZOOM_SPACE, element);
}

void OnvifCameraEmulator::goToAll(const AxisValues& position, TimePoint now)
{
  velocity_axes_ = {};
  for (Axis axis : ALL_AXES)
  {
    model_.goToAxis(axis, position[axis], now);
  }
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
    return fault(true, { "ter:WellFormed" }, "the request is not a SOAP 1.2 envelope");
  }
  const std::string operation = localName(*message.content);
  const std::string service = namespaceOf(*message.content);
  const char* expected = target == DEVICE_PATH ? ns::DEVICE : target == MEDIA_PATH ? ns::MEDIA : ns::PTZ;
  if (service != expected)
  {
    return fault(false, { "ter:ActionNotSupported" }, operation + " is not an operation of " + target);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (operation != "GetSystemDateAndTime")
  {
    const Element* token = path(child(message.header, ns::WSSE, "Security"), ns::WSSE, { "UsernameToken" });
    if (token != nullptr)
    {
      server_->recordSecrets({ text(child(token, ns::WSSE, "Nonce")), text(child(token, ns::WSSE, "Password")) });
    }
    const std::string refused = checkToken(message);
    if (!refused.empty())
    {
      ++refused_tokens_;
      return fault(true, { "ter:NotAuthorized" }, "Sender not Authorized: " + refused);
    }
  }
  const TimePoint now = clock_->now();
  expireVelocity(now);
  if (target == DEVICE_PATH)
  {
    return device(operation, message);
  }
  return target == MEDIA_PATH ? media(operation, message) : ptz(operation, message, now);
}

HttpAnswer OnvifCameraEmulator::device(const std::string& operation, const SoapMessage& message)
{
  const std::string host = "http://" + config_.advertised_host;
  if (operation == "GetSystemDateAndTime")
  {
    const std::string iso = isoTime(cameraUtc());
    int year, month, day, hour, minute, second;
    std::sscanf(iso.c_str(), "%d-%d-%dT%d:%d:%d", &year, &month, &day, &hour, &minute, &second);
    return respond(ns::DEVICE, formatText("GetSystemDateAndTimeResponse><SystemDateAndTime><sch:DateTimeType>NTP"
                                          "</sch:DateTimeType><sch:DaylightSavings>false</sch:DaylightSavings>"
                                          "<sch:UTCDateTime><sch:Time><sch:Hour>%d</sch:Hour><sch:Minute>%d"
                                          "</sch:Minute><sch:Second>%d</sch:Second></sch:Time><sch:Date><sch:Year>%d"
                                          "</sch:Year><sch:Month>%d</sch:Month><sch:Day>%d</sch:Day></sch:Date>"
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
  if (operation == "GetServices")
  {
    const bool capabilities = text(child(message.content, ns::DEVICE, "IncludeCapability")) == "true";
    auto service = [&](const char* name, const char* service_path, const std::string& own) {
      return std::string("<Service><Namespace>") + name + "</Namespace><XAddr>" + host + service_path + "</XAddr>" +
             (capabilities ? "<Capabilities>" + own + "</Capabilities>" : "") +
             "<Version><sch:Major>2</sch:Major><sch:Minor>60</sch:Minor></Version></Service>";
    };
    return respond(ns::DEVICE, "GetServicesResponse>" +
                                   service(ns::DEVICE, DEVICE_PATH,
                                           "<Capabilities><Network/><Security UsernameToken=\"true\" HttpDigest=\"" +
                                               std::string(config_.http.auth == HttpAuth::DIGEST ? "true" : "false") +
                                               "\"/><System/></Capabilities>") +
                                   service(ns::MEDIA, MEDIA_PATH,
                                           std::string("<m:Capabilities xmlns:m=\"") + ns::MEDIA +
                                               "\" SnapshotUri=\"false\"><m:ProfileCapabilities "
                                               "MaximumNumberOfProfiles=\"2\"/>"
                                               "<m:StreamingCapabilities RTPMulticast=\"false\" RTP_TCP=\"false\" "
                                               "RTP_RTSP_TCP=\"false\"/>"
                                               "</m:Capabilities>") +
                                   service(ns::PTZ, PTZ_PATH,
                                           std::string("<p:Capabilities xmlns:p=\"") + ns::PTZ +
                                               "\" EFlip=\"false\" Reverse=\"false\" "
                                               "GetCompatibleConfigurations=\"false\" MoveStatus=\"true\" "
                                               "StatusPosition=\"" +
                                               (config_.status_position ? "true" : "false") + "\"/>") +
                                   "</GetServicesResponse>");
  }
  if (operation == "GetDeviceInformation")
  {
    return respond(ns::DEVICE, "GetDeviceInformationResponse><Manufacturer>ptz_action_server</Manufacturer><Model>"
                               "onvif_camera_emulator</Model><FirmwareVersion>1.0</FirmwareVersion><SerialNumber>0001"
                               "</SerialNumber><HardwareId>emulated</HardwareId></GetDeviceInformationResponse>");
  }
  return notSupported(operation);
}

HttpAnswer OnvifCameraEmulator::media(const std::string& operation, const SoapMessage& message)
{
  auto profileWithoutPtz = [](const char* element) {
    return std::string("<") + element + " token=\"" + PROFILE_WITHOUT_PTZ +
           "\" fixed=\"true\"><sch:Name>sub</sch:Name>" + videoSourceConfiguration() + "</" + element + ">";
  };
  auto profileWithPtz = [this](const char* element) {
    return std::string("<") + element + " token=\"" + PROFILE + "\" fixed=\"true\"><sch:Name>main</sch:Name>" +
           videoSourceConfiguration() + ptzConfiguration("sch:PTZConfiguration") + "</" + element + ">";
  };
  if (operation == "GetProfiles")
  {
    return respond(ns::MEDIA, "GetProfilesResponse>" + profileWithoutPtz("Profiles") + profileWithPtz("Profiles") +
                                  "</GetProfilesResponse>");
  }
  if (operation == "GetProfile")
  {
    const std::string token = text(child(message.content, ns::MEDIA, "ProfileToken"));
    if (token == PROFILE)
    {
      return respond(ns::MEDIA, "GetProfileResponse>" + profileWithPtz("Profile") + "</GetProfileResponse>");
    }
    if (token == PROFILE_WITHOUT_PTZ)
    {
      return respond(ns::MEDIA, "GetProfileResponse>" + profileWithoutPtz("Profile") + "</GetProfileResponse>");
    }
    return invalid("ter:NoProfile", "The requested profile token ProfileToken does not exist");
  }
  if (operation == "GetVideoSources")
  {
    return respond(ns::MEDIA, std::string("GetVideoSourcesResponse><VideoSources token=\"") + VIDEO_SOURCE +
                                  "\"><sch:Framerate>25</sch:Framerate><sch:Resolution><sch:Width>1920</sch:Width>"
                                  "<sch:Height>1080</sch:Height></sch:Resolution></VideoSources>"
                                  "</GetVideoSourcesResponse>");
  }
  return notSupported(operation);
}

HttpAnswer OnvifCameraEmulator::ptz(const std::string& operation, const SoapMessage& message, TimePoint now)
{
  const Element* request = message.content;
  if (operation == "GetServiceCapabilities")
  {
    return respond(ns::PTZ, std::string("GetServiceCapabilitiesResponse><Capabilities EFlip=\"false\" "
                                        "Reverse=\"false\" GetCompatibleConfigurations=\"false\" MoveStatus=\"true\" "
                                        "StatusPosition=\"") +
                                (config_.status_position ? "true" : "false") + "\"/></GetServiceCapabilitiesResponse>");
  }
  const std::string node =
      std::string("<PTZNode token=\"") + NODE +
      "\" FixedHomePosition=\"false\"><sch:Name>node</sch:Name><sch:SupportedPTZSpaces>" + supportedSpaces() +
      "</sch:SupportedPTZSpaces>" +
      formatText("<sch:MaximumNumberOfPresets>%d</sch:MaximumNumberOfPresets>", config_.max_presets) +
      "<sch:HomeSupported>" + (config_.home ? "true" : "false") + "</sch:HomeSupported></PTZNode>";
  if (operation == "GetNodes")
  {
    return respond(ns::PTZ, "GetNodesResponse>" + node + "</GetNodesResponse>");
  }
  if (operation == "GetNode")
  {
    if (text(child(request, ns::PTZ, "NodeToken")) != NODE)
    {
      return invalid("ter:NoEntity", "No such PTZ node on the device");
    }
    return respond(ns::PTZ, "GetNodeResponse>" + node + "</GetNodeResponse>");
  }
  if (operation == "GetConfigurations")
  {
    return respond(ns::PTZ, "GetConfigurationsResponse>" + ptzConfiguration("PTZConfiguration") +
                                "</GetConfigurationsResponse>");
  }
  if (operation == "GetConfiguration" || operation == "GetConfigurationOptions")
  {
    const bool options = operation == "GetConfigurationOptions";
    if (text(child(request, ns::PTZ, options ? "ConfigurationToken" : "PTZConfigurationToken")) != CONFIGURATION)
    {
      return invalid("ter:NoConfig", "The requested configuration does not exist");
    }
    if (!options)
    {
      return respond(ns::PTZ, "GetConfigurationResponse>" + ptzConfiguration("PTZConfiguration") +
                                  "</GetConfigurationResponse>");
    }
    return respond(ns::PTZ, "GetConfigurationOptionsResponse><PTZConfigurationOptions><sch:Spaces>" +
                                supportedSpaces() +
                                formatText("</sch:Spaces><sch:PTZTimeout><sch:Min>PT%gS</sch:Min><sch:Max>PT%gS"
                                           "</sch:Max></sch:PTZTimeout>",
                                           MIN_TIMEOUT, MAX_TIMEOUT) +
                                "</PTZConfigurationOptions></GetConfigurationOptionsResponse>");
  }
  // Everything below acts on a profile: it must exist and have PTZ.
  const std::string profile = text(child(request, ns::PTZ, "ProfileToken"));
  if (profile == PROFILE_WITHOUT_PTZ)
  {
    return invalid("ter:NoPTZProfile", "The requested profile token does not reference a PTZ configuration");
  }
  if (profile != PROFILE)
  {
    return invalid("ter:NoProfile", "The requested profile token ProfileToken does not exist");
  }
  const bool moves = operation == "AbsoluteMove" || operation == "ContinuousMove" || operation == "RelativeMove" ||
                     operation == "GotoPreset" || operation == "GotoHomePosition";
  if (moves && refuse_)
  {
    return fault(true, { "ter:InvalidArgVal" }, OnvifCameraEmulator::REFUSAL);
  }
  const SimDeviceConfig& device = config_.device;
  const double zoom_max = device.axes[ZOOM].range.max;
  if (operation == "GetStatus")
  {
    const PtzSample state = model_.sample(now);
    const bool pan_tilt_moves = std::abs(state.velocity[PAN]) > MOVING || std::abs(state.velocity[TILT]) > MOVING;
    const bool zoom_moves = std::abs(state.velocity[ZOOM]) > MOVING;
    return respond(ns::PTZ, "GetStatusResponse><PTZStatus>" +
                                (config_.status_position ? positionVector("Position", state.position) : std::string()) +
                                "<sch:MoveStatus><sch:PanTilt>" + (pan_tilt_moves ? "MOVING" : "IDLE") +
                                "</sch:PanTilt><sch:Zoom>" + (zoom_moves ? "MOVING" : "IDLE") +
                                "</sch:Zoom></sch:MoveStatus><sch:UtcTime>" + isoTime(cameraUtc()) +
                                "</sch:UtcTime></PTZStatus></GetStatusResponse>");
  }
  if (operation == "Stop")
  {
    const std::string pan_tilt = text(child(request, ns::PTZ, "PanTilt"));
    const std::string zoom = text(child(request, ns::PTZ, "Zoom"));
    const bool stop_pan_tilt = pan_tilt != "false" && pan_tilt != "0";  // both default to true
    const bool stop_zoom = zoom != "false" && zoom != "0";
    if (stop_pan_tilt && stop_zoom)
    {
      velocity_axes_ = {};
      model_.stop(now);
    }
    for (Axis axis : { PAN, TILT, ZOOM })
    {
      if ((axis == ZOOM ? stop_zoom : stop_pan_tilt) && !(stop_pan_tilt && stop_zoom))
      {
        velocity_axes_[axis] = false;
        model_.moveAxisAtVelocity(axis, 0.0, now);
      }
    }
    return respond(ns::PTZ, "StopResponse></StopResponse>");
  }
  if (operation == "ContinuousMove")
  {
    const Element* velocity = child(request, ns::PTZ, "Velocity");
    const PanTiltArgument pan_tilt = panTiltOf(velocity);
    const ZoomArgument zoom = zoomOf(velocity);
    double timeout = 5.0;  // DefaultPTZTimeout
    const Element* timeout_element = child(request, ns::PTZ, "Timeout");
    if ((pan_tilt.given && !pan_tilt.space.empty() && pan_tilt.space != GENERIC_PAN_TILT_VELOCITY) ||
        (zoom.given && !zoom.space.empty() && zoom.space != GENERIC_ZOOM_VELOCITY))
    {
      return invalid("ter:SpaceNotSupported", "A space is referenced which is not supported by the PTZ node");
    }
    if (!pan_tilt.numbers || !zoom.number || std::abs(pan_tilt.x) > 1 || std::abs(pan_tilt.y) > 1 ||
        std::abs(zoom.x) > 1)
    {
      return invalid("ter:InvalidVelocity", "The requested speed is out of bounds");
    }
    if (timeout_element != nullptr &&
        (!parseDuration(text(timeout_element), timeout) || timeout < MIN_TIMEOUT || timeout > MAX_TIMEOUT))
    {
      return invalid("ter:TimeoutNotSupported", "The specified timeout argument is not within the supported timeout "
                                                "range");
    }
    // An axis left out goes on as it was; one at 0 stops.
    if (pan_tilt.given)
    {
      model_.moveAxisAtVelocity(PAN, pan_tilt.x * device.axes[PAN].motion.max_speed, now);
      model_.moveAxisAtVelocity(TILT, pan_tilt.y * device.axes[TILT].motion.max_speed, now);
      velocity_axes_[PAN] = velocity_axes_[TILT] = true;
    }
    if (zoom.given)
    {
      model_.moveAxisAtVelocity(ZOOM, zoom.x * device.axes[ZOOM].motion.max_speed, now);
      velocity_axes_[ZOOM] = true;
    }
    velocity_until_ = addSeconds(now, timeout);
    return respond(ns::PTZ, "ContinuousMoveResponse></ContinuousMoveResponse>");
  }
  if (!config_.absolute)
  {
    return notSupported(operation);  // the continuous-only cameras: no positions, so no presets or home either
  }
  if (operation == "AbsoluteMove" || operation == "RelativeMove")
  {
    const bool absolute = operation == "AbsoluteMove";
    if ((absolute && config_.refuse_absolute_move) || (!absolute && !config_.relative))
    {
      return notSupported(operation);
    }
    const Element* argument = child(request, ns::PTZ, absolute ? "Position" : "Translation");
    PanTiltArgument pan_tilt = panTiltOf(argument);
    ZoomArgument zoom = zoomOf(argument);
    if (pan_tilt.space.empty())
    {
      pan_tilt.space = absolute ? defaultSpace() : GENERIC_PAN_TILT_TRANSLATION;
    }
    if (zoom.space.empty())
    {
      zoom.space = absolute ? GENERIC_ZOOM_SPACE : GENERIC_ZOOM_TRANSLATION;
    }
    const bool degrees = pan_tilt.space == (absolute ? DEGREE_SPACE : DEGREE_TRANSLATION);
    const bool generic = pan_tilt.space == (absolute ? GENERIC_PAN_TILT_SPACE : GENERIC_PAN_TILT_TRANSLATION);
    if ((pan_tilt.given && !(generic || (degrees && config_.degree_space))) ||
        (zoom.given && zoom.space != (absolute ? GENERIC_ZOOM_SPACE : GENERIC_ZOOM_TRANSLATION)))
    {
      return invalid("ter:SpaceNotSupported", "A space is referenced that is not supported by the PTZ node");
    }
    // The camera's own ranges, whatever GetNodes lists (generic: the whole travel; degrees: its mechanics).
    const double limit_x = degrees ? (absolute ? 180.0 : 360.0) : (absolute ? 1.0 : 2.0);
    const double limit_y = degrees ? (absolute ? 90.0 : 180.0) : (absolute ? 1.0 : 2.0);
    const bool zoom_in_range = absolute ? zoom.x >= 0.0 && zoom.x <= 1.0 : std::abs(zoom.x) <= 1.0;
    if (!pan_tilt.numbers || !zoom.number || std::abs(pan_tilt.x) > limit_x || std::abs(pan_tilt.y) > limit_y ||
        !zoom_in_range)
    {
      return absolute ? invalid("ter:InvalidPosition", "The requested position is out of bounds") :
                        invalid("ter:InvalidTranslation", "The requested translation is out of bounds");
    }
    const AxisValues at = model_.sample(now).position;
    for (Axis axis : ALL_AXES)
    {
      velocity_axes_[axis] = velocity_axes_[axis] && !(axis == ZOOM ? zoom.given : pan_tilt.given);
    }
    if (pan_tilt.given)
    {
      const double pan = degrees ? toRadians(pan_tilt.x) : pan_tilt.x * M_PI;
      const double tilt = degrees ? toRadians(pan_tilt.y) : pan_tilt.y * M_PI / 2.0;
      // A translation beyond the travel stops at its border (the model clamps).
      model_.goToAxis(PAN, absolute ? pan : at[PAN] + pan, now);
      model_.goToAxis(TILT, absolute ? tilt : at[TILT] + tilt, now);
    }
    if (zoom.given)
    {
      const double z = absolute ? zoom.x : std::log(at[ZOOM]) / std::log(zoom_max) + zoom.x;
      model_.goToAxis(ZOOM, std::pow(zoom_max, std::clamp(z, 0.0, 1.0)), now);
    }
    return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
  }
  if (operation == "GotoHomePosition" || operation == "SetHomePosition")
  {
    if (!config_.home)
    {
      return notSupported(operation);
    }
    if (operation == "SetHomePosition")
    {
      home_ = model_.sample(now).position;
    }
    else
    {
      goToAll(home_, now);
    }
    return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
  }
  const bool preset_operation =
      operation == "GetPresets" || operation == "SetPreset" || operation == "GotoPreset" || operation == "RemovePreset";
  if (!preset_operation || !config_.presets || config_.max_presets <= 0)
  {
    return notSupported(operation);
  }
  if (operation == "GetPresets")
  {
    std::string listed;
    for (const auto& preset : presets_)
    {
      listed += formatText("<Preset token=\"%d\"><sch:Name>", preset.first) + escaped(preset.second.name) +
                "</sch:Name>" + positionVector("PTZPosition", preset.second.position) + "</Preset>";
    }
    return respond(ns::PTZ, "GetPresetsResponse>" + listed + "</GetPresetsResponse>");
  }
  const std::string token_text = text(child(request, ns::PTZ, "PresetToken"));
  char* end = nullptr;
  const long token = std::strtol(token_text.c_str(), &end, 10);
  const auto found = !token_text.empty() && *end == '\0' ? presets_.find(static_cast<int>(token)) : presets_.end();
  if (operation == "SetPreset")
  {
    if (!token_text.empty() && found == presets_.end())
    {
      return invalid("ter:NoToken", "The requested preset token does not exist");
    }
    const Element* name_element = child(request, ns::PTZ, "PresetName");
    std::string name = text(name_element);
    for (const auto& preset : presets_)
    {
      if (name_element != nullptr && preset.second.name == name &&
          (found == presets_.end() || found->first != preset.first))
      {
        return invalid("ter:PresetExist", "The requested name already exist for another preset");
      }
    }
    const PtzSample state = model_.sample(now);
    if (state.moving)
    {
      return fault(false, { "ter:Action", "ter:MovingPTZ" }, "Preset cannot be set while PTZ unit is moving");
    }
    if (found == presets_.end() && static_cast<int>(presets_.size()) >= config_.max_presets)
    {
      return fault(false, { "ter:Action", "ter:TooManyPresets" }, "Maximum number of Presets reached");
    }
    const int stored = found != presets_.end() ? found->first : next_preset_++;
    Preset& preset = presets_[stored];
    if (name_element != nullptr || preset.name.empty())
    {
      preset.name = name_element != nullptr ? name : formatText("Preset %d", stored);
    }
    preset.position = state.position;
    return respond(ns::PTZ, formatText("SetPresetResponse><PresetToken>%d</PresetToken></SetPresetResponse>", stored));
  }
  if (found == presets_.end())
  {
    return invalid("ter:NoToken", "The requested preset token does not exist");
  }
  if (operation == "GotoPreset")
  {
    goToAll(found->second.position, now);
  }
  else
  {
    presets_.erase(found);
  }
  return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
}

}  // namespace ptz_action_server

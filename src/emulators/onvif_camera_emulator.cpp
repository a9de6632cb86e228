#include "ptz_action_server/emulators/onvif_camera_emulator.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "onvif_camera_emulator_internal.h"
#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace onvif_emulator
{
using namespace onvif;

HttpAnswer respond(const char* service, const std::string& content)
{
  return HttpAnswer{ 200, CONTENT_TYPE,
                     std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<env:Envelope xmlns:env=\"") + ns::SOAP +
                         "\" xmlns:sch=\"" + ns::SCHEMA + "\"><env:Body><" + content.substr(0, content.find('>')) +
                         " xmlns=\"" + service + "\"" + content.substr(content.find('>')) +
                         "</env:Body></env:Envelope>" };
}

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

HttpAnswer invalid(const char* what, const std::string& reason)
{
  return fault(true, { "ter:InvalidArgVal", what }, reason);
}

HttpAnswer notSupported(const std::string& operation)
{
  return fault(false, { "ter:ActionNotSupported" }, "The operation " + operation + " is not supported");
}

namespace
{
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

/// A media configuration of the profiles, as clients expect each profile to have one (the npm onvif client takes a
/// profile with a video source and a video encoder configuration as a video source's default profile).
std::string videoConfigurations(const char* encoder_token, int width, int height)
{
  return std::string("<sch:VideoSourceConfiguration token=\"video_source_configuration_0\"><sch:Name>video</sch:Name>"
                     "<sch:UseCount>2</sch:UseCount><sch:SourceToken>") +
         VIDEO_SOURCE +
         "</sch:SourceToken><sch:Bounds x=\"0\" y=\"0\" width=\"1920\" "
         "height=\"1080\"/></sch:VideoSourceConfiguration>" +
         "<sch:VideoEncoderConfiguration token=\"" + encoder_token + "\"><sch:Name>" + encoder_token +
         "</sch:Name><sch:UseCount>1</sch:UseCount><sch:Encoding>H264</sch:Encoding>" +
         formatText("<sch:Resolution><sch:Width>%d</sch:Width><sch:Height>%d</sch:Height></sch:Resolution>", width,
                    height) +
         "<sch:Quality>5</sch:Quality><sch:RateControl><sch:FrameRateLimit>25</"
         "sch:FrameRateLimit><sch:EncodingInterval>"
         "1</sch:EncodingInterval><sch:BitrateLimit>4096</sch:BitrateLimit></sch:RateControl><sch:SessionTimeout>PT60S"
         "</sch:SessionTimeout></sch:VideoEncoderConfiguration>";
}
}  // namespace

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
}  // namespace onvif_emulator

using namespace onvif;
using namespace onvif_emulator;

namespace
{
/// The motion model of \p config: its zoom ends where its lens really does (honoured_zoom of the listed range).
SimDeviceConfig modelOf(const OnvifCameraEmulatorConfig& config)
{
  SimDeviceConfig device = config.device;
  AxisRange& zoom = device.axes[ZOOM].range;
  zoom.max = std::pow(zoom.max, std::clamp(config.honoured_zoom, 0.0, 1.0));
  return device;
}
}  // namespace

OnvifCameraEmulator::OnvifCameraEmulator(const OnvifCameraEmulatorConfig& config, std::shared_ptr<const Clock> clock)
  : HttpCameraEmulator(modelOf(config), std::move(clock))
  , config_(config)
  , lens_(FieldOfViewModel::fromWideEnd(config.field_of_view))
{
  approach_.fill(std::numeric_limits<double>::quiet_NaN());
  commanded_speed_ = { { config.device.axes[PAN].motion.max_speed, config.device.axes[TILT].motion.max_speed,
                         config.device.axes[ZOOM].motion.max_speed } };
  focus_iris_ = SimLensModel(config.lens, clock_->now());
  home_ = { { config.device.axes[PAN].initial_position, config.device.axes[TILT].initial_position,
              config.device.axes[ZOOM].initial_position } };
  server_ = std::make_unique<HttpCameraServer>(
      config_.http,
      [this](const std::string&, const std::string& target, const std::string& body) { return handle(target, body); });
}

OnvifCameraEmulator::~OnvifCameraEmulator() = default;

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

std::string OnvifCameraEmulator::serviceAddress() const
{
  if (config_.advertised_host.empty())
  {
    return server_->url();  // where it listens: a client that follows XAddrs reaches it, and stays on this machine
  }
  return std::string(config_.http.tls ? "https://" : "http://") + config_.advertised_host + ":" +
         std::to_string(server_->port());
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
  const bool imaging_target = config_.imaging && target == IMAGING_PATH;
  if (target != DEVICE_PATH && target != MEDIA_PATH && target != PTZ_PATH && !imaging_target)
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
  const char* expected = target == DEVICE_PATH ? ns::DEVICE :
                         target == MEDIA_PATH  ? ns::MEDIA :
                         imaging_target        ? ns::IMAGING :
                                                 ns::PTZ;
  if (service != expected)
  {
    return fault(false, { "ter:ActionNotSupported" }, operation + " is not an operation of " + target);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const Element* token = path(child(message.header, ns::WSSE, "Security"), ns::WSSE, { "UsernameToken" });
  if (token != nullptr)
  {
    server_->recordSecrets({ text(child(token, ns::WSSE, "Nonce")), text(child(token, ns::WSSE, "Password")) });
  }
  if (operation != "GetSystemDateAndTime" || !config_.open_clock)
  {
    const std::string refused = checkToken(message);
    if (!refused.empty() && operation == "GetSystemDateAndTime")
    {
      // Axis: its web server asks for the credentials of a request that brings no valid UsernameToken, even this one.
      ++refused_tokens_;
      HttpAnswer unauthorized{ 401, "text/html", "<HTML><HEAD><TITLE>401 Unauthorized</TITLE></HEAD></HTML>\r\n" };
      unauthorized.challenge = "Digest realm=\"" + config_.http.realm + "\", nonce=\"" + base64Encode(randomBytes(16)) +
                               "\", algorithm=MD5, qop=\"auth\"";
      return unauthorized;
    }
    if (!refused.empty())
    {
      ++refused_tokens_;
      return fault(true, { "ter:NotAuthorized" }, "Sender not Authorized: " + refused);
    }
  }
  const TimePoint now = clock_->now();
  advance(now);
  if (target == DEVICE_PATH)
  {
    return device(operation, message);
  }
  if (imaging_target)
  {
    return imaging(operation, message.content, now);
  }
  return target == MEDIA_PATH ? media(operation, message) : ptz(operation, message, now);
}

HttpAnswer OnvifCameraEmulator::device(const std::string& operation, const SoapMessage& message)
{
  const std::string host = serviceAddress();
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
    return respond(ns::DEVICE,
                   "GetCapabilitiesResponse><Capabilities><sch:Device><sch:XAddr>" + host + DEVICE_PATH +
                       "</sch:XAddr></sch:Device>" +
                       (config_.imaging ?
                            "<sch:Imaging><sch:XAddr>" + host + IMAGING_PATH + "</sch:XAddr></sch:Imaging>" :
                            std::string()) +
                       "<sch:Media><sch:XAddr>" + host + MEDIA_PATH + "</sch:XAddr></sch:Media><sch:PTZ><sch:XAddr>" +
                       host + PTZ_PATH + "</sch:XAddr></sch:PTZ></Capabilities></GetCapabilitiesResponse>");
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
                                   (config_.imaging ? service(ns::IMAGING, IMAGING_PATH,
                                                              std::string("<i:Capabilities xmlns:i=\"") + ns::IMAGING +
                                                                  "\" ImageStabilization=\"false\"/>") :
                                                      std::string()) +
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
           "\" fixed=\"true\"><sch:Name>sub</sch:Name>" + videoConfigurations("video_encoder_1", 640, 360) + "</" +
           element + ">";
  };
  auto profileWithPtz = [this](const char* element) {
    return std::string("<") + element + " token=\"" + PROFILE + "\" fixed=\"true\"><sch:Name>main</sch:Name>" +
           videoConfigurations("video_encoder_0", 1920, 1080) + ptzConfiguration("sch:PTZConfiguration") + "</" +
           element + ">";
  };
  if (operation == "GetProfiles")
  {
    // Clients that take the first profile (node-onvif) find the one with PTZ first.
    const std::string with = profileWithPtz("Profiles");
    const std::string without = profileWithoutPtz("Profiles");
    return respond(ns::MEDIA, "GetProfilesResponse>" + (config_.ptz_profile_first ? with + without : without + with) +
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

}  // namespace ptz_action_server

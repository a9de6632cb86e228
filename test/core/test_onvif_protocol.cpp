/**
 * \file
 * \brief What only the ONVIF backend does, against onvif_camera_emulator's camera on 127.0.0.1: the bring-up (clock
 * offset, configured host kept, profile, node), ContinuousMove re-sent before its timeout, and the start-up failures
 * named (a wrong password, a missing profile). Then the cameras of the field
 * (OnvifFieldCameras): a scripted camera that plays golden replies written from the specification and the field
 * reports (degrees listed but the status generic, the wrong generic range, faults and malformed statuses at start-up,
 * spaces left out). The emulator's field modes are test_onvif_field_modes.cpp's, the cheap cameras' modes
 * test_onvif_cheap_cameras.cpp's.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <map>
#include <mutex>

#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"
#include "ptz_action_server/core/text.h"
#include "onvif_backend_test_support.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif_backend_test;

TEST(OnvifBackend, BringsUpInTheCamerasClockAndKeepsTheConfiguredHost)
{
  OnvifCameraEmulatorConfig camera_config;
  camera_config.clock_offset = 3600.0;  // tokens stamped in our clock would be an hour off and refused
  OnvifCameraEmulator camera(camera_config);
  auto backend = makeDeviceBackend<OnvifProtocol>(configFor(camera));
  backend->start();
  EXPECT_EQ(camera.refusedTokens(), 0u);
  const Capabilities capabilities = backend->capabilities();
  EXPECT_NEAR(capabilities.axes[PAN].range.max, M_PI, 1e-9);  // from the degree space's XRange
  EXPECT_NEAR(capabilities.axes[TILT].range.min, -M_PI / 2.0, 1e-9);
  EXPECT_TRUE(capabilities.axes[ZOOM].present);
  EXPECT_NEAR(capabilities.axes[ZOOM].range.max, 18.0, 1e-9);
  for (const char* operation :
       { "GetSystemDateAndTime", "GetCapabilities", "GetProfiles", "GetNodes", "GetConfigurationOptions", "GetStatus" })
  {
    EXPECT_GE(countOf(camera.server(), operation), 1u) << operation;
  }
  // The camera advertised 192.0.2.1; every request still reached it at the configured 127.0.0.1.
  backend->goTo({ 0.4, -0.1, 3.0 });
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[PAN] - 0.4) < 1e-3 && !backend->sample().moving; }, WAIT));
  EXPECT_NEAR(camera.sample().position[ZOOM], 3.0, 1e-3);
  EXPECT_NEAR(backend->sample().position[ZOOM], 3.0, 1e-3);
  EXPECT_EQ(camera.server().counters().connections, 1u);
}

TEST(OnvifBackend, AContinuousMoveIsResentBeforeItsTimeout)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  DeviceConfig<OnvifProtocol> config = configFor(camera);
  config.settings.velocity_timeout = 1;
  auto backend = makeDeviceBackend<OnvifProtocol>(config);
  backend->start();
  backend->moveAtVelocity({ 0.3, 0.0, 0.0 });
  const auto& protocol = backend->protocol<OnvifProtocol>();
  // Three refreshes take 1.5 s: without them the camera would have stopped after its 1 s timeout.
  ASSERT_TRUE(waitUntil([&] { return protocol.counters().velocity_refreshes >= 3; }, WAIT));
  EXPECT_NEAR(camera.sample().velocity[PAN], 0.3, 0.02);
  EXPECT_NE(countOf(camera.server(), "<tptz:Timeout>PT1S</tptz:Timeout>"), 0u);
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !camera.sample().moving; }, WAIT));
  EXPECT_EQ(countOf(camera.server(), "<tptz:Stop>"), 1u);
}

TEST(OnvifBackendStartup, AWrongPasswordIsTheCamerasFaultWithoutThePassword)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  const std::string error = startupError(configFor(camera, "hunter2"));
  EXPECT_EQ(error, "an ONVIF camera on http://127.0.0.1:" + std::to_string(camera.port()) +
                       ": the ONVIF camera refused GetCapabilities: ter:NotAuthorized: Sender not Authorized: a wrong "
                       "username or password");
  EXPECT_EQ(error.find("hunter2"), std::string::npos);
}

TEST(OnvifBackendStartup, AMissingProfileIsNamed)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  DeviceConfig<OnvifProtocol> config = configFor(camera);
  config.settings.profile = "nope";
  EXPECT_EQ(startupError(config), "an ONVIF camera on http://127.0.0.1:" + std::to_string(camera.port()) +
                                      ": GetProfiles answered no profile 'nope' with a PTZConfiguration (profiles: "
                                      "profile_1, profile_0)");
}

TEST(OnvifBackendStartup, ACameraThatDemandsHttpDigestTooIsServed)
{
  OnvifCameraEmulatorConfig camera_config;
  camera_config.http.auth = HttpAuth::DIGEST;
  camera_config.http.username = "admin";
  camera_config.http.password = "admin";
  OnvifCameraEmulator camera(camera_config);
  auto backend = makeDeviceBackend<OnvifProtocol>(configFor(camera));
  backend->start();
  EXPECT_TRUE(backend->sample().link_up);
  // The first POST goes without HTTP authentication (a camera may want none) and meets the one challenge; its
  // nonce serves the rest of the bring-up and every poll.
  EXPECT_EQ(camera.server().counters().challenges, 1u);
  EXPECT_EQ(camera.server().counters().refused_credentials, 0u);
}

// ---------------------------------------------------------------- the cameras of the field

/**
 * \brief A camera that answers each operation with a fixed reply, without authentication: golden replies written from
 * the ONVIF WSDLs and the field reports, played back. GetSystemDateAndTime answers the time of the request.
 */
class ScriptedCamera
{
public:
  ScriptedCamera()
  {
    HttpCameraServerConfig http;
    http.auth = HttpAuth::NONE;
    server_ = std::make_unique<HttpCameraServer>(
        http, [this](const std::string&, const std::string&, const std::string& body) { return answer(body); });
  }
  /// \p operation answers \p response (the element in s:Body: a response, or an s:Fault).
  void set(const std::string& operation, const std::string& response, unsigned status = 200)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    replies_[operation] = std::make_pair(status, response);
  }
  std::uint16_t port() const
  {
    return server_->port();
  }
  HttpCameraServer& server()
  {
    return *server_;
  }

private:
  HttpAnswer answer(const std::string& body)
  {
    onvif::SoapMessage message;
    const std::string operation = onvif::parseSoap(body, message).empty() ? onvif::localName(*message.content) : "";
    std::pair<unsigned, std::string> reply{ 500, FAULT_NOT_SUPPORTED };
    if (operation == "GetSystemDateAndTime")
    {
      const std::time_t now = std::time(nullptr);
      std::tm utc{};
      gmtime_r(&now, &utc);
      reply = { 200, formatText("<tds:GetSystemDateAndTimeResponse><tds:SystemDateAndTime><tt:UTCDateTime><tt:Time>"
                                "<tt:Hour>%d</tt:Hour><tt:Minute>%d</tt:Minute><tt:Second>%d</tt:Second></tt:Time>"
                                "<tt:Date><tt:Year>%d</tt:Year><tt:Month>%d</tt:Month><tt:Day>%d</tt:Day></tt:Date>"
                                "</tt:UTCDateTime></tds:SystemDateAndTime></tds:GetSystemDateAndTimeResponse>",
                                utc.tm_hour, utc.tm_min, utc.tm_sec, utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday) };
    }
    else
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto found = replies_.find(operation);
      if (found != replies_.end())
      {
        reply = found->second;
      }
    }
    return HttpAnswer{ reply.first, onvif::SOAP_CONTENT_TYPE,
                       "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<env:Envelope "
                       "xmlns:env=\"http://www.w3.org/2003/05/soap-envelope\" "
                       "xmlns:ter=\"http://www.onvif.org/ver10/error\" "
                       "xmlns:tds=\"http://www.onvif.org/ver10/device/wsdl\" "
                       "xmlns:trt=\"http://www.onvif.org/ver10/media/wsdl\" "
                       "xmlns:tptz=\"http://www.onvif.org/ver20/ptz/wsdl\" "
                       "xmlns:tt=\"http://www.onvif.org/ver10/schema\">"
                       "<env:Body>" +
                           reply.second + "</env:Body></env:Envelope>" };
  }

  static constexpr const char* FAULT_NOT_SUPPORTED = "<env:Fault><env:Code><env:Value>env:Receiver</"
                                                     "env:Value><env:Subcode><env:Value>ter:ActionNotSupported"
                                                     "</env:Value></env:Subcode></env:Code><env:Reason><env:Text "
                                                     "xml:lang=\"en\">Optional Action Not Implemented"
                                                     "</env:Text></env:Reason></env:Fault>";

  std::mutex mutex_;
  std::map<std::string, std::pair<unsigned, std::string>> replies_;
  std::unique_ptr<HttpCameraServer> server_;
};

/// The profile of the field's camera: its PTZ configuration's default space is \p default_space ("" = none declared).
std::string profilesWithDefault(const std::string& default_space)
{
  return "<trt:GetProfilesResponse><trt:Profiles token=\"Profile_1\" fixed=\"true\"><tt:Name>mainStream</tt:Name>"
         "<tt:PTZConfiguration token=\"PTZConfiguration_1\"><tt:Name>ptz</tt:Name><tt:UseCount>2</tt:UseCount>"
         "<tt:NodeToken>PTZNODETOKEN</tt:NodeToken>" +
         (default_space.empty() ? std::string() :
                                  "<tt:DefaultAbsolutePantTiltPositionSpace>" + default_space +
                                      "</tt:DefaultAbsolutePantTiltPositionSpace>") +
         "<tt:DefaultPTZTimeout>PT5S</tt:DefaultPTZTimeout></tt:PTZConfiguration></trt:Profiles>"
         "</trt:GetProfilesResponse>";
}

/// A GetStatus reply with \p position inside tt:Position ("" = none).
std::string statusReply(const std::string& position)
{
  return "<tptz:GetStatusResponse><tptz:PTZStatus>" +
         (position.empty() ? "" : "<tt:Position>" + position + "</tt:Position>") +
         "<tt:MoveStatus><tt:PanTilt>IDLE</tt:PanTilt><tt:Zoom>IDLE</tt:Zoom></tt:MoveStatus><tt:UtcTime>"
         "2026-11-21T10:20:30Z</tt:UtcTime></tptz:PTZStatus></tptz:GetStatusResponse>";
}

/**
 * \brief The camera of the issue, as the field reports it: GetNodes lists SphericalPositionSpaceDegrees and the generic
 * space, the generic pan range as 0..1; its configuration's default space is the generic one, and GetStatus reports
 * pan -0.864666 there; GetPresets answers ter:ActionNotSupported though the node lists presets.
 */
void playTheFieldCamera(ScriptedCamera& camera)
{
  camera.set("GetCapabilities", "<tds:GetCapabilitiesResponse><tds:Capabilities><tt:Media><tt:XAddr>"
                                "http://192.168.1.64/onvif/Media</tt:XAddr></tt:Media><tt:PTZ><tt:XAddr>"
                                "http://192.168.1.64/onvif/PTZ</tt:XAddr></tt:PTZ></tds:Capabilities>"
                                "</tds:GetCapabilitiesResponse>");
  camera.set("GetProfiles", profilesWithDefault(onvif::GENERIC_PAN_TILT_SPACE));
  camera.set("GetNodes", "<tptz:GetNodesResponse><tptz:PTZNode token=\"PTZNODETOKEN\"><tt:Name>PTZNODE</tt:Name>"
                         "<tt:SupportedPTZSpaces><tt:AbsolutePanTiltPositionSpace><tt:URI>http://www.onvif.org/ver10/"
                         "tptz/"
                         "PanTiltSpaces/PositionGenericSpace</tt:URI><tt:XRange><tt:Min>0</tt:Min><tt:Max>1</tt:Max></"
                         "tt:XRange>"
                         "<tt:YRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:YRange></"
                         "tt:AbsolutePanTiltPositionSpace>"
                         "<tt:AbsolutePanTiltPositionSpace><tt:URI>http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                         "SphericalPositionSpaceDegrees</tt:URI><tt:XRange><tt:Min>-180</tt:Min><tt:Max>180</tt:Max></"
                         "tt:XRange>"
                         "<tt:YRange><tt:Min>-90</tt:Min><tt:Max>90</tt:Max></tt:YRange></"
                         "tt:AbsolutePanTiltPositionSpace>"
                         "<tt:AbsoluteZoomPositionSpace><tt:URI>http://www.onvif.org/ver10/tptz/ZoomSpaces/"
                         "PositionGenericSpace"
                         "</tt:URI><tt:XRange><tt:Min>0</tt:Min><tt:Max>1</tt:Max></tt:XRange></"
                         "tt:AbsoluteZoomPositionSpace>"
                         "<tt:ContinuousPanTiltVelocitySpace><tt:URI>http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                         "VelocityGenericSpace</tt:URI><tt:XRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></"
                         "tt:XRange><tt:YRange>"
                         "<tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:YRange></tt:ContinuousPanTiltVelocitySpace>"
                         "<tt:ContinuousZoomVelocitySpace><tt:URI>http://www.onvif.org/ver10/tptz/ZoomSpaces/"
                         "VelocityGenericSpace"
                         "</tt:URI><tt:XRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:XRange></"
                         "tt:ContinuousZoomVelocitySpace>"
                         "</tt:SupportedPTZSpaces><tt:MaximumNumberOfPresets>300</"
                         "tt:MaximumNumberOfPresets><tt:HomeSupported>"
                         "true</tt:HomeSupported></tptz:PTZNode></tptz:GetNodesResponse>");
  camera.set("GetConfigurationOptions", "<tptz:GetConfigurationOptionsResponse><tptz:PTZConfigurationOptions>"
                                        "<tt:PTZTimeout><tt:Min>PT1S</tt:Min><tt:Max>PT60S</tt:Max></tt:PTZTimeout>"
                                        "</tptz:PTZConfigurationOptions></tptz:GetConfigurationOptionsResponse>");
  camera.set("GetStatus", statusReply("<tt:PanTilt x=\"-0.864666\" y=\"0.1\" space=\"http://www.onvif.org/ver10/tptz/"
                                      "PanTiltSpaces/PositionGenericSpace\"/><tt:Zoom x=\"0.2\" "
                                      "space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/PositionGenericSpace\"/>"));
  camera.set("AbsoluteMove", "<tptz:AbsoluteMoveResponse/>");
}

DeviceConfig<OnvifProtocol> configForScripted(const ScriptedCamera& camera)
{
  DeviceConfig<OnvifProtocol> config;
  config.link.port = camera.port();
  config.session.startup_timeout = 5.0;
  config.session.state_timeout = 1.0;
  return config;  // no credentials: the scripted camera asks none
}

TEST(OnvifFieldCameras, ACameraThatListsDegreesButReportsGenericStartsAndTrustsItsStatusOverItsRange)
{
  ScriptedCamera camera;
  playTheFieldCamera(camera);
  DeviceConfig<OnvifProtocol> config = configForScripted(camera);
  ASSERT_TRUE(config.settings.prefer_degrees);  // the default, with which this camera never started
  std::vector<std::string> told;
  auto backend = makeDeviceBackend<OnvifProtocol>(config);
  backend->start();
  const auto& protocol = backend->protocol<OnvifProtocol>();
  // The status is read in the space it names and converted.
  const PtzSample sample = backend->sample();
  EXPECT_TRUE(sample.link_up);
  EXPECT_NEAR(sample.position[PAN], -0.864666 * M_PI, 1e-9);
  EXPECT_NEAR(sample.position[TILT], 0.1 * M_PI / 2.0, 1e-9);
  EXPECT_NEAR(sample.position[ZOOM], std::pow(18.0, 0.2), 1e-9);
  // The listed generic pan range [0, 1] leaves out where the camera is: the status wins, told once.
  const Capabilities capabilities = backend->capabilities();
  EXPECT_TRUE(capabilities.axes[PAN].absolute && capabilities.axes[PAN].feedback && capabilities.axes[PAN].velocity);
  EXPECT_NEAR(capabilities.axes[PAN].range.min, -M_PI, 1e-9);
  EXPECT_NEAR(capabilities.axes[PAN].range.max, M_PI, 1e-9);
  EXPECT_TRUE(capabilities.axes[ZOOM].present && capabilities.axes[ZOOM].feedback);
  EXPECT_FALSE(capabilities.device_presets);  // GetPresets: ter:ActionNotSupported, and it started all the same
  EXPECT_TRUE(capabilities.device_home);
  const std::uint64_t statuses = protocol.counters().statuses;
  ASSERT_TRUE(waitUntil([&] { return protocol.counters().statuses >= statuses + 5; }, WAIT));
  {
    told = backend->takeWarnings();  // as the node takes them: it logs each and lists them in its diagnostics
    EXPECT_TRUE(backend->takeWarnings().empty());
    ASSERT_EQ(told.size(), 1u);
    EXPECT_EQ(told[0], "the camera's GetNodes lists the PositionGenericSpace pan range [0, 1], but its GetStatus "
                       "answered x = -0.864666: the listed range is wrong; the backend trusts the status and uses "
                       "[-1, 1] (the generic space's whole range by the specification)");
  }
  EXPECT_EQ(protocol.warnings().size(), 1u);
  std::vector<DiagnosticValue> values;
  backend->diagnostics(values);
  EXPECT_NE(std::find_if(values.begin(), values.end(),
                         [](const DiagnosticValue& value) {
                           return value.first == "presets on the camera" && value.second == "none: the ONVIF camera "
                                                                                            "refused GetPresets: "
                                                                                            "ter:ActionNotSupported: "
                                                                                            "Optional Action Not "
                                                                                            "Implemented";
                         }),
            values.end());
  // Goals go in the space the status comes in (it lists degrees too), within the range in use: -0.5 rad is x -0.159155,
  // not clamped to the listed 0.
  backend->goTo({ -0.5, 0.2, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return !lastBodyOf(camera.server(), "AbsoluteMove").empty(); }, WAIT));
  EXPECT_NE(lastBodyOf(camera.server(), "AbsoluteMove")
                .find("<tt:PanTilt x=\"-0.159155\" y=\"0.127324\" space=\"http://www.onvif.org/ver10/tptz/"
                      "PanTiltSpaces/PositionGenericSpace\"/>"),
            std::string::npos)
      << lastBodyOf(camera.server(), "AbsoluteMove");
  EXPECT_EQ(backend->sample().fault_count, 0u);
}

TEST(OnvifFieldCameras, AStartUpThatFailsOnAStatusSaysWhatTheCameraAnswered)
{
  ScriptedCamera camera;
  playTheFieldCamera(camera);
  const std::string where = "an ONVIF camera on http://127.0.0.1:" + std::to_string(camera.port()) + ": ";
  camera.set("GetStatus",
             "<env:Fault><env:Code><env:Value>env:Sender</env:Value><env:Subcode><env:Value>ter:InvalidArgVal"
             "</env:Value><env:Subcode><env:Value>ter:NoProfile</env:Value></env:Subcode></env:Subcode></env:Code>"
             "<env:Reason><env:Text xml:lang=\"en\">The requested profile token ProfileToken does not exist."
             "</env:Text></env:Reason></env:Fault>",
             400);
  EXPECT_EQ(startupError(configForScripted(camera)), where + "the ONVIF camera refused GetStatus: "
                                                             "ter:InvalidArgVal/ter:NoProfile: The requested profile "
                                                             "token "
                                                             "ProfileToken does not exist.");
  camera.set("GetStatus", statusReply("<tt:PanTilt x=\"NaN\" y=\"0\"/>"));
  EXPECT_EQ(startupError(configForScripted(camera)), where + "GetStatus answered a Position with a PanTilt without "
                                                             "numbers x and y");
  camera.set("GetStatus", "<tptz:GetStatusResponse/>");
  EXPECT_EQ(startupError(configForScripted(camera)), where + "GetStatus answered no PTZStatus");
}

TEST(OnvifFieldCameras, AStatusWithoutASpaceIsInTheConfigurationsDefaultElseTheGenericSpace)
{
  ScriptedCamera camera;
  playTheFieldCamera(camera);
  camera.set("GetStatus", statusReply("<tt:PanTilt x=\"-45\" y=\"10\"/>"));
  camera.set("GetProfiles", profilesWithDefault(onvif::DEGREE_SPACE));
  {
    auto backend = makeDeviceBackend<OnvifProtocol>(configForScripted(camera));
    backend->start();
    EXPECT_NEAR(backend->sample().position[PAN], toRadians(-45.0), 1e-9);
    EXPECT_NEAR(backend->sample().position[TILT], toRadians(10.0), 1e-9);
    EXPECT_FALSE(backend->capabilities().axes[ZOOM].feedback);  // no zoom in its status
    EXPECT_EQ(backend->capabilities().axes[ZOOM].limitation, "this camera's GetStatus answers no zoom position");
    // Unreported, its zoom still goes to its widest view (generic zoom 0): a zoom 1 goal is sent as that.
    EXPECT_TRUE(backend->capabilities().axes[ZOOM].widest_view);
    backend->goTo({ std::nan(""), std::nan(""), 1.0 });
    ASSERT_TRUE(waitUntil([&] { return !lastBodyOf(camera.server(), "AbsoluteMove").empty(); }, WAIT));
    EXPECT_NE(lastBodyOf(camera.server(), "AbsoluteMove").find("<tt:Zoom x=\"0.000000\""), std::string::npos);
  }
  camera.set("GetStatus", statusReply("<tt:PanTilt x=\"0.5\" y=\"-0.5\"/>"));
  camera.set("GetProfiles", profilesWithDefault(""));
  auto backend = makeDeviceBackend<OnvifProtocol>(configForScripted(camera));
  backend->start();
  EXPECT_NEAR(backend->sample().position[PAN], M_PI / 2.0, 1e-9);  // the generic space, through pan/scale
  EXPECT_NEAR(backend->sample().position[TILT], -M_PI / 4.0, 1e-9);
}

TEST(OnvifFieldCameras, AStatusInASpaceThisBackendCannotConvertIsNoFeedbackNamingIt)
{
  ScriptedCamera camera;
  playTheFieldCamera(camera);
  camera.set("GetStatus", statusReply("<tt:PanTilt x=\"3\" y=\"4\" space=\"urn:vendor:PixelSpace\"/>"));
  auto backend = makeDeviceBackend<OnvifProtocol>(configForScripted(camera));
  backend->start();
  EXPECT_TRUE(backend->sample().link_up);
  const Capabilities capabilities = backend->capabilities();
  EXPECT_FALSE(capabilities.axes[PAN].feedback);
  EXPECT_EQ(findUnsupported(capabilities, PAN, AxisRequest::POSITION), "this camera's GetStatus answers the pan-tilt "
                                                                       "position in 'urn:vendor:PixelSpace', a space "
                                                                       "this backend "
                                                                       "cannot convert: pan goals are not supported");
  EXPECT_EQ(findUnsupported(capabilities, PAN, AxisRequest::VELOCITY), "");
}

}  // namespace
}  // namespace ptz_action_server

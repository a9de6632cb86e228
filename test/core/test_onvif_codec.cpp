/**
 * \file
 * \brief The ONVIF codec's replies: in any prefixes, SOAP faults (two deep, as the PTZ service sends them), status in
 * each space and without a position, profiles' default spaces, nodes' spaces and ranges (INF, a wrong listed range
 * read as listed), services and presets (with their requests), and what malformed replies are called. The replies are
 * written from the ONVIF PTZ, media and device WSDLs and the PTZ service specification. The requests, WS-Security,
 * times and durations are test_onvif_requests.cpp's.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ptz_action_server/core/onvif/onvif_codec.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif;

TEST(OnvifCodec, RepliesReadTheSameWhateverTheirPrefixes)
{
  const char* const statuses[] = {
    // The client's own prefixes.
    "<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\" "
    "xmlns:tptz=\"http://www.onvif.org/ver20/ptz/wsdl\" "
    "xmlns:tt=\"http://www.onvif.org/ver10/schema\"><s:Body><tptz:GetStatusResponse><tptz:PTZStatus><tt:Position>"
    "<tt:PanTilt x=\"12.5\" y=\"-3\" space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
    "SphericalPositionSpaceDegrees\"/><tt:Zoom x=\"0.5\"/></tt:Position><tt:MoveStatus><tt:PanTilt>MOVING</tt:PanTilt>"
    "</tt:MoveStatus></tptz:PTZStatus></tptz:GetStatusResponse></s:Body></s:Envelope>",
    // Other prefixes, a default namespace, declarations on inner elements.
    "<SOAP-ENV:Envelope xmlns:SOAP-ENV=\"http://www.w3.org/2003/05/soap-envelope\"><SOAP-ENV:Body>"
    "<GetStatusResponse xmlns=\"http://www.onvif.org/ver20/ptz/wsdl\"><PTZStatus><a:Position "
    "xmlns:a=\"http://www.onvif.org/ver10/schema\"><a:PanTilt x=\"12.5\" y=\"-3\" space=\"http://www.onvif.org/ver10/"
    "tptz/PanTiltSpaces/SphericalPositionSpaceDegrees\"/><a:Zoom x=\"0.5\"/></a:Position><b:MoveStatus "
    "xmlns:b=\"http://www.onvif.org/ver10/schema\"><b:PanTilt>MOVING</b:PanTilt></b:MoveStatus></PTZStatus>"
    "</GetStatusResponse></SOAP-ENV:Body></SOAP-ENV:Envelope>",
  };
  for (const char* xml : statuses)
  {
    SoapMessage message;
    ASSERT_EQ(parseSoap(xml, message), "");
    Status status;
    ASSERT_EQ(readStatus(message.content, status), "");
    EXPECT_EQ(status.x, 12.5);
    EXPECT_EQ(status.y, -3.0);
    EXPECT_EQ(status.space, DEGREE_SPACE);
    EXPECT_TRUE(status.has_zoom);
    EXPECT_EQ(status.zoom, 0.5);
    EXPECT_EQ(status.move_status, "MOVING");
  }
  // The right local names in the wrong namespace are not the answer.
  SoapMessage message;
  ASSERT_EQ(parseSoap("<e:Envelope xmlns:e=\"http://www.w3.org/2003/05/soap-envelope\"><e:Body><x:GetStatusResponse "
                      "xmlns:x=\"urn:other\"><x:PTZStatus/></x:GetStatusResponse></e:Body></e:Envelope>",
                      message),
            "");
  Status status;
  EXPECT_EQ(readStatus(message.content, status), "no PTZStatus");
}

TEST(OnvifCodec, FaultsCarryTheSubcodeAndTheReason)
{
  SoapMessage message;
  ASSERT_EQ(parseSoap("<env:Envelope xmlns:env=\"http://www.w3.org/2003/05/soap-envelope\" "
                      "xmlns:ter=\"http://www.onvif.org/ver10/error\"><env:Body><env:Fault><env:Code><env:Value>"
                      "env:Sender</env:Value><env:Subcode><env:Value>ter:NotAuthorized</env:Value></env:Subcode>"
                      "</env:Code><env:Reason><env:Text xml:lang=\"en\">Sender not Authorized</env:Text></env:Reason>"
                      "</env:Fault></env:Body></env:Envelope>",
                      message),
            "");
  EXPECT_TRUE(message.fault);
  EXPECT_EQ(message.fault_text, "ter:NotAuthorized: Sender not Authorized");
  EXPECT_TRUE(faultHas(message, "NotAuthorized"));
  EXPECT_TRUE(faultHas(message, "Sender"));
  EXPECT_FALSE(faultHas(message, "ActionNotSupported"));

  // The PTZ service's faults are two deep (env:Sender - ter:InvalidArgVal - ter:NoPTZProfile): both are kept.
  ASSERT_EQ(parseSoap("<e:Envelope xmlns:e=\"http://www.w3.org/2003/05/soap-envelope\" "
                      "xmlns:t=\"http://www.onvif.org/ver10/error\"><e:Body><e:Fault><e:Code><e:Value>e:Sender</"
                      "e:Value>"
                      "<e:Subcode><e:Value>t:InvalidArgVal</e:Value><e:Subcode><e:Value>t:NoPTZProfile</e:Value>"
                      "</e:Subcode></e:Subcode></e:Code><e:Reason><e:Text xml:lang=\"en\">The requested profile token "
                      "does not reference a PTZ configuration.</e:Text></e:Reason></e:Fault></e:Body></e:Envelope>",
                      message),
            "");
  EXPECT_EQ(message.fault_code, "e:Sender");
  EXPECT_EQ(message.subcodes, (std::vector<std::string>{ "t:InvalidArgVal", "t:NoPTZProfile" }));
  EXPECT_EQ(message.fault_text, "t:InvalidArgVal/t:NoPTZProfile: The requested profile token does not reference a PTZ "
                                "configuration.");
  EXPECT_TRUE(faultHas(message, "NoPTZProfile"));
  EXPECT_FALSE(faultHas(message, "NoProfile"));

  // What a camera without presets answers GetPresets (env:Receiver - ter:ActionNotSupported), without a reason.
  ASSERT_EQ(parseSoap("<env:Envelope xmlns:env=\"http://www.w3.org/2003/05/soap-envelope\"><env:Body><env:Fault>"
                      "<env:Code><env:Value>env:Receiver</env:Value><env:Subcode><env:Value>ter:ActionNotSupported"
                      "</env:Value></env:Subcode></env:Code></env:Fault></env:Body></env:Envelope>",
                      message),
            "");
  EXPECT_EQ(message.fault_text, "ter:ActionNotSupported");
  EXPECT_TRUE(faultHas(message, "ActionNotSupported"));
}

TEST(OnvifCodec, MalformedEnvelopesAreNamed)
{
  SoapMessage message;
  EXPECT_EQ(parseSoap("", message).rfind("not XML", 0), 0u);
  EXPECT_EQ(parseSoap("<html>401</html>", message), "no SOAP 1.2 Envelope");
  EXPECT_EQ(parseSoap("<Envelope xmlns=\"http://schemas.xmlsoap.org/soap/envelope/\"><Body/></Envelope>", message),
            "no SOAP 1.2 Envelope");  // SOAP 1.1 is not ONVIF's
  EXPECT_EQ(parseSoap("<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\"/>", message), "no SOAP Body");
  EXPECT_EQ(
      parseSoap("<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\"><s:Body/></s:Envelope>", message),
      "an empty SOAP Body");
  EXPECT_EQ(parseSoap("<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\"><s:Body><a></s:Body>", message)
                .rfind("not XML", 0),
            0u);
}

TEST(OnvifCodec, BringUpReplies)
{
  SoapMessage message;
  ASSERT_EQ(parseSoap("<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\" "
                      "xmlns:tds=\"http://www.onvif.org/ver10/device/wsdl\" "
                      "xmlns:tt=\"http://www.onvif.org/ver10/schema\">"
                      "<s:Body><tds:GetSystemDateAndTimeResponse><tds:SystemDateAndTime><tt:UTCDateTime><tt:Time>"
                      "<tt:Hour>7</tt:Hour><tt:Minute>50</tt:Minute><tt:Second>45</tt:Second></tt:Time><tt:Date>"
                      "<tt:Year>2010</tt:Year><tt:Month>9</tt:Month><tt:Day>16</tt:Day></tt:Date></tt:UTCDateTime>"
                      "</tds:SystemDateAndTime></tds:GetSystemDateAndTimeResponse></s:Body></s:Envelope>",
                      message),
            "");
  double utc = 0.0;
  ASSERT_EQ(readSystemTime(message.content, utc), "");
  EXPECT_EQ(utc, 1284623445.0);
  EXPECT_EQ(isoTime(utc + 0.25), "2010-09-16T07:50:45.250Z");

  ASSERT_EQ(parseSoap("<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\"><s:Body><r "
                      "xmlns=\"http://www.onvif.org/ver10/device/wsdl\"><Capabilities><m:Media "
                      "xmlns:m=\"http://www.onvif.org/ver10/schema\"><m:XAddr>http://10.1.1.1/onvif/media</m:XAddr>"
                      "</m:Media></Capabilities></r></s:Body></s:Envelope>",
                      message),
            "");
  ServicePaths paths;
  EXPECT_EQ(readCapabilities(message.content, paths), "no PTZ XAddr");

  // A number no clock has (the fuzzer's): named, not cast.
  ASSERT_EQ(parseSoap("<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\" "
                      "xmlns:tt=\"http://www.onvif.org/ver10/schema\"><s:Body><r xmlns=\"http://www.onvif.org/ver10/"
                      "device/wsdl\"><SystemDateAndTime><tt:UTCDateTime><tt:Time><tt:Hour>7</tt:Hour><tt:Minute>50"
                      "</tt:Minute><tt:Second>4555555555555555555555</tt:Second></tt:Time><tt:Date><tt:Year>2010</"
                      "tt:Year>"
                      "<tt:Month>9</tt:Month><tt:Day>16</tt:Day></tt:Date></tt:UTCDateTime>"
                      "</SystemDateAndTime></r></s:Body></s:Envelope>",
                      message),
            "");
  EXPECT_EQ(readSystemTime(message.content, utc), "no UTCDateTime Second (a whole number 0..9999)");
}

/// A reply envelope around \p body, in the prefixes the PTZ specification's examples use.
std::string reply(const std::string& body)
{
  return "<env:Envelope xmlns:env=\"http://www.w3.org/2003/05/soap-envelope\" "
         "xmlns:tds=\"http://www.onvif.org/ver10/device/wsdl\" xmlns:trt=\"http://www.onvif.org/ver10/media/wsdl\" "
         "xmlns:tptz=\"http://www.onvif.org/ver20/ptz/wsdl\" "
         "xmlns:tt=\"http://www.onvif.org/ver10/schema\"><env:Body>" +
         body + "</env:Body></env:Envelope>";
}

Status statusOf(const std::string& ptz_status)
{
  SoapMessage message;
  EXPECT_EQ(parseSoap(reply("<tptz:GetStatusResponse>" + ptz_status + "</tptz:GetStatusResponse>"), message), "");
  Status status;
  EXPECT_EQ(readStatus(message.content, status), "") << ptz_status;
  return status;
}

TEST(OnvifCodec, StatusIsReadInWhateverSpaceItNames)
{
  // The generic space, named (a camera that lists the degree space may still report here: its default space).
  Status status = statusOf("<tptz:PTZStatus><tt:Position><tt:PanTilt x=\"-0.864666\" y=\"0.25\" "
                           "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/PositionGenericSpace\"/><tt:Zoom "
                           "x=\"0.1\" space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/PositionGenericSpace\"/>"
                           "</tt:Position><tt:MoveStatus><tt:PanTilt>IDLE</tt:PanTilt><tt:Zoom>MOVING</tt:Zoom>"
                           "</tt:MoveStatus><tt:UtcTime>2026-11-21T10:20:30Z</tt:UtcTime></tptz:PTZStatus>");
  EXPECT_TRUE(status.has_pan_tilt);
  EXPECT_EQ(status.x, -0.864666);
  EXPECT_EQ(status.y, 0.25);
  EXPECT_EQ(status.space, GENERIC_PAN_TILT_SPACE);
  EXPECT_TRUE(status.has_zoom);
  EXPECT_EQ(status.zoom, 0.1);
  EXPECT_EQ(status.zoom_space, GENERIC_ZOOM_SPACE);
  EXPECT_EQ(status.move_status, "IDLE");  // per axis: the pan-tilt rests while the zoom moves
  EXPECT_EQ(status.zoom_move_status, "MOVING");

  // Degrees, named.
  status = statusOf("<tptz:PTZStatus><tt:Position><tt:PanTilt x=\"-155.64\" y=\"-12.5\" "
                    "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/SphericalPositionSpaceDegrees\"/>"
                    "</tt:Position><tt:UtcTime>2026-11-21T10:20:30Z</tt:UtcTime></tptz:PTZStatus>");
  EXPECT_EQ(status.space, DEGREE_SPACE);
  EXPECT_EQ(status.x, -155.64);
  EXPECT_FALSE(status.has_zoom);
  EXPECT_EQ(status.move_status, "");

  // No space: the PTZ configuration's default (the reader leaves it to whoever knows the profile).
  status = statusOf("<tptz:PTZStatus><tt:Position><tt:PanTilt x=\"0.5\" y=\"-0.5\"/><tt:Zoom x=\"1\"/></tt:Position>"
                    "<tt:UtcTime>2026-11-21T10:20:30Z</tt:UtcTime></tptz:PTZStatus>");
  EXPECT_TRUE(status.has_pan_tilt);
  EXPECT_EQ(status.space, "");
  EXPECT_EQ(status.zoom_space, "");

  // No position at all (the capability StatusPosition is optional): a status all the same.
  status = statusOf("<tptz:PTZStatus><tt:MoveStatus><tt:PanTilt>UNKNOWN</tt:PanTilt></tt:MoveStatus><tt:Error>none"
                    "</tt:Error><tt:UtcTime>2026-11-21T10:20:30Z</tt:UtcTime></tptz:PTZStatus>");
  EXPECT_FALSE(status.has_pan_tilt);
  EXPECT_FALSE(status.has_zoom);
  EXPECT_EQ(status.move_status, "UNKNOWN");
  EXPECT_EQ(status.error, "none");

  // A position that is there but unreadable is named.
  SoapMessage message;
  ASSERT_EQ(parseSoap(reply("<tptz:GetStatusResponse><tptz:PTZStatus><tt:Position><tt:PanTilt x=\"left\" y=\"0\"/>"
                            "</tt:Position></tptz:PTZStatus></tptz:GetStatusResponse>"),
                      message),
            "");
  EXPECT_EQ(readStatus(message.content, status), "a Position with a PanTilt without numbers x and y");
}

TEST(OnvifCodec, ProfilesNameTheirConfigurationsDefaultSpaces)
{
  SoapMessage message;
  ASSERT_EQ(parseSoap(reply("<trt:GetProfilesResponse><trt:Profiles token=\"main\" fixed=\"true\"><tt:Name>main"
                            "</tt:Name><tt:VideoSourceConfiguration token=\"vsc\"><tt:SourceToken>cam_0"
                            "</tt:SourceToken></tt:VideoSourceConfiguration><tt:PTZConfiguration "
                            "token=\"ptz\"><tt:Name>ptz</tt:Name><tt:UseCount>1"
                            "</tt:UseCount><tt:NodeToken>node</tt:NodeToken><tt:DefaultAbsolutePantTiltPositionSpace>"
                            "http://www.onvif.org/ver10/tptz/PanTiltSpaces/PositionGenericSpace"
                            "</tt:DefaultAbsolutePantTiltPositionSpace><tt:DefaultAbsoluteZoomPositionSpace>"
                            "http://www.onvif.org/ver10/tptz/ZoomSpaces/PositionGenericSpace"
                            "</tt:DefaultAbsoluteZoomPositionSpace></tt:PTZConfiguration></trt:Profiles>"
                            "<trt:Profiles token=\"bare\"><tt:Name>bare</tt:Name><tt:PTZConfiguration token=\"ptz2\">"
                            "<tt:NodeToken>node</tt:NodeToken></tt:PTZConfiguration></trt:Profiles>"
                            "</trt:GetProfilesResponse>"),
                      message),
            "");
  Profile profile;
  ASSERT_EQ(readProfiles(message.content, "", profile), "");
  EXPECT_EQ(profile.token, "main");
  EXPECT_EQ(profile.ptz_configuration, "ptz");
  EXPECT_EQ(profile.node, "node");
  EXPECT_EQ(profile.default_pan_tilt_space, GENERIC_PAN_TILT_SPACE);
  EXPECT_EQ(profile.default_zoom_space, GENERIC_ZOOM_SPACE);
  EXPECT_EQ(profile.video_source, "cam_0");  // what the Imaging service's requests name
  ASSERT_EQ(readProfiles(message.content, "bare", profile), "");
  EXPECT_EQ(profile.default_pan_tilt_space, "");  // declares none
  EXPECT_EQ(profile.video_source, "");
}

TEST(OnvifCodec, NodesListTheirSpacesRangesPresetsAndHome)
{
  // A Profile T camera: degrees with an unbounded pan (-INF..INF, as the specification writes it), the generic spaces
  // with a generic pan range of 0..1 (as a camera in the field lists it), translation and velocity spaces.
  SoapMessage message;
  ASSERT_EQ(parseSoap(reply("<tptz:GetNodesResponse><tptz:PTZNode token=\"node\" FixedHomePosition=\"false\">"
                            "<tt:Name>node</tt:Name><tt:SupportedPTZSpaces><tt:AbsolutePanTiltPositionSpace><tt:URI>"
                            "http://www.onvif.org/ver10/tptz/PanTiltSpaces/SphericalPositionSpaceDegrees</tt:URI>"
                            "<tt:XRange><tt:Min>-INF</tt:Min><tt:Max>INF</tt:Max></tt:XRange><tt:YRange><tt:Min>-90"
                            "</tt:Min><tt:Max>0</tt:Max></tt:YRange></tt:AbsolutePanTiltPositionSpace>"
                            "<tt:AbsolutePanTiltPositionSpace><tt:URI>http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                            "PositionGenericSpace</tt:URI><tt:XRange><tt:Min>0</tt:Min><tt:Max>1</tt:Max></tt:XRange>"
                            "<tt:YRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:YRange>"
                            "</tt:AbsolutePanTiltPositionSpace><tt:AbsoluteZoomPositionSpace><tt:URI>"
                            "http://www.onvif.org/ver10/tptz/ZoomSpaces/PositionGenericSpace</"
                            "tt:URI><tt:XRange><tt:Min>0"
                            "</tt:Min><tt:Max>1</tt:Max></tt:XRange></tt:AbsoluteZoomPositionSpace>"
                            "<tt:RelativePanTiltTranslationSpace><tt:URI>http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                            "TranslationGenericSpace</tt:URI><tt:XRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max>"
                            "</tt:XRange><tt:YRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:YRange>"
                            "</tt:RelativePanTiltTranslationSpace><tt:ContinuousPanTiltVelocitySpace><tt:URI>"
                            "http://www.onvif.org/ver10/tptz/PanTiltSpaces/VelocityGenericSpace</tt:URI><tt:XRange>"
                            "<tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:XRange><tt:YRange><tt:Min>-1</tt:Min><tt:Max>1"
                            "</tt:Max></tt:YRange></tt:ContinuousPanTiltVelocitySpace></tt:SupportedPTZSpaces>"
                            "<tt:MaximumNumberOfPresets>255</tt:MaximumNumberOfPresets><tt:HomeSupported>true"
                            "</tt:HomeSupported></tptz:PTZNode></tptz:GetNodesResponse>"),
                      message),
            "");
  Node node;
  ASSERT_EQ(readNode(message.content, "node", node), "");
  ASSERT_EQ(node.absolute_pan_tilt.size(), 2u);
  const Space* degrees = findSpace(node.absolute_pan_tilt, DEGREE_SPACE);
  ASSERT_NE(degrees, nullptr);
  EXPECT_TRUE(std::isinf(degrees->x.min) && degrees->x.min < 0.0);
  EXPECT_TRUE(std::isinf(degrees->x.max) && degrees->x.max > 0.0);
  EXPECT_EQ(degrees->y.min, -90.0);
  EXPECT_EQ(degrees->y.max, 0.0);
  const Space* generic = findSpace(node.absolute_pan_tilt, GENERIC_PAN_TILT_SPACE);
  ASSERT_NE(generic, nullptr);
  EXPECT_EQ(generic->x.min, 0.0);  // read as listed: the backend judges it against the status
  EXPECT_EQ(generic->x.max, 1.0);
  EXPECT_NE(findSpace(node.absolute_zoom, GENERIC_ZOOM_SPACE), nullptr);
  EXPECT_NE(findSpace(node.relative_pan_tilt, GENERIC_PAN_TILT_TRANSLATION), nullptr);
  EXPECT_TRUE(node.relative_zoom.empty());
  EXPECT_NE(findSpace(node.continuous_pan_tilt, GENERIC_PAN_TILT_VELOCITY), nullptr);
  EXPECT_TRUE(node.continuous_zoom.empty());
  EXPECT_EQ(node.max_presets, 255);
  EXPECT_TRUE(node.home_supported);

  // A camera on a Goke GK7102 chip: velocity spaces only, no presets or home. Read as it is, without complaint.
  ASSERT_EQ(parseSoap(reply("<tptz:GetNodesResponse><tptz:PTZNode token=\"n\"><tt:SupportedPTZSpaces>"
                            "<tt:ContinuousPanTiltVelocitySpace><tt:URI>http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                            "VelocityGenericSpace</tt:URI><tt:XRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:XRange>"
                            "<tt:YRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:YRange>"
                            "</tt:ContinuousPanTiltVelocitySpace></tt:SupportedPTZSpaces><tt:MaximumNumberOfPresets>0"
                            "</tt:MaximumNumberOfPresets><tt:HomeSupported>false</tt:HomeSupported></tptz:PTZNode>"
                            "</tptz:GetNodesResponse>"),
                      message),
            "");
  ASSERT_EQ(readNode(message.content, "", node), "");
  EXPECT_TRUE(node.absolute_pan_tilt.empty());
  EXPECT_EQ(node.continuous_pan_tilt.size(), 1u);
  EXPECT_EQ(node.max_presets, 0);
  EXPECT_FALSE(node.home_supported);

  // A range that is no range is named with its space.
  ASSERT_EQ(parseSoap(reply("<tptz:GetNodesResponse><tptz:PTZNode token=\"n\"><tt:SupportedPTZSpaces>"
                            "<tt:AbsolutePanTiltPositionSpace><tt:URI>http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                            "PositionGenericSpace</tt:URI><tt:XRange><tt:Min>1</tt:Min><tt:Max>-1</tt:Max></tt:XRange>"
                            "<tt:YRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:YRange>"
                            "</tt:AbsolutePanTiltPositionSpace></tt:SupportedPTZSpaces></tptz:PTZNode>"
                            "</tptz:GetNodesResponse>"),
                      message),
            "");
  EXPECT_EQ(readNode(message.content, "", node), "PTZ node 'n': AbsolutePanTiltPositionSpace 'PositionGenericSpace': a "
                                                 "range without Min <= Max");
}

TEST(OnvifCodec, ServicesPresetsAndTheirRequests)
{
  SoapMessage message;
  ASSERT_EQ(parseSoap(reply("<tds:GetServicesResponse><tds:Service><tds:Namespace>http://www.onvif.org/ver10/device/"
                            "wsdl</tds:Namespace><tds:XAddr>http://10.0.0.9/onvif/device_service</tds:XAddr>"
                            "<tds:Version><tt:Major>2</tt:Major><tt:Minor>60</tt:Minor></tds:Version></tds:Service>"
                            "<tds:Service><tds:Namespace>http://www.onvif.org/ver10/media/wsdl</tds:Namespace>"
                            "<tds:XAddr>http://10.0.0.9/onvif/Media</tds:XAddr></tds:Service><tds:Service>"
                            "<tds:Namespace>http://www.onvif.org/ver20/ptz/wsdl</tds:Namespace><tds:XAddr>"
                            "http://10.0.0.9:8000/onvif/PTZ</tds:XAddr></tds:Service></tds:GetServicesResponse>"),
                      message),
            "");
  ServicePaths paths;
  ASSERT_EQ(readServices(message.content, paths), "");
  EXPECT_EQ(paths.media, "/onvif/Media");
  EXPECT_EQ(paths.ptz, "/onvif/PTZ");
  EXPECT_EQ(paths.imaging, "");  // no Imaging service listed: no focus or iris

  ASSERT_EQ(parseSoap(reply("<tptz:GetPresetsResponse><tptz:Preset token=\"1\"><tt:Name>door</tt:Name><tt:PTZPosition>"
                            "<tt:PanTilt x=\"0.5\" y=\"-0.25\" space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                            "PositionGenericSpace\"/><tt:Zoom x=\"0\"/></tt:PTZPosition></tptz:Preset>"
                            "<tptz:Preset token=\"2\"/></tptz:GetPresetsResponse>"),
                      message),
            "");
  std::vector<Preset> presets;
  ASSERT_EQ(readPresets(message.content, presets), "");
  ASSERT_EQ(presets.size(), 2u);
  EXPECT_EQ(presets[0].token, "1");
  EXPECT_EQ(presets[0].name, "door");
  EXPECT_TRUE(presets[0].position.has_pan_tilt);
  EXPECT_EQ(presets[0].position.x, 0.5);
  EXPECT_TRUE(presets[0].position.has_zoom);
  EXPECT_FALSE(presets[1].position.has_pan_tilt);  // a preset without a position (optional in the schema)

  ASSERT_EQ(parseSoap(reply("<tptz:SetPresetResponse><tptz:PresetToken>7</tptz:PresetToken></tptz:SetPresetResponse>"),
                      message),
            "");
  std::string token;
  ASSERT_EQ(readPresetToken(message.content, token), "");
  EXPECT_EQ(token, "7");

  EXPECT_EQ(getServices(false), "<tds:GetServices><tds:IncludeCapability>false</tds:IncludeCapability></"
                                "tds:GetServices>");
  EXPECT_EQ(getPresets("p"), "<tptz:GetPresets><tptz:ProfileToken>p</tptz:ProfileToken></tptz:GetPresets>");
  EXPECT_EQ(setPreset("p", "door"), "<tptz:SetPreset><tptz:ProfileToken>p</tptz:ProfileToken><tptz:PresetName>door"
                                    "</tptz:PresetName></tptz:SetPreset>");
  EXPECT_EQ(gotoPreset("p", "7"), "<tptz:GotoPreset><tptz:ProfileToken>p</tptz:ProfileToken><tptz:PresetToken>7"
                                  "</tptz:PresetToken></tptz:GotoPreset>");
  EXPECT_EQ(gotoHomePosition("p"), "<tptz:GotoHomePosition><tptz:ProfileToken>p</tptz:ProfileToken>"
                                   "</tptz:GotoHomePosition>");
  EXPECT_EQ(getConfiguration("ptz0"), "<tptz:GetConfiguration><tptz:PTZConfigurationToken>ptz0"
                                      "</tptz:PTZConfigurationToken></tptz:GetConfiguration>");
  Vector translation;
  translation.pan_tilt = true;
  translation.x = 0.1;
  EXPECT_EQ(relativeMove("p", translation), "<tptz:RelativeMove><tptz:ProfileToken>p</tptz:ProfileToken>"
                                            "<tptz:Translation><tt:PanTilt x=\"0.100000\" y=\"0.000000\"/>"
                                            "</tptz:Translation></tptz:RelativeMove>");  // no space: the default one
  Vector zoom_only;
  zoom_only.zoom = true;
  zoom_only.z = 0.5;
  zoom_only.zoom_space = GENERIC_ZOOM_SPACE;
  EXPECT_EQ(absoluteMove("p", zoom_only), "<tptz:AbsoluteMove><tptz:ProfileToken>p</tptz:ProfileToken><tptz:Position>"
                                          "<tt:Zoom x=\"0.500000\" space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/"
                                          "PositionGenericSpace\"/></tptz:Position></tptz:AbsoluteMove>");
  EXPECT_EQ(continuousMove("p", 0.0, 0.0, true, -0.5, 2, false),
            "<tptz:ContinuousMove><tptz:ProfileToken>p</tptz:ProfileToken><tptz:Velocity><tt:Zoom x=\"-0.500000\" "
            "space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/VelocityGenericSpace\"/></tptz:Velocity>"
            "<tptz:Timeout>PT2S</tptz:Timeout></tptz:ContinuousMove>");  // the pan-tilt goes on as it was
}

}  // namespace
}  // namespace ptz_action_server

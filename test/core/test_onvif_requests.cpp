/**
 * \file
 * \brief The ONVIF codec's requests: WS-Security PasswordDigest against the ONVIF programmer's guide example, nonces
 * that never repeat (10,000 headers, in the same millisecond), golden request envelopes, and the times and durations
 * they carry. The replies are test_onvif_codec.cpp's.
 */
#include <gtest/gtest.h>

#include <cstddef>
#include <set>
#include <string>
#include <utility>

#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif;

TEST(OnvifCodec, PasswordDigestOfTheProgrammersGuideExample)
{
  std::string nonce;
  ASSERT_TRUE(base64Decode("LKqI6G/AikKCQrN0zqZFlg==", nonce));
  EXPECT_EQ(passwordDigest(nonce, "2010-09-16T07:50:45Z", "userpassword"), "tuOSpGlFlIXsozq4HFNeeGeFLEI=");
}

/// The text of the first <wsse:NAME ...>TEXT</wsse:NAME> in \p xml.
std::string wsseText(const std::string& xml, const std::string& name)
{
  const std::size_t open = xml.find("<wsse:" + name);
  const std::size_t start = open == std::string::npos ? open : xml.find('>', open);
  const std::size_t end = start == std::string::npos ? start : xml.find("</wsse:" + name + ">", start);
  return end == std::string::npos ? std::string() : xml.substr(start + 1, end - start - 1);
}

TEST(OnvifCodec, WsSecurityNoncesNeverRepeatEvenWithinOneCreatedTime)
{
  // Every header in the same millisecond with the same password: only the nonce tells them apart, so a nonce that
  // repeats also repeats the PasswordDigest (a replay a camera must refuse).
  constexpr int HEADERS = 10000;
  const std::string created = isoTime(1.7e9);
  std::set<std::string> nonces;
  std::set<std::string> digests;
  for (int i = 0; i < HEADERS; ++i)
  {
    const UsernameToken token = newUsernameToken("operator", created);
    ASSERT_EQ(token.nonce.size(), 16u);
    const std::string xml = envelope("<tptz:Stop/>", &token, "s3cret");
    ASSERT_EQ(xml.find("s3cret"), std::string::npos);  // only its digest travels
    const std::string nonce = wsseText(xml, "Nonce");
    std::string raw;
    ASSERT_TRUE(base64Decode(nonce, raw)) << nonce;
    ASSERT_EQ(raw, token.nonce);
    EXPECT_EQ(wsseText(xml, "Password"), passwordDigest(raw, created, "s3cret"));
    nonces.insert(nonce);
    digests.insert(wsseText(xml, "Password"));
  }
  EXPECT_EQ(nonces.size(), static_cast<std::size_t>(HEADERS));
  EXPECT_EQ(digests.size(), static_cast<std::size_t>(HEADERS));
}

TEST(OnvifCodec, AbsoluteMoveEnvelopeIsGolden)
{
  std::string nonce;
  ASSERT_TRUE(base64Decode("LKqI6G/AikKCQrN0zqZFlg==", nonce));
  const UsernameToken token{ "user", nonce, "2010-09-16T07:50:45Z" };
  EXPECT_EQ(
      envelope(absoluteMove("profile_1", 28.647890, -11.459156, DEGREE_SPACE, true, 0.239812), &token, "userpassword"),
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<s:Envelope xmlns:s=\"http://www.w3.org/2003/05/soap-envelope\" "
      "xmlns:tds=\"http://www.onvif.org/ver10/device/wsdl\" xmlns:trt=\"http://www.onvif.org/ver10/media/wsdl\" "
      "xmlns:tptz=\"http://www.onvif.org/ver20/ptz/wsdl\" xmlns:tt=\"http://www.onvif.org/ver10/schema\">"
      "<s:Header><wsse:Security s:mustUnderstand=\"1\" "
      "xmlns:wsse=\"http://docs.oasis-open.org/wss/2004/01/oasis-200401-wss-wssecurity-secext-1.0.xsd\" "
      "xmlns:wsu=\"http://docs.oasis-open.org/wss/2004/01/oasis-200401-wss-wssecurity-utility-1.0.xsd\">"
      "<wsse:UsernameToken><wsse:Username>user</wsse:Username>"
      "<wsse:Password Type=\"http://docs.oasis-open.org/wss/2004/01/"
      "oasis-200401-wss-username-token-profile-1.0#PasswordDigest\">tuOSpGlFlIXsozq4HFNeeGeFLEI=</wsse:Password>"
      "<wsse:Nonce EncodingType=\"http://docs.oasis-open.org/wss/2004/01/"
      "oasis-200401-wss-soap-message-security-1.0#Base64Binary\">LKqI6G/AikKCQrN0zqZFlg==</wsse:Nonce>"
      "<wsu:Created>2010-09-16T07:50:45Z</wsu:Created></wsse:UsernameToken></wsse:Security></s:Header>"
      "<s:Body><tptz:AbsoluteMove><tptz:ProfileToken>profile_1</tptz:ProfileToken><tptz:Position>"
      "<tt:PanTilt x=\"28.647890\" y=\"-11.459156\" "
      "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/SphericalPositionSpaceDegrees\"/>"
      "<tt:Zoom x=\"0.239812\" space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/PositionGenericSpace\"/>"
      "</tptz:Position></tptz:AbsoluteMove></s:Body></s:Envelope>");
}

TEST(OnvifCodec, AbsoluteMoveWithASpeedIsGolden)
{
  // PTZ specification: AbsoluteMove{ProfileToken, Position, Speed?}; the Speed a PTZSpeed in the generic speed spaces,
  // shares 0..1 of the top speed.
  const Vector position = Vector::of(true, -0.5, 0.25, GENERIC_PAN_TILT_SPACE, true, 0.5, GENERIC_ZOOM_SPACE);
  const Vector speed = Vector::of(true, 0.25, 1.0, GENERIC_PAN_TILT_SPEED, true, 0.1, GENERIC_ZOOM_SPEED);
  EXPECT_EQ(absoluteMove("profile_1", position, speed), "<tptz:AbsoluteMove><tptz:ProfileToken>profile_1</"
                                                        "tptz:ProfileToken><tptz:Position>"
                                                        "<tt:PanTilt x=\"-0.500000\" y=\"0.250000\" "
                                                        "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                                                        "PositionGenericSpace\"/>"
                                                        "<tt:Zoom x=\"0.500000\" "
                                                        "space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/"
                                                        "PositionGenericSpace\"/>"
                                                        "</tptz:Position><tptz:Speed>"
                                                        "<tt:PanTilt x=\"0.250000\" y=\"1.000000\" "
                                                        "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                                                        "GenericSpeedSpace\"/>"
                                                        "<tt:Zoom x=\"0.100000\" "
                                                        "space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/"
                                                        "ZoomGenericSpeedSpace\"/>"
                                                        "</tptz:Speed></tptz:AbsoluteMove>");
  // Only the zoom's speed; and none at all: no Speed element (the camera's default speed).
  const Vector zoom_only = Vector::of(false, 0.0, 0.0, "", true, 0.3, GENERIC_ZOOM_SPEED);
  EXPECT_EQ(absoluteMove("p", Vector::of(false, 0.0, 0.0, "", true, 1.0, ""), zoom_only), "<tptz:AbsoluteMove><tptz:"
                                                                                          "ProfileToken>p</"
                                                                                          "tptz:ProfileToken><tptz:"
                                                                                          "Position><tt:Zoom "
                                                                                          "x=\"1.000000\"/>"
                                                                                          "</"
                                                                                          "tptz:Position><tptz:Speed><"
                                                                                          "tt:Zoom x=\"0.300000\" "
                                                                                          "space=\"http://"
                                                                                          "www.onvif.org/ver10/tptz/"
                                                                                          "ZoomSpaces/"
                                                                                          "ZoomGenericSpeedSpace\"/></"
                                                                                          "tptz:Speed>"
                                                                                          "</tptz:AbsoluteMove>");
  EXPECT_EQ(absoluteMove("p", position, Vector()), absoluteMove("p", position));
  EXPECT_EQ(absoluteMove("p", position).find("Speed"), std::string::npos);
}

TEST(OnvifCodec, OtherRequestBodiesAreGolden)
{
  const std::string unsigned_request = envelope(getSystemDateAndTime());
  const std::string tail = "xmlns:tt=\"http://www.onvif.org/ver10/schema\"><s:Body><tds:GetSystemDateAndTime/></s:Body>"
                           "</s:Envelope>";
  ASSERT_GT(unsigned_request.size(), tail.size());
  EXPECT_EQ(unsigned_request.substr(unsigned_request.size() - tail.size()), tail);  // no header: no authentication
  EXPECT_EQ(continuousMove("p<1>", 0.2, -1.0, false, 0.0, 2), "<tptz:ContinuousMove><tptz:ProfileToken>p&lt;1&gt;</"
                                                              "tptz:ProfileToken><tptz:Velocity>"
                                                              "<tt:PanTilt x=\"0.200000\" y=\"-1.000000\" "
                                                              "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                                                              "VelocityGenericSpace\"/></tptz:Velocity>"
                                                              "<tptz:Timeout>PT2S</tptz:Timeout></"
                                                              "tptz:ContinuousMove>");
  EXPECT_EQ(stop("profile_1"), "<tptz:Stop><tptz:ProfileToken>profile_1</tptz:ProfileToken><tptz:PanTilt>true"
                               "</tptz:PanTilt><tptz:Zoom>true</tptz:Zoom></tptz:Stop>");
  EXPECT_EQ(getStatus("profile_1"), "<tptz:GetStatus><tptz:ProfileToken>profile_1</tptz:ProfileToken></"
                                    "tptz:GetStatus>");
}

TEST(OnvifCodec, TimesAndDurations)
{
  double seconds = 0.0;
  EXPECT_TRUE(parseIsoTime("2010-09-16T07:50:45Z", seconds));
  EXPECT_EQ(seconds, 1284623445.0);
  EXPECT_TRUE(parseIsoTime("2010-09-16T07:50:45.5Z", seconds));
  EXPECT_EQ(seconds, 1284623445.5);
  // Every xsd:dateTime is a valid wsu:Created: python-onvif-zeep (Home Assistant's ONVIF integration) stamps
  // "+00:00" with microseconds; a zone moves the instant; a time without one is UTC; 24:00:00 ends the day.
  const std::pair<const char*, double> valid[] = {
    { "2010-09-16T07:50:45+00:00", 1284623445.0 }, { "2010-09-16T07:50:45.123456+00:00", 1284623445.123456 },
    { "2010-09-16T08:50:45+01:00", 1284623445.0 }, { "2010-09-16T02:20:45-05:30", 1284623445.0 },
    { "2010-09-16T07:50:45", 1284623445.0 },       { "2010-09-15T24:00:00Z", 1284595200.0 },
    { "2012-02-29T00:00:00Z", 1330473600.0 },      { "2010-09-16T07:50:45.25-00:00", 1284623445.25 },
  };
  for (const auto& time : valid)
  {
    EXPECT_TRUE(parseIsoTime(time.first, seconds)) << time.first;
    EXPECT_NEAR(seconds, time.second, 1e-6) << time.first;
  }
  for (const char* bad :
       { "", "2010-09-16 07:50:45Z", "2010-13-16T07:50:45Z", "2010-09-16T07:50:45.Z", "2010-09-16T07:50:45+1:00",
         "2010-09-16T07:50:45+15:00", "2010-09-16T07:50:45+01:60", "2011-02-29T00:00:00Z", "2010-09-31T00:00:00Z",
         "2010-09-16T24:00:01Z", "2010-09-16T07:50:45Zjunk", "10-09-16T07:50:45Z", "02010-09-16T07:50:45Z",
         "2010-9-16T07:50:45Z" })
  {
    EXPECT_FALSE(parseIsoTime(bad, seconds)) << bad;
  }
  EXPECT_TRUE(parseDuration("PT5S", seconds));
  EXPECT_EQ(seconds, 5.0);
  EXPECT_TRUE(parseDuration("PT1M", seconds));
  EXPECT_EQ(seconds, 60.0);
  EXPECT_TRUE(parseDuration("PT0.5S", seconds));
  EXPECT_EQ(seconds, 0.5);
  for (const char* bad : { "", "5", "PTS", "P5S", "PT-1S", "PT5X" })
  {
    EXPECT_FALSE(parseDuration(bad, seconds)) << bad;
  }
}

}  // namespace
}  // namespace ptz_action_server

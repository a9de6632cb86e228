/**
 * \file
 * \brief The ONVIF codec: WS-Security PasswordDigest against the ONVIF programmer's guide example, golden request
 * envelopes, replies in any prefixes, SOAP faults, times and durations, and what malformed replies are called.
 */
#include <gtest/gtest.h>

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
  EXPECT_EQ(readStatus(message.content, status), "no Position/PanTilt x and y");
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

TEST(OnvifCodec, TimesAndDurations)
{
  double seconds = 0.0;
  EXPECT_TRUE(parseIsoTime("2010-09-16T07:50:45Z", seconds));
  EXPECT_EQ(seconds, 1284623445.0);
  EXPECT_TRUE(parseIsoTime("2010-09-16T07:50:45.5Z", seconds));
  EXPECT_EQ(seconds, 1284623445.5);
  for (const char* bad : { "", "2010-09-16T07:50:45", "2010-09-16 07:50:45Z", "2010-13-16T07:50:45Z",
                           "2010-09-16T07:50:45.Z", "2010-09-16T07:50:45+01:00" })
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

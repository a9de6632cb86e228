/**
 * \file
 * \brief The VAPIX codec against the replies of protocols.md section 6 and of a camera in the field (issue 21: no
 * zoom attributes), the documented attributes, info=1 and brand answers, the zoom table, the model families, and the
 * digests IP cameras authenticate with (RFC 7616's MD5 example; SHA-1 and Base64 vectors).
 */
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
namespace
{
using namespace vapix;

TEST(VapixCodec, ReadsThePositionReplyOfTheSpec)
{
  Reply reply;
  ASSERT_EQ(parseReply("pan=51.2891\r\ntilt=46.1914\r\nzoom=1\r\niris=2500\r\nfocus=7000\r\nautofocus=on\r\n"
                       "autoiris=on\r\n",
                       reply),
            "");
  EXPECT_FALSE(reply.error);
  ASSERT_EQ(reply.values.size(), 7u);
  ASSERT_NE(reply.find("autofocus"), nullptr);
  EXPECT_EQ(*reply.find("autofocus"), "on");
  Position position;
  ASSERT_EQ(readPosition(reply, position), "");
  EXPECT_DOUBLE_EQ(position.pan, 51.2891);  // fractional degrees, never rounded to whole ones
  EXPECT_DOUBLE_EQ(position.tilt, 46.1914);
  EXPECT_DOUBLE_EQ(position.zoom, 1.0);
}

TEST(VapixCodec, ReadsTheLimitsReplyOfTheSpec)
{
  Reply reply;
  ASSERT_EQ(parseReply("MinPan=-170\nMaxPan=170\nMinTilt=-20\nMaxTilt=90\nMinZoom=1\nMaxZoom=9999\nMinIris=1\n"
                       "MaxIris=9999\nMinFocus=1\nMaxFocus=9999\nMinFieldAngle=22\nMaxFieldAngle=623\n",
                       reply),
            "");
  Limits limits;
  ASSERT_EQ(readLimits(reply, limits), "");
  EXPECT_EQ(limits.min_pan, -170.0);
  EXPECT_EQ(limits.max_pan, 170.0);
  EXPECT_EQ(limits.min_tilt, -20.0);
  EXPECT_EQ(limits.max_tilt, 90.0);
  EXPECT_TRUE(limits.has_zoom);
  EXPECT_EQ(limits.max_zoom, 9999.0);
}

TEST(VapixCodec, AnErrorBodyCarriesTheCamerasWords)
{
  Reply reply;
  ASSERT_EQ(parseReply("Error:\nquery: unknown value: X\n", reply), "");
  EXPECT_TRUE(reply.error);
  EXPECT_EQ(reply.error_text, "query: unknown value: X");
  ASSERT_EQ(parseReply("Error:\r\nfirst\r\nsecond", reply), "");
  EXPECT_EQ(reply.error_text, "first; second");
  ASSERT_EQ(parseReply("Error:", reply), "");
  EXPECT_EQ(reply.error_text, "(no reason given)");
}

TEST(VapixCodec, MalformedRepliesAreNamed)
{
  Reply reply;
  EXPECT_EQ(parseReply("pan=1\ngarbage\n", reply), "line 2 'garbage' is not key=value");
  EXPECT_TRUE(reply.values.empty());
  EXPECT_EQ(parseReply("<html>401</html>", reply), "line 1 '<html>401</html>' is not key=value");
  ASSERT_EQ(parseReply("", reply), "");
  Position position;
  EXPECT_EQ(readPosition(reply, position), "no pan");
  ASSERT_EQ(parseReply("pan=abc\ntilt=1", reply), "");
  EXPECT_EQ(readPosition(reply, position), "pan 'abc' is not a number");
  ASSERT_EQ(parseReply("pan=nan\ntilt=1", reply), "");
  EXPECT_EQ(readPosition(reply, position), "pan 'nan' is not a number");
  ASSERT_EQ(parseReply("pan=1e9\ntilt=1", reply), "");
  EXPECT_NE(readPosition(reply, position), "");
  Limits limits;
  ASSERT_EQ(parseReply("MinPan=10\nMaxPan=-10\nMinTilt=-20\nMaxTilt=90", reply), "");
  EXPECT_NE(readLimits(reply, limits).find("make no sense"), std::string::npos);
  double value = 0.0;
  for (const char* bad : { "", " 1", "1 ", "0x10", "inf", "1,5", "--1" })
  {
    EXPECT_FALSE(parseNumber(bad, value)) << bad;
  }
  EXPECT_TRUE(parseNumber("-0.5", value));
  EXPECT_EQ(value, -0.5);
}

TEST(VapixCodec, CommandsCarryFractionalDegreesAndClampedPercentages)
{
  std::string out;
  appendAbsoluteMove(out, 51.28912, -3.5, 2345.4, 100);
  EXPECT_EQ(out, "pan=51.2891&tilt=-3.5000&zoom=2345&speed=100");
  out.clear();
  appendAbsoluteMove(out, 0.25, 0.0, 0.0, 250);  // no zoom; speed at most 100
  EXPECT_EQ(out, "pan=0.2500&tilt=0.0000&speed=100");
  out.clear();
  appendContinuousMove(out, 20, -130, 50, true);
  EXPECT_EQ(out, "continuouspantiltmove=20,-100&continuouszoommove=50");
  out.clear();
  appendContinuousMove(out, 0, 0, 0, false);
  EXPECT_EQ(out, "continuouspantiltmove=0,0");
}

TEST(VapixZoomTable, MapsLinearlyBetweenTheTablesPoints)
{
  ZoomTable table;
  ASSERT_EQ(ZoomTable::parse("1:1,5000:4,9999:18", table), "");
  EXPECT_DOUBLE_EQ(table.toFactor(1), 1.0);
  EXPECT_DOUBLE_EQ(table.toFactor(5000), 4.0);
  EXPECT_DOUBLE_EQ(table.toFactor(9999), 18.0);
  // Halfway between two points, halfway between their X: Axis cameras step the value evenly per X.
  EXPECT_NEAR(table.toFactor(2500.5), 2.5, 1e-9);
  EXPECT_NEAR(table.toFactor(7499.5), 11.0, 1e-9);
  for (double factor : { 1.0, 1.5, 2.0, 3.999, 4.0, 7.5, 17.9, 18.0 })
  {
    EXPECT_NEAR(table.toFactor(table.toValue(factor)), factor, 1e-9) << factor;
  }
  EXPECT_DOUBLE_EQ(table.toValue(0.5), 1.0);  // clamped into the table
  EXPECT_DOUBLE_EQ(table.toValue(40.0), 9999.0);
  EXPECT_DOUBLE_EQ(table.toValue(NAN), 1.0);
  EXPECT_EQ(table.toText(), "1:1,5000:4,9999:18");
  // The ends stay the ends.
  ASSERT_EQ(ZoomTable::parse("1:1,1000:1.35,2000:918", table), "");
  EXPECT_EQ(table.toFactor(table.maxValue()), table.maxFactor());
  EXPECT_EQ(table.toValue(table.maxFactor()), table.maxValue());
}

TEST(VapixZoomTable, ALinearTableMeetsTheStepsCamerasList)
{
  // A Q6075-E's steps (40X): 2X at 257, 3X at 513, 4X at 770, 12X at 2820 (1 + (X - 1) * 9998 / 39, rounded down).
  const ZoomTable q6075 = ZoomTable::linear(40.0);
  ASSERT_FALSE(q6075.empty());
  EXPECT_EQ(q6075.toText(), "1:1,9999:40");
  for (const auto& step : { std::make_pair(257.0, 2.0), std::make_pair(513.0, 3.0), std::make_pair(770.0, 4.0),
                            std::make_pair(2820.0, 12.0) })
  {
    EXPECT_NEAR(q6075.toValue(step.second), step.first, 1.0) << step.second << "X";
  }
  // A 29X camera with 12X digital zoom, as its web interface lists it: 15X at 5000, 29X at 9999, 58X at 10909,
  // 348X at 19999.
  const ZoomTable digital = ZoomTable::linear(29.0, 12.0);
  EXPECT_NEAR(digital.toFactor(5000), 15.0, 0.01);
  EXPECT_DOUBLE_EQ(digital.toFactor(9999), 29.0);
  EXPECT_NEAR(digital.toFactor(10909), 58.0, 0.1);
  EXPECT_DOUBLE_EQ(digital.toFactor(19999), 348.0);
  EXPECT_TRUE(ZoomTable::linear(1.0).empty());
  EXPECT_TRUE(ZoomTable::linear(NAN).empty());
}

TEST(VapixZoomTable, RejectsTablesThatCannotMap)
{
  ZoomTable table;
  EXPECT_EQ(ZoomTable::parse("", table), "a zoom table needs at least two VALUE:X points");
  EXPECT_EQ(ZoomTable::parse("1:1", table), "a zoom table needs at least two VALUE:X points");
  EXPECT_EQ(ZoomTable::parse("1:1,500", table), "point 2 '500' is not VALUE:X");
  EXPECT_EQ(ZoomTable::parse("1:1,500:0.5", table), "point 2 '500:0.5': values and X must increase");
  EXPECT_EQ(ZoomTable::parse("1:1,1:2", table), "point 2 '1:2': values and X must increase");
  EXPECT_NE(ZoomTable::parse("1:0,2:1", table), "");
  EXPECT_EQ(ZoomTable::parse("1:1,9999:1e300", table), "point 2 '9999:1e300': X must be 0.01..100000 and the value "
                                                       "0..19999");
  // X one ulp apart (found by the fuzzer): no value between them could be read back from its X.
  EXPECT_EQ(ZoomTable::parse("0:1,9999:1.0000000000000002", table), "point 2 '9999:1.0000000000000002': X must grow by "
                                                                    "at least 0.001 % from the point before");
  EXPECT_TRUE(table.empty());
  // The smallest step taken still maps every value in the table there and back.
  ASSERT_EQ(ZoomTable::parse("0:1,9999:1.000011", table), "");
  for (double value : { 0.0, 1.0, 2999.7, 5000.0, 9999.0 })
  {
    EXPECT_NEAR(table.toValue(table.toFactor(value)), value, 1e-6 * std::max(1.0, value)) << value;
  }
}

// ---------------------------------------------------------------- a camera in the field (issue 21)

/// Its info=1: the commands VAPIX documents, and no attributes among the queries.
const char* const FIELD_INFO = "Available commands:\r\n"
                               "{camera=[n]}\r\n"
                               "whoami=yes\r\n"
                               "center=[x],[y]\r\n"
                               "   imagewidth=[n]\r\n"
                               "   imageheight=[n]\r\n"
                               "areazoom=[x],[y],[z]\r\n"
                               "   imagewidth=[n]\r\n"
                               "   imageheight=[n]\r\n"
                               "move={ home | up | down | left | right | upleft | upright | downleft | downright | "
                               "stop }\r\n"
                               "pan=[abspos]\r\n"
                               "tilt=[abspos]\r\n"
                               "zoom=[n]\r\n"
                               "focus=[n]\r\n"
                               "iris=[n]\r\n"
                               "brightness=[offset]\r\n"
                               "rpan=[offset]\r\n"
                               "rtilt=[offset]\r\n"
                               "rzoom=[offset]\r\n"
                               "autofocus={ on | off }\r\n"
                               "autoiris={ on | off }\r\n"
                               "continuouspantiltmove=[x-speed],[y-speed]\r\n"
                               "continuouszoommove=[speed]\r\n"
                               "continuousfocusmove=[speed]\r\n"
                               "gotoserverpresetname=[name]\r\n"
                               "gotoserverpresetno=[n]\r\n"
                               "speed=[n]\r\n"
                               "query={ speed | position | limits | presetposcam | presetposall }\r\n";

TEST(VapixFieldCamera, InfoListsNoAttributesButPresetsHomeAndRelativeMoves)
{
  const CommandList commands = readCommandList(FIELD_INFO);
  ASSERT_FALSE(commands.empty());
  for (const char* name : { "camera", "pan", "tilt", "zoom", "rpan", "rtilt", "continuouspantiltmove",
                            "continuouszoommove", "gotoserverpresetno", "speed", "query" })
  {
    EXPECT_TRUE(commands.has(name)) << name;
  }
  for (const char* query : { "speed", "position", "limits", "presetposcam", "presetposall" })
  {
    EXPECT_TRUE(commands.offers("query", query)) << query;
  }
  EXPECT_FALSE(commands.offers("query", "attributes"));
  EXPECT_TRUE(commands.offers("move", "home"));
  EXPECT_FALSE(commands.offers("move", "sideways"));
  EXPECT_FALSE(commands.has("Available commands:"));
  // An Error: body or nonsense offers nothing (the backend then assumes what VAPIX documents).
  EXPECT_TRUE(readCommandList("Error:\r\ninfo: unknown value: 2\r\n").empty());
  EXPECT_TRUE(readCommandList("<html>oops</html>").empty());
}

TEST(VapixFieldCamera, AskingForTheAttributesIsRefusedInTheCamerasWords)
{
  for (const char* body : { "Error:\r\nquery: unknown value: attributes\r\n", "Error: query: unknown value: "
                                                                              "attributes" })
  {
    ZoomAttributes attributes;
    ASSERT_EQ(readZoomAttributes(body, 1, attributes), "") << body;
    EXPECT_TRUE(attributes.refused);
    EXPECT_EQ(attributes.refusal, "query: unknown value: attributes");
    ZoomTable table;
    EXPECT_NE(zoomTableOf(attributes, table), "");
    EXPECT_TRUE(table.empty());
  }
}

TEST(VapixFieldCamera, LimitsAndPositionCarryTheZoomAndMore)
{
  Reply reply;
  ASSERT_EQ(parseReply("MinPan=-180\r\nMaxPan=180\r\nMinTilt=-90\r\nMaxTilt=20\r\nMinZoom=1\r\nMaxZoom=9999\r\n"
                       "MinIris=1\r\nMaxIris=9999\r\nMinFocus=1\r\nMaxFocus=9999\r\nMinFieldAngle=23\r\n"
                       "MaxFieldAngle=642\r\n",
                       reply),
            "");
  Limits limits;
  ASSERT_EQ(readLimits(reply, limits), "");
  EXPECT_TRUE(limits.has_zoom);
  EXPECT_EQ(limits.min_zoom, 1.0);
  EXPECT_EQ(limits.max_zoom, 9999.0);
  EXPECT_EQ(limits.max_tilt, 20.0);
  ASSERT_EQ(parseReply("pan=-12.3456\r\ntilt=-30.5\r\nzoom=2500\r\niris=3072\r\nfocus=6554\r\nbrightness=4999\r\n"
                       "autofocus=on\r\nautoiris=on\r\n",
                       reply),
            "");
  Position position;
  ASSERT_EQ(readPosition(reply, position), "");
  EXPECT_TRUE(position.has_zoom);
  EXPECT_EQ(position.zoom, 2500.0);
  EXPECT_EQ(position.pan, -12.3456);
  ASSERT_EQ(parseReply("pan=1\r\ntilt=2\r\n", reply), "");
  ASSERT_EQ(readPosition(reply, position), "");
  EXPECT_FALSE(position.has_zoom);
}

TEST(VapixAttributes, TheDocumentedSectionsGiveTheZoomStepsOfTheChannelAsked)
{
  const std::string body = "Attributes for camera 1\r\n"
                           "speeds=value=1 | speed=0.05,value=9 | speed=0.16,value=100 | speed=150\r\n"
                           "maxOpticalZoomMag=30\r\n"
                           "zoomSteps=value=1 | zoom=1,value=3868 | zoom=2 | visible=false,value=7736 | zoom=3,"
                           "value=9999 | zoom=3.584961\r\n"
                           "Attributes for camera 2\r\n"
                           "maxOpticalZoomMag=12\r\n"
                           "maxDigitalZoomMag=4\r\n";
  ZoomAttributes first;
  ASSERT_EQ(readZoomAttributes(body, 1, first), "");
  EXPECT_FALSE(first.refused);
  EXPECT_EQ(first.max_optical, 30.0);
  ASSERT_EQ(first.steps.size(), 4u);
  EXPECT_EQ(first.steps[1], std::make_pair(3868.0, 2.0));
  EXPECT_EQ(first.steps[3], std::make_pair(9999.0, 3.584961));
  ZoomTable table;
  ASSERT_EQ(zoomTableOf(first, table), "");  // the steps win over the maximum
  EXPECT_DOUBLE_EQ(table.toFactor(7736), 3.0);
  EXPECT_DOUBLE_EQ(table.maxFactor(), 3.584961);

  ZoomAttributes second;
  ASSERT_EQ(readZoomAttributes(body, 2, second), "");
  EXPECT_TRUE(second.steps.empty());
  ASSERT_EQ(zoomTableOf(second, table), "");  // no steps: the maximum, linear, with the digital range
  EXPECT_DOUBLE_EQ(table.toFactor(9999), 12.0);
  EXPECT_DOUBLE_EQ(table.toFactor(19999), 48.0);

  ZoomAttributes third;
  EXPECT_EQ(readZoomAttributes(body, 3, third), "no attributes for camera 3");
  // Without sections the answer is the channel's own; without zoom figures it gives no table.
  ASSERT_EQ(readZoomAttributes("maxOpticalZoomMag=20\r\n", 1, third), "");
  EXPECT_EQ(third.max_optical, 20.0);
  ASSERT_EQ(readZoomAttributes("Attributes for camera 1\r\n", 1, third), "");
  EXPECT_EQ(zoomTableOf(third, table), "no zoomSteps and no maxOpticalZoomMag");
}

TEST(VapixAttributes, UnreadableAttributesAreNamed)
{
  ZoomAttributes attributes;
  EXPECT_EQ(
      readZoomAttributes("Attributes for camera 1\r\nzoomSteps=value=1 | zoom=1,value=x | zoom=2\r\n", 1, attributes),
      "zoomSteps entry 2 'value=x | zoom=2' has no numbers value= and zoom=");
  EXPECT_EQ(readZoomAttributes("<html>hello</html>", 1, attributes), "line 1 '<html>hello</html>' is neither "
                                                                     "'Attributes for camera N' nor name=value");
  EXPECT_EQ(readZoomAttributes("maxOpticalZoomMag=0.5", 1, attributes), "maxOpticalZoomMag '0.5' is not a "
                                                                        "magnification");
  ASSERT_EQ(readZoomAttributes("zoomSteps=value=1 | zoom=2,value=2 | zoom=1", 1, attributes), "");
  ZoomTable table;
  EXPECT_EQ(zoomTableOf(attributes, table), "point 2 '2:1': values and X must increase");
}

TEST(VapixBrand, TheProductNumberAndItsFamilysZoom)
{
  Reply reply;
  ASSERT_EQ(parseReply("root.Brand.Brand=AXIS\r\nroot.Brand.ProdFullName=AXIS Q6155-E PTZ Dome Network Camera\r\n"
                       "root.Brand.ProdNbr=Q6155-E\r\nroot.Brand.ProdShortName=AXIS Q6155-E\r\n"
                       "root.Brand.ProdType=PTZ Dome Network Camera\r\nroot.Brand.ProdVariant=\r\n"
                       "root.Brand.WebURL=http://www.axis.com\r\n",
                       reply),
            "");
  Product product;
  ASSERT_EQ(readProduct(reply, product), "");
  EXPECT_EQ(product.number, "Q6155-E");
  EXPECT_EQ(product.full_name, "AXIS Q6155-E PTZ Dome Network Camera");
  FamilyZoom zoom;
  ASSERT_TRUE(modelFamilyZoom(product.number, zoom));
  EXPECT_EQ(zoom.family, "Q61");
  EXPECT_EQ(zoom.max_optical, 30.0);
  ASSERT_TRUE(modelFamilyZoom("m5525-e", zoom));
  EXPECT_EQ(zoom.max_optical, 10.0);
  for (const char* unknown : { "Q8665-E", "214", "M1065-LW", "", "Q6" })
  {
    EXPECT_FALSE(modelFamilyZoom(unknown, zoom)) << unknown;
  }
  for (const FamilyZoom& family : modelFamilyZooms())
  {
    EXPECT_FALSE(ZoomTable::linear(family.max_optical).empty()) << family.family;
  }
  ASSERT_EQ(parseReply("# Error: Error -1 getting param in group 'root.Brand'\r\n", reply).empty(), false);
  ASSERT_EQ(parseReply("root.Brand.Brand=AXIS\r\n", reply), "");
  EXPECT_EQ(readProduct(reply, product), "no root.Brand.ProdNbr");
}

TEST(VapixCodec, AnAxisGivenAsNaNIsLeftOut)
{
  std::string out;
  appendAbsoluteMove(out, 12.5, NAN, NAN, 50);
  EXPECT_EQ(out, "pan=12.5000&speed=50");
  out.clear();
  appendAbsoluteMove(out, NAN, -3.0, 4000.4, 100);
  EXPECT_EQ(out, "tilt=-3.0000&zoom=4000&speed=100");
}

TEST(CameraDigests, Rfc7616Md5Example)
{
  // RFC 7616 section 3.9.1, MD5.
  EXPECT_EQ(httpDigestResponse("Mufasa", "http-auth@example.org", "Circle of Life", "GET", "/dir/index.html",
                               "7ypf/xlj9XXwfDPEoM4URrv/xwf94BcCAzFZH4GiTo0v", "00000001",
                               "f2/wE4q74E6zIJEtWaHKaf5wv/H5QzzpXusqGemxURZJ"),
            "8ca523f5e9506fed4657c9700eebdbec");
}

TEST(CameraDigests, Sha1AndBase64Vectors)
{
  EXPECT_EQ(md5Hex(""), "d41d8cd98f00b204e9800998ecf8427e");
  EXPECT_EQ(base64Encode(sha1("abc")), "qZk+NkcGgWq6PiVxeFDCbJzQ2J0=");  // a9993e36...d89d
  EXPECT_EQ(base64Encode(""), "");
  EXPECT_EQ(base64Encode("f"), "Zg==");
  EXPECT_EQ(base64Encode("fo"), "Zm8=");
  EXPECT_EQ(base64Encode("foo"), "Zm9v");
  std::string decoded;
  ASSERT_TRUE(base64Decode("Zm8=", decoded));
  EXPECT_EQ(decoded, "fo");
  ASSERT_TRUE(base64Decode("Zg==", decoded));
  EXPECT_EQ(decoded, "f");
  EXPECT_FALSE(base64Decode("Zm8", decoded));
  EXPECT_FALSE(base64Decode("Z!8=", decoded));
}

}  // namespace
}  // namespace ptz_action_server

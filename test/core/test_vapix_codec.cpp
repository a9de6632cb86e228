/**
 * \file
 * \brief The VAPIX codec against the replies of protocols.md section 6, the zoom table, and the digests IP cameras
 * authenticate with (RFC 7616's MD5 example; SHA-1 and Base64 vectors).
 */
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/http/crypto.h"
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

TEST(VapixZoomTable, MapsThroughTheTableNeverLinearly)
{
  ZoomTable table;
  ASSERT_EQ(ZoomTable::parse("1:1,5000:4,9999:18", table), "");
  EXPECT_DOUBLE_EQ(table.toFactor(1), 1.0);
  EXPECT_DOUBLE_EQ(table.toFactor(5000), 4.0);
  EXPECT_DOUBLE_EQ(table.toFactor(9999), 18.0);
  // Halfway between two points, the magnification is their geometric mean: 2X at 2500.5, not the linear 2.5X.
  EXPECT_NEAR(table.toFactor(2500.5), 2.0, 1e-9);
  const double linear_guess = 1.0 + (9999.0 - 1.0) * (2.0 - 1.0) / (18.0 - 1.0);
  EXPECT_GT(std::abs(table.toValue(2.0) - linear_guess), 1000.0);
  for (double factor : { 1.0, 1.5, 2.0, 3.999, 4.0, 7.5, 17.9, 18.0 })
  {
    EXPECT_NEAR(table.toFactor(table.toValue(factor)), factor, 1e-9) << factor;
  }
  EXPECT_DOUBLE_EQ(table.toValue(0.5), 1.0);  // clamped into the table
  EXPECT_DOUBLE_EQ(table.toValue(40.0), 9999.0);
  EXPECT_EQ(table.toText(), "1:1,5000:4,9999:18");
  // The ends stay the ends (the fuzzer found pow an ulp beyond them).
  ASSERT_EQ(ZoomTable::parse("1:1,1000:1.35,2000:918", table), "");
  EXPECT_EQ(table.toFactor(table.maxValue()), table.maxFactor());
  EXPECT_EQ(table.toValue(table.maxFactor()), table.maxValue());
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
  EXPECT_EQ(ZoomTable::parse("1:1,9999:1e300", table), "point 2 '9999:1e300': X must be 0.01..100000 and the value 0..19999");
  // X one ulp apart (found by the fuzzer): no value between them could be read back from its X.
  EXPECT_EQ(ZoomTable::parse("0:1,9999:1.0000000000000002", table),
            "point 2 '9999:1.0000000000000002': X must grow by at least 0.0001 % from the point before");
  EXPECT_TRUE(table.empty());
  // The smallest step taken still maps every value in the table there and back.
  ASSERT_EQ(ZoomTable::parse("0:1,9999:1.0000011", table), "");
  for (double value : { 0.0, 1.0, 2999.7, 5000.0, 9999.0 })
  {
    EXPECT_NEAR(table.toValue(table.toFactor(value)), value, 1e-6 * std::max(1.0, value)) << value;
  }
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

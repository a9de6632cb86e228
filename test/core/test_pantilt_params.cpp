#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

// The params frame (PanTiltParams encode/decode, the mask) and JSON; the commands are in test_pantilt_codec.cpp.

using namespace cr::pantilt;
using Bytes = std::vector<std::uint8_t>;

namespace
{
const WireVersion BOTH_VERSIONS[] = { WireVersion::V1_0, WireVersion::V1_1 };

Bytes paramsFrame(const PanTiltParams& params, WireVersion version, const PanTiltParamsMask* mask = nullptr)
{
  Bytes frame(MAX_PARAMS_FRAME_SIZE);
  int size = -1;
  EXPECT_TRUE(params.encode(frame.data(), static_cast<int>(frame.size()), size, mask, version));
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

/// Params with a distinct value in every field.
PanTiltParams distinctParams()
{
  PanTiltParams params;
  params.panMotorPosition = 43565;
  params.tiltMotorPosition = 10500;
  params.panAngle = 30.5f;
  params.tiltAngle = -89.9f;
  params.panTiltMotorPosition = 300;
  params.panTiltAngle = 60.0f;
  params.panMotorSpeed = 50.0f;
  params.tiltMotorSpeed = 100.0f;
  params.panTiltMotorSpeed = 10.5f;
  params.isConnected = true;
  params.isOpen = true;
  params.custom1 = 1.25f;
  params.custom2 = -2.5f;
  params.custom3 = 1e6f;
  return params;
}
}  // namespace

// --- Golden frames from protocols.md

TEST(PanTiltGolden, FullParamsFrameIn1_1)
{
  PanTiltParams params;
  params.panMotorPosition = 100;
  params.tiltMotorPosition = 200;
  params.panAngle = 10.0f;
  params.tiltAngle = -5.0f;
  params.panMotorSpeed = 1.0f;
  params.tiltMotorSpeed = 2.0f;
  params.isConnected = true;
  params.isOpen = true;
  Bytes expected = { 0x02, 0x01, 0x01, 0xFF, 0xE0, 0x64, 0x00, 0x00, 0x00, 0xC8, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20,
                     0x41, 0x00, 0x00, 0xA0, 0xC0, 0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0x40, 0x01, 0x01 };
  expected.resize(expected.size() + 12, 0x00);
  EXPECT_EQ(paramsFrame(params, WireVersion::V1_1), expected);
  EXPECT_EQ(expected.size(), 43u);
}

TEST(PanTiltGolden, FullParamsFrameIn1_0HasNineFieldsAndTwoMaskBytes)
{
  const Bytes frame = paramsFrame(distinctParams(), WireVersion::V1_0);
  ASSERT_EQ(frame.size(), 41u);
  EXPECT_EQ(frame[0], 0x02);
  EXPECT_EQ(frame[1], 0x01);
  EXPECT_EQ(frame[2], 0x00);
  EXPECT_EQ(frame[3], 0xFF);
  EXPECT_EQ(frame[4], 0x80);
  EXPECT_EQ((Bytes(frame.begin() + 5, frame.begin() + 9)), (Bytes{ 0x2D, 0xAA, 0x00, 0x00 }));  // 43565
}

// --- Round trips

TEST(PanTiltRoundTrip, ParamsWithEveryMask)
{
  const PanTiltParams source = distinctParams();
  for (WireVersion version : BOTH_VERSIONS)
  {
    // The fields of this format, in frame order, as mask members.
    std::vector<bool PanTiltParamsMask::*> fields = { &PanTiltParamsMask::panMotorPosition,
                                                      &PanTiltParamsMask::tiltMotorPosition,
                                                      &PanTiltParamsMask::panAngle, &PanTiltParamsMask::tiltAngle };
    if (version == WireVersion::V1_0)
    {
      fields.insert(fields.end(), { &PanTiltParamsMask::panTiltMotorPosition, &PanTiltParamsMask::panTiltAngle,
                                    &PanTiltParamsMask::panMotorSpeed, &PanTiltParamsMask::tiltMotorSpeed,
                                    &PanTiltParamsMask::panTiltMotorSpeed });
    }
    else
    {
      fields.insert(fields.end(),
                    { &PanTiltParamsMask::panMotorSpeed, &PanTiltParamsMask::tiltMotorSpeed,
                      &PanTiltParamsMask::isConnected, &PanTiltParamsMask::isOpen, &PanTiltParamsMask::custom1,
                      &PanTiltParamsMask::custom2, &PanTiltParamsMask::custom3 });
    }
    for (unsigned bits = 0; bits < (1u << fields.size()); ++bits)
    {
      PanTiltParamsMask mask = PanTiltParamsMask::none();
      for (std::size_t index = 0; index < fields.size(); ++index)
      {
        mask.*fields[index] = (bits >> index) & 1u;
      }
      const Bytes frame = paramsFrame(source, version, &mask);
      PanTiltParams decoded = distinctParams();  // decode must overwrite every field
      DecodeError error = DecodeError::BAD_ID;
      ASSERT_TRUE(decoded.decode(frame.data(), static_cast<int>(frame.size()), version, &error)) << bits;
      EXPECT_EQ(error, DecodeError::NONE);
      PanTiltParams expected;  // absent fields, and the other format's fields, decode as 0
      expected.panMotorPosition = mask.panMotorPosition ? source.panMotorPosition : 0;
      expected.tiltMotorPosition = mask.tiltMotorPosition ? source.tiltMotorPosition : 0;
      expected.panAngle = mask.panAngle ? source.panAngle : 0.0f;
      expected.tiltAngle = mask.tiltAngle ? source.tiltAngle : 0.0f;
      expected.panMotorSpeed = mask.panMotorSpeed ? source.panMotorSpeed : 0.0f;
      expected.tiltMotorSpeed = mask.tiltMotorSpeed ? source.tiltMotorSpeed : 0.0f;
      if (version == WireVersion::V1_0)
      {
        expected.panTiltMotorPosition = mask.panTiltMotorPosition ? source.panTiltMotorPosition : 0;
        expected.panTiltAngle = mask.panTiltAngle ? source.panTiltAngle : 0.0f;
        expected.panTiltMotorSpeed = mask.panTiltMotorSpeed ? source.panTiltMotorSpeed : 0.0f;
      }
      else
      {
        expected.isConnected = mask.isConnected && source.isConnected;
        expected.isOpen = mask.isOpen && source.isOpen;
        expected.custom1 = mask.custom1 ? source.custom1 : 0.0f;
        expected.custom2 = mask.custom2 ? source.custom2 : 0.0f;
        expected.custom3 = mask.custom3 ? source.custom3 : 0.0f;
      }
      ASSERT_EQ(decoded, expected) << "mask bits " << bits;
    }
  }
}

TEST(PanTiltRoundTrip, EncodeRefusesASmallBuffer)
{
  std::uint8_t frame[40];
  int size = -1;
  EXPECT_FALSE(distinctParams().encode(frame, sizeof(frame), size));
  EXPECT_EQ(size, 0);
  std::uint8_t exact[41];
  EXPECT_TRUE(distinctParams().encode(exact, sizeof(exact), size));
  EXPECT_EQ(size, 41);
}

TEST(PanTiltRoundTrip, JsonFileUnderAKey)
{
  const std::string path = ::testing::TempDir() + "pantilt_params.json";
  const PanTiltParams source = distinctParams();
  ASSERT_TRUE(source.writeToFile(path));
  std::ifstream file(path);
  const nlohmann::json document = nlohmann::json::parse(file);
  ASSERT_TRUE(document.contains("panTiltParams"));
  EXPECT_EQ(document["panTiltParams"]["panMotorPosition"], 43565);
  EXPECT_EQ(document["panTiltParams"]["isOpen"], true);
  EXPECT_EQ(document["panTiltParams"].size(), 14u);

  PanTiltParams read;
  std::string error;
  ASSERT_TRUE(read.readFromFile(path, "panTiltParams", &error)) << error;
  EXPECT_EQ(read, source);
  EXPECT_FALSE(read.readFromFile(path, "otherKey", &error));
  EXPECT_NE(error.find("otherKey"), std::string::npos);

  nlohmann::json wrong = source.toJson();
  wrong["panAngle"] = "thirty";
  PanTiltParams unchanged = source;
  EXPECT_FALSE(unchanged.fromJson(wrong, &error));
  EXPECT_EQ(error, "field 'panAngle' has the wrong type");
  EXPECT_EQ(unchanged, source);
  std::remove(path.c_str());
}

// --- Rejections

TEST(PanTiltDecoder, RejectsMalformedParamsAndKeepsTheOldValues)
{
  const Bytes full = paramsFrame(distinctParams(), WireVersion::V1_0);
  Bytes truncated = full;
  truncated.pop_back();
  Bytes longer = full;
  longer.push_back(0);
  Bytes unknown_bit = full;
  unknown_bit[4] |= 0x40;  // a tenth field in 1.0
  Bytes wrong_version = full;
  wrong_version[2] = 1;
  Bytes wrong_header = full;
  wrong_header[0] = 0x01;
  PanTiltParamsMask only_pan = PanTiltParamsMask::none();
  only_pan.panAngle = true;
  const Bytes short_frame = paramsFrame(distinctParams(), WireVersion::V1_0, &only_pan);
  Bytes mask_claims_more = short_frame;
  mask_claims_more[3] |= 0x01;  // claims tiltMotorSpeed too, 4 bytes that are not there
  const Bytes v11 = paramsFrame(distinctParams(), WireVersion::V1_1);
  Bytes v11_unknown_bit = v11;
  v11_unknown_bit[4] |= 0x10;  // a twelfth field in 1.1
  struct Case
  {
    const char* name;
    Bytes bytes;
    WireVersion version;
    DecodeError error;
  };
  const std::vector<Case> cases = {
    { "empty", {}, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "header only, 4 bytes", Bytes(full.begin(), full.begin() + 4), WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "one byte short", truncated, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "one byte long", longer, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "mask claims a field that is not there", mask_claims_more, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "unknown mask bit", unknown_bit, WireVersion::V1_0, DecodeError::BAD_MASK },
    { "unknown 1.1 mask bit", v11_unknown_bit, WireVersion::V1_1, DecodeError::BAD_MASK },
    { "wrong version", wrong_version, WireVersion::V1_0, DecodeError::BAD_VERSION },
    { "1.1 frame to a 1.0 decoder", v11, WireVersion::V1_0, DecodeError::BAD_VERSION },
    { "command header", wrong_header, WireVersion::V1_0, DecodeError::BAD_HEADER },
  };
  for (const Case& item : cases)
  {
    PanTiltParams params = distinctParams();
    DecodeError error = DecodeError::NONE;
    EXPECT_FALSE(params.decode(item.bytes.data(), static_cast<int>(item.bytes.size()), item.version, &error))
        << item.name;
    EXPECT_EQ(error, item.error) << item.name << ": " << toString(error);
    EXPECT_EQ(params, distinctParams()) << item.name;
  }
  // An empty mask is a valid (5-byte) frame: it is the backend's state request.
  const PanTiltParamsMask none = PanTiltParamsMask::none();
  EXPECT_EQ(paramsFrame(distinctParams(), WireVersion::V1_0, &none), (Bytes{ 0x02, 0x01, 0x00, 0x00, 0x00 }));
}

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "pantilt_golden_params.h"
#include "ptz_action_server/core/pantilt/pantilt_codec.h"

// The params frame (PanTiltParams encode/decode, the mask) and JSON; the commands are in test_pantilt_codec.cpp.

using namespace cr::pantilt;
using Bytes = std::vector<std::uint8_t>;

using pantilt_test::goldenParams;

namespace
{
Bytes paramsFrame(const PanTiltParams& params, WireFormat format, const PanTiltParamsMask* mask = nullptr)
{
  Bytes frame(MAX_PARAMS_FRAME_SIZE);
  int size = -1;
  EXPECT_TRUE(params.encode(frame.data(), static_cast<int>(frame.size()), size, mask, format));
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

/// \p params with the fields \p format lacks zeroed: what a frame of \p format decodes to.
PanTiltParams onlyFieldsOf(PanTiltParams params, WireFormat format)
{
  if (format == WireFormat::SEED)
  {
    params.isConnected = params.isOpen = false;
    params.custom1 = params.custom2 = params.custom3 = 0.0f;
  }
  else
  {
    params.panTiltMotorPosition = 0;
    params.panTiltAngle = params.panTiltMotorSpeed = 0.0f;
  }
  return params;
}

PanTiltParamsMask only(bool PanTiltParamsMask::*field)
{
  PanTiltParamsMask mask = PanTiltParamsMask::none();
  mask.*field = true;
  return mask;
}
}  // namespace

// --- Golden frames printed by the published implementations (published-wire-facts.md 2.2, 2.3), both ways

TEST(PanTiltGolden, SeedParamsFramesInThePublishedEncodersAlphabeticalOrder)
{
  // Not the class's declaration order (which the seed's text suggests and this library once used): mask0 bit 7 is
  // panAngle, the first field alphabetically.
  const Bytes full = { 0x02, 0x01, 0x00, 0xFF, 0x80, 0x00, 0x00, 0x20, 0x41, 0x64, 0x00, 0x00, 0x00, 0x00,
                       0x00, 0x80, 0x3F, 0x00, 0x00, 0x36, 0x42, 0x2C, 0x01, 0x00, 0x00, 0x00, 0x00, 0x40,
                       0x40, 0x00, 0x00, 0xA0, 0xC0, 0xC8, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x40 };
  const Bytes pan_motor_position = { 0x02, 0x01, 0x00, 0x40, 0x00, 0x64, 0x00, 0x00, 0x00 };
  const Bytes tilt_motor_speed = { 0x02, 0x01, 0x00, 0x00, 0x80, 0x00, 0x00, 0x00, 0x40 };
  const PanTiltParamsMask pan_motor_position_mask = only(&PanTiltParamsMask::panMotorPosition);
  const PanTiltParamsMask tilt_motor_speed_mask = only(&PanTiltParamsMask::tiltMotorSpeed);
  const PanTiltParamsMask none = PanTiltParamsMask::none();
  EXPECT_EQ(paramsFrame(goldenParams(), WireFormat::SEED), full);
  EXPECT_EQ(full.size(), 41u);
  EXPECT_EQ(paramsFrame(goldenParams(), WireFormat::SEED, &pan_motor_position_mask), pan_motor_position);
  EXPECT_EQ(paramsFrame(goldenParams(), WireFormat::SEED, &tilt_motor_speed_mask), tilt_motor_speed);
  EXPECT_EQ(paramsFrame(goldenParams(), WireFormat::SEED, &none), (Bytes{ 0x02, 0x01, 0x00, 0x00, 0x00 }));

  PanTiltParams decoded;
  ASSERT_TRUE(decoded.decode(full.data(), static_cast<int>(full.size()), WireFormat::SEED));
  EXPECT_EQ(decoded, onlyFieldsOf(goldenParams(), WireFormat::SEED));
  ASSERT_TRUE(decoded.decode(pan_motor_position.data(), static_cast<int>(pan_motor_position.size()), WireFormat::SEED));
  PanTiltParams expected;
  expected.panMotorPosition = 100;
  EXPECT_EQ(decoded, expected);
}

TEST(PanTiltGolden, V1ParamsFramesDifferOnlyInTheMinorByte)
{
  Bytes full = { 0x02, 0x01, 0x01, 0xFF, 0xE0, 0x64, 0x00, 0x00, 0x00, 0xC8, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20,
                 0x41, 0x00, 0x00, 0xA0, 0xC0, 0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0x40, 0x01, 0x01 };
  full.resize(full.size() + 12, 0x00);  // the customs
  Bytes pan_motor_position = { 0x02, 0x01, 0x01, 0x80, 0x00, 0x64, 0x00, 0x00, 0x00 };
  const PanTiltParamsMask pan_motor_position_mask = only(&PanTiltParamsMask::panMotorPosition);
  for (WireFormat format : { WireFormat::V1_1, WireFormat::V1_0 })
  {
    SCOPED_TRACE(toString(format));
    full[2] = pan_motor_position[2] = format == WireFormat::V1_1 ? 0x01 : 0x00;
    EXPECT_EQ(paramsFrame(goldenParams(), format), full);
    EXPECT_EQ(full.size(), 43u);
    EXPECT_EQ(paramsFrame(goldenParams(), format, &pan_motor_position_mask), pan_motor_position);
    PanTiltParams decoded;
    ASSERT_TRUE(decoded.decode(full.data(), static_cast<int>(full.size()), format));
    EXPECT_EQ(decoded, onlyFieldsOf(goldenParams(), format));
  }
}

// --- Round trips

TEST(PanTiltRoundTrip, ParamsWithEveryMask)
{
  const PanTiltParams source = distinctParams();
  for (WireFormat format : ALL_WIRE_FORMATS)
  {
    // The fields of this format, as mask members.
    std::vector<bool PanTiltParamsMask::*> fields = { &PanTiltParamsMask::panMotorPosition,
                                                      &PanTiltParamsMask::tiltMotorPosition,
                                                      &PanTiltParamsMask::panAngle, &PanTiltParamsMask::tiltAngle };
    const bool seed = format == WireFormat::SEED;
    if (seed)
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
      const Bytes frame = paramsFrame(source, format, &mask);
      PanTiltParams decoded = distinctParams();  // decode must overwrite every field
      DecodeError error = DecodeError::BAD_ID;
      ASSERT_TRUE(decoded.decode(frame.data(), static_cast<int>(frame.size()), format, &error))
          << toString(format) << " mask bits " << bits << ": " << toString(error);
      EXPECT_EQ(error, DecodeError::NONE);
      PanTiltParams expected;  // absent fields, and the other format's fields, decode as 0
      expected.panMotorPosition = mask.panMotorPosition ? source.panMotorPosition : 0;
      expected.tiltMotorPosition = mask.tiltMotorPosition ? source.tiltMotorPosition : 0;
      expected.panAngle = mask.panAngle ? source.panAngle : 0.0f;
      expected.tiltAngle = mask.tiltAngle ? source.tiltAngle : 0.0f;
      expected.panMotorSpeed = mask.panMotorSpeed ? source.panMotorSpeed : 0.0f;
      expected.tiltMotorSpeed = mask.tiltMotorSpeed ? source.tiltMotorSpeed : 0.0f;
      if (seed)
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
      ASSERT_EQ(decoded, expected) << toString(format) << " mask bits " << bits;
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
  const Bytes full = paramsFrame(distinctParams(), WireFormat::SEED);
  Bytes truncated = full;
  truncated.pop_back();
  Bytes longer = full;
  longer.push_back(0);
  Bytes unknown_bit = full;
  unknown_bit[4] |= 0x40;  // a tenth field in the seed's format
  Bytes wrong_version = full;
  wrong_version[2] = 1;
  Bytes wrong_header = full;
  wrong_header[0] = 0x01;
  const PanTiltParamsMask only_pan = only(&PanTiltParamsMask::panAngle);
  const Bytes short_frame = paramsFrame(distinctParams(), WireFormat::SEED, &only_pan);
  Bytes mask_claims_more = short_frame;
  mask_claims_more[3] |= 0x01;  // claims tiltMotorPosition too, 4 bytes that are not there
  const Bytes v11 = paramsFrame(distinctParams(), WireFormat::V1_1);
  Bytes v11_unknown_bit = v11;
  v11_unknown_bit[4] |= 0x10;  // a twelfth field in v1.1
  // Values no device reports (the frame's size and mask are right).
  auto seed_with = [](auto change) {
    PanTiltParams params = distinctParams();
    change(params);
    return paramsFrame(params, WireFormat::SEED);
  };
  const Bytes pan_angle_too_large = seed_with([](PanTiltParams& params) { params.panAngle = 180.5f; });
  const Bytes tilt_angle_nan = seed_with([](PanTiltParams& params) { params.tiltAngle = std::nanf(""); });
  const Bytes tilt_angle_subnormal = seed_with([](PanTiltParams& params) { params.tiltAngle = 1e-40f; });
  const Bytes negative_position = seed_with([](PanTiltParams& params) { params.tiltMotorPosition = -1; });
  const Bytes position_too_large = seed_with([](PanTiltParams& params) { params.panTiltMotorPosition = 65536; });
  const Bytes speed_too_large = seed_with([](PanTiltParams& params) { params.panTiltMotorSpeed = 100.5f; });
  Bytes v11_flag_two = v11;
  v11_flag_two[29] = 2;  // isConnected, after the six 4-byte fields
  struct Case
  {
    const char* name;
    Bytes bytes;
    WireFormat format;
    DecodeError error;
  };
  const std::vector<Case> cases = {
    { "empty", {}, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "header only, 4 bytes", Bytes(full.begin(), full.begin() + 4), WireFormat::SEED, DecodeError::BAD_SIZE },
    { "one byte short", truncated, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "one byte long", longer, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "mask claims a field that is not there", mask_claims_more, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "unknown mask bit", unknown_bit, WireFormat::SEED, DecodeError::BAD_MASK },
    { "unknown v1.1 mask bit", v11_unknown_bit, WireFormat::V1_1, DecodeError::BAD_MASK },
    { "wrong version", wrong_version, WireFormat::SEED, DecodeError::BAD_VERSION },
    { "command header", wrong_header, WireFormat::SEED, DecodeError::BAD_HEADER },
    { "pan angle 180.5", pan_angle_too_large, WireFormat::SEED, DecodeError::BAD_VALUE },
    { "tilt angle NaN", tilt_angle_nan, WireFormat::SEED, DecodeError::BAD_VALUE },
    { "subnormal tilt angle", tilt_angle_subnormal, WireFormat::SEED, DecodeError::BAD_VALUE },
    { "motor position -1", negative_position, WireFormat::SEED, DecodeError::BAD_VALUE },
    { "motor position 65536", position_too_large, WireFormat::SEED, DecodeError::BAD_VALUE },
    { "speed 100.5 %", speed_too_large, WireFormat::SEED, DecodeError::BAD_VALUE },
    { "flag 2", v11_flag_two, WireFormat::V1_1, DecodeError::BAD_VALUE },
    // A valid frame, but of another format (test_pantilt_formats.cpp has every pair).
    { "v1.1 frame to a seed decoder", v11, WireFormat::SEED, DecodeError::FOREIGN_FORMAT },
  };
  for (const Case& item : cases)
  {
    PanTiltParams params = distinctParams();
    DecodeError error = DecodeError::NONE;
    EXPECT_FALSE(params.decode(item.bytes.data(), static_cast<int>(item.bytes.size()), item.format, &error))
        << item.name;
    EXPECT_EQ(error, item.error) << item.name << ": " << toString(error);
    EXPECT_EQ(params, distinctParams()) << item.name;
  }
  // An empty mask is a valid (5-byte) frame: it is the backend's state request.
  const PanTiltParamsMask none = PanTiltParamsMask::none();
  EXPECT_EQ(paramsFrame(distinctParams(), WireFormat::SEED, &none), (Bytes{ 0x02, 0x01, 0x00, 0x00, 0x00 }));
}

TEST(PanTiltDecoder, TakesTheLimitsThemselvesAndAnyCustomValue)
{
  PanTiltParams edge = distinctParams();
  edge.panAngle = -180.0f;
  edge.tiltAngle = 90.0f;
  edge.panMotorPosition = 65535;
  edge.tiltMotorPosition = 0;
  edge.panMotorSpeed = 100.0f;
  edge.custom1 = std::nanf("");
  edge.custom2 = 1e-40f;  // subnormal: the implementation's value, not a sign of another format
  edge.custom3 = -std::numeric_limits<float>::infinity();
  for (WireFormat format : ALL_WIRE_FORMATS)
  {
    const Bytes frame = paramsFrame(edge, format);
    PanTiltParams decoded;
    DecodeError error = DecodeError::NONE;
    EXPECT_TRUE(decoded.decode(frame.data(), static_cast<int>(frame.size()), format, &error))
        << toString(format) << ": " << toString(error);
    EXPECT_EQ(decoded, onlyFieldsOf(edge, format)) << toString(format);
  }
}

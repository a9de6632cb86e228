/**
 * \file
 * \brief Frames of one PanTilt wire format to a decoder of another (published-wire-facts.md 2.4): every frame that
 * can be recognised as another format is reported as DecodeError::FOREIGN_FORMAT, and exactly the frames the facts call
 * undetectable are taken (the reason the format is configured, never guessed).
 */
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "pantilt_golden_params.h"
#include "ptz_action_server/core/pantilt/pantilt_codec.h"

using namespace cr::pantilt;
using Bytes = std::vector<std::uint8_t>;

using pantilt_test::goldenParams;

namespace
{
/// The formats that share the version bytes `1 0`.
bool shareVersionBytes(WireFormat first, WireFormat second)
{
  return first != WireFormat::V1_1 && second != WireFormat::V1_1;
}

/// The mask fields of \p format in mask-bit order (mask0 bit 7 first).
std::vector<bool PanTiltParamsMask::*> maskFields(WireFormat format)
{
  using M = PanTiltParamsMask;
  if (format == WireFormat::SEED)
  {
    return { &M::panAngle,     &M::panMotorPosition,     &M::panMotorSpeed,
             &M::panTiltAngle, &M::panTiltMotorPosition, &M::panTiltMotorSpeed,
             &M::tiltAngle,    &M::tiltMotorPosition,    &M::tiltMotorSpeed };
  }
  return { &M::panMotorPosition, &M::tiltMotorPosition, &M::panAngle,    &M::tiltAngle,
           &M::panMotorSpeed,    &M::tiltMotorSpeed,    &M::isConnected, &M::isOpen,
           &M::custom1,          &M::custom2,           &M::custom3 };
}

/// The params frame of \p format whose mask bits (mask0 bit 7 = bit 0 of \p bits) are \p bits.
Bytes paramsFrame(WireFormat format, unsigned bits)
{
  const std::vector<bool PanTiltParamsMask::*> fields = maskFields(format);
  PanTiltParamsMask mask = PanTiltParamsMask::none();
  for (std::size_t index = 0; index < fields.size(); ++index)
  {
    mask.*fields[index] = (bits >> index) & 1u;
  }
  Bytes frame(MAX_PARAMS_FRAME_SIZE);
  int size = 0;
  EXPECT_TRUE(goldenParams().encode(frame.data(), static_cast<int>(frame.size()), size, &mask, format));
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

DecodeError paramsError(const Bytes& frame, WireFormat format)
{
  PanTiltParams params;
  DecodeError error = DecodeError::NONE;
  params.decode(frame.data(), static_cast<int>(frame.size()), format, &error);
  return error;
}

DecodeError commandError(const Bytes& frame, WireFormat format, PanTiltParam* param = nullptr)
{
  PanTiltParam decoded_param{};
  PanTiltCommand command{};
  float value = 0.0f;
  DecodeError error = DecodeError::NONE;
  PanTilt::decodeCommand(frame.data(), static_cast<int>(frame.size()), decoded_param, command, value, format, nullptr,
                         &error);
  if (param)
  {
    *param = decoded_param;
  }
  return error;
}
}  // namespace

TEST(PanTiltFormats, EveryCommandIsAnotherFormatToTheOthers)
{
  for (WireFormat sender : ALL_WIRE_FORMATS)
  {
    for (WireFormat receiver : ALL_WIRE_FORMATS)
    {
      if (sender == receiver)
      {
        continue;
      }
      // 7 against 15 bytes, or the version bytes: a COMMAND always tells its format.
      for (int id = 1; id <= (sender == WireFormat::SEED ? 9 : 12); ++id)
      {
        Bytes frame(MAX_COMMAND_SIZE);
        int size = 0;
        ASSERT_TRUE(PanTilt::encodeCommand(frame.data(), size, static_cast<PanTiltCommand>(id), sender, 10.0f, -5.0f));
        frame.resize(static_cast<std::size_t>(size));
        EXPECT_EQ(commandError(frame, receiver), DecodeError::FOREIGN_FORMAT)
            << toString(sender) << " command " << id << " to " << toString(receiver);
      }
    }
  }
}

TEST(PanTiltFormats, SetParamsTellTheirFormatExceptIdsTheSeedAndV1_0Share)
{
  for (WireFormat sender : ALL_WIRE_FORMATS)
  {
    for (WireFormat receiver : ALL_WIRE_FORMATS)
    {
      if (sender == receiver)
      {
        continue;
      }
      for (std::int32_t id = 1; id <= (sender == WireFormat::SEED ? 9 : 11); ++id)
      {
        Bytes frame = { SET_PARAM_HEADER,
                        1,
                        static_cast<std::uint8_t>(sender == WireFormat::V1_1 ? 1 : 0),
                        static_cast<std::uint8_t>(id),
                        0,
                        0,
                        0,
                        0,
                        0,
                        0x48,
                        0x42 };  // value 50
        // Ids 1..9 of the seed and v1.0 look the same: the receiver takes them in its own meaning.
        const bool undetectable = shareVersionBytes(sender, receiver) && id <= 9;
        EXPECT_EQ(commandError(frame, receiver), undetectable ? DecodeError::NONE : DecodeError::FOREIGN_FORMAT)
            << toString(sender) << " SET_PARAM id " << id << " to " << toString(receiver);
      }
    }
  }
  // What the undetectable ids do: the seed's PAN_MOTOR_SPEED is v1.0's IS_CONNECTED, and v1.0's PAN_MOTOR_SPEED is the
  // seed's PAN_TILT_MOTOR_POSITION.
  Bytes frame(SET_PARAM_SIZE);
  int size = 0;
  PanTiltParam param{};
  ASSERT_TRUE(
      PanTilt::encodeSetParamCommand(frame.data(), size, PanTiltParam::PAN_MOTOR_SPEED, 50.0f, WireFormat::SEED));
  ASSERT_EQ(commandError(frame, WireFormat::V1_0, &param), DecodeError::NONE);
  EXPECT_EQ(param, PanTiltParam::IS_CONNECTED);
  ASSERT_TRUE(
      PanTilt::encodeSetParamCommand(frame.data(), size, PanTiltParam::PAN_MOTOR_SPEED, 50.0f, WireFormat::V1_0));
  ASSERT_EQ(commandError(frame, WireFormat::SEED, &param), DecodeError::NONE);
  EXPECT_EQ(param, PanTiltParam::PAN_TILT_MOTOR_POSITION);
}

TEST(PanTiltFormats, ParamsFramesOfEveryMaskAreAnotherFormatUnlessNothingCanTell)
{
  // Between the seed and v1.0 (same header `02 01 00`), a frame of the goldens' values is taken by the other decoder
  // only when nothing tells it apart (published-wire-facts.md 2.4): mask0 bits 1 and 0 clear (lengths, 4 against 1
  // byte per field), bit 7 and bit 3 clear (an int read as a float is subnormal, a float read as an int is far above
  // 65535, or the other way round) and, from v1.0, mask1 bits 6 and 5 clear (reserved in the seed's format).
  // v1.1 differs from both in its version bytes.
  for (WireFormat sender : ALL_WIRE_FORMATS)
  {
    const unsigned field_count = static_cast<unsigned>(maskFields(sender).size());
    for (WireFormat receiver : ALL_WIRE_FORMATS)
    {
      if (sender == receiver)
      {
        continue;
      }
      unsigned taken = 0;
      for (unsigned bits = 0; bits < (1u << field_count); ++bits)
      {
        const Bytes frame = paramsFrame(sender, bits);
        ASSERT_EQ(paramsError(frame, sender), DecodeError::NONE);
        constexpr unsigned TELLING_BITS = (1u << 0) | (1u << 4) | (1u << 6) | (1u << 7) | (1u << 9) | (1u << 10);
        const bool undetectable = shareVersionBytes(sender, receiver) && (bits & TELLING_BITS) == 0;
        EXPECT_EQ(paramsError(frame, receiver), undetectable ? DecodeError::NONE : DecodeError::FOREIGN_FORMAT)
            << toString(sender) << " mask bits " << bits << " to " << toString(receiver);
        taken += undetectable ? 1 : 0;
      }
      EXPECT_EQ(taken, shareVersionBytes(sender, receiver) ? 32u : 0u)
          << toString(sender) << " to " << toString(receiver);
    }
  }
}

TEST(PanTiltFormats, TheFactsExamplesOfFramesBothDecodersTake)
{
  // `02 01 00 40 00 64 00 00 00` is the seed's panMotorPosition = 100 and v1.0's tiltMotorPosition = 100.
  const Bytes frame = { 0x02, 0x01, 0x00, 0x40, 0x00, 0x64, 0x00, 0x00, 0x00 };
  PanTiltParams seed;
  PanTiltParams v1_0;
  ASSERT_TRUE(seed.decode(frame.data(), static_cast<int>(frame.size()), WireFormat::SEED));
  ASSERT_TRUE(v1_0.decode(frame.data(), static_cast<int>(frame.size()), WireFormat::V1_0));
  EXPECT_EQ(seed.panMotorPosition, 100);
  EXPECT_EQ(v1_0.tiltMotorPosition, 100);
  // The state request `02 01 00 00 00` is the same in both, and harmless; v1.1's is another format to them.
  const Bytes request = { 0x02, 0x01, 0x00, 0x00, 0x00 };
  EXPECT_EQ(paramsError(request, WireFormat::SEED), DecodeError::NONE);
  EXPECT_EQ(paramsError(request, WireFormat::V1_0), DecodeError::NONE);
  EXPECT_EQ(paramsError(request, WireFormat::V1_1), DecodeError::FOREIGN_FORMAT);
}

TEST(PanTiltFormats, AFrameNoFormatTakesKeepsItsOwnReason)
{
  // Implausible in every format: not another format's frame, a bad one.
  PanTiltParams params = goldenParams();
  params.panAngle = std::numeric_limits<float>::quiet_NaN();
  Bytes frame(MAX_PARAMS_FRAME_SIZE);
  int size = 0;
  PanTiltParamsMask pan_angle = PanTiltParamsMask::none();
  pan_angle.panAngle = true;
  ASSERT_TRUE(params.encode(frame.data(), static_cast<int>(frame.size()), size, &pan_angle, WireFormat::SEED));
  frame.resize(static_cast<std::size_t>(size));
  EXPECT_EQ(paramsError(frame, WireFormat::SEED), DecodeError::BAD_VALUE);  // as v1.0: position 0x7FC00000
  frame[4] = 0x10;                                                          // and a mask bit no format has
  EXPECT_EQ(paramsError(frame, WireFormat::SEED), DecodeError::BAD_MASK);
  EXPECT_EQ(paramsError(frame, WireFormat::V1_0), DecodeError::BAD_MASK);
}

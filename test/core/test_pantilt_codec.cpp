#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"
#include "ptz_action_server/emulators/sim_pantilt.h"

// SET_PARAM and COMMAND frames, and the sim device they drive; the params frame and JSON are in
// test_pantilt_params.cpp.

using namespace cr::pantilt;
using Bytes = std::vector<std::uint8_t>;

namespace
{
Bytes setParamFrame(PanTiltParam id, float value, WireFormat format)
{
  Bytes frame(SET_PARAM_SIZE);
  int size = -1;
  EXPECT_TRUE(PanTilt::encodeSetParamCommand(frame.data(), size, id, value, format));
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

Bytes commandFrame(PanTiltCommand id, WireFormat format, float arg1 = 0.0f, float arg2 = 0.0f)
{
  Bytes frame(MAX_COMMAND_SIZE);
  int size = -1;
  EXPECT_TRUE(PanTilt::encodeCommand(frame.data(), size, id, format, arg1, arg2));
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

std::vector<PanTiltParam> paramsOf(WireFormat format)
{
  std::vector<PanTiltParam> params;
  for (int value : { 1, 2, 3, 4, 5, 6, 7, 8, 9, 101, 102, 103, 104, 105 })
  {
    const auto param = static_cast<PanTiltParam>(value);
    if (PanTilt::wireId(param, format) != 0)
    {
      params.push_back(param);
    }
  }
  return params;
}
}  // namespace

// --- Golden frames printed by the published implementations (published-wire-facts.md 2.2, 2.3)

TEST(PanTiltGolden, SeedCommands)
{
  EXPECT_EQ(commandFrame(PanTiltCommand::STOP, WireFormat::SEED), (Bytes{ 0x00, 0x01, 0x00, 0x02, 0x00, 0x00, 0x00 }));
  EXPECT_EQ(commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, WireFormat::SEED, 10.0f, -5.0f),
            (Bytes{ 0x00, 0x01, 0x00, 0x08, 0x00, 0x00, 0x00 }));  // the seed's COMMAND has no arguments
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_ANGLE, 10.0f, WireFormat::SEED),
            (Bytes{ 0x01, 0x01, 0x00, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 }));
}

TEST(PanTiltGolden, V1_0Commands)
{
  EXPECT_EQ(commandFrame(PanTiltCommand::STOP, WireFormat::V1_0),
            (Bytes{ 0x00, 0x01, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00 }));
  // The same bytes as the seed's: only the ids from 5 on tell the formats apart, and nothing on the wire does.
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_ANGLE, 10.0f, WireFormat::V1_0),
            (Bytes{ 0x01, 0x01, 0x00, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 }));
}

TEST(PanTiltGolden, V1_1Commands)
{
  EXPECT_EQ(commandFrame(PanTiltCommand::STOP, WireFormat::V1_1),
            (Bytes{ 0x00, 0x01, 0x01, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00 }));
  EXPECT_EQ(commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, WireFormat::V1_1, 10.0f, -5.0f),
            (Bytes{ 0x00, 0x01, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41, 0x00, 0x00, 0xA0, 0xC0 }));
  EXPECT_EQ(commandFrame(PanTiltCommand::MOVE_PAN_TILT, WireFormat::V1_1, 50.0f, -25.0f),
            (Bytes{ 0x00, 0x01, 0x01, 0x0C, 0x00, 0x00, 0x00, 0x00, 0x00, 0x48, 0x42, 0x00, 0x00, 0xC8, 0xC1 }));
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_ANGLE, 10.0f, WireFormat::V1_1),
            (Bytes{ 0x01, 0x01, 0x01, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 }));
}

TEST(PanTiltGolden, FormatNames)
{
  for (WireFormat format : ALL_WIRE_FORMATS)
  {
    WireFormat parsed = format == WireFormat::SEED ? WireFormat::V1_1 : WireFormat::SEED;
    ASSERT_TRUE(parseWireFormat(toString(format), parsed)) << toString(format);
    EXPECT_EQ(parsed, format);
  }
  EXPECT_STREQ(toString(WireFormat::SEED), "seed");
  EXPECT_STREQ(toString(WireFormat::V1_0), "v1.0");
  EXPECT_STREQ(toString(WireFormat::V1_1), "v1.1");
  WireFormat format = WireFormat::V1_1;
  EXPECT_FALSE(parseWireFormat("1.0", format));  // the old name: two formats answered to it
  EXPECT_FALSE(parseWireFormat("1.1", format));
  EXPECT_EQ(format, WireFormat::V1_1);
}

TEST(PanTiltGolden, VersionString)
{
  EXPECT_EQ(PanTilt::getVersion(), "1.0.0");
}

// --- Round trips

TEST(PanTiltRoundTrip, EveryCommandInEveryFormat)
{
  for (WireFormat format : ALL_WIRE_FORMATS)
  {
    const bool seed = format == WireFormat::SEED;
    const int last = seed ? 9 : 12;
    for (int id = 1; id <= last; ++id)
    {
      const auto command = static_cast<PanTiltCommand>(id);
      const Bytes frame = commandFrame(command, format, 12.5f, -7.25f);
      ASSERT_EQ(frame.size(), seed ? 7u : 15u);
      PanTiltParam param{};
      PanTiltCommand decoded{};
      float value = -1.0f;
      float second = -1.0f;
      DecodeError error = DecodeError::BAD_ID;
      ASSERT_EQ(PanTilt::decodeCommand(frame.data(), static_cast<int>(frame.size()), param, decoded, value, format,
                                       &second, &error),
                0)
          << toString(format) << " command " << id;
      EXPECT_EQ(decoded, command);
      EXPECT_EQ(error, DecodeError::NONE);
      EXPECT_FLOAT_EQ(value, seed ? 0.0f : 12.5f);
      EXPECT_FLOAT_EQ(second, seed ? 0.0f : -7.25f);
    }
  }
  // The v1.x-only commands do not exist in the seed's format.
  std::uint8_t frame[MAX_COMMAND_SIZE];
  int size = -1;
  EXPECT_FALSE(PanTilt::encodeCommand(frame, size, PanTiltCommand::MOVE_PAN, WireFormat::SEED));
  EXPECT_EQ(size, 0);
}

TEST(PanTiltRoundTrip, EveryParamInEveryFormat)
{
  for (WireFormat format : ALL_WIRE_FORMATS)
  {
    const std::vector<PanTiltParam> params = paramsOf(format);
    EXPECT_EQ(params.size(), format == WireFormat::SEED ? 9u : 11u);
    for (PanTiltParam id : params)
    {
      for (float value : { 0.0f, -180.0f, 65535.0f, 3.14159f, std::numeric_limits<float>::infinity() })
      {
        const Bytes frame = setParamFrame(id, value, format);
        PanTiltParam decoded{};
        PanTiltCommand command{};
        float decoded_value = 0.0f;
        ASSERT_EQ(PanTilt::decodeCommand(frame.data(), static_cast<int>(frame.size()), decoded, command, decoded_value,
                                         format),
                  1);
        EXPECT_EQ(decoded, id);
        EXPECT_EQ(decoded_value, value);
      }
    }
  }
  // v1.0 and v1.1 number their params differently from the seed: PAN_MOTOR_SPEED is 7 in the seed's format, 5 in v1.x.
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 0.0f, WireFormat::SEED)[3], 7);
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 0.0f, WireFormat::V1_0)[3], 5);
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 0.0f, WireFormat::V1_1)[3], 5);
  std::uint8_t frame[SET_PARAM_SIZE];
  int size = -1;
  EXPECT_FALSE(PanTilt::encodeSetParamCommand(frame, size, PanTiltParam::PAN_TILT_ANGLE, 1.0f, WireFormat::V1_0));
  EXPECT_FALSE(PanTilt::encodeSetParamCommand(frame, size, PanTiltParam::PAN_TILT_ANGLE, 1.0f, WireFormat::V1_1));
  EXPECT_FALSE(PanTilt::encodeSetParamCommand(frame, size, PanTiltParam::IS_OPEN, 1.0f, WireFormat::SEED));
  EXPECT_EQ(size, 0);
}

// --- Rejections

TEST(PanTiltDecoder, RejectsMalformedCommandsWithOneReasonAndDefinedOutputs)
{
  struct Case
  {
    const char* name;
    Bytes bytes;
    WireFormat format;
    DecodeError error;
  };
  const Bytes stop = commandFrame(PanTiltCommand::STOP, WireFormat::SEED);
  const Bytes set = setParamFrame(PanTiltParam::TILT_ANGLE, 1.0f, WireFormat::SEED);
  Bytes longer_stop = stop;
  longer_stop.push_back(0);
  Bytes short_set = set;
  short_set.pop_back();
  Bytes bad_major = stop;
  bad_major[1] = 2;
  Bytes minor_seven = stop;
  minor_seven[2] = 7;
  Bytes command_id_zero = stop;
  command_id_zero[3] = 0;
  Bytes command_id_ten = stop;
  command_id_ten[3] = 10;  // MOVE_PAN: v1.x only, and a v1.x command is 15 bytes
  Bytes command_id_negative = stop;
  command_id_negative[6] = 0x80;
  Bytes param_id_twelve = set;
  param_id_twelve[3] = 12;
  Bytes param_id_huge = set;
  param_id_huge[5] = 0x01;
  const Bytes move_pan_tilt = commandFrame(PanTiltCommand::MOVE_PAN_TILT, WireFormat::V1_1);
  Bytes command_id_thirteen = move_pan_tilt;
  command_id_thirteen[3] = 13;
  Bytes v1_0_command_id_thirteen = command_id_thirteen;
  v1_0_command_id_thirteen[2] = 0;
  const Bytes short_move(move_pan_tilt.begin(), move_pan_tilt.end() - 1);
  Bytes param_v11_id_twelve = setParamFrame(PanTiltParam::CUSTOM_3, 1.0f, WireFormat::V1_1);
  param_v11_id_twelve[3] = 12;
  const std::vector<Case> cases = {
    { "empty", {}, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "two bytes", { 0x00, 0x01 }, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "params header", { 0x02, 0x01, 0x00, 0x00, 0x00 }, WireFormat::SEED, DecodeError::BAD_HEADER },
    { "header 0xFF", { 0xFF, 0x01, 0x00, 0x02, 0, 0, 0 }, WireFormat::SEED, DecodeError::BAD_HEADER },
    { "major 2", bad_major, WireFormat::SEED, DecodeError::BAD_VERSION },
    { "minor 7", minor_seven, WireFormat::V1_0, DecodeError::BAD_VERSION },
    { "command one byte long", longer_stop, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "v1.1 command one byte short", short_move, WireFormat::V1_1, DecodeError::BAD_SIZE },
    { "set param one byte short", short_set, WireFormat::SEED, DecodeError::BAD_SIZE },
    { "command id 0", command_id_zero, WireFormat::SEED, DecodeError::BAD_ID },
    { "command id 10 in the seed's format", command_id_ten, WireFormat::SEED, DecodeError::BAD_ID },
    { "negative command id", command_id_negative, WireFormat::SEED, DecodeError::BAD_ID },
    { "command id 13 in v1.1", command_id_thirteen, WireFormat::V1_1, DecodeError::BAD_ID },
    { "15-byte command with id 13 to a seed decoder", v1_0_command_id_thirteen, WireFormat::SEED,
      DecodeError::BAD_SIZE },
    { "param id 12 in the seed's format", param_id_twelve, WireFormat::SEED, DecodeError::BAD_ID },
    { "param id 65539", param_id_huge, WireFormat::SEED, DecodeError::BAD_ID },
    { "param id 12 in v1.1", param_v11_id_twelve, WireFormat::V1_1, DecodeError::BAD_ID },
    // Valid frames, but of another format (test_pantilt_formats.cpp has every pair).
    { "seed frame to a v1.1 decoder", stop, WireFormat::V1_1, DecodeError::FOREIGN_FORMAT },
    { "v1.1 frame to a seed decoder", move_pan_tilt, WireFormat::SEED, DecodeError::FOREIGN_FORMAT },
  };
  for (const Case& item : cases)
  {
    PanTiltParam param = PanTiltParam::TILT_ANGLE;
    PanTiltCommand command = PanTiltCommand::GO_TO_HOME;
    float value = 99.0f;
    float second = 99.0f;
    DecodeError error = DecodeError::NONE;
    EXPECT_EQ(PanTilt::decodeCommand(item.bytes.data(), static_cast<int>(item.bytes.size()), param, command, value,
                                     item.format, &second, &error),
              -1)
        << item.name;
    EXPECT_EQ(error, item.error) << item.name << ": " << toString(error);
    EXPECT_EQ(param, PanTiltParam{}) << item.name;
    EXPECT_EQ(command, PanTiltCommand{}) << item.name;
    EXPECT_EQ(value, 0.0f) << item.name;
    EXPECT_EQ(second, 0.0f) << item.name;
  }
  PanTiltParam param{};
  PanTiltCommand command{};
  float value = 0.0f;
  EXPECT_EQ(PanTilt::decodeCommand(nullptr, 7, param, command, value), -1);
}

// --- The custom implementation over the sim model

TEST(SimPanTilt, ExecutesSeedStyleSetParamThenCommand)
{
  auto clock = std::make_shared<ptz_action_server::ManualClock>();
  SimPanTilt device(ptz_action_server::SimDeviceConfig::defaults(), clock);
  const Bytes pan = setParamFrame(PanTiltParam::PAN_ANGLE, 30.0f, WireFormat::SEED);
  const Bytes tilt = setParamFrame(PanTiltParam::TILT_ANGLE, -10.0f, WireFormat::SEED);
  const Bytes go = commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, WireFormat::SEED);
  EXPECT_TRUE(device.decodeAndExecuteCommand(pan.data(), static_cast<int>(pan.size())));
  EXPECT_TRUE(device.decodeAndExecuteCommand(tilt.data(), static_cast<int>(tilt.size())));
  EXPECT_EQ(device.sample().moving, false);  // targets set, nothing moves before the command
  EXPECT_TRUE(device.decodeAndExecuteCommand(go.data(), static_cast<int>(go.size())));
  clock->advance(3.0);
  // Positive PanTilt pan is clockwise, as the contract's: the same sign in radians.
  EXPECT_NEAR(device.sample().position[ptz_action_server::PAN], 30.0 * M_PI / 180.0, 1e-3);
  EXPECT_NEAR(device.sample().position[ptz_action_server::TILT], -10.0 * M_PI / 180.0, 1e-3);
  EXPECT_NEAR(device.getParam(PanTiltParam::PAN_ANGLE), 30.0f, 0.05f);
  PanTiltParams params;
  device.getParams(params);
  EXPECT_EQ(params.panMotorPosition, SimPanTilt::angleToMotorPosition(ptz_action_server::PAN, params.panAngle));
  EXPECT_NEAR(params.panMotorPosition, (30.0 + 180.0) / 360.0 * 65535.0, 20.0);
}

TEST(SimPanTilt, RefusesValuesOutsideTheSeedsRanges)
{
  auto clock = std::make_shared<ptz_action_server::ManualClock>();
  SimPanTilt device(ptz_action_server::SimDeviceConfig::defaults(), clock);
  EXPECT_FALSE(device.setParam(PanTiltParam::PAN_ANGLE, 181.0f));
  EXPECT_FALSE(device.setParam(PanTiltParam::TILT_ANGLE, -90.5f));
  EXPECT_FALSE(device.setParam(PanTiltParam::PAN_MOTOR_SPEED, 101.0f));
  EXPECT_FALSE(device.setParam(PanTiltParam::TILT_MOTOR_POSITION, 65536.0f));
  EXPECT_FALSE(device.setParam(PanTiltParam::PAN_ANGLE, std::numeric_limits<float>::quiet_NaN()));
  EXPECT_FALSE(device.setParam(PanTiltParam::IS_CONNECTED, 1.0f));
  EXPECT_FALSE(device.executeCommand(PanTiltCommand::MOVE_PAN, 50.0f));  // a v1.x command on a seed device
  EXPECT_TRUE(device.setParam(PanTiltParam::TILT_ANGLE, 90.0f));
  EXPECT_TRUE(device.setParam(PanTiltParam::CUSTOM_2, 7.0f));
  EXPECT_FLOAT_EQ(device.getParam(PanTiltParam::CUSTOM_2), 7.0f);
}

TEST(SimPanTilt, SpeedParamsScaleTheMove)
{
  auto clock = std::make_shared<ptz_action_server::ManualClock>();
  SimPanTilt device(ptz_action_server::SimDeviceConfig::defaults(), clock);
  ASSERT_TRUE(device.setParam(PanTiltParam::PAN_MOTOR_SPEED, 50.0f));
  ASSERT_TRUE(device.setParam(PanTiltParam::PAN_ANGLE, 90.0f));
  ASSERT_TRUE(device.executeCommand(PanTiltCommand::GO_TO_PAN_ANGLE));
  clock->advance(1.0);
  EXPECT_NEAR(device.sample().velocity[ptz_action_server::PAN], 0.75, 1e-9);  // 50 % of 1.5 rad/s
  EXPECT_FLOAT_EQ(device.getParam(PanTiltParam::PAN_MOTOR_SPEED), 50.0f);
}

TEST(SimPanTilt, AV1_0SpeedIsASpeedNotAMotorPosition)
{
  // PanTilt 1.0.x's SET_PARAM PAN_MOTOR_SPEED = 100 (id 5): the old "1.0" took it as the seed's
  // PAN_TILT_MOTOR_POSITION, a target for both axes.
  const Bytes speed = { 0x01, 0x01, 0x00, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC8, 0x42 };
  auto clock = std::make_shared<ptz_action_server::ManualClock>();
  SimPanTilt device(ptz_action_server::SimDeviceConfig::defaults(), clock, WireFormat::V1_0);
  ASSERT_TRUE(device.setParam(PanTiltParam::PAN_MOTOR_SPEED, 20.0f));
  ASSERT_TRUE(device.decodeAndExecuteCommand(speed.data(), static_cast<int>(speed.size())));
  EXPECT_FLOAT_EQ(device.getParam(PanTiltParam::PAN_MOTOR_SPEED), 100.0f);
  const Bytes go = commandFrame(PanTiltCommand::GO_TO_PAN_TILT_POSITION, WireFormat::V1_0, 60000.0f, 30000.0f);
  ASSERT_TRUE(device.decodeAndExecuteCommand(go.data(), static_cast<int>(go.size())));
  clock->advance(1.0);
  EXPECT_NEAR(device.sample().velocity[ptz_action_server::PAN], 1.5, 1e-9);  // 100 % of 1.5 rad/s, not 20 %
}

TEST(SimPanTilt, V1CommandsCarryTheirTargetsAndSpeeds)
{
  for (WireFormat format : { WireFormat::V1_0, WireFormat::V1_1 })
  {
    SCOPED_TRACE(toString(format));
    auto clock = std::make_shared<ptz_action_server::ManualClock>();
    SimPanTilt device(ptz_action_server::SimDeviceConfig::defaults(), clock, format);
    const Bytes go = commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, format, -20.0f, 15.0f);
    ASSERT_TRUE(device.decodeAndExecuteCommand(go.data(), static_cast<int>(go.size())));
    clock->advance(3.0);
    EXPECT_NEAR(device.sample().position[ptz_action_server::PAN], -20.0 * M_PI / 180.0, 1e-3);
    EXPECT_NEAR(device.sample().position[ptz_action_server::TILT], 15.0 * M_PI / 180.0, 1e-3);
    const Bytes move = commandFrame(PanTiltCommand::MOVE_PAN, format, -40.0f);
    ASSERT_TRUE(device.decodeAndExecuteCommand(move.data(), static_cast<int>(move.size())));
    clock->advance(1.0);
    EXPECT_NEAR(device.sample().velocity[ptz_action_server::PAN], -0.6, 1e-9);  // 40 % of 1.5 rad/s, anticlockwise
    const Bytes stop = commandFrame(PanTiltCommand::STOP, format);
    ASSERT_TRUE(device.decodeAndExecuteCommand(stop.data(), static_cast<int>(stop.size())));
    clock->advance(1.0);
    EXPECT_FALSE(device.sample().moving);
  }
}

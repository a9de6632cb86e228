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
const WireVersion BOTH_VERSIONS[] = { WireVersion::V1_0, WireVersion::V1_1 };

Bytes setParamFrame(PanTiltParam id, float value, WireVersion version)
{
  Bytes frame(SET_PARAM_SIZE);
  int size = -1;
  EXPECT_TRUE(PanTilt::encodeSetParamCommand(frame.data(), size, id, value, version));
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

Bytes commandFrame(PanTiltCommand id, WireVersion version, float arg1 = 0.0f, float arg2 = 0.0f)
{
  Bytes frame(COMMAND_SIZE_V1_1);
  int size = -1;
  EXPECT_TRUE(PanTilt::encodeCommand(frame.data(), size, id, version, arg1, arg2));
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

std::vector<PanTiltParam> paramsOf(WireVersion version)
{
  std::vector<PanTiltParam> params;
  for (int value : { 1, 2, 3, 4, 5, 6, 7, 8, 9, 101, 102, 103, 104, 105 })
  {
    const auto param = static_cast<PanTiltParam>(value);
    if (PanTilt::wireId(param, version) != 0)
    {
      params.push_back(param);
    }
  }
  return params;
}
}  // namespace

// --- Golden frames from protocols.md

TEST(PanTiltGolden, StopInTheSeedsFormat)
{
  EXPECT_EQ(commandFrame(PanTiltCommand::STOP, WireVersion::V1_0), (Bytes{ 0x00, 0x01, 0x00, 0x02, 0x00, 0x00, 0x00 }));
}

TEST(PanTiltGolden, SetPanAngleInBothFormats)
{
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_ANGLE, 10.0f, WireVersion::V1_0),
            (Bytes{ 0x01, 0x01, 0x00, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 }));
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_ANGLE, 10.0f, WireVersion::V1_1),
            (Bytes{ 0x01, 0x01, 0x01, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 }));
}

TEST(PanTiltGolden, GoToPanTiltAngleWithArgumentsIn1_1)
{
  EXPECT_EQ(commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, WireVersion::V1_1, 10.0f, -5.0f),
            (Bytes{ 0x00, 0x01, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41, 0x00, 0x00, 0xA0, 0xC0 }));
}

TEST(PanTiltGolden, VersionString)
{
  EXPECT_EQ(PanTilt::getVersion(), "1.0.0");
}

// --- Round trips

TEST(PanTiltRoundTrip, EveryCommandInEveryFormat)
{
  for (WireVersion version : BOTH_VERSIONS)
  {
    const int last = version == WireVersion::V1_0 ? 9 : 12;
    for (int id = 1; id <= last; ++id)
    {
      const auto command = static_cast<PanTiltCommand>(id);
      const Bytes frame = commandFrame(command, version, 12.5f, -7.25f);
      ASSERT_EQ(frame.size(), version == WireVersion::V1_0 ? 7u : 15u);
      PanTiltParam param{};
      PanTiltCommand decoded{};
      float value = -1.0f;
      float second = -1.0f;
      DecodeError error = DecodeError::BAD_ID;
      ASSERT_EQ(PanTilt::decodeCommand(frame.data(), static_cast<int>(frame.size()), param, decoded, value, version,
                                       &second, &error),
                0)
          << "command " << id;
      EXPECT_EQ(decoded, command);
      EXPECT_EQ(error, DecodeError::NONE);
      EXPECT_FLOAT_EQ(value, version == WireVersion::V1_1 ? 12.5f : 0.0f);
      EXPECT_FLOAT_EQ(second, version == WireVersion::V1_1 ? -7.25f : 0.0f);
    }
  }
  // The 1.1-only commands do not exist in 1.0.
  std::uint8_t frame[COMMAND_SIZE_V1_1];
  int size = -1;
  EXPECT_FALSE(PanTilt::encodeCommand(frame, size, PanTiltCommand::MOVE_PAN, WireVersion::V1_0));
  EXPECT_EQ(size, 0);
}

TEST(PanTiltRoundTrip, EveryParamInEveryFormat)
{
  for (WireVersion version : BOTH_VERSIONS)
  {
    const std::vector<PanTiltParam> params = paramsOf(version);
    EXPECT_EQ(params.size(), version == WireVersion::V1_0 ? 9u : 11u);
    for (PanTiltParam id : params)
    {
      for (float value : { 0.0f, -180.0f, 65535.0f, 3.14159f, std::numeric_limits<float>::infinity() })
      {
        const Bytes frame = setParamFrame(id, value, version);
        PanTiltParam decoded{};
        PanTiltCommand command{};
        float decoded_value = 0.0f;
        ASSERT_EQ(PanTilt::decodeCommand(frame.data(), static_cast<int>(frame.size()), decoded, command, decoded_value,
                                         version),
                  1);
        EXPECT_EQ(decoded, id);
        EXPECT_EQ(decoded_value, value);
      }
    }
  }
  // 1.1 numbers its params differently: PAN_MOTOR_SPEED is 7 in 1.0 and 5 in 1.1.
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 0.0f, WireVersion::V1_0)[3], 7);
  EXPECT_EQ(setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 0.0f, WireVersion::V1_1)[3], 5);
  std::uint8_t frame[SET_PARAM_SIZE];
  int size = -1;
  EXPECT_FALSE(PanTilt::encodeSetParamCommand(frame, size, PanTiltParam::PAN_TILT_ANGLE, 1.0f, WireVersion::V1_1));
  EXPECT_FALSE(PanTilt::encodeSetParamCommand(frame, size, PanTiltParam::IS_OPEN, 1.0f, WireVersion::V1_0));
  EXPECT_EQ(size, 0);
}

// --- Rejections

TEST(PanTiltDecoder, RejectsMalformedCommandsWithOneReasonAndDefinedOutputs)
{
  struct Case
  {
    const char* name;
    Bytes bytes;
    WireVersion version;
    DecodeError error;
  };
  const Bytes stop = commandFrame(PanTiltCommand::STOP, WireVersion::V1_0);
  const Bytes set = setParamFrame(PanTiltParam::TILT_ANGLE, 1.0f, WireVersion::V1_0);
  Bytes longer_stop = stop;
  longer_stop.push_back(0);
  Bytes short_set = set;
  short_set.pop_back();
  Bytes bad_major = stop;
  bad_major[1] = 2;
  Bytes command_id_zero = stop;
  command_id_zero[3] = 0;
  Bytes command_id_ten = stop;
  command_id_ten[3] = 10;  // MOVE_PAN: 1.1 only
  Bytes command_id_negative = stop;
  command_id_negative[6] = 0x80;
  Bytes param_id_ten = set;
  param_id_ten[3] = 10;
  Bytes param_id_huge = set;
  param_id_huge[5] = 0x01;
  const Bytes move_pan_tilt = commandFrame(PanTiltCommand::MOVE_PAN_TILT, WireVersion::V1_1);
  Bytes command_id_thirteen = move_pan_tilt;
  command_id_thirteen[3] = 13;
  Bytes param_v11_id_twelve = setParamFrame(PanTiltParam::CUSTOM_3, 1.0f, WireVersion::V1_1);
  param_v11_id_twelve[3] = 12;
  const std::vector<Case> cases = {
    { "empty", {}, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "two bytes", { 0x00, 0x01 }, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "params header", { 0x02, 0x01, 0x00, 0x00, 0x00 }, WireVersion::V1_0, DecodeError::BAD_HEADER },
    { "header 0xFF", { 0xFF, 0x01, 0x00, 0x02, 0, 0, 0 }, WireVersion::V1_0, DecodeError::BAD_HEADER },
    { "1.0 frame to a 1.1 decoder", stop, WireVersion::V1_1, DecodeError::BAD_VERSION },
    { "1.1 frame to a 1.0 decoder", move_pan_tilt, WireVersion::V1_0, DecodeError::BAD_VERSION },
    { "major 2", bad_major, WireVersion::V1_0, DecodeError::BAD_VERSION },
    { "command one byte long", longer_stop, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "1.0 command of 1.1 size", Bytes(move_pan_tilt.begin(), move_pan_tilt.end()), WireVersion::V1_0,
      DecodeError::BAD_VERSION },
    { "set param one byte short", short_set, WireVersion::V1_0, DecodeError::BAD_SIZE },
    { "command id 0", command_id_zero, WireVersion::V1_0, DecodeError::BAD_ID },
    { "command id 10 in 1.0", command_id_ten, WireVersion::V1_0, DecodeError::BAD_ID },
    { "negative command id", command_id_negative, WireVersion::V1_0, DecodeError::BAD_ID },
    { "command id 13 in 1.1", command_id_thirteen, WireVersion::V1_1, DecodeError::BAD_ID },
    { "param id 10 in 1.0", param_id_ten, WireVersion::V1_0, DecodeError::BAD_ID },
    { "param id 65539", param_id_huge, WireVersion::V1_0, DecodeError::BAD_ID },
    { "param id 12 in 1.1", param_v11_id_twelve, WireVersion::V1_1, DecodeError::BAD_ID },
  };
  for (const Case& item : cases)
  {
    PanTiltParam param = PanTiltParam::TILT_ANGLE;
    PanTiltCommand command = PanTiltCommand::GO_TO_HOME;
    float value = 99.0f;
    float second = 99.0f;
    DecodeError error = DecodeError::NONE;
    EXPECT_EQ(PanTilt::decodeCommand(item.bytes.data(), static_cast<int>(item.bytes.size()), param, command, value,
                                     item.version, &second, &error),
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
  const Bytes pan = setParamFrame(PanTiltParam::PAN_ANGLE, 30.0f, WireVersion::V1_0);
  const Bytes tilt = setParamFrame(PanTiltParam::TILT_ANGLE, -10.0f, WireVersion::V1_0);
  const Bytes go = commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, WireVersion::V1_0);
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
  EXPECT_FALSE(device.executeCommand(PanTiltCommand::MOVE_PAN, 50.0f));  // a 1.1 command on a 1.0 device
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

TEST(SimPanTilt, OneOneCommandsCarryTheirTargetsAndSpeeds)
{
  auto clock = std::make_shared<ptz_action_server::ManualClock>();
  SimPanTilt device(ptz_action_server::SimDeviceConfig::defaults(), clock, WireVersion::V1_1);
  const Bytes go = commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, WireVersion::V1_1, -20.0f, 15.0f);
  ASSERT_TRUE(device.decodeAndExecuteCommand(go.data(), static_cast<int>(go.size())));
  clock->advance(3.0);
  EXPECT_NEAR(device.sample().position[ptz_action_server::PAN], -20.0 * M_PI / 180.0, 1e-3);
  EXPECT_NEAR(device.sample().position[ptz_action_server::TILT], 15.0 * M_PI / 180.0, 1e-3);
  const Bytes move = commandFrame(PanTiltCommand::MOVE_PAN, WireVersion::V1_1, -40.0f);
  ASSERT_TRUE(device.decodeAndExecuteCommand(move.data(), static_cast<int>(move.size())));
  clock->advance(1.0);
  EXPECT_NEAR(device.sample().velocity[ptz_action_server::PAN], -0.6, 1e-9);  // 40 % of 1.5 rad/s, anticlockwise
  const Bytes stop = commandFrame(PanTiltCommand::STOP, WireVersion::V1_1);
  ASSERT_TRUE(device.decodeAndExecuteCommand(stop.data(), static_cast<int>(stop.size())));
  clock->advance(1.0);
  EXPECT_FALSE(device.sample().moving);
}

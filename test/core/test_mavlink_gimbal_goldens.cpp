/**
 * \file
 * \brief Golden frames of the gimbal messages the backend and the emulator decode, written from their definitions.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mavlink_test_frames.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using namespace mavlink_test;

namespace
{
// GIMBAL_MANAGER_SET_ATTITUDE from a ground station 255/190 to the manager 1/1 (seq 3): YAW_LOCK, the attitude yaw 90
// degrees (q = cos 45, 0, 0, sin 45), rates NaN, for the gimbal device 154. 35 bytes: nothing to cut.
const char* GOLDEN_SET_ATTITUDE_ANGLES = "fd23000003ffbe1a010010000000f304353f0000000000000000f304353f0000c07f0000c07f0"
                                         "000"
                                         "c07f01019a9847";
// The same message with rates only (seq 4): flags 0, q all NaN, x NaN, y 0.5, z -0.25, for every gimbal of 1/1 (0,
// cut: 34 bytes on the wire).
const char* GOLDEN_SET_ATTITUDE_RATES = "fd22000004ffbe1a0100000000000000c07f0000c07f0000c07f0000c07f0000c07f0000003f00"
                                        "00"
                                        "80be0101e751";
// GIMBAL_MANAGER_INFORMATION of the autopilot 1/1 (seq 0) for the gimbal device 154: time 1000 ms, cap_flags 0x7e2
// (NEUTRAL, PITCH_AXIS/FOLLOW/LOCK, YAW_AXIS/FOLLOW/LOCK), roll 0..0, pitch -pi/2..pi/4, yaw -pi..pi.
const char* GOLDEN_INFORMATION = "fd210000000101180100e8030000e20700000000000000000000db0fc9bfdb0f493fdb0f49c0db0f4940"
                                 "9a2fe3";
// GIMBAL_MANAGER_STATUS of 1/1 (seq 1) for its gimbal 2: primary control 1/191, no secondary (cut: 11 bytes).
const char* GOLDEN_STATUS = "fd0b0000010101190100e8030000000000000201bf471f";
// GIMBAL_DEVICE_ATTITUDE_STATUS of the gimbal device 1/154 (seq 2): level, straight ahead, still, YAW_IN_VEHICLE_FRAME,
// delta_yaw 0.5, delta_yaw_velocity NaN, gimbal_device_id 0 (a device of its own; cut: 48 bytes).
const char* GOLDEN_ATTITUDE_OF_A_DEVICE = "fd30000002019a1d0100e80300000000803f0000000000000000000000000000000000000000"
                                          "0000"
                                          "000000000000200000000000003f0000c07fd7ba";
// The same attitude sent by the manager 1/1 for its gimbal 2 inside it (49 bytes).
const char* GOLDEN_ATTITUDE_INSIDE_A_MANAGER = "fd3100000201011d0100e80300000000803f00000000000000000000000000000000000"
                                               "0000"
                                               "00000000000000000200000000000003f0000c07f02738c";

GimbalDeviceAttitudeStatus levelAttitude(std::uint8_t gimbal_device_id)
{
  GimbalDeviceAttitudeStatus attitude;
  attitude.time_boot_ms = 1000;
  attitude.q = Quaternion{ { 1.0f, 0.0f, 0.0f, 0.0f } };
  attitude.angular_velocity_x = attitude.angular_velocity_y = attitude.angular_velocity_z = 0.0f;
  attitude.flags = gimbal_flags::YAW_IN_VEHICLE_FRAME;
  attitude.delta_yaw = 0.5f;
  attitude.gimbal_device_id = gimbal_device_id;
  return attitude;
}

Frame parseOne(const char* hex)
{
  FrameParser parser;
  const std::vector<Frame> frames = parseAll(parser, fromHex(hex));
  EXPECT_EQ(frames.size(), 1u) << hex;
  return frames.empty() ? Frame{} : frames.front();
}
}  // namespace

TEST(MavlinkGolden, SetAttitudeWithAnglesAndWithRatesOnly)
{
  GimbalManagerSetAttitude angles;
  angles.flags = gimbal_flags::YAW_LOCK;
  angles.q =
      Quaternion{ { static_cast<float>(std::cos(M_PI / 4.0)), 0.0f, 0.0f, static_cast<float>(std::sin(M_PI / 4.0)) } };
  angles.target_system = 1;
  angles.target_component = 1;
  angles.gimbal_device_id = 154;
  EXPECT_EQ(bytesOf(encode(gcs(3), angles)), fromHex(GOLDEN_SET_ATTITUDE_ANGLES));

  GimbalManagerSetAttitude rates;
  rates.angular_velocity_y = 0.5f;
  rates.angular_velocity_z = -0.25f;
  rates.target_system = 1;
  rates.target_component = 1;
  const Bytes encoded = bytesOf(encode(gcs(4), rates));
  EXPECT_EQ(encoded, fromHex(GOLDEN_SET_ATTITUDE_RATES));
  EXPECT_EQ(encoded[1], 34) << "gimbal_device_id 0 is cut";

  const auto back = decode<GimbalManagerSetAttitude>(parseOne(GOLDEN_SET_ATTITUDE_ANGLES));
  EXPECT_EQ(back.flags, gimbal_flags::YAW_LOCK);
  EXPECT_NEAR(panTiltFromQuaternion(back.q).pan, M_PI / 2.0, 1e-6);
  EXPECT_NEAR(panTiltFromQuaternion(back.q).tilt, 0.0, 1e-6);
  EXPECT_TRUE(std::isnan(back.angular_velocity_z));
  EXPECT_EQ(back.gimbal_device_id, 154);
  const auto rates_back = decode<GimbalManagerSetAttitude>(parseOne(GOLDEN_SET_ATTITUDE_RATES));
  EXPECT_TRUE(std::isnan(rates_back.q[0]) && std::isnan(rates_back.q[3]));
  EXPECT_TRUE(std::isnan(rates_back.angular_velocity_x));
  EXPECT_EQ(rates_back.angular_velocity_y, 0.5f);
  EXPECT_EQ(rates_back.angular_velocity_z, -0.25f);
  EXPECT_EQ(rates_back.target_component, 1);
  EXPECT_EQ(rates_back.gimbal_device_id, 0);
}

TEST(MavlinkGolden, ManagerInformationAndStatusNameTheirGimbal)
{
  GimbalManagerInformation information;
  information.time_boot_ms = 1000;
  information.cap_flags = 0x7E2;
  information.pitch_min = static_cast<float>(-M_PI / 2.0);
  information.pitch_max = static_cast<float>(M_PI / 4.0);
  information.yaw_min = static_cast<float>(-M_PI);
  information.yaw_max = static_cast<float>(M_PI);
  information.gimbal_device_id = 154;
  EXPECT_EQ(bytesOf(encode(FrameHeader{ 0, 1, 1 }, information)), fromHex(GOLDEN_INFORMATION));
  const Frame information_frame = parseOne(GOLDEN_INFORMATION);
  EXPECT_EQ(information_frame.header.component_id, 1);
  const auto information_back = decode<GimbalManagerInformation>(information_frame);
  EXPECT_EQ(information_back.gimbal_device_id, 154);
  EXPECT_EQ(information_back.cap_flags, gimbal_caps::HAS_NEUTRAL | gimbal_caps::HAS_PITCH_AXIS |
                                            gimbal_caps::HAS_PITCH_FOLLOW | gimbal_caps::HAS_PITCH_LOCK |
                                            gimbal_caps::HAS_YAW_AXIS | gimbal_caps::HAS_YAW_FOLLOW |
                                            gimbal_caps::HAS_YAW_LOCK);
  EXPECT_EQ(information_back.pitch_max, static_cast<float>(M_PI / 4.0));
  EXPECT_EQ(information_back.yaw_min, static_cast<float>(-M_PI));

  GimbalManagerStatus status;
  status.time_boot_ms = 1000;
  status.gimbal_device_id = 2;
  status.primary_control_sysid = 1;
  status.primary_control_compid = 191;
  const Bytes encoded = bytesOf(encode(FrameHeader{ 1, 1, 1 }, status));
  EXPECT_EQ(encoded, fromHex(GOLDEN_STATUS));
  EXPECT_EQ(encoded[1], 11);
  const auto status_back = decode<GimbalManagerStatus>(parseOne(GOLDEN_STATUS));
  EXPECT_EQ(status_back.gimbal_device_id, 2);
  EXPECT_EQ(status_back.primary_control_sysid, 1);
  EXPECT_EQ(status_back.primary_control_compid, 191);
  EXPECT_EQ(status_back.secondary_control_compid, 0);
}

TEST(MavlinkGolden, AttitudeOfAGimbalDeviceAndOfAGimbalInsideItsManager)
{
  const Bytes device = bytesOf(encode(FrameHeader{ 2, 1, 154 }, levelAttitude(0)));
  EXPECT_EQ(device, fromHex(GOLDEN_ATTITUDE_OF_A_DEVICE));
  EXPECT_EQ(device[1], 48) << "gimbal_device_id 0 is cut";
  EXPECT_EQ(bytesOf(encode(FrameHeader{ 2, 1, 1 }, levelAttitude(2))), fromHex(GOLDEN_ATTITUDE_INSIDE_A_MANAGER));

  const Frame device_frame = parseOne(GOLDEN_ATTITUDE_OF_A_DEVICE);
  EXPECT_EQ(device_frame.header.component_id, 154);
  const auto device_back = decode<GimbalDeviceAttitudeStatus>(device_frame);
  EXPECT_EQ(device_back.gimbal_device_id, 0);
  EXPECT_EQ(device_back.flags, gimbal_flags::YAW_IN_VEHICLE_FRAME);
  EXPECT_EQ(device_back.delta_yaw, 0.5f);
  EXPECT_TRUE(std::isnan(device_back.delta_yaw_velocity));
  EXPECT_EQ(device_back.q[0], 1.0f);
  const Frame inside_frame = parseOne(GOLDEN_ATTITUDE_INSIDE_A_MANAGER);
  EXPECT_EQ(inside_frame.header.component_id, 1);
  EXPECT_EQ(decode<GimbalDeviceAttitudeStatus>(inside_frame).gimbal_device_id, 2);
}

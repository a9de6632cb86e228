/**
 * \file
 * \brief The MAVLink messages: every one through the codec and back, their CRC_EXTRA from common.xml's definitions,
 * their flags and result names, and the attitude's quaternion and the pan and tilt it points at.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mavlink_test_frames.h"
#include "ptz_action_server/core/units.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using namespace mavlink_test;

// --- round trips of every message this codec packs

TEST(MavlinkMessages, EveryMessageRoundTrips)
{
  FrameParser parser;
  auto through = [&parser](const auto& message) {
    const EncodedFrame encoded = encode(FrameHeader{ 7, 1, 154 }, message);
    std::vector<Frame> frames = parseAll(parser, Bytes(encoded.data(), encoded.data() + encoded.size));
    EXPECT_EQ(frames.size(), 1u);
    using Message = std::decay_t<decltype(message)>;
    EXPECT_EQ(frames.empty() ? 0u : frames[0].message_id, Message::ID);
    return frames.empty() ? Message{} : decode<Message>(frames[0]);
  };

  Heartbeat heartbeat;
  heartbeat.custom_mode = 0x01020304;
  heartbeat.type = MAV_TYPE_GIMBAL;
  heartbeat.base_mode = 0x81;
  const Heartbeat heartbeat_back = through(heartbeat);
  EXPECT_EQ(heartbeat_back.custom_mode, heartbeat.custom_mode);
  EXPECT_EQ(heartbeat_back.type, MAV_TYPE_GIMBAL);
  EXPECT_EQ(heartbeat_back.base_mode, 0x81);
  EXPECT_EQ(heartbeat_back.mavlink_version, 3);

  CommandLong command;
  command.params = { 1.5f, -2.0f, 3.25f, UNSET, 5.0f, 6.0f, 7.0f };
  command.command = command_id::SET_MESSAGE_INTERVAL;
  command.target_system = 3;
  command.target_component = 4;
  command.confirmation = 2;
  const CommandLong command_back = through(command);
  EXPECT_EQ(command_back.params[2], 3.25f);
  EXPECT_TRUE(std::isnan(command_back.params[3]));
  EXPECT_EQ(command_back.params[6], 7.0f);
  EXPECT_EQ(command_back.command, command_id::SET_MESSAGE_INTERVAL);
  EXPECT_EQ(command_back.target_component, 4);
  EXPECT_EQ(command_back.confirmation, 2);

  CommandAck ack;
  ack.command = command_id::DO_GIMBAL_MANAGER_CONFIGURE;
  ack.result = Result::DENIED;
  ack.result_param2 = -7;
  ack.target_system = 1;
  ack.target_component = 191;
  const CommandAck ack_back = through(ack);
  EXPECT_EQ(ack_back.command, command_id::DO_GIMBAL_MANAGER_CONFIGURE);
  EXPECT_EQ(ack_back.result, Result::DENIED);
  EXPECT_EQ(ack_back.result_param2, -7);
  EXPECT_EQ(ack_back.target_component, 191);

  GimbalManagerInformation information;
  information.time_boot_ms = 1234;
  information.cap_flags = 0xFFFF;
  information.pitch_min = -1.5f;
  information.pitch_max = 0.5f;
  information.yaw_min = -3.0f;
  information.yaw_max = 3.0f;
  information.gimbal_device_id = 1;
  const GimbalManagerInformation information_back = through(information);
  EXPECT_EQ(information_back.pitch_min, -1.5f);
  EXPECT_EQ(information_back.pitch_max, 0.5f);
  EXPECT_EQ(information_back.yaw_min, -3.0f);
  EXPECT_EQ(information_back.yaw_max, 3.0f);
  EXPECT_EQ(information_back.cap_flags, 0xFFFFu);
  EXPECT_EQ(information_back.gimbal_device_id, 1);

  GimbalManagerStatus status;
  status.flags = gimbal_flags::YAW_LOCK;
  status.gimbal_device_id = 1;
  status.primary_control_sysid = 1;
  status.primary_control_compid = 191;
  status.secondary_control_sysid = 255;
  status.secondary_control_compid = 190;
  const GimbalManagerStatus status_back = through(status);
  EXPECT_EQ(status_back.flags, gimbal_flags::YAW_LOCK);
  EXPECT_EQ(status_back.primary_control_compid, 191);
  EXPECT_EQ(status_back.secondary_control_sysid, 255);
  EXPECT_EQ(status_back.secondary_control_compid, 190);

  GimbalManagerSetAttitude attitude;
  attitude.flags = gimbal_flags::YAW_IN_VEHICLE_FRAME;
  attitude.q = quaternionFromPanTilt(0.3, -0.2);
  attitude.angular_velocity_z = 0.1f;
  attitude.target_system = 1;
  attitude.target_component = 154;
  attitude.gimbal_device_id = 2;
  const GimbalManagerSetAttitude attitude_back = through(attitude);
  EXPECT_EQ(attitude_back.q, attitude.q);
  EXPECT_TRUE(std::isnan(attitude_back.angular_velocity_x));
  EXPECT_EQ(attitude_back.angular_velocity_z, 0.1f);
  EXPECT_EQ(attitude_back.gimbal_device_id, 2);

  GimbalDeviceAttitudeStatus device;
  device.time_boot_ms = 99;
  device.q = quaternionFromPanTilt(-1.0, 0.4);
  device.angular_velocity_x = 0.0f;
  device.angular_velocity_y = 0.2f;
  device.angular_velocity_z = -0.3f;
  device.failure_flags = 2;
  device.flags = gimbal_flags::YAW_IN_VEHICLE_FRAME;
  device.delta_yaw = 0.75f;
  device.gimbal_device_id = 1;
  const GimbalDeviceAttitudeStatus device_back = through(device);
  EXPECT_EQ(device_back.q, device.q);
  EXPECT_EQ(device_back.angular_velocity_z, -0.3f);
  EXPECT_EQ(device_back.failure_flags, 2u);
  EXPECT_EQ(device_back.flags, gimbal_flags::YAW_IN_VEHICLE_FRAME);
  EXPECT_EQ(device_back.delta_yaw, 0.75f);
  EXPECT_EQ(device_back.gimbal_device_id, 1);

  const GimbalManagerSetPitchYaw pitch_yaw_back = through(pitchYawGolden());
  EXPECT_EQ(pitch_yaw_back.pitch, -0.5f);
  EXPECT_EQ(pitch_yaw_back.yaw, 0.25f);

  EXPECT_EQ(parser.counts().frames, 8u);
  for (std::size_t error = 0; error < FRAME_ERROR_COUNT; ++error)
  {
    EXPECT_EQ(parser.counts().errors[error], 0u) << toString(static_cast<FrameError>(error));
  }
}

TEST(MavlinkMessages, AnAttitudeStatusWithoutItsExtensionsReadsThemAsZero)
{
  // A device built before the extensions sends 40 bytes; the receiver zero-fills the rest.
  GimbalDeviceAttitudeStatus device;
  device.q = quaternionFromPanTilt(0.5, 0.1);
  device.target_system = 1;
  device.target_component = 191;
  Payload payload{};
  pack(device, payload);
  const EncodedFrame encoded = encodeFrame(FrameHeader{ 0, 1, 154 },
                                           *findMessage(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS), payload.data(), 40);
  EXPECT_EQ(encoded.bytes[1], 40);
  FrameParser parser;
  const std::vector<Frame> frames = parseAll(parser, Bytes(encoded.data(), encoded.data() + encoded.size));
  ASSERT_EQ(frames.size(), 1u);
  const auto back = decode<GimbalDeviceAttitudeStatus>(frames[0]);
  EXPECT_EQ(back.q, device.q);
  EXPECT_EQ(back.delta_yaw, 0.0f);
  EXPECT_EQ(back.gimbal_device_id, 0);
}

TEST(MavlinkMessages, ResultNames)
{
  EXPECT_EQ(toString(Result::ACCEPTED), "ACCEPTED");
  EXPECT_EQ(toString(Result::TEMPORARILY_REJECTED), "TEMPORARILY_REJECTED");
  EXPECT_EQ(toString(Result::DENIED), "DENIED");
  EXPECT_EQ(toString(Result::COMMAND_UNSUPPORTED_MAV_FRAME), "COMMAND_UNSUPPORTED_MAV_FRAME");
  EXPECT_EQ(toString(static_cast<Result>(42)), "result 42");
}

// --- CRC_EXTRA, from the message definitions of common.xml

namespace
{
/// A field of a message definition, in wire order (sorted by type size, extensions left out).
struct FieldDefinition
{
  const char* type;  ///< as common.xml has it, without the array length
  const char* name;
  std::uint8_t array_length;  ///< 0: not an array
};

/// CRC_EXTRA as MAVLink's generator derives it: the CRC of "NAME " and of "type name " per field (with the array
/// length as a byte after an array), its two bytes xor-ed.
std::uint8_t crcExtraOf(const std::string& name, const std::vector<FieldDefinition>& fields)
{
  auto text = [](const std::string& value, std::uint16_t crc) {
    return crc16(reinterpret_cast<const std::uint8_t*>(value.data()), value.size(), crc);
  };
  std::uint16_t crc = text(name + " ", 0xFFFF);
  for (const FieldDefinition& field : fields)
  {
    crc = text(std::string(field.type) + " ", crc);
    crc = text(std::string(field.name) + " ", crc);
    if (field.array_length != 0)
    {
      crc = crcAccumulate(field.array_length, crc);
    }
  }
  return static_cast<std::uint8_t>((crc & 0xFF) ^ (crc >> 8));
}
}  // namespace

TEST(MavlinkCrcExtra, EveryMessageDecodedHereHasTheCrcExtraOfItsCommonXmlDefinition)
{
  // The fields of common.xml's definitions, in the order the wire has them (and mavlink_messages.h's offsets).
  const std::vector<std::pair<std::uint32_t, std::vector<FieldDefinition>>> definitions = {
    { message_id::HEARTBEAT,
      { { "uint32_t", "custom_mode", 0 },
        { "uint8_t", "type", 0 },
        { "uint8_t", "autopilot", 0 },
        { "uint8_t", "base_mode", 0 },
        { "uint8_t", "system_status", 0 },
        { "uint8_t", "mavlink_version", 0 } } },
    { message_id::COMMAND_LONG,
      { { "float", "param1", 0 },
        { "float", "param2", 0 },
        { "float", "param3", 0 },
        { "float", "param4", 0 },
        { "float", "param5", 0 },
        { "float", "param6", 0 },
        { "float", "param7", 0 },
        { "uint16_t", "command", 0 },
        { "uint8_t", "target_system", 0 },
        { "uint8_t", "target_component", 0 },
        { "uint8_t", "confirmation", 0 } } },
    { message_id::COMMAND_ACK, { { "uint16_t", "command", 0 }, { "uint8_t", "result", 0 } } },
    { message_id::GIMBAL_MANAGER_INFORMATION,
      { { "uint32_t", "time_boot_ms", 0 },
        { "uint32_t", "cap_flags", 0 },
        { "float", "roll_min", 0 },
        { "float", "roll_max", 0 },
        { "float", "pitch_min", 0 },
        { "float", "pitch_max", 0 },
        { "float", "yaw_min", 0 },
        { "float", "yaw_max", 0 },
        { "uint8_t", "gimbal_device_id", 0 } } },
    { message_id::GIMBAL_MANAGER_STATUS,
      { { "uint32_t", "time_boot_ms", 0 },
        { "uint32_t", "flags", 0 },
        { "uint8_t", "gimbal_device_id", 0 },
        { "uint8_t", "primary_control_sysid", 0 },
        { "uint8_t", "primary_control_compid", 0 },
        { "uint8_t", "secondary_control_sysid", 0 },
        { "uint8_t", "secondary_control_compid", 0 } } },
    { message_id::GIMBAL_MANAGER_SET_ATTITUDE,
      { { "uint32_t", "flags", 0 },
        { "float", "q", 4 },
        { "float", "angular_velocity_x", 0 },
        { "float", "angular_velocity_y", 0 },
        { "float", "angular_velocity_z", 0 },
        { "uint8_t", "target_system", 0 },
        { "uint8_t", "target_component", 0 },
        { "uint8_t", "gimbal_device_id", 0 } } },
    { message_id::GIMBAL_DEVICE_ATTITUDE_STATUS,  // delta_yaw, delta_yaw_velocity, gimbal_device_id: extensions
      { { "uint32_t", "time_boot_ms", 0 },
        { "float", "q", 4 },
        { "float", "angular_velocity_x", 0 },
        { "float", "angular_velocity_y", 0 },
        { "float", "angular_velocity_z", 0 },
        { "uint32_t", "failure_flags", 0 },
        { "uint16_t", "flags", 0 },
        { "uint8_t", "target_system", 0 },
        { "uint8_t", "target_component", 0 } } },
    { message_id::GIMBAL_MANAGER_SET_PITCHYAW,
      { { "uint32_t", "flags", 0 },
        { "float", "pitch", 0 },
        { "float", "yaw", 0 },
        { "float", "pitch_rate", 0 },
        { "float", "yaw_rate", 0 },
        { "uint8_t", "target_system", 0 },
        { "uint8_t", "target_component", 0 },
        { "uint8_t", "gimbal_device_id", 0 } } },
  };
  for (const auto& definition : definitions)
  {
    const MessageSpec* spec = findMessage(definition.first);
    ASSERT_NE(spec, nullptr) << definition.first;
    EXPECT_EQ(spec->crc_extra, crcExtraOf(spec->name, definition.second)) << spec->name;
  }
}

TEST(MavlinkMessages, YawFrameFlags)
{
  EXPECT_FALSE(yawInEarthFrame(0));
  EXPECT_TRUE(yawInEarthFrame(gimbal_flags::YAW_LOCK)) << "before the frame flags, YAW_LOCK meant North";
  EXPECT_TRUE(yawInEarthFrame(gimbal_flags::YAW_IN_EARTH_FRAME));
  EXPECT_FALSE(yawInEarthFrame(gimbal_flags::YAW_IN_VEHICLE_FRAME | gimbal_flags::YAW_LOCK));
  EXPECT_TRUE(isInternalGimbalId(1) && isInternalGimbalId(6));
  EXPECT_FALSE(isInternalGimbalId(0) || isInternalGimbalId(7) || isInternalGimbalId(MAV_COMP_ID_GIMBAL));
}

// --- attitude

TEST(MavlinkAttitude, TheQuaternionOfProtocolsMdAndBack)
{
  const double pan = 0.7, tilt = -0.4;
  const Quaternion q = quaternionFromPanTilt(pan, tilt);
  const double p = tilt / 2.0, y = pan / 2.0;
  EXPECT_NEAR(q[0], std::cos(p) * std::cos(y), 1e-7);
  EXPECT_NEAR(q[1], -std::sin(p) * std::sin(y), 1e-7);
  EXPECT_NEAR(q[2], std::sin(p) * std::cos(y), 1e-7);
  EXPECT_NEAR(q[3], std::cos(p) * std::sin(y), 1e-7);
  const PanTilt back = panTiltFromQuaternion(q);
  EXPECT_NEAR(back.pan, pan, 1e-6);
  EXPECT_NEAR(back.tilt, tilt, 1e-6);
}

TEST(MavlinkAttitude, SignsAreTheContracts)
{
  // Pitch up is positive tilt; yaw right (clockwise seen from above, FRD) is positive pan.
  const PanTilt up = panTiltFromQuaternion(quaternionFromPanTilt(0.0, 0.3));
  EXPECT_NEAR(up.tilt, 0.3, 1e-6);
  // A pure rotation of +0.5 rad about z down turns x towards y (right).
  const PanTilt right = panTiltFromQuaternion(
      Quaternion{ { static_cast<float>(std::cos(0.25)), 0.0f, 0.0f, static_cast<float>(std::sin(0.25)) } });
  EXPECT_NEAR(right.pan, 0.5, 1e-6);
  EXPECT_NEAR(right.tilt, 0.0, 1e-6);
}

TEST(MavlinkAttitude, NoSingularityAtPitchMinusNinetyDegrees)
{
  for (double pan : { -2.5, -1.0, 0.0, 0.6, 3.0 })
  {
    for (double tilt_degrees : { -90.0, -89.99, -89.9, -89.0, 89.99, 90.0 })
    {
      const double tilt = toRadians(tilt_degrees);
      const PanTilt back = panTiltFromQuaternion(quaternionFromPanTilt(pan, tilt));
      EXPECT_NEAR(back.tilt, tilt, 1e-5) << pan << " " << tilt_degrees;
      EXPECT_NEAR(std::remainder(back.pan - pan, 2 * M_PI), 0.0, 2e-3) << pan << " " << tilt_degrees;
    }
  }
}

TEST(MavlinkAttitude, AQuaternionThatIsNotNormalisedGivesTheSameAngles)
{
  Quaternion q = quaternionFromPanTilt(-0.9, 0.2);
  for (float& component : q)
  {
    component *= 3.0f;
  }
  const PanTilt back = panTiltFromQuaternion(q);
  EXPECT_NEAR(back.pan, -0.9, 1e-6);
  EXPECT_NEAR(back.tilt, 0.2, 1e-6);
}

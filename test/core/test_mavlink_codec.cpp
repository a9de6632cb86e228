#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ptz_action_server/core/mavlink/mavlink_messages.h"
#include "ptz_action_server/core/units.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using Bytes = std::vector<std::uint8_t>;

namespace
{
Bytes fromHex(const std::string& hex)
{
  Bytes bytes;
  for (std::size_t index = 0; index + 1 < hex.size(); index += 2)
  {
    bytes.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(index, 2), nullptr, 16)));
  }
  return bytes;
}

Bytes bytesOf(const EncodedFrame& frame)
{
  return Bytes(frame.data(), frame.data() + frame.size);
}

FrameHeader gcs(std::uint8_t sequence)
{
  return FrameHeader{ sequence, 255, 190 };
}

std::vector<Frame> parseAll(FrameParser& parser, const Bytes& bytes)
{
  std::vector<Frame> frames;
  parser.feed(bytes.data(), bytes.size(), [&frames](const Frame& frame) { frames.push_back(frame); });
  return frames;
}

std::uint64_t errors(const FrameParser& parser, FrameError error)
{
  return parser.counts().errors[static_cast<std::size_t>(error)];
}

// The three golden frames of protocols.md section 9 (sysid 255, compid 190).
const char* GOLDEN_HEARTBEAT = "fd09000000ffbe0000000000000006080004033d48";
const char* GOLDEN_SET_PITCHYAW = "fd16000001ffbe1f010000000000000000bf0000803e0000c07f0000c07f019a6271";
const char* GOLDEN_CONFIGURE = "fd20000002ffbe4c0000000000c0000000c0000080bf000080bf000000000000000000000000e9030101f5f"
                               "1";

CommandLong configureGolden()
{
  CommandLong command;
  command.params = { -2.0f, -2.0f, -1.0f, -1.0f, 0.0f, 0.0f, 0.0f };
  command.command = command_id::DO_GIMBAL_MANAGER_CONFIGURE;
  command.target_system = 1;
  command.target_component = 1;
  return command;
}

GimbalManagerSetPitchYaw pitchYawGolden()
{
  GimbalManagerSetPitchYaw message;
  message.pitch = -0.5f;
  message.yaw = 0.25f;
  message.target_system = 1;
  message.target_component = 154;
  return message;
}
}  // namespace

TEST(MavlinkCrc, CheckValueOfMcrf4xx)
{
  const std::string text = "123456789";
  EXPECT_EQ(crc16(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), 0x6F91);
}

TEST(MavlinkGolden, HeartbeatOfAGroundStation)
{
  Heartbeat heartbeat;
  heartbeat.type = MAV_TYPE_GCS;
  heartbeat.autopilot = MAV_AUTOPILOT_INVALID;
  heartbeat.system_status = MAV_STATE_ACTIVE;
  EXPECT_EQ(bytesOf(encode(gcs(0), heartbeat)), fromHex(GOLDEN_HEARTBEAT));
}

TEST(MavlinkGolden, SetPitchYawWithTheTrailingZeroCut)
{
  const Bytes encoded = bytesOf(encode(gcs(1), pitchYawGolden()));
  EXPECT_EQ(encoded, fromHex(GOLDEN_SET_PITCHYAW));
  EXPECT_EQ(encoded[1], 22) << "gimbal_device_id 0 is cut";
}

TEST(MavlinkGolden, ConfigureCommandLong)
{
  EXPECT_EQ(bytesOf(encode(gcs(2), configureGolden())), fromHex(GOLDEN_CONFIGURE));
}

TEST(MavlinkGolden, GoldenFramesParseBackWithTheCutBytesZeroFilled)
{
  FrameParser parser;
  Bytes stream = fromHex(GOLDEN_HEARTBEAT);
  for (const char* hex : { GOLDEN_SET_PITCHYAW, GOLDEN_CONFIGURE })
  {
    const Bytes frame = fromHex(hex);
    stream.insert(stream.end(), frame.begin(), frame.end());
  }
  const std::vector<Frame> frames = parseAll(parser, stream);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].message_id, message_id::HEARTBEAT);
  EXPECT_EQ(decode<Heartbeat>(frames[0]).type, MAV_TYPE_GCS);
  EXPECT_EQ(frames[1].header.sequence, 1);
  EXPECT_EQ(frames[1].header.system_id, 255);
  EXPECT_EQ(frames[1].header.component_id, 190);
  const auto pitch_yaw = decode<GimbalManagerSetPitchYaw>(frames[1]);
  EXPECT_EQ(pitch_yaw.pitch, -0.5f);
  EXPECT_EQ(pitch_yaw.yaw, 0.25f);
  EXPECT_TRUE(std::isnan(pitch_yaw.pitch_rate));
  EXPECT_TRUE(std::isnan(pitch_yaw.yaw_rate));
  EXPECT_EQ(pitch_yaw.target_component, 154);
  EXPECT_EQ(pitch_yaw.gimbal_device_id, 0);
  const auto configure = decode<CommandLong>(frames[2]);
  EXPECT_EQ(configure.command, command_id::DO_GIMBAL_MANAGER_CONFIGURE);
  EXPECT_EQ(configure.params[0], -2.0f);
  EXPECT_EQ(configure.params[3], -1.0f);
  EXPECT_EQ(configure.confirmation, 0);
  EXPECT_EQ(parser.counts().frames, 3u);
}

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

// --- golden frames of the gimbal messages the backend and the emulator decode, written from the definitions

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

TEST(MavlinkMessages, YawFrameFlags)
{
  EXPECT_FALSE(yawInEarthFrame(0));
  EXPECT_TRUE(yawInEarthFrame(gimbal_flags::YAW_LOCK)) << "before the frame flags, YAW_LOCK meant North";
  EXPECT_TRUE(yawInEarthFrame(gimbal_flags::YAW_IN_EARTH_FRAME));
  EXPECT_FALSE(yawInEarthFrame(gimbal_flags::YAW_IN_VEHICLE_FRAME | gimbal_flags::YAW_LOCK));
  EXPECT_TRUE(isInternalGimbalId(1) && isInternalGimbalId(6));
  EXPECT_FALSE(isInternalGimbalId(0) || isInternalGimbalId(7) || isInternalGimbalId(MAV_COMP_ID_GIMBAL));
}

// --- the parser on a byte stream

TEST(MavlinkParser, AStreamSplitAtEveryOffsetWithGarbageBetweenFramesYieldsEveryFrame)
{
  // Garbage that holds start bytes too: a lone 0xFD, a 0xFD followed by a plausible header, a 0xFE.
  const Bytes garbage = { 0x00, 0xFD, 0x11, 0xFE, 0x03, 0xFD, 0x02, 0x00, 0x00, 0x05, 0x01, 0x01, 0x1F, 0x01, 0x00 };
  Bytes stream;
  const char* frames_hex[] = { GOLDEN_HEARTBEAT, GOLDEN_SET_PITCHYAW, GOLDEN_CONFIGURE };
  for (const char* hex : frames_hex)
  {
    stream.insert(stream.end(), garbage.begin(), garbage.end());
    const Bytes frame = fromHex(hex);
    stream.insert(stream.end(), frame.begin(), frame.end());
  }
  stream.insert(stream.end(), garbage.begin(), garbage.end());

  for (std::size_t split = 0; split <= stream.size(); ++split)
  {
    FrameParser parser;
    std::vector<Frame> frames;
    auto keep = [&frames](const Frame& frame) { frames.push_back(frame); };
    parser.feed(stream.data(), split, keep);
    parser.feed(stream.data() + split, stream.size() - split, keep);
    ASSERT_EQ(frames.size(), 3u) << "split at " << split;
    EXPECT_EQ(frames[0].message_id, message_id::HEARTBEAT);
    EXPECT_EQ(frames[1].message_id, message_id::GIMBAL_MANAGER_SET_PITCHYAW);
    EXPECT_EQ(frames[2].message_id, message_id::COMMAND_LONG);
    EXPECT_EQ(frames[2].header.sequence, 2);
    EXPECT_GT(parser.counts().noise_bytes, 0u);
  }
}

TEST(MavlinkParser, AStreamFedByteByByteYieldsEveryFrame)
{
  Bytes stream;
  for (const char* hex : { GOLDEN_CONFIGURE, GOLDEN_HEARTBEAT, GOLDEN_SET_PITCHYAW })
  {
    const Bytes frame = fromHex(hex);
    stream.insert(stream.end(), frame.begin(), frame.end());
  }
  FrameParser parser;
  std::vector<std::uint32_t> ids;
  for (std::uint8_t byte : stream)
  {
    parser.feed(&byte, 1, [&ids](const Frame& frame) { ids.push_back(frame.message_id); });
  }
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{ message_id::COMMAND_LONG, message_id::HEARTBEAT,
                                              message_id::GIMBAL_MANAGER_SET_PITCHYAW }));
}

TEST(MavlinkParser, ADamagedFrameIsCountedAndTheNextOneSurvives)
{
  Bytes damaged = fromHex(GOLDEN_SET_PITCHYAW);
  damaged[14] ^= 0x40;  // a bit of the pitch
  Bytes stream = damaged;
  const Bytes good = fromHex(GOLDEN_HEARTBEAT);
  stream.insert(stream.end(), good.begin(), good.end());
  FrameParser parser;
  const std::vector<Frame> frames = parseAll(parser, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].message_id, message_id::HEARTBEAT);
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 1u);
}

TEST(MavlinkParser, TheWrongCrcExtraFailsTheCheck)
{
  // The same bytes framed with another message's CRC_EXTRA: a receiver must refuse them.
  Payload payload{};
  pack(pitchYawGolden(), payload);
  MessageSpec wrong = *findMessage(message_id::GIMBAL_MANAGER_SET_PITCHYAW);
  wrong.crc_extra = 2;
  const EncodedFrame encoded = encodeFrame(gcs(1), wrong, payload.data(), wrong.length);
  FrameParser parser;
  EXPECT_TRUE(parseAll(parser, Bytes(encoded.data(), encoded.data() + encoded.size)).empty());
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 1u);
}

TEST(MavlinkParser, UnknownIncompatFlagsAreDroppedAndCounted)
{
  Bytes frame = fromHex(GOLDEN_HEARTBEAT);
  frame[2] = 0x02;
  FrameParser parser;
  EXPECT_TRUE(parseAll(parser, frame).empty());
  EXPECT_EQ(errors(parser, FrameError::BAD_INCOMPAT), 1u);
}

TEST(MavlinkParser, ASignedFrameIsTakenWithItsSignatureSkipped)
{
  // The signature is not verified (no key is configured); the CRC still covers the frame.
  Payload payload{};
  pack(Heartbeat(), payload);
  const MessageSpec& spec = *findMessage(message_id::HEARTBEAT);
  Bytes frame = { STX_V2, 9, INCOMPAT_SIGNED, 0, 5, 1, 1, 0, 0, 0 };
  frame.insert(frame.end(), payload.begin(), payload.begin() + 9);
  std::uint16_t crc = crcAccumulate(spec.crc_extra, crc16(frame.data() + 1, frame.size() - 1));
  frame.push_back(static_cast<std::uint8_t>(crc));
  frame.push_back(static_cast<std::uint8_t>(crc >> 8));
  frame.insert(frame.end(), SIGNATURE_SIZE, 0xAB);
  const Bytes next = fromHex(GOLDEN_HEARTBEAT);
  frame.insert(frame.end(), next.begin(), next.end());
  FrameParser parser;
  EXPECT_EQ(parseAll(parser, frame).size(), 2u);
  EXPECT_EQ(parser.counts().signed_frames, 1u);
  EXPECT_EQ(parser.counts().noise_bytes, 0u);
}

TEST(MavlinkParser, MavlinkOneFramesAreCountedAndSkippedWhole)
{
  // A MAVLink 1 HEARTBEAT: FE len seq sys comp msgid(1) payload crc. Its payload holds a 0xFD that must not start
  // a frame.
  Bytes v1 = { STX_V1, 9, 0, 1, 1, 0, 0xFD, 0x09, 0, 0, 2, 3, 0, 4, 3 };
  const std::uint16_t crc =
      crcAccumulate(findMessage(message_id::HEARTBEAT)->crc_extra, crc16(v1.data() + 1, v1.size() - 1));
  v1.push_back(static_cast<std::uint8_t>(crc));
  v1.push_back(static_cast<std::uint8_t>(crc >> 8));
  const Bytes good = fromHex(GOLDEN_HEARTBEAT);
  v1.insert(v1.end(), good.begin(), good.end());
  FrameParser parser;
  EXPECT_EQ(parseAll(parser, v1).size(), 1u);
  EXPECT_EQ(errors(parser, FrameError::MAVLINK1), 1u);
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 0u);
}

TEST(MavlinkParser, AFrameOfAnUnknownMessageIsSkippedWholeWhenAnotherFollows)
{
  // msgid 33 (GLOBAL_POSITION_INT) is nothing this codec knows; the frame after it must come through.
  Bytes unknown = { STX_V2, 4, 0, 0, 9, 1, 1, 33, 0, 0, 0xFD, 0xFD, 0xFD, 0xFD, 0x12, 0x34 };
  const Bytes good = fromHex(GOLDEN_HEARTBEAT);
  unknown.insert(unknown.end(), good.begin(), good.end());
  FrameParser parser;
  EXPECT_EQ(parseAll(parser, unknown).size(), 1u);
  EXPECT_EQ(errors(parser, FrameError::UNKNOWN_MESSAGE), 1u);
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 0u);
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

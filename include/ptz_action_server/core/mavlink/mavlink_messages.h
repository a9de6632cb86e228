/**
 * \file
 * \brief The MAVLink messages of Gimbal Protocol v2 (and the few common ones it needs), with their wire layouts:
 * fields sorted by type size, extension fields last (protocols.md section 9).
 */
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include "ptz_action_server/core/byte_order.h"
#include "ptz_action_server/core/mavlink/mavlink_codec.h"
#include "ptz_action_server/core/mavlink/mavlink_quaternion.h"

namespace ptz_action_server
{
namespace mavlink
{
namespace message_id
{
constexpr std::uint32_t HEARTBEAT = 0;
constexpr std::uint32_t COMMAND_INT = 75;
constexpr std::uint32_t COMMAND_LONG = 76;
constexpr std::uint32_t COMMAND_ACK = 77;
constexpr std::uint32_t GIMBAL_MANAGER_INFORMATION = 280;
constexpr std::uint32_t GIMBAL_MANAGER_STATUS = 281;
constexpr std::uint32_t GIMBAL_MANAGER_SET_ATTITUDE = 282;
constexpr std::uint32_t GIMBAL_DEVICE_INFORMATION = 283;
constexpr std::uint32_t GIMBAL_DEVICE_SET_ATTITUDE = 284;
constexpr std::uint32_t GIMBAL_DEVICE_ATTITUDE_STATUS = 285;
constexpr std::uint32_t AUTOPILOT_STATE_FOR_GIMBAL_DEVICE = 286;
constexpr std::uint32_t GIMBAL_MANAGER_SET_PITCHYAW = 287;
constexpr std::uint32_t GIMBAL_MANAGER_SET_MANUAL_CONTROL = 288;
}  // namespace message_id

/// MAV_CMD values this backend sends.
namespace command_id
{
constexpr std::uint16_t SET_MESSAGE_INTERVAL = 511;
constexpr std::uint16_t REQUEST_MESSAGE = 512;
constexpr std::uint16_t DO_GIMBAL_MANAGER_PITCHYAW = 1000;
constexpr std::uint16_t DO_GIMBAL_MANAGER_CONFIGURE = 1001;
}  // namespace command_id

/// MAV_RESULT.
enum class Result : std::uint8_t
{
  ACCEPTED = 0,
  TEMPORARILY_REJECTED = 1,
  DENIED = 2,
  UNSUPPORTED = 3,
  FAILED = 4,
  IN_PROGRESS = 5,
  CANCELLED = 6,
  COMMAND_LONG_ONLY = 7,
  COMMAND_INT_ONLY = 8,
  COMMAND_UNSUPPORTED_MAV_FRAME = 9,
};
/// "DENIED", or "result 42" for a value MAVLink does not define.
std::string toString(Result result);

/// GIMBAL_MANAGER_FLAGS / GIMBAL_DEVICE_FLAGS.
namespace gimbal_flags
{
constexpr std::uint32_t RETRACT = 1;
constexpr std::uint32_t NEUTRAL = 2;
constexpr std::uint32_t ROLL_LOCK = 4;
constexpr std::uint32_t PITCH_LOCK = 8;
constexpr std::uint32_t YAW_LOCK = 16;  ///< yaw relative to North (earth frame)
constexpr std::uint32_t YAW_IN_VEHICLE_FRAME = 32;
constexpr std::uint32_t YAW_IN_EARTH_FRAME = 64;
}  // namespace gimbal_flags

/// The yaw of a setpoint or an attitude with \p flags is relative to North (the earth frame): YAW_IN_EARTH_FRAME,
/// or, when neither frame flag is set (senders from before those flags), YAW_LOCK.
inline bool yawInEarthFrame(std::uint32_t flags)
{
  if ((flags & (gimbal_flags::YAW_IN_EARTH_FRAME | gimbal_flags::YAW_IN_VEHICLE_FRAME)) == 0)
  {
    return (flags & gimbal_flags::YAW_LOCK) != 0;
  }
  return (flags & gimbal_flags::YAW_IN_EARTH_FRAME) != 0;
}

/// GIMBAL_MANAGER_CAP_FLAGS (its low 16 bits are GIMBAL_DEVICE_CAP_FLAGS).
namespace gimbal_caps
{
constexpr std::uint32_t HAS_RETRACT = 1;
constexpr std::uint32_t HAS_NEUTRAL = 2;
constexpr std::uint32_t HAS_ROLL_AXIS = 4;
constexpr std::uint32_t HAS_ROLL_FOLLOW = 8;
constexpr std::uint32_t HAS_ROLL_LOCK = 16;
constexpr std::uint32_t HAS_PITCH_AXIS = 32;
constexpr std::uint32_t HAS_PITCH_FOLLOW = 64;
constexpr std::uint32_t HAS_PITCH_LOCK = 128;
constexpr std::uint32_t HAS_YAW_AXIS = 256;
constexpr std::uint32_t HAS_YAW_FOLLOW = 512;
constexpr std::uint32_t HAS_YAW_LOCK = 1024;
constexpr std::uint32_t SUPPORTS_INFINITE_YAW = 2048;
}  // namespace gimbal_caps

/// MAV_TYPE and MAV_AUTOPILOT values a heartbeat carries here.
constexpr std::uint8_t MAV_TYPE_GCS = 6;
constexpr std::uint8_t MAV_TYPE_ONBOARD_CONTROLLER = 18;
constexpr std::uint8_t MAV_TYPE_GIMBAL = 26;
constexpr std::uint8_t MAV_AUTOPILOT_INVALID = 8;
constexpr std::uint8_t MAV_STATE_ACTIVE = 4;
constexpr std::uint8_t MAV_COMP_ID_AUTOPILOT1 = 1;
constexpr std::uint8_t MAV_COMP_ID_GIMBAL = 154;
constexpr std::uint8_t MAV_COMP_ID_GIMBAL2 = 171;  ///< .. MAV_COMP_ID_GIMBAL6 = 175
constexpr std::uint8_t MAV_COMP_ID_GIMBAL6 = 175;

/**
 * \brief gimbal_device_id (Gimbal Protocol v2, "Addressing of gimbal devices"): 1..6 names a gimbal that is no MAVLink
 * component of its own but part of its manager's component (a gimbal the autopilot drives over PWM, a camera-gimbal
 * that is its own manager); any other value is the component id of a MAVLink gimbal device (154, 171..175, ...).
 * In commands and setpoints 0 means every gimbal of the addressed manager component. GIMBAL_DEVICE_ATTITUDE_STATUS
 * carries 1..6 when the manager's component sends it for a gimbal inside it, and 0 when a gimbal device sends it
 * from its own component (the sender's component id says which gimbal it is).
 */
constexpr std::uint8_t MAX_INTERNAL_GIMBAL_ID = 6;
inline bool isInternalGimbalId(std::uint8_t gimbal_device_id)
{
  return gimbal_device_id >= 1 && gimbal_device_id <= MAX_INTERNAL_GIMBAL_ID;
}

/// Not set: the value MAVLink uses for a float field left unset.
constexpr float UNSET = std::numeric_limits<float>::quiet_NaN();

struct Heartbeat
{
  static constexpr std::uint32_t ID = message_id::HEARTBEAT;
  std::uint32_t custom_mode = 0;
  std::uint8_t type = MAV_TYPE_ONBOARD_CONTROLLER;
  std::uint8_t autopilot = MAV_AUTOPILOT_INVALID;
  std::uint8_t base_mode = 0;
  std::uint8_t system_status = MAV_STATE_ACTIVE;
  std::uint8_t mavlink_version = 3;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.custom_mode);
    visit(4, self.type);
    visit(5, self.autopilot);
    visit(6, self.base_mode);
    visit(7, self.system_status);
    visit(8, self.mavlink_version);
  }
};

struct CommandLong
{
  static constexpr std::uint32_t ID = message_id::COMMAND_LONG;
  std::array<float, 7> params{};
  std::uint16_t command = 0;
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::uint8_t confirmation = 0;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.params);
    visit(28, self.command);
    visit(30, self.target_system);
    visit(31, self.target_component);
    visit(32, self.confirmation);
  }
};

struct CommandAck
{
  static constexpr std::uint32_t ID = message_id::COMMAND_ACK;
  std::uint16_t command = 0;
  Result result = Result::ACCEPTED;
  // Extensions.
  std::uint8_t progress = 0;
  std::int32_t result_param2 = 0;
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.command);
    visit(2, self.result);
    visit(3, self.progress);
    visit(4, self.result_param2);
    visit(8, self.target_system);
    visit(9, self.target_component);
  }
};

struct GimbalManagerInformation
{
  static constexpr std::uint32_t ID = message_id::GIMBAL_MANAGER_INFORMATION;
  std::uint32_t time_boot_ms = 0;
  std::uint32_t cap_flags = 0;
  float roll_min = 0.0f, roll_max = 0.0f;  ///< rad
  float pitch_min = 0.0f, pitch_max = 0.0f;
  float yaw_min = 0.0f, yaw_max = 0.0f;
  std::uint8_t gimbal_device_id = 0;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.time_boot_ms);
    visit(4, self.cap_flags);
    visit(8, self.roll_min);
    visit(12, self.roll_max);
    visit(16, self.pitch_min);
    visit(20, self.pitch_max);
    visit(24, self.yaw_min);
    visit(28, self.yaw_max);
    visit(32, self.gimbal_device_id);
  }
};

struct GimbalManagerStatus
{
  static constexpr std::uint32_t ID = message_id::GIMBAL_MANAGER_STATUS;
  std::uint32_t time_boot_ms = 0;
  std::uint32_t flags = 0;
  std::uint8_t gimbal_device_id = 0;
  std::uint8_t primary_control_sysid = 0;
  std::uint8_t primary_control_compid = 0;
  std::uint8_t secondary_control_sysid = 0;
  std::uint8_t secondary_control_compid = 0;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.time_boot_ms);
    visit(4, self.flags);
    visit(8, self.gimbal_device_id);
    visit(9, self.primary_control_sysid);
    visit(10, self.primary_control_compid);
    visit(11, self.secondary_control_sysid);
    visit(12, self.secondary_control_compid);
  }
};

struct GimbalManagerSetAttitude
{
  static constexpr std::uint32_t ID = message_id::GIMBAL_MANAGER_SET_ATTITUDE;
  std::uint32_t flags = 0;
  Quaternion q{ { UNSET, UNSET, UNSET, UNSET } };
  float angular_velocity_x = UNSET, angular_velocity_y = UNSET, angular_velocity_z = UNSET;  ///< rad/s
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::uint8_t gimbal_device_id = 0;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.flags);
    visit(4, self.q);
    visit(20, self.angular_velocity_x);
    visit(24, self.angular_velocity_y);
    visit(28, self.angular_velocity_z);
    visit(32, self.target_system);
    visit(33, self.target_component);
    visit(34, self.gimbal_device_id);
  }
};

struct GimbalDeviceAttitudeStatus
{
  static constexpr std::uint32_t ID = message_id::GIMBAL_DEVICE_ATTITUDE_STATUS;
  std::uint32_t time_boot_ms = 0;
  Quaternion q{ { 1.0f, 0.0f, 0.0f, 0.0f } };
  float angular_velocity_x = UNSET, angular_velocity_y = UNSET, angular_velocity_z = UNSET;  ///< rad/s
  std::uint32_t failure_flags = 0;
  std::uint16_t flags = 0;
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  // Extensions.
  float delta_yaw = UNSET;           ///< rad: the yaw between the earth and vehicle frame quaternions
  float delta_yaw_velocity = UNSET;  ///< rad/s
  std::uint8_t gimbal_device_id = 0;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.time_boot_ms);
    visit(4, self.q);
    visit(20, self.angular_velocity_x);
    visit(24, self.angular_velocity_y);
    visit(28, self.angular_velocity_z);
    visit(32, self.failure_flags);
    visit(36, self.flags);
    visit(38, self.target_system);
    visit(39, self.target_component);
    visit(40, self.delta_yaw);
    visit(44, self.delta_yaw_velocity);
    visit(48, self.gimbal_device_id);
  }
};

struct GimbalManagerSetPitchYaw
{
  static constexpr std::uint32_t ID = message_id::GIMBAL_MANAGER_SET_PITCHYAW;
  std::uint32_t flags = 0;
  float pitch = UNSET, yaw = UNSET;            ///< rad; NaN: not set
  float pitch_rate = UNSET, yaw_rate = UNSET;  ///< rad/s; NaN: not set
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::uint8_t gimbal_device_id = 0;

  /// The wire layout: \p visit(offset, field) for every field.
  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.flags);
    visit(4, self.pitch);
    visit(8, self.yaw);
    visit(12, self.pitch_rate);
    visit(16, self.yaw_rate);
    visit(20, self.target_system);
    visit(21, self.target_component);
    visit(22, self.gimbal_device_id);
  }
};

namespace detail
{
/// Writes fields into a payload, little-endian, floats by their bits.
struct PayloadWriter
{
  Payload& out;
  template <class Unsigned>
  std::enable_if_t<std::is_unsigned<Unsigned>::value> operator()(std::size_t offset, Unsigned value)
  {
    putLittleEndian<Unsigned>(out.data() + offset, value);
  }
  void operator()(std::size_t offset, std::int32_t value)
  {
    (*this)(offset, static_cast<std::uint32_t>(value));
  }
  void operator()(std::size_t offset, float value)
  {
    (*this)(offset, floatBits(value));
  }
  void operator()(std::size_t offset, Result value)
  {
    (*this)(offset, static_cast<std::uint8_t>(value));
  }
  template <std::size_t N>
  void operator()(std::size_t offset, const std::array<float, N>& values)
  {
    for (std::size_t index = 0; index < N; ++index)
    {
      (*this)(offset + 4 * index, values[index]);
    }
  }
};

/// Reads fields from a (zero-filled) payload.
struct PayloadReader
{
  const Payload& in;
  template <class Unsigned>
  std::enable_if_t<std::is_unsigned<Unsigned>::value> operator()(std::size_t offset, Unsigned& value)
  {
    value = getLittleEndian<Unsigned>(in.data() + offset);
  }
  void operator()(std::size_t offset, std::int32_t& value)
  {
    value = static_cast<std::int32_t>(getLittleEndian<std::uint32_t>(in.data() + offset));
  }
  void operator()(std::size_t offset, float& value)
  {
    value = floatFromBits(getLittleEndian<std::uint32_t>(in.data() + offset));
  }
  void operator()(std::size_t offset, Result& value)
  {
    value = static_cast<Result>(in[offset]);
  }
  template <std::size_t N>
  void operator()(std::size_t offset, std::array<float, N>& values)
  {
    for (std::size_t index = 0; index < N; ++index)
    {
      (*this)(offset + 4 * index, values[index]);
    }
  }
};
}  // namespace detail

/// Writes \p message's fields at their wire offsets in \p out.
template <class Message>
void pack(const Message& message, Payload& out)
{
  detail::PayloadWriter writer{ out };
  Message::fields(message, writer);
}

/// The message whose fields \p in holds.
template <class Message>
Message unpack(const Payload& in)
{
  Message message;
  detail::PayloadReader reader{ in };
  Message::fields(message, reader);
  return message;
}

/// Frames \p message (its fields sorted as on the wire, trailing zeros cut).
template <class Message>
EncodedFrame encode(const FrameHeader& header, const Message& message)
{
  Payload payload{};
  pack(message, payload);
  const MessageSpec& spec = *findMessage(Message::ID);
  return encodeFrame(header, spec, payload.data(), spec.length);
}

/// The message in \p frame, which must carry Message::ID.
template <class Message>
Message decode(const Frame& frame)
{
  return unpack<Message>(frame.payload);
}

}  // namespace mavlink
}  // namespace ptz_action_server

#include "ptz_action_server/core/mavlink/mavlink_messages.h"

#include <cmath>

#include "ptz_action_server/core/byte_order.h"

namespace ptz_action_server
{
namespace mavlink
{
namespace
{
void putFloat(Payload& out, std::size_t offset, float value)
{
  putLittleEndian<std::uint32_t>(out.data() + offset, floatBits(value));
}
float getFloat(const Payload& in, std::size_t offset)
{
  return floatFromBits(getLittleEndian<std::uint32_t>(in.data() + offset));
}
void putU32(Payload& out, std::size_t offset, std::uint32_t value)
{
  putLittleEndian<std::uint32_t>(out.data() + offset, value);
}
std::uint32_t getU32(const Payload& in, std::size_t offset)
{
  return getLittleEndian<std::uint32_t>(in.data() + offset);
}
void putU16(Payload& out, std::size_t offset, std::uint16_t value)
{
  putLittleEndian<std::uint16_t>(out.data() + offset, value);
}
std::uint16_t getU16(const Payload& in, std::size_t offset)
{
  return getLittleEndian<std::uint16_t>(in.data() + offset);
}
void putQuaternion(Payload& out, std::size_t offset, const Quaternion& q)
{
  for (std::size_t index = 0; index < q.size(); ++index)
  {
    putFloat(out, offset + 4 * index, q[index]);
  }
}
Quaternion getQuaternion(const Payload& in, std::size_t offset)
{
  Quaternion q{};
  for (std::size_t index = 0; index < q.size(); ++index)
  {
    q[index] = getFloat(in, offset + 4 * index);
  }
  return q;
}
}  // namespace

std::string toString(Result result)
{
  static const char* const NAMES[] = { "ACCEPTED",         "TEMPORARILY_REJECTED",
                                       "DENIED",           "UNSUPPORTED",
                                       "FAILED",           "IN_PROGRESS",
                                       "CANCELLED",        "COMMAND_LONG_ONLY",
                                       "COMMAND_INT_ONLY", "COMMAND_UNSUPPORTED_MAV_FRAME" };
  const auto value = static_cast<std::size_t>(result);
  if (value < sizeof(NAMES) / sizeof(NAMES[0]))
  {
    return NAMES[value];
  }
  return "result " + std::to_string(value);
}

// ---------------------------------------------------------------- HEARTBEAT 0

void Heartbeat::pack(Payload& out) const
{
  putU32(out, 0, custom_mode);
  out[4] = type;
  out[5] = autopilot;
  out[6] = base_mode;
  out[7] = system_status;
  out[8] = mavlink_version;
}

Heartbeat Heartbeat::unpack(const Payload& in)
{
  Heartbeat message;
  message.custom_mode = getU32(in, 0);
  message.type = in[4];
  message.autopilot = in[5];
  message.base_mode = in[6];
  message.system_status = in[7];
  message.mavlink_version = in[8];
  return message;
}

// ---------------------------------------------------------------- COMMAND_LONG 76

void CommandLong::pack(Payload& out) const
{
  for (std::size_t index = 0; index < params.size(); ++index)
  {
    putFloat(out, 4 * index, params[index]);
  }
  putU16(out, 28, command);
  out[30] = target_system;
  out[31] = target_component;
  out[32] = confirmation;
}

CommandLong CommandLong::unpack(const Payload& in)
{
  CommandLong message;
  for (std::size_t index = 0; index < message.params.size(); ++index)
  {
    message.params[index] = getFloat(in, 4 * index);
  }
  message.command = getU16(in, 28);
  message.target_system = in[30];
  message.target_component = in[31];
  message.confirmation = in[32];
  return message;
}

// ---------------------------------------------------------------- COMMAND_ACK 77

void CommandAck::pack(Payload& out) const
{
  putU16(out, 0, command);
  out[2] = static_cast<std::uint8_t>(result);
  out[3] = progress;
  putU32(out, 4, static_cast<std::uint32_t>(result_param2));
  out[8] = target_system;
  out[9] = target_component;
}

CommandAck CommandAck::unpack(const Payload& in)
{
  CommandAck message;
  message.command = getU16(in, 0);
  message.result = static_cast<Result>(in[2]);
  message.progress = in[3];
  message.result_param2 = static_cast<std::int32_t>(getU32(in, 4));
  message.target_system = in[8];
  message.target_component = in[9];
  return message;
}

// ---------------------------------------------------------------- GIMBAL_MANAGER_INFORMATION 280

void GimbalManagerInformation::pack(Payload& out) const
{
  putU32(out, 0, time_boot_ms);
  putU32(out, 4, cap_flags);
  putFloat(out, 8, roll_min);
  putFloat(out, 12, roll_max);
  putFloat(out, 16, pitch_min);
  putFloat(out, 20, pitch_max);
  putFloat(out, 24, yaw_min);
  putFloat(out, 28, yaw_max);
  out[32] = gimbal_device_id;
}

GimbalManagerInformation GimbalManagerInformation::unpack(const Payload& in)
{
  GimbalManagerInformation message;
  message.time_boot_ms = getU32(in, 0);
  message.cap_flags = getU32(in, 4);
  message.roll_min = getFloat(in, 8);
  message.roll_max = getFloat(in, 12);
  message.pitch_min = getFloat(in, 16);
  message.pitch_max = getFloat(in, 20);
  message.yaw_min = getFloat(in, 24);
  message.yaw_max = getFloat(in, 28);
  message.gimbal_device_id = in[32];
  return message;
}

// ---------------------------------------------------------------- GIMBAL_MANAGER_STATUS 281

void GimbalManagerStatus::pack(Payload& out) const
{
  putU32(out, 0, time_boot_ms);
  putU32(out, 4, flags);
  out[8] = gimbal_device_id;
  out[9] = primary_control_sysid;
  out[10] = primary_control_compid;
  out[11] = secondary_control_sysid;
  out[12] = secondary_control_compid;
}

GimbalManagerStatus GimbalManagerStatus::unpack(const Payload& in)
{
  GimbalManagerStatus message;
  message.time_boot_ms = getU32(in, 0);
  message.flags = getU32(in, 4);
  message.gimbal_device_id = in[8];
  message.primary_control_sysid = in[9];
  message.primary_control_compid = in[10];
  message.secondary_control_sysid = in[11];
  message.secondary_control_compid = in[12];
  return message;
}

// ---------------------------------------------------------------- GIMBAL_MANAGER_SET_ATTITUDE 282

void GimbalManagerSetAttitude::pack(Payload& out) const
{
  putU32(out, 0, flags);
  putQuaternion(out, 4, q);
  putFloat(out, 20, angular_velocity_x);
  putFloat(out, 24, angular_velocity_y);
  putFloat(out, 28, angular_velocity_z);
  out[32] = target_system;
  out[33] = target_component;
  out[34] = gimbal_device_id;
}

GimbalManagerSetAttitude GimbalManagerSetAttitude::unpack(const Payload& in)
{
  GimbalManagerSetAttitude message;
  message.flags = getU32(in, 0);
  message.q = getQuaternion(in, 4);
  message.angular_velocity_x = getFloat(in, 20);
  message.angular_velocity_y = getFloat(in, 24);
  message.angular_velocity_z = getFloat(in, 28);
  message.target_system = in[32];
  message.target_component = in[33];
  message.gimbal_device_id = in[34];
  return message;
}

// ---------------------------------------------------------------- GIMBAL_DEVICE_ATTITUDE_STATUS 285

void GimbalDeviceAttitudeStatus::pack(Payload& out) const
{
  putU32(out, 0, time_boot_ms);
  putQuaternion(out, 4, q);
  putFloat(out, 20, angular_velocity_x);
  putFloat(out, 24, angular_velocity_y);
  putFloat(out, 28, angular_velocity_z);
  putU32(out, 32, failure_flags);
  putU16(out, 36, flags);
  out[38] = target_system;
  out[39] = target_component;
  putFloat(out, 40, delta_yaw);
  putFloat(out, 44, delta_yaw_velocity);
  out[48] = gimbal_device_id;
}

GimbalDeviceAttitudeStatus GimbalDeviceAttitudeStatus::unpack(const Payload& in)
{
  GimbalDeviceAttitudeStatus message;
  message.time_boot_ms = getU32(in, 0);
  message.q = getQuaternion(in, 4);
  message.angular_velocity_x = getFloat(in, 20);
  message.angular_velocity_y = getFloat(in, 24);
  message.angular_velocity_z = getFloat(in, 28);
  message.failure_flags = getU32(in, 32);
  message.flags = getU16(in, 36);
  message.target_system = in[38];
  message.target_component = in[39];
  message.delta_yaw = getFloat(in, 40);
  message.delta_yaw_velocity = getFloat(in, 44);
  message.gimbal_device_id = in[48];
  return message;
}

// ---------------------------------------------------------------- GIMBAL_MANAGER_SET_PITCHYAW 287

void GimbalManagerSetPitchYaw::pack(Payload& out) const
{
  putU32(out, 0, flags);
  putFloat(out, 4, pitch);
  putFloat(out, 8, yaw);
  putFloat(out, 12, pitch_rate);
  putFloat(out, 16, yaw_rate);
  out[20] = target_system;
  out[21] = target_component;
  out[22] = gimbal_device_id;
}

GimbalManagerSetPitchYaw GimbalManagerSetPitchYaw::unpack(const Payload& in)
{
  GimbalManagerSetPitchYaw message;
  message.flags = getU32(in, 0);
  message.pitch = getFloat(in, 4);
  message.yaw = getFloat(in, 8);
  message.pitch_rate = getFloat(in, 12);
  message.yaw_rate = getFloat(in, 16);
  message.target_system = in[20];
  message.target_component = in[21];
  message.gimbal_device_id = in[22];
  return message;
}

// ---------------------------------------------------------------- attitude

Quaternion quaternionFromPanTilt(double pan, double tilt)
{
  const double cy = std::cos(pan / 2.0), sy = std::sin(pan / 2.0);
  const double cp = std::cos(tilt / 2.0), sp = std::sin(tilt / 2.0);
  // q_yaw(z) * q_pitch(y), FRD: (cos p cos y, -sin p sin y, sin p cos y, cos p sin y).
  return Quaternion{ { static_cast<float>(cp * cy), static_cast<float>(-sp * sy), static_cast<float>(sp * cy),
                       static_cast<float>(cp * sy) } };
}

PanTilt panTiltFromQuaternion(const Quaternion& q)
{
  double w = q[0], x = q[1], y = q[2], z = q[3];
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  if (norm > 0.0)
  {
    w /= norm;
    x /= norm;
    y /= norm;
    z /= norm;
  }
  // The optical axis is body x; the rotation's first column.
  const double forward_x = 1.0 - 2.0 * (y * y + z * z);
  const double forward_y = 2.0 * (x * y + w * z);
  const double forward_z = 2.0 * (x * z - w * y);
  const double horizontal = std::hypot(forward_x, forward_y);
  PanTilt result;
  result.tilt = std::atan2(-forward_z, horizontal);  // z points down: up is -z
  if (horizontal > 1e-3)  // below: float noise in q would swing the yaw (1e-3 is 0.06 degrees from vertical)
  {
    result.pan = std::atan2(forward_y, forward_x);
  }
  else
  {
    // Straight up or down: the right axis (body y, the second column) still points where the yaw does.
    const double right_x = 2.0 * (x * y - w * z);
    const double right_y = 1.0 - 2.0 * (x * x + z * z);
    result.pan = std::atan2(-right_x, right_y);
  }
  return result;
}

}  // namespace mavlink
}  // namespace ptz_action_server

#include "ptz_action_server/core/digiview/digiview_codec.h"

#include <cstring>

#include "digiview_payload.h"

namespace ptz_action_server
{
namespace digiview
{
using namespace detail;

Message packTargeting(MessageType type, const CamTargeting& targeting)
{
  Message message = withPayload(type, ParamType::CAM_TARGETING);
  Payload payload(message.data);
  writeCamera(payload, targeting.camera);
  payload.u8(9, targeting.targeting_mode);
  payload.u8(10, targeting.euler_delta ? 1 : 0);
  payload.scaled32(11, targeting.yaw, ANGLE_SCALE);
  payload.scaled32(15, targeting.pitch, ANGLE_SCALE);
  payload.scaled32(19, targeting.roll, ANGLE_SCALE);
  payload.u8(23, targeting.lock_flags);
  payload.scaled16(24, targeting.x_offset);
  payload.scaled16(26, targeting.y_offset);
  payload.scaled32(28, targeting.target_latitude, ANGLE_SCALE);
  payload.scaled32(32, targeting.target_longitude, ANGLE_SCALE);
  payload.scaled32(36, targeting.target_altitude, ANGLE_SCALE);
  return message;
}

UnpackError unpackTargeting(const Message& message, CamTargeting& targeting)
{
  targeting = CamTargeting();
  if (message.param_type != ParamType::CAM_TARGETING)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message.data);
  const std::int32_t yaw = reader.i32(11);
  const std::int32_t pitch = reader.i32(15);
  const std::int32_t roll = reader.i32(19);
  const std::int16_t x_offset = reader.i16(24);
  const std::int16_t y_offset = reader.i16(26);
  const std::int32_t latitude = reader.i32(28);
  const std::int32_t longitude = reader.i32(32);
  const std::int32_t altitude = reader.i32(36);
  CamTargeting read;
  const bool valid = readCamera(reader, read.camera) && reader.u8(9) <= 3 && reader.u8(10) <= 1 &&
                     within(yaw, -MAX_YAW, MAX_YAW) && within(pitch, -MAX_PITCH, MAX_PITCH) &&
                     within(roll, -MAX_PITCH, MAX_PITCH) && reader.u8(23) <= 7 && x_offset >= -32767 &&
                     y_offset >= -32767 && within(latitude, -90000, 90000) && within(longitude, -180000, 179999) &&
                     within(altitude, -1000000, 10000000);
  if (!valid)
  {
    return UnpackError::BAD_DATA;
  }
  read.targeting_mode = reader.u8(9);
  read.euler_delta = reader.u8(10) != 0;
  read.yaw = yaw / ANGLE_SCALE;
  read.pitch = pitch / ANGLE_SCALE;
  read.roll = roll / ANGLE_SCALE;
  read.lock_flags = reader.u8(23);
  read.x_offset = x_offset / OFFSET_SCALE;
  read.y_offset = y_offset / OFFSET_SCALE;
  read.target_latitude = latitude / ANGLE_SCALE;
  read.target_longitude = longitude / ANGLE_SCALE;
  read.target_altitude = altitude / ANGLE_SCALE;
  targeting = read;
  return UnpackError::NONE;
}

Message packOptics(MessageType type, const CamOpticsAndControl& optics)
{
  Message message = withPayload(type, ParamType::CAM_OPTICS_AND_CONTROL);
  Payload payload(message.data);
  writeCamera(payload, optics.camera);
  payload.u8(9, static_cast<std::uint8_t>(optics.zoom));
  payload.scaled32(10, optics.fov, ANGLE_SCALE);
  payload.u8(14, optics.crop_mode);
  return message;
}

UnpackError unpackOptics(const Message& message, CamOpticsAndControl& optics)
{
  optics = CamOpticsAndControl();
  if (message.param_type != ParamType::CAM_OPTICS_AND_CONTROL)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message.data);
  CamOpticsAndControl read;
  const auto zoom = static_cast<std::int8_t>(reader.u8(9));
  const std::int32_t fov = reader.i32(10);
  if (!readCamera(reader, read.camera) || zoom == -128 || !within(fov, 0, MAX_YAW) || reader.u8(14) > 2)
  {
    return UnpackError::BAD_DATA;
  }
  read.zoom = zoom;
  read.fov = fov / ANGLE_SCALE;
  read.crop_mode = reader.u8(14);
  optics = read;
  return UnpackError::NONE;
}

Message packSystemStatus(MessageType type, const SystemStatus& status)
{
  Message message = withPayload(type, ParamType::SYSTEM_STATUS);
  Payload payload(message.data);
  payload.u8(0, status.status);
  payload.u8(1, status.error);
  payload.u32(2, floatBits(status.jetson_temp));
  return message;
}

UnpackError unpackSystemStatus(const Message& message, SystemStatus& status)
{
  status = SystemStatus();
  if (message.param_type != ParamType::SYSTEM_STATUS)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message.data);
  const float temperature = floatFromBits(reader.u32(2));
  if (reader.u8(0) > 3 || reader.u8(1) != 0 || !(temperature >= 0.0f && temperature <= 105.0f))
  {
    return UnpackError::BAD_DATA;
  }
  status.status = reader.u8(0);
  status.error = reader.u8(1);
  status.jetson_temp = temperature;
  return UnpackError::NONE;
}

Message packVideoOutput(MessageType type, const VideoOutput& output)
{
  Message message = withPayload(type, ParamType::VIDEO_OUTPUT);
  Payload payload(message.data);
  payload.name(0, output.stream_name);
  payload.u16(8, output.width);
  payload.u16(10, output.height);
  payload.u8(12, output.fps);
  // A GET reply carries num_user_views in the 4 MSB of the layout byte; a SET only the layout mode.
  const std::uint8_t views = type == MessageType::CURRENT_PARAMETERS ? output.num_user_views : 0;
  payload.u8(13, static_cast<std::uint8_t>((views << 4) | (output.layout_mode & 0x0F)));
  payload.u8(14, output.detection_overlay_mode);
  for (std::size_t index = 0; index < output.views.size(); ++index)
  {
    payload.box(15 + 8 * index, output.views[index]);
  }
  payload.box(47, output.detection_overlay_box);
  payload.u16(55, output.single_detection_size);
  return message;
}

UnpackError unpackVideoOutput(const Message& message, VideoOutput& output)
{
  output = VideoOutput();
  if (message.param_type != ParamType::VIDEO_OUTPUT)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message.data);
  VideoOutput read;
  const std::uint8_t layout = reader.u8(13);
  const bool reply = message.message_type == MessageType::CURRENT_PARAMETERS;
  read.layout_mode = layout & 0x0F;
  read.num_user_views = layout >> 4;
  read.width = reader.u16(8);
  read.height = reader.u16(10);
  const bool valid = reader.name(0, read.stream_name) && within(read.width, 640, 1920) &&
                     within(read.height, 480, 1080) && read.layout_mode <= 6 &&
                     (reply ? within(read.num_user_views, 1, 4) : read.num_user_views == 0) && reader.u8(14) <= 5;
  if (!valid)
  {
    return UnpackError::BAD_DATA;
  }
  read.fps = reader.u8(12);
  read.detection_overlay_mode = reader.u8(14);
  for (std::size_t index = 0; index < read.views.size(); ++index)
  {
    read.views[index] = reader.box(15 + 8 * index);
  }
  read.detection_overlay_box = reader.box(47);
  read.single_detection_size = reader.u16(55);
  output = read;
  return UnpackError::NONE;
}

Message packGet(ParamType param, const CameraId& camera)
{
  Message message = withPayload(MessageType::GET_PARAMETERS, param);
  Payload payload(message.data);
  writeCamera(payload, camera);
  return message;
}

UnpackError unpackCamera(const Message& message, CameraId& camera)
{
  camera = CameraId();
  const Reader reader(message.data);
  CameraId read;
  if (!readCamera(reader, read))
  {
    return UnpackError::BAD_DATA;
  }
  camera = read;
  return UnpackError::NONE;
}

Message packInterval(const IntervalRequest& request)
{
  Message message = withPayload(MessageType::GET_INTERVAL, request.param);
  Payload payload(message.data);
  writeCamera(payload, request.camera);
  payload.u32(12, request.interval_ms);
  return message;
}

UnpackError unpackInterval(const Message& message, IntervalRequest& request)
{
  request = IntervalRequest();
  if (message.message_type != MessageType::GET_INTERVAL)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message.data);
  IntervalRequest read;
  if (!readCamera(reader, read.camera))
  {
    return UnpackError::BAD_DATA;
  }
  read.param = message.param_type;
  read.interval_ms = reader.u32(12);
  request = read;
  return UnpackError::NONE;
}

Message packBare(MessageType type, ParamType param)
{
  return withPayload(type, param);
}

}  // namespace digiview
}  // namespace ptz_action_server

#include "ptz_action_server/core/digiview/digiview_codec.h"

#include <algorithm>

#include "digiview_payload.h"

namespace ptz_action_server
{
namespace digiview
{
using namespace detail;

/// Where a format puts CAM_TARGETING's coordinates: 0.5 as its packer writes them (latitude twice), 1.0 and 1.1 in
/// order.
struct CoordinateOffsets
{
  std::size_t latitude;
  std::size_t longitude;
  std::size_t altitude;
};

CoordinateOffsets coordinatesOf(Format format)
{
  return format == Format::V0_5 ? CoordinateOffsets{ 28, 36, 40 } : CoordinateOffsets{ 28, 32, 36 };
}

/// 1.1 appends detection_id to CAM_TARGETING, after the altitude.
constexpr std::size_t DETECTION_ID_OFFSET = 40;

Message packTargeting(Format format, MessageType type, const CamTargeting& targeting)
{
  Message message = withPayload(format, type, ParamType::CAM_TARGETING);
  Payload payload(message.data);
  writeCamera(payload, targeting.camera);
  payload.u8(9, targeting.targeting_mode);
  payload.u8(10, targeting.euler_delta ? 1 : 0);
  payload.scaled32(11, targeting.yaw, MILLI_SCALE);
  payload.scaled32(15, targeting.pitch, MILLI_SCALE);
  payload.scaled32(19, targeting.roll, MILLI_SCALE);
  payload.u8(23, targeting.lock_flags);
  payload.scaled16(24, targeting.x_offset);
  payload.scaled16(26, targeting.y_offset);
  const CoordinateOffsets at = coordinatesOf(format);
  if (format == Format::V0_5)
  {
    payload.scaled32(32, targeting.target_latitude, MILLI_SCALE);  // the 0.5 packer writes it twice
  }
  payload.scaled32(at.latitude, targeting.target_latitude, MILLI_SCALE);
  payload.scaled32(at.longitude, targeting.target_longitude, MILLI_SCALE);
  payload.scaled32(at.altitude, targeting.target_altitude, MILLI_SCALE);
  if (format == Format::V1_1)
  {
    payload.u16(DETECTION_ID_OFFSET, static_cast<std::uint16_t>(targeting.detection_id));
  }
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
  const CoordinateOffsets at = coordinatesOf(message.format);
  const std::int32_t latitude = reader.i32(at.latitude);
  const std::int32_t longitude = reader.i32(at.longitude);
  const std::int32_t altitude = reader.i32(at.altitude);
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
  read.yaw = unscaled(yaw, MILLI_SCALE);
  read.pitch = unscaled(pitch, MILLI_SCALE);
  read.roll = unscaled(roll, MILLI_SCALE);
  read.lock_flags = reader.u8(23);
  read.x_offset = unscaled(x_offset, OFFSET_SCALE);
  read.y_offset = unscaled(y_offset, OFFSET_SCALE);
  read.target_latitude = unscaled(latitude, MILLI_SCALE);
  read.target_longitude = unscaled(longitude, MILLI_SCALE);
  read.target_altitude = unscaled(altitude, MILLI_SCALE);
  if (message.format == Format::V1_1)
  {
    read.detection_id = reader.i16(DETECTION_ID_OFFSET);  // any value: DigiView judges it in detection mode
  }
  targeting = read;
  return UnpackError::NONE;
}

Message packOptics(Format format, MessageType type, const CamOpticsAndControl& optics)
{
  Message message = withPayload(format, type, ParamType::CAM_OPTICS_AND_CONTROL);
  Payload payload(message.data);
  writeCamera(payload, optics.camera);
  payload.u8(9, static_cast<std::uint8_t>(optics.zoom));
  payload.scaled32(10, optics.fov, MILLI_SCALE);
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
  read.fov = unscaled(fov, MILLI_SCALE);
  read.crop_mode = reader.u8(14);
  optics = read;
  return UnpackError::NONE;
}

Message packSystemStatus(Format format, MessageType type, const SystemStatus& status)
{
  Message message = withPayload(format, type, ParamType::SYSTEM_STATUS);
  Payload payload(message.data);
  payload.u8(0, status.status);
  payload.u8(1, status.error);
  payload.scaled32(2, status.jetson_temp, MILLI_SCALE);
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
  const std::int32_t temperature = reader.i32(2);
  if (reader.u8(0) > 3 || reader.u8(1) != 0 || !within(temperature, 0, 105000))
  {
    return UnpackError::BAD_DATA;
  }
  status.status = reader.u8(0);
  status.error = reader.u8(1);
  status.jetson_temp = unscaled(temperature, MILLI_SCALE);
  return UnpackError::NONE;
}

Message packVideoOutput(Format format, MessageType type, const VideoOutput& output)
{
  Message message = withPayload(format, type, ParamType::VIDEO_OUTPUT);
  Payload payload(message.data);
  payload.name(0, output.stream_name);
  payload.u16(8, output.width);
  payload.u16(10, output.height);
  payload.u8(12, output.fps);
  payload.u8(13, output.layout_mode);
  payload.u8(14, output.detection_overlay_mode);
  // As the published helpers: a SET carries no views; otherwise num_user_views (at most 4), then that many boxes.
  const std::size_t views =
      type == MessageType::SET_PARAMETERS ? 0 : std::min<std::size_t>(output.num_user_views, output.views.size());
  payload.u8(15, static_cast<std::uint8_t>(views));
  for (std::size_t index = 0; index < views; ++index)
  {
    payload.box(16 + 8 * index, output.views[index]);
  }
  payload.box(16 + 8 * views, output.detection_overlay_box);
  payload.u16(24 + 8 * views, output.single_detection_size);
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
  read.width = reader.u16(8);
  read.height = reader.u16(10);
  read.layout_mode = reader.u8(13);
  read.detection_overlay_mode = reader.u8(14);
  read.num_user_views = reader.u8(15);
  const bool valid = reader.name(0, read.stream_name) && within(read.width, 640, 1920) &&
                     within(read.height, 480, 1080) && read.layout_mode <= 6 && read.detection_overlay_mode <= 5 &&
                     read.num_user_views <= read.views.size();
  if (!valid)
  {
    return UnpackError::BAD_DATA;
  }
  read.fps = reader.u8(12);
  const std::size_t views = read.num_user_views;
  for (std::size_t index = 0; index < views; ++index)
  {
    read.views[index] = reader.box(16 + 8 * index);
  }
  read.detection_overlay_box = reader.box(16 + 8 * views);
  read.single_detection_size = reader.u16(24 + 8 * views);
  output = read;
  return UnpackError::NONE;
}

Message packGet(Format format, ParamType param, const CameraId& camera)
{
  Message message = withPayload(format, MessageType::GET_PARAMETERS, param);
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

Message packInterval(Format format, const IntervalRequest& request)
{
  if (subscribesWithGet(format))
  {
    Message message = packGet(format, request.param, request.camera);
    message.interval_ms = request.interval_ms;
    return message;
  }
  Message message = withPayload(format, MessageType::GET_INTERVAL, request.param);
  Payload payload(message.data);
  writeCamera(payload, request.camera);
  payload.u32(12, request.interval_ms);
  return message;
}

UnpackError unpackInterval(const Message& message, IntervalRequest& request)
{
  request = IntervalRequest();
  const bool get_interval = message.message_type == MessageType::GET_INTERVAL;  // only 0.5 has one
  const bool get_with_interval =
      subscribesWithGet(message.format) && message.message_type == MessageType::GET_PARAMETERS;
  const Reader reader(message.data);
  IntervalRequest read;
  if (!(get_interval || get_with_interval) || !readCamera(reader, read.camera))
  {
    return UnpackError::BAD_DATA;
  }
  read.param = message.param_type;
  read.interval_ms = get_interval ? reader.u32(12) : message.interval_ms;
  request = read;
  return UnpackError::NONE;
}

Message packBare(Format format, MessageType type, ParamType param)
{
  return withPayload(format, type, param);
}

}  // namespace digiview
}  // namespace ptz_action_server

#include "ptz_action_server/core/digiview/digiview_codec.h"

#include <algorithm>

#include "digiview_payload.h"

namespace ptz_action_server
{
namespace digiview
{
using namespace detail;

/// Where a format puts CAM_TARGETING's coordinates after the camera id (@b: the end of the name): 0.5 as its packer
/// writes them (latitude twice), from 1.0 on in order.
struct CoordinateOffsets
{
  std::size_t latitude;
  std::size_t longitude;
  std::size_t altitude;
};

CoordinateOffsets coordinatesOf(Format format, std::size_t b)
{
  return format == Format::V0_5 ? CoordinateOffsets{ b + 20, b + 28, b + 32 } :
                                  CoordinateOffsets{ b + 20, b + 24, b + 28 };
}

/// After the altitude: 1.1's detection_id, or 1.2's track_id, view_id and lock_target.
constexpr std::size_t TARGETING_TAIL = 32;

Message packTargeting(const Wire& wire, MessageType type, const CamTargeting& targeting)
{
  Message message = withPayload(wire, type, ParamType::CAM_TARGETING);
  Payload payload(message);
  const std::size_t b = payload.afterName();
  writeCamera(payload, targeting.camera);
  payload.u8(b + 1, targeting.targeting_mode);
  payload.u8(b + 2, targeting.euler_delta ? 1 : 0);
  payload.angle(b + 3, targeting.yaw);
  payload.angle(b + 7, targeting.pitch);
  payload.angle(b + 11, targeting.roll);
  payload.u8(b + 15, targeting.lock_flags);
  payload.scaled16(b + 16, targeting.x_offset);
  payload.scaled16(b + 18, targeting.y_offset);
  const CoordinateOffsets at = coordinatesOf(wire.format, b);
  if (wire.format == Format::V0_5)
  {
    payload.scaled32(b + 24, targeting.target_latitude, MILLI_SCALE);  // the 0.5 packer writes it twice
  }
  payload.scaled32(at.latitude, targeting.target_latitude, MILLI_SCALE);
  payload.scaled32(at.longitude, targeting.target_longitude, MILLI_SCALE);
  payload.scaled32(at.altitude, targeting.target_altitude, MILLI_SCALE);
  if (wire.format == Format::V1_1)
  {
    payload.u16(b + TARGETING_TAIL, static_cast<std::uint16_t>(targeting.detection_id));
  }
  else if (wire.format == Format::V1_2)
  {
    payload.u16(b + TARGETING_TAIL, targeting.track_id);
    payload.u16(b + TARGETING_TAIL + 2, static_cast<std::uint16_t>(targeting.view_id));
    payload.u8(b + TARGETING_TAIL + 4, targeting.lock_target ? 1 : 0);
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
  const Reader reader(message);
  const std::size_t b = reader.afterName();
  const std::int32_t yaw = reader.i32(b + 3);
  const std::int32_t pitch = reader.i32(b + 7);
  const std::int32_t roll = reader.i32(b + 11);
  const std::int16_t x_offset = reader.i16(b + 16);
  const std::int16_t y_offset = reader.i16(b + 18);
  const CoordinateOffsets at = coordinatesOf(message.format, b);
  const std::int32_t latitude = reader.i32(at.latitude);
  const std::int32_t longitude = reader.i32(at.longitude);
  const std::int32_t altitude = reader.i32(at.altitude);
  const AngleLimits limits = reader.angleLimits();
  const bool v1_2 = message.format == Format::V1_2;
  CamTargeting read;
  const bool valid =
      readCamera(reader, read.camera) && reader.u8(b + 1) <= 3 && reader.u8(b + 2) <= 1 &&
      within(yaw, -limits.half_turn, limits.half_turn) && within(pitch, -limits.quarter_turn, limits.quarter_turn) &&
      within(roll, -limits.quarter_turn, limits.quarter_turn) && reader.u8(b + 15) <= 7 && x_offset >= -32767 &&
      y_offset >= -32767 && within(latitude, -90000, 90000) && within(longitude, -180000, 179999) &&
      within(altitude, -1000000, 10000000) && (!v1_2 || reader.u8(b + TARGETING_TAIL + 4) <= 1);
  if (!valid)
  {
    return UnpackError::BAD_DATA;
  }
  read.targeting_mode = reader.u8(b + 1);
  read.euler_delta = reader.u8(b + 2) != 0;
  read.yaw = reader.radians(yaw);
  read.pitch = reader.radians(pitch);
  read.roll = reader.radians(roll);
  read.lock_flags = reader.u8(b + 15);
  read.x_offset = unscaled(x_offset, OFFSET_SCALE);
  read.y_offset = unscaled(y_offset, OFFSET_SCALE);
  read.target_latitude = unscaled(latitude, MILLI_SCALE);
  read.target_longitude = unscaled(longitude, MILLI_SCALE);
  read.target_altitude = unscaled(altitude, MILLI_SCALE);
  if (message.format == Format::V1_1)
  {
    read.detection_id = reader.i16(b + TARGETING_TAIL);  // any value: DigiView judges it in detection mode
  }
  else if (v1_2)
  {
    read.track_id = reader.u16(b + TARGETING_TAIL);
    read.view_id = reader.i16(b + TARGETING_TAIL + 2);
    read.lock_target = reader.u8(b + TARGETING_TAIL + 4) != 0;
  }
  targeting = read;
  return UnpackError::NONE;
}

Message packOptics(const Wire& wire, MessageType type, const CamOpticsAndControl& optics)
{
  Message message = withPayload(wire, type, ParamType::CAM_OPTICS_AND_CONTROL);
  Payload payload(message);
  const std::size_t b = payload.afterName();
  writeCamera(payload, optics.camera);
  payload.u8(b + 1, static_cast<std::uint8_t>(optics.zoom));
  payload.angle(b + 2, optics.fov);
  if (wire.format != Format::V1_2)  // 1.2 has no crop_mode
  {
    payload.u8(b + 6, optics.crop_mode);
  }
  return message;
}

UnpackError unpackOptics(const Message& message, CamOpticsAndControl& optics)
{
  optics = CamOpticsAndControl();
  if (message.param_type != ParamType::CAM_OPTICS_AND_CONTROL)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message);
  const std::size_t b = reader.afterName();
  const bool has_crop = message.format != Format::V1_2;
  CamOpticsAndControl read;
  const auto zoom = static_cast<std::int8_t>(reader.u8(b + 1));
  const std::int32_t fov = reader.i32(b + 2);
  if (!readCamera(reader, read.camera) || zoom == -128 || !within(fov, 0, reader.angleLimits().half_turn) ||
      (has_crop && reader.u8(b + 6) > 2))
  {
    return UnpackError::BAD_DATA;
  }
  read.zoom = zoom;
  read.fov = reader.radians(fov);
  if (has_crop)
  {
    read.crop_mode = reader.u8(b + 6);
  }
  optics = read;
  return UnpackError::NONE;
}

Message packSystemStatus(const Wire& wire, MessageType type, const SystemStatus& status)
{
  Message message = withPayload(wire, type, ParamType::SYSTEM_STATUS);
  Payload payload(message);
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
  const Reader reader(message);
  const std::int32_t temperature = reader.i32(2);
  // The seed's status 0..3 and error "always 0" before 1.1; app_status 0..4 (HALT) and any error from 1.1 on.
  const bool app_status = hasAppStatus(message.format);
  if (reader.u8(0) > (app_status ? APP_STATUS_HALT : 3) || (!app_status && reader.u8(1) != 0) ||
      !within(temperature, 0, 105000))
  {
    return UnpackError::BAD_DATA;
  }
  status.status = reader.u8(0);
  status.error = reader.u8(1);
  status.jetson_temp = unscaled(temperature, MILLI_SCALE);
  return UnpackError::NONE;
}

Message packVideoOutput(const Wire& wire, MessageType type, const VideoOutput& output)
{
  Message message = withPayload(wire, type, ParamType::VIDEO_OUTPUT);
  Payload payload(message);
  const std::size_t b = payload.afterName();
  payload.name(0, output.stream_name);
  payload.u16(b, output.width);
  payload.u16(b + 2, output.height);
  payload.u8(b + 4, output.fps);
  payload.u8(b + 5, output.layout_mode);
  payload.u8(b + 6, output.detection_overlay_mode);
  // As the published helpers: a SET carries no views; otherwise num_user_views (at most 4), then that many boxes.
  const std::size_t views =
      type == MessageType::SET_PARAMETERS ? 0 : std::min<std::size_t>(output.num_user_views, output.views.size());
  payload.u8(b + 7, static_cast<std::uint8_t>(views));
  for (std::size_t index = 0; index < views; ++index)
  {
    payload.box(b + 8 + 8 * index, output.views[index]);
  }
  payload.box(b + 8 + 8 * views, output.detection_overlay_box);
  payload.u16(b + 16 + 8 * views, output.single_detection_size);
  return message;
}

UnpackError unpackVideoOutput(const Message& message, VideoOutput& output)
{
  output = VideoOutput();
  if (message.param_type != ParamType::VIDEO_OUTPUT)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message);
  const std::size_t b = reader.afterName();
  VideoOutput read;
  read.width = reader.u16(b);
  read.height = reader.u16(b + 2);
  read.layout_mode = reader.u8(b + 5);
  read.detection_overlay_mode = reader.u8(b + 6);
  read.num_user_views = reader.u8(b + 7);
  const bool valid = reader.name(0, read.stream_name) && within(read.width, 640, 1920) &&
                     within(read.height, 480, 1080) && read.layout_mode <= 6 && read.detection_overlay_mode <= 5 &&
                     read.num_user_views <= read.views.size();
  if (!valid)
  {
    return UnpackError::BAD_DATA;
  }
  read.fps = reader.u8(b + 4);
  const std::size_t views = read.num_user_views;
  for (std::size_t index = 0; index < views; ++index)
  {
    read.views[index] = reader.box(b + 8 + 8 * index);
  }
  read.detection_overlay_box = reader.box(b + 8 + 8 * views);
  read.single_detection_size = reader.u16(b + 16 + 8 * views);
  output = read;
  return UnpackError::NONE;
}

Message packGet(const Wire& wire, ParamType param, const CameraId& camera)
{
  Message message = withPayload(wire, MessageType::GET_PARAMETERS, param);
  Payload payload(message);
  writeCamera(payload, camera);
  return message;
}

UnpackError unpackCamera(const Message& message, CameraId& camera)
{
  camera = CameraId();
  const Reader reader(message);
  CameraId read;
  if (!readCamera(reader, read))
  {
    return UnpackError::BAD_DATA;
  }
  camera = read;
  return UnpackError::NONE;
}

Message packInterval(const Wire& wire, const IntervalRequest& request)
{
  if (subscribesWithGet(wire.format))
  {
    Message message = packGet(wire, request.param, request.camera);
    message.interval_ms = request.interval_ms;
    return message;
  }
  Message message = withPayload(wire, MessageType::GET_INTERVAL, request.param);
  Payload payload(message);
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
  const Reader reader(message);
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

Message packBare(const Wire& wire, MessageType type, ParamType param)
{
  return withPayload(wire, type, param);
}

Message packDebug(const Wire& wire, const DebugValues& values)
{
  Message message = withPayload(wire, MessageType::DEBUG, ParamType::SYSTEM_STATUS);
  Payload payload(message);
  for (std::size_t index = 0; index < values.size(); ++index)
  {
    payload.u32(4 * index, static_cast<std::uint32_t>(values[index]));
  }
  return message;
}

UnpackError unpackDebug(const Message& message, DebugValues& values)
{
  values = DebugValues{};
  if (message.message_type != MessageType::DEBUG)
  {
    return UnpackError::BAD_DATA;
  }
  const Reader reader(message);
  for (std::size_t index = 0; index < values.size(); ++index)
  {
    values[index] = reader.i32(4 * index);
  }
  return UnpackError::NONE;
}

}  // namespace digiview
}  // namespace ptz_action_server

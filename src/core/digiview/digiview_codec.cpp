#include "ptz_action_server/core/digiview/digiview_codec.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace ptz_action_server
{
namespace digiview
{
namespace
{
/// The reflected form of 0xA7.
constexpr std::uint8_t REFLECTED_POLY = 0xE5;

constexpr std::array<std::uint8_t, 256> makeCrcTable()
{
  std::array<std::uint8_t, 256> table{};
  for (int value = 0; value < 256; ++value)
  {
    std::uint8_t crc = static_cast<std::uint8_t>(value);
    for (int bit = 0; bit < 8; ++bit)
    {
      crc = (crc & 1u) ? static_cast<std::uint8_t>((crc >> 1) ^ REFLECTED_POLY) : static_cast<std::uint8_t>(crc >> 1);
    }
    table[static_cast<std::size_t>(value)] = crc;
  }
  return table;
}
constexpr std::array<std::uint8_t, 256> CRC_TABLE = makeCrcTable();

// Scaled fields: angles and coordinates x 1000, offsets x 32767.
constexpr double ANGLE_SCALE = 1000.0;
constexpr double OFFSET_SCALE = 32767.0;
constexpr std::int32_t MAX_YAW = 3142;    ///< pi, in milliradians, rounded up
constexpr std::int32_t MAX_PITCH = 1571;  ///< pi / 2

/// Little-endian writes and reads into the 64-byte data field, by offset.
class Payload
{
public:
  explicit Payload(std::array<std::uint8_t, DATA_SIZE>& data) : data_(data)
  {
  }
  void u8(std::size_t at, std::uint8_t value)
  {
    data_[at] = value;
  }
  void u16(std::size_t at, std::uint16_t value)
  {
    data_[at] = static_cast<std::uint8_t>(value);
    data_[at + 1] = static_cast<std::uint8_t>(value >> 8);
  }
  void u32(std::size_t at, std::uint32_t value)
  {
    for (std::size_t index = 0; index < 4; ++index)
    {
      data_[at + index] = static_cast<std::uint8_t>(value >> (8 * index));
    }
  }
  void scaled32(std::size_t at, double value, double scale)
  {
    const double scaled = std::round(value * scale);
    const double bounded =
        std::clamp(std::isfinite(scaled) ? scaled : 0.0, static_cast<double>(std::numeric_limits<std::int32_t>::min()),
                   static_cast<double>(std::numeric_limits<std::int32_t>::max()));
    u32(at, static_cast<std::uint32_t>(static_cast<std::int32_t>(bounded)));
  }
  void scaled16(std::size_t at, double value)
  {
    const double scaled = std::clamp(std::round(value * OFFSET_SCALE), -OFFSET_SCALE, OFFSET_SCALE);
    u16(at, static_cast<std::uint16_t>(static_cast<std::int16_t>(std::isfinite(scaled) ? scaled : 0.0)));
  }
  void name(std::size_t at, const std::string& text)
  {
    for (std::size_t index = 0; index < NAME_SIZE; ++index)
    {
      data_[at + index] = index < text.size() ? static_cast<std::uint8_t>(text[index]) : 0;
    }
  }
  void box(std::size_t at, const BoundingBox& box)
  {
    u16(at, box.x);
    u16(at + 2, box.y);
    u16(at + 4, box.w);
    u16(at + 6, box.h);
  }

private:
  std::array<std::uint8_t, DATA_SIZE>& data_;
};

class Reader
{
public:
  explicit Reader(const std::array<std::uint8_t, DATA_SIZE>& data) : data_(data)
  {
  }
  std::uint8_t u8(std::size_t at) const
  {
    return data_[at];
  }
  std::uint16_t u16(std::size_t at) const
  {
    return static_cast<std::uint16_t>(data_[at] | (data_[at + 1] << 8));
  }
  std::uint32_t u32(std::size_t at) const
  {
    std::uint32_t value = 0;
    for (std::size_t index = 0; index < 4; ++index)
    {
      value |= static_cast<std::uint32_t>(data_[at + index]) << (8 * index);
    }
    return value;
  }
  std::int32_t i32(std::size_t at) const
  {
    return static_cast<std::int32_t>(u32(at));
  }
  std::int16_t i16(std::size_t at) const
  {
    return static_cast<std::int16_t>(u16(at));
  }
  /// The NUL-padded name; false if it holds a non-printable character before the first NUL.
  bool name(std::size_t at, std::string& text) const
  {
    text.clear();
    for (std::size_t index = 0; index < NAME_SIZE && data_[at + index] != 0; ++index)
    {
      const std::uint8_t character = data_[at + index];
      if (character < 0x20 || character > 0x7E)
      {
        return false;
      }
      text.push_back(static_cast<char>(character));
    }
    return true;
  }
  BoundingBox box(std::size_t at) const
  {
    return BoundingBox{ u16(at), u16(at + 2), u16(at + 4), u16(at + 6) };
  }

private:
  const std::array<std::uint8_t, DATA_SIZE>& data_;
};

bool within(std::int64_t value, std::int64_t min, std::int64_t max)
{
  return value >= min && value <= max;
}

Message withPayload(MessageType type, ParamType param)
{
  Message message;
  message.message_type = type;
  message.param_type = param;
  return message;
}

void writeCamera(Payload& payload, const CameraId& camera)
{
  payload.name(0, camera.stream_name);
  payload.u8(8, camera.cam_id);
}

bool readCamera(const Reader& reader, CameraId& camera)
{
  camera.cam_id = reader.u8(8);
  return reader.name(0, camera.stream_name) && camera.cam_id <= 3;
}
}  // namespace

bool isMessageType(std::uint8_t value)
{
  return value <= static_cast<std::uint8_t>(MessageType::UNKNOWN) ||
         value == static_cast<std::uint8_t>(MessageType::QUIT);
}

bool isParamType(std::uint8_t value)
{
  return value <= static_cast<std::uint8_t>(ParamType::SINGLE_TARGET_TRACKING);
}

const char* toString(MessageType type)
{
  switch (type)
  {
    case MessageType::EMPTY:
      return "EMPTY";
    case MessageType::GET_PARAMETERS:
      return "GET_PARAMETERS";
    case MessageType::SET_PARAMETERS:
      return "SET_PARAMETERS";
    case MessageType::CURRENT_PARAMETERS:
      return "CURRENT_PARAMETERS";
    case MessageType::GET_INTERVAL:
      return "GET_INTERVAL";
    case MessageType::ACKNOWLEDGEMENT:
      return "ACKNOWLEDGEMENT";
    case MessageType::CHECKSUM_ERROR:
      return "CHECKSUM_ERROR";
    case MessageType::DATA_ERROR:
      return "DATA_ERROR";
    case MessageType::FORBIDDEN:
      return "FORBIDDEN";
    case MessageType::UNKNOWN:
      return "UNKNOWN";
    case MessageType::QUIT:
      return "QUIT";
  }
  return "?";
}

const char* toString(ParamType type)
{
  static const char* const NAMES[] = { "SYSTEM_STATUS",
                                       "AI",
                                       "MODEL",
                                       "VIDEO_OUTPUT",
                                       "CAPTURE",
                                       "DETECTION",
                                       "DETECTED_ROI",
                                       "CAM_TARGETING",
                                       "CAM_OPTICS_AND_CONTROL",
                                       "CAM_OFFSET",
                                       "SENSOR",
                                       "CAM_DEPTH_ESTIMATION",
                                       "SINGLE_TARGET_TRACKING" };
  const auto index = static_cast<std::size_t>(type);
  return index < sizeof(NAMES) / sizeof(NAMES[0]) ? NAMES[index] : "?";
}

const char* describeError(MessageType type)
{
  switch (type)
  {
    case MessageType::CHECKSUM_ERROR:
      return "the checksum of the message did not match";
    case MessageType::DATA_ERROR:
      return "DigiView could not interpret the data";
    case MessageType::FORBIDDEN:
      return "the sender does not have permission to perform the requested action";
    case MessageType::UNKNOWN:
      return "the parameter or message type is unknown to DigiView";
    default:
      return "not an error";
  }
}

const char* toString(UnpackError error)
{
  switch (error)
  {
    case UnpackError::NONE:
      return "none";
    case UnpackError::BAD_SIZE:
      return "bad size";
    case UnpackError::BAD_CHECKSUM:
      return "bad checksum";
    case UnpackError::BAD_VERSION:
      return "bad version";
    case UnpackError::BAD_MESSAGE_TYPE:
      return "bad message type";
    case UnpackError::BAD_PARAM_TYPE:
      return "bad param type";
    case UnpackError::BAD_DATA:
      return "bad data";
  }
  return "?";
}

std::uint8_t crc8(const std::uint8_t* data, std::size_t size)
{
  std::uint8_t crc = 0;
  for (std::size_t index = 0; index < size; ++index)
  {
    crc = CRC_TABLE[crc ^ data[index]];
  }
  return crc;
}

Bytes Message::pack() const
{
  Bytes bytes{};
  for (std::size_t index = 0; index < 8; ++index)
  {
    bytes[index] = static_cast<std::uint8_t>(timestamp >> (8 * index));
  }
  bytes[8] = version;
  bytes[9] = static_cast<std::uint8_t>(message_type);
  bytes[10] = static_cast<std::uint8_t>(param_type);
  std::copy(data.begin(), data.end(), bytes.begin() + DATA_OFFSET);
  bytes[CHECKSUM_OFFSET] = crc8(bytes.data(), CHECKSUM_OFFSET);
  return bytes;
}

UnpackError Message::unpack(const std::uint8_t* bytes, std::size_t size, Message& message)
{
  message = Message();
  if (bytes == nullptr || size != MESSAGE_SIZE)
  {
    return UnpackError::BAD_SIZE;
  }
  if (crc8(bytes, CHECKSUM_OFFSET) != bytes[CHECKSUM_OFFSET])
  {
    return UnpackError::BAD_CHECKSUM;
  }
  if (bytes[8] != VERSION)
  {
    return UnpackError::BAD_VERSION;
  }
  if (!isMessageType(bytes[9]))
  {
    return UnpackError::BAD_MESSAGE_TYPE;
  }
  if (!isParamType(bytes[10]))
  {
    return UnpackError::BAD_PARAM_TYPE;
  }
  for (std::size_t index = 0; index < 8; ++index)
  {
    message.timestamp |= static_cast<std::uint64_t>(bytes[index]) << (8 * index);
  }
  message.version = bytes[8];
  message.message_type = static_cast<MessageType>(bytes[9]);
  message.param_type = static_cast<ParamType>(bytes[10]);
  std::copy(bytes + DATA_OFFSET, bytes + DATA_OFFSET + DATA_SIZE, message.data.begin());
  return UnpackError::NONE;
}

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
  std::uint32_t bits = 0;
  std::memcpy(&bits, &status.jetson_temp, sizeof(bits));
  payload.u32(2, bits);
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
  const std::uint32_t bits = reader.u32(2);
  float temperature = 0.0f;
  std::memcpy(&temperature, &bits, sizeof(temperature));
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

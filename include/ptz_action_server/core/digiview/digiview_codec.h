/**
 * \file
 * \brief DigiView (Synclair Vision) message definitions, format 0.5: 80-byte messages with a CRC-8/BLUETOOTH.
 *
 * Layout: timestamp uint64 @0, version uint8 @8 (0), message_type @9, param_type @10, data[64] @11..74, checksum
 * @75 (CRC-8/BLUETOOTH over bytes 0..74), padding @76..79 (zero). Multi-byte fields are little-endian. Angles and
 * coordinates travel as int32 = value x 1000 (milliradians for angles), view offsets as int16 = value x 32767,
 * strings NUL-padded to 8 bytes.
 *
 * Where the seed leaves the layout open, this library decides (and the README says so):
 * - GET_INTERVAL carries stream_name @0, cam_id @8, the parameter's request data as for a GET, and the interval in
 *   milliseconds as uint32 @12 (0 cancels, below 100 is ignored by DigiView).
 * - SYSTEM_STATUS: status @0, error @1, jetson_temp float32 @2.
 * - VIDEO_OUTPUT: stream_name @0, width uint16 @8, height uint16 @10, fps @12, layout_mode @13 (in a GET reply the
 *   4 MSB carry num_user_views), detection_overlay_mode @14, views 4 x bounding box (x, y, w, h uint16) @15,
 *   detection_overlay_box @47, single_detection_size uint16 @55.
 * No ROS here.
 */
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace ptz_action_server
{
namespace digiview
{
constexpr std::size_t MESSAGE_SIZE = 80;
constexpr std::size_t DATA_OFFSET = 11;
constexpr std::size_t DATA_SIZE = 64;
constexpr std::size_t CHECKSUM_OFFSET = 75;
constexpr std::uint8_t VERSION = 0;
constexpr std::size_t NAME_SIZE = 8;
constexpr std::uint32_t MIN_INTERVAL_MS = 100;

enum class MessageType : std::uint8_t
{
  EMPTY = 0,
  GET_PARAMETERS = 1,
  SET_PARAMETERS = 2,
  CURRENT_PARAMETERS = 3,
  GET_INTERVAL = 4,
  ACKNOWLEDGEMENT = 5,
  CHECKSUM_ERROR = 6,
  DATA_ERROR = 7,
  FORBIDDEN = 8,
  UNKNOWN = 9,
  QUIT = 255,
};

enum class ParamType : std::uint8_t
{
  SYSTEM_STATUS = 0,
  AI = 1,
  MODEL = 2,
  VIDEO_OUTPUT = 3,
  CAPTURE = 4,
  DETECTION = 5,
  DETECTED_ROI = 6,
  CAM_TARGETING = 7,
  CAM_OPTICS_AND_CONTROL = 8,
  CAM_OFFSET = 9,
  SENSOR = 10,
  CAM_DEPTH_ESTIMATION = 11,
  SINGLE_TARGET_TRACKING = 12,
};

bool isMessageType(std::uint8_t value);
bool isParamType(std::uint8_t value);
const char* toString(MessageType type);
const char* toString(ParamType type);
/// What an error reply means, in the seed's words.
const char* describeError(MessageType type);

/// Why unpacking failed. Every refused message has exactly one reason.
enum class UnpackError
{
  NONE = 0,
  BAD_SIZE,
  BAD_CHECKSUM,
  BAD_VERSION,
  BAD_MESSAGE_TYPE,
  BAD_PARAM_TYPE,
  BAD_DATA,  ///< a field outside its valid range, or the wrong param type for this unpack
};
const char* toString(UnpackError error);

/// CRC-8/BLUETOOTH: poly 0xA7, init 0, reflected in and out, xorout 0. Check value ("123456789"): 0x26.
std::uint8_t crc8(const std::uint8_t* data, std::size_t size);

/// The 80 bytes of one message.
using Bytes = std::array<std::uint8_t, MESSAGE_SIZE>;

/// The base message: header fields and the raw data.
struct Message
{
  std::uint64_t timestamp = 0;
  std::uint8_t version = VERSION;
  MessageType message_type = MessageType::EMPTY;
  ParamType param_type = ParamType::SYSTEM_STATUS;
  std::array<std::uint8_t, DATA_SIZE> data{};

  /// The message with its checksum, padding zero.
  Bytes pack() const;
  /// Checks size, checksum, version and types; never reads outside [bytes, bytes + size).
  static UnpackError unpack(const std::uint8_t* bytes, std::size_t size, Message& message);
};

/// Which user-controllable camera of which stream a message is about.
struct CameraId
{
  std::string stream_name;  ///< at most 8 characters
  std::uint8_t cam_id = 0;
};

struct CamTargeting
{
  CameraId camera;
  std::uint8_t targeting_mode = 0;  ///< 0 directional, 1 coordinal, 2 detection, 3 single target tracking
  bool euler_delta = false;
  double yaw = 0.0;             ///< rad, clockwise from north (Tait-Bryan)
  double pitch = 0.0;           ///< rad, up positive
  double roll = 0.0;            ///< rad (ignored by DigiView)
  std::uint8_t lock_flags = 0;  ///< 3 LSB: yaw, pitch, roll locked
  double x_offset = 0.0;        ///< [-1, 1] of the view
  double y_offset = 0.0;
  double target_latitude = 0.0;   ///< deg
  double target_longitude = 0.0;  ///< deg
  double target_altitude = 0.0;   ///< m, relative to the system
};

struct CamOpticsAndControl
{
  CameraId camera;
  std::int8_t zoom = 0;  ///< relative zoom step: 0 none, positive in, negative out
  double fov = 0.0;      ///< rad
  std::uint8_t crop_mode = 1;
};

struct SystemStatus
{
  std::uint8_t status = 0;  ///< 0 idle, 1 running, 2 finished, 3 error
  std::uint8_t error = 0;
  float jetson_temp = 0.0f;
};

struct BoundingBox
{
  std::uint16_t x = 0;
  std::uint16_t y = 0;
  std::uint16_t w = 0;
  std::uint16_t h = 0;
};

struct VideoOutput
{
  std::string stream_name;
  std::uint16_t width = 1920;
  std::uint16_t height = 1080;
  std::uint8_t fps = 0;
  std::uint8_t layout_mode = 0;     ///< [0, 6]
  std::uint8_t num_user_views = 1;  ///< GET replies only: the 4 MSB of the layout byte, [1, 4]
  std::uint8_t detection_overlay_mode = 0;
  std::array<BoundingBox, 4> views{};
  BoundingBox detection_overlay_box;
  std::uint16_t single_detection_size = 0;
};

/// A GET_INTERVAL request: periodic CURRENT_PARAMETERS of \p param for one camera (0 ms cancels).
struct IntervalRequest
{
  ParamType param = ParamType::CAM_TARGETING;
  CameraId camera;
  std::uint32_t interval_ms = 0;
};

// Packing: build the message of the given type around the payload.
Message packTargeting(MessageType type, const CamTargeting& targeting);
Message packOptics(MessageType type, const CamOpticsAndControl& optics);
Message packSystemStatus(MessageType type, const SystemStatus& status);
Message packVideoOutput(MessageType type, const VideoOutput& output);
/// A GET_PARAMETERS request for \p param about \p camera (stream_name @0, cam_id @8).
Message packGet(ParamType param, const CameraId& camera);
Message packInterval(const IntervalRequest& request);
/// A reply without payload (ACKNOWLEDGEMENT, an error, QUIT) about \p param.
Message packBare(MessageType type, ParamType param);

// Unpacking the payload of an unpacked message; BAD_DATA when the param type differs or a field is out of range.
UnpackError unpackTargeting(const Message& message, CamTargeting& targeting);
UnpackError unpackOptics(const Message& message, CamOpticsAndControl& optics);
UnpackError unpackSystemStatus(const Message& message, SystemStatus& status);
UnpackError unpackVideoOutput(const Message& message, VideoOutput& output);
UnpackError unpackCamera(const Message& message, CameraId& camera);
UnpackError unpackInterval(const Message& message, IntervalRequest& request);

}  // namespace digiview
}  // namespace ptz_action_server

/**
 * \file
 * \brief DigiView (Synclair Vision) message definitions in the wire formats in the field: "0.5" (80-byte messages, the
 * seed's tables; msg_defs.hpp 72c80d2), "1.0" (88-byte messages; msg_defs.hpp 835b28e, 2026-01-26) and "1.1" (1.0
 * with detection_id at the end of CAM_TARGETING; msg_defs.hpp 305a8ab, 2026-03-24, the first with a checksum helper).
 *
 * A message is the published `struct message` as x86-64 lays it out and `memcpy`s it: little-endian, natural padding.
 *
 * | field                          | 0.5    | 1.0, 1.1 |
 * |--------------------------------|--------|----------|
 * | timestamp uint64               | 0..7   | 0..7     |
 * | version uint8 (0 in all)       | 8      | 8        |
 * | message_type uint8             | 9      | 9        |
 * | param_type uint8               | 10     | 10       |
 * | padding                        | -      | 11       |
 * | interval_ms uint32             | -      | 12..15   |
 * | data[64]                       | 11..74 | 16..79   |
 * | checksum uint8                 | 75     | 80       |
 * | padding                        | 76..79 | 81..87   |
 *
 * MessageType holds the seed's values, which are format 0.5's on the wire. Formats 1.0 and 1.1 have no GET_INTERVAL
 * and number the replies one lower: ACKNOWLEDGEMENT 4, CHECKSUM_ERROR 5, DATA_ERROR 6, FORBIDDEN 7, UNKNOWN 8. The
 * version byte is 0 in all, so nothing in a message names its format: sender and receiver are configured with one.
 * 1.0 and 1.1 differ only in CAM_TARGETING's detection_id (int16 @40 of data in 1.1, where 1.0 leaves zeros), so a
 * message of one reads as the other (detection_id aside).
 *
 * Where the published code is silent, this library decides (the README says the same):
 * - Checksum: CRC-8/BLUETOOTH over bytes [0, offsetof(checksum)), i.e. 0..74 (0.5) and 0..79 (1.0, 1.1), the rule of
 *   the first published helper that fills it (1.1's add_checksum_for_digiview_message). Every message packed here
 *   carries it. The published helpers of 0.5 and 1.0 never fill it, so a receiver can be told that its peer does not
 *   (ChecksumRule::ZERO_ACCEPTED): a message whose checksum byte is 0 is then accepted unverified, and unpack() says
 *   so; any other byte must verify.
 * - Padding bytes and data bytes a payload does not use are zero when packed and ignored when unpacked.
 * - Subscriptions: in 0.5, GET_INTERVAL carries the GET's request data (stream_name @0, cam_id @8) and the interval in
 *   milliseconds as uint32 @12 of data (the published 0.5 code defines no field for it). In 1.0 and 1.1, a
 *   GET_PARAMETERS with interval_ms set in the header subscribes, as the published helpers intend. In all, 100 ms
 *   (MIN_INTERVAL_MS) or more subscribes, 0 cancels, anything between is ignored (the whole request). A 1.0 or 1.1 GET
 *   that is not ignored is answered at once; a 0.5 GET_INTERVAL only by its reports.
 * - Replies: CURRENT_PARAMETERS carries the parameter's payload as its request's packer lays it out, interval_ms 0;
 *   ACKNOWLEDGEMENT and the error replies carry the request's param_type and no data (nothing published defines more).
 * - Scaled fields are packed as the published packers do: the value as a float, times 1000 (angles in milliradians,
 *   latitude and longitude in 1/1000 degree, altitude in mm, fov in milliradians, temperature in 1/1000 degree C)
 *   or times 32767 (view offsets), in single precision, truncated toward zero. Outside the integer's range the
 *   published cast is undefined: here it saturates (NaN packs 0). Unpacking divides.
 * - CAM_TARGETING: stream_name @0, cam_id @8, targeting_mode @9, euler_delta @10, yaw int32 @11, pitch @15, roll @19,
 *   lock_flags @23, x_offset int16 @24, y_offset @26; then in 0.5 what its packer writes, latitude @28 and again
 *   @32, longitude @36, altitude @40 (44 bytes: what every 0.5 sender sends; the published 0.5 unpacker reads
 *   longitude @32 and altitude @36 instead, which its own packer never wrote); in 1.0 latitude @28, longitude @32,
 *   altitude @36 (40 bytes); 1.1 as 1.0, then detection_id int16 @40 (42 bytes; int16 and -1 for "no detection"
 *   as the repository's message-definitions.md documents the field).
 * - SYSTEM_STATUS: status @0, error @1, jetson_temp int32 (x 1000) @2. The first 0.5 revision sent no temperature:
 *   its zero bytes read as 0 degrees.
 * - VIDEO_OUTPUT: stream_name @0, width uint16 @8, height @10, fps @12, layout_mode @13, detection_overlay_mode @14,
 *   num_user_views @15, then that many view boxes (x, y, w, h uint16) @16, detection_overlay_box @16 + 8n,
 *   single_detection_size uint16 @24 + 8n. A SET carries n = 0 and no boxes, as the published SET helper.
 * - Ranges checked on unpacking: lock_flags 0..7 (three flag bits; the seed's table says 0..4), targeting_mode 0..3,
 *   crop_mode 0..2 (the table says 0..1, the text 1..2), num_user_views 0..4; the others as the seed's tables.
 * No ROS here.
 */
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ptz_action_server
{
namespace digiview
{
constexpr std::size_t DATA_SIZE = 64;
constexpr std::size_t MAX_MESSAGE_SIZE = 88;
constexpr std::uint8_t VERSION = 0;
constexpr std::size_t NAME_SIZE = 8;
constexpr std::uint32_t MIN_INTERVAL_MS = 100;

/// The wire formats in the field, each a published revision of msg_defs.hpp (SynclairVision/message-definitions).
enum class Format : std::uint8_t
{
  V0_5,  ///< "0.5": 80-byte messages, the seed's tables (72c80d2, 2025-10-17)
  V1_0,  ///< "1.0": 88-byte messages, interval_ms in the header, no GET_INTERVAL, replies renumbered (835b28e)
  V1_1,  ///< "1.1": 1.0 with detection_id appended to CAM_TARGETING, and a checksum helper (305a8ab, 2026-03-24)
};
/// Every format, oldest first.
inline constexpr Format FORMATS[] = { Format::V0_5, Format::V1_0, Format::V1_1 };
const char* toString(Format format);  ///< "0.5", "1.0", "1.1"
/// "0.5", "1.0" or "1.1" into \p format; false for anything else.
bool parseFormat(const std::string& text, Format& format);

/// Where a format puts the parts of a message (offsets in bytes).
struct Layout
{
  std::size_t size;
  std::size_t data_offset;
  std::size_t checksum_offset;  ///< also the number of bytes the checksum covers
  std::size_t interval_offset;  ///< 0: the format has no interval_ms (and has GET_INTERVAL instead)
};
Layout layoutOf(Format format);
/// A subscription is a GET_PARAMETERS with interval_ms in the header (1.0, 1.1), not a GET_INTERVAL (0.5).
inline bool subscribesWithGet(Format format)
{
  return layoutOf(format).interval_offset != 0;
}

/// What a receiver takes for a checksum.
enum class ChecksumRule : std::uint8_t
{
  REQUIRED,       ///< every message must carry its CRC
  ZERO_ACCEPTED,  ///< the peer may not fill it: a checksum byte of 0 is accepted unverified, any other must verify
};
const char* toString(ChecksumRule rule);  ///< "required", "zero_accepted"
bool parseChecksumRule(const std::string& text, ChecksumRule& rule);

/// How one side of a DigiView link reads the wire.
struct Wire
{
  Format format = Format::V0_5;
  ChecksumRule checksum = ChecksumRule::REQUIRED;
};

/// The seed's message types (their values are format 0.5's wire values; see toWire()).
enum class MessageType : std::uint8_t
{
  EMPTY = 0,
  GET_PARAMETERS = 1,
  SET_PARAMETERS = 2,
  CURRENT_PARAMETERS = 3,
  GET_INTERVAL = 4,  ///< 0.5 only
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

/// The byte \p type is in \p format; false for GET_INTERVAL in 1.0 and 1.1, which have none.
bool toWire(Format format, MessageType type, std::uint8_t& wire);
/// The message type the byte \p wire is in \p format; false if it is none.
bool fromWire(Format format, std::uint8_t wire, MessageType& type);
bool isParamType(std::uint8_t value);
const char* toString(MessageType type);
const char* toString(ParamType type);
/// What an error reply means, in the seed's words.
const char* describeError(MessageType type);

/// Why unpacking failed. Every refused message has exactly one reason.
enum class UnpackError
{
  NONE = 0,
  BAD_SIZE,  ///< not the format's size (also what a message of the other format is)
  BAD_CHECKSUM,
  BAD_VERSION,
  BAD_MESSAGE_TYPE,  ///< not a message type of the format
  BAD_PARAM_TYPE,
  BAD_DATA,  ///< a field outside its valid range, or the wrong param or message type for this unpack
};
const char* toString(UnpackError error);

/// CRC-8/BLUETOOTH: poly 0xA7, init 0, reflected in and out, xorout 0. Check value ("123456789"): 0x26.
std::uint8_t crc8(const std::uint8_t* data, std::size_t size);

/// The bytes of one message: layoutOf(format).size of them.
using Bytes = std::vector<std::uint8_t>;

/// The base message: header fields and the raw data.
struct Message
{
  Format format = Format::V0_5;
  std::uint64_t timestamp = 0;
  std::uint8_t version = VERSION;
  MessageType message_type = MessageType::EMPTY;
  ParamType param_type = ParamType::SYSTEM_STATUS;
  std::uint32_t interval_ms = 0;  ///< 1.0, 1.1: a GET with it subscribes (0.5 has no such field)
  std::array<std::uint8_t, DATA_SIZE> data{};

  /// The message in its format, with its checksum, padding zero. Throws std::invalid_argument for what the format
  /// cannot carry (GET_INTERVAL in 1.0 and 1.1, an interval_ms in 0.5).
  Bytes pack() const;
  /// Checks size, checksum (by \p wire's rule), version and types; never reads outside [bytes, bytes + size).
  /// \p unverified (if given) tells whether a checksum byte of 0 was accepted without verifying.
  static UnpackError unpack(const std::uint8_t* bytes, std::size_t size, const Wire& wire, Message& message,
                            bool* unverified = nullptr);
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
  double target_latitude = 0.0;    ///< deg
  double target_longitude = 0.0;   ///< deg
  double target_altitude = 0.0;    ///< m, relative to the system
  std::int16_t detection_id = -1;  ///< 1.1 only: the detection to aim at in detection mode; -1: none
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
  double jetson_temp = 0.0;  ///< degrees C
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
  std::uint8_t layout_mode = 0;  ///< [0, 6]
  std::uint8_t detection_overlay_mode = 0;
  std::uint8_t num_user_views = 1;     ///< [0, 4]: the views of the layout (a SET carries 0)
  std::array<BoundingBox, 4> views{};  ///< the first num_user_views travel
  BoundingBox detection_overlay_box;
  std::uint16_t single_detection_size = 0;
};

/// A subscription request: periodic CURRENT_PARAMETERS of \p param for one camera (0 ms cancels).
struct IntervalRequest
{
  ParamType param = ParamType::CAM_TARGETING;
  CameraId camera;
  std::uint32_t interval_ms = 0;
};

// Packing: build the message of the given format and type around the payload.
Message packTargeting(Format format, MessageType type, const CamTargeting& targeting);
Message packOptics(Format format, MessageType type, const CamOpticsAndControl& optics);
Message packSystemStatus(Format format, MessageType type, const SystemStatus& status);
Message packVideoOutput(Format format, MessageType type, const VideoOutput& output);
/// A GET_PARAMETERS request for \p param about \p camera (stream_name @0, cam_id @8).
Message packGet(Format format, ParamType param, const CameraId& camera);
/// 0.5: a GET_INTERVAL (interval @12 of data); 1.0, 1.1: a GET_PARAMETERS with interval_ms.
Message packInterval(Format format, const IntervalRequest& request);
/// A message without payload (ACKNOWLEDGEMENT, an error, QUIT) about \p param.
Message packBare(Format format, MessageType type, ParamType param);

// Unpacking the payload of an unpacked message; BAD_DATA when the param type differs or a field is out of range.
UnpackError unpackTargeting(const Message& message, CamTargeting& targeting);
UnpackError unpackOptics(const Message& message, CamOpticsAndControl& optics);
UnpackError unpackSystemStatus(const Message& message, SystemStatus& status);
UnpackError unpackVideoOutput(const Message& message, VideoOutput& output);
UnpackError unpackCamera(const Message& message, CameraId& camera);
/// A 0.5 GET_INTERVAL, or a 1.0 / 1.1 GET_PARAMETERS (whose interval_ms may be 0: a plain GET).
UnpackError unpackInterval(const Message& message, IntervalRequest& request);

}  // namespace digiview
}  // namespace ptz_action_server

/**
 * \file
 * \brief DigiView (Synclair Vision) message definitions in the wire formats in the field: "0.5" (80-byte messages, the
 * seed's tables; msg_defs.hpp 72c80d2), "1.0" (88-byte messages; msg_defs.hpp 835b28e, 2026-01-26), "1.1" (1.0
 * with detection_id at the end of CAM_TARGETING; msg_defs.hpp 305a8ab, 2026-03-24, the first with a checksum helper)
 * and "1.2" (96-byte messages, 16-character stream names, parameter types renumbered; msg_defs.hpp 1cbc39f,
 * 2026-08-20).
 *
 * A message is the published `struct message` as x86-64 lays it out and `memcpy`s it: little-endian, natural padding.
 *
 * | field                          | 0.5    | 1.0, 1.1 | 1.2      |
 * |--------------------------------|--------|----------|----------|
 * | timestamp uint64               | 0..7   | 0..7     | 0..7     |
 * | version uint8 (0 in all)       | 8      | 8        | 8        |
 * | message_type uint8             | 9      | 9        | 9        |
 * | param_type uint8               | 10     | 10       | 10       |
 * | padding                        | -      | 11       | 11       |
 * | interval_ms uint32             | -      | 12..15   | 12..15   |
 * | data                           | 11..74 | 16..79   | 16..87   |
 * | checksum uint8                 | 75     | 80       | 88       |
 * | padding                        | 76..79 | 81..87   | 89..95   |
 *
 * MessageType holds the seed's values, which are format 0.5's on the wire. Formats 1.0, 1.1 and 1.2 have no
 * GET_INTERVAL and number the replies one lower: ACKNOWLEDGEMENT 4, CHECKSUM_ERROR 5, DATA_ERROR 6, FORBIDDEN 7,
 * UNKNOWN 8; 1.2 adds DEBUG 9. ParamType holds the values of 0.5, 1.0 and 1.1; 1.2 renumbers them (CAM_TARGETING 13,
 * CAM_OPTICS_AND_CONTROL 14, ...: paramToWire()). The version byte is 0 in all, so nothing in a message names its
 * format: sender and receiver are configured with one. 1.0 and 1.1 differ only in CAM_TARGETING's detection_id
 * (int16 @40 of data in 1.1, where 1.0 leaves zeros), so a message of one reads as the other (detection_id aside).
 *
 * Where the published code is silent, this library decides (doc/backends/digiview.md says the same):
 * - Checksum: CRC-8/BLUETOOTH over bytes [0, offsetof(checksum)), i.e. 0..74 (0.5), 0..79 (1.0, 1.1) and 0..87 (1.2),
 *   the rule of the published helper that fills it (add_checksum_for_digiview_message, from 1.1 on). Every message
 *   packed here carries it. The published packers never call that helper, so a receiver can be told that its peer
 *   does not (ChecksumRule::ZERO_ACCEPTED): a message whose checksum byte is 0 is then accepted unverified, and
 *   unpack() says so; any other byte must verify.
 * - Padding bytes and data bytes a payload does not use are zero when packed and ignored when unpacked.
 * - Subscriptions: in 0.5, GET_INTERVAL carries the GET's request data (stream_name @0, cam_id @8) and the interval in
 *   milliseconds as uint32 @12 of data (the published 0.5 code defines no field for it). From 1.0 on, a
 *   GET_PARAMETERS with interval_ms set in the header subscribes, as the published helpers intend. minIntervalOf()
 *   (100 ms; 50 ms in 1.2) or more subscribes, 0 cancels; anything between is ignored (the whole request) before
 *   1.2, and answered once in 1.2 (its documentation). A GET that is not ignored is answered at once; a 0.5
 *   GET_INTERVAL only by its reports.
 * - Replies: CURRENT_PARAMETERS carries the parameter's payload as its request's packer lays it out, interval_ms 0;
 *   ACKNOWLEDGEMENT and the error replies carry the request's param_type and no data (nothing published defines more).
 * - Scaled fields are packed as the published packers do: the value as a float, times 1000 (angles and fov in the
 *   wire's AngleUnit, latitude and longitude in 1/1000 degree, altitude in mm, temperature in 1/1000 degree C) or
 *   times 32767 (view offsets), in single precision, truncated toward zero. Outside the integer's range the published
 *   cast is undefined: here it saturates (NaN packs 0). Unpacking divides. Payload structs hold radians: the wire's
 *   unit is converted on the way (Wire::angles).
 * - Offsets below are inside data for names of 8 bytes (0.5 to 1.1); 1.2's 16-byte names move everything after the
 *   name 8 bytes on (cam_id @16).
 * - CAM_TARGETING: stream_name @0, cam_id @8, targeting_mode @9, euler_delta @10, yaw int32 @11, pitch @15, roll @19,
 *   lock_flags @23, x_offset int16 @24, y_offset @26; then in 0.5 what its packer writes, latitude @28 and again
 *   @32, longitude @36, altitude @40 (44 bytes: what every 0.5 sender sends; the published 0.5 unpacker reads
 *   longitude @32 and altitude @36 instead, which its own packer never wrote); from 1.0 on latitude @28, longitude
 *   @32, altitude @36 (40 bytes); 1.1 then detection_id int16 @40 (42 bytes; -1 for "no detection" as the
 *   repository's message-definitions.md documents the field); 1.2 then track_id uint16 @40 (0: none), view_id int16
 *   @42 (-1: no detection lock) and lock_target @44 (i.e. @48, @50, @52 with its 16-byte name; 53 bytes).
 * - CAM_OPTICS_AND_CONTROL: stream_name @0, cam_id @8, zoom int8 @9, fov int32 @10, crop_mode @14; 1.2 has no
 *   crop_mode (22 bytes).
 * - SYSTEM_STATUS: status @0, error @1, jetson_temp int32 (x 1000) @2. The first 0.5 revision sent no temperature:
 *   its zero bytes read as 0 degrees. status is the seed's (0 idle, 1 running, 2 finished, 3 error) in 0.5 and 1.0,
 *   app_status (0 startup, 1 loading, 2 running, 3 error, 4 halt) from 1.1 on, as each revision's documentation
 *   gives it; error is 0 in 0.5 and 1.0 ("always 0"), any value from 1.1 on.
 * - VIDEO_OUTPUT: stream_name @0, width uint16 @8, height @10, fps @12, layout_mode @13, detection_overlay_mode @14,
 *   num_user_views @15, then that many view boxes (x, y, w, h uint16) @16, detection_overlay_box @16 + 8n,
 *   single_detection_size uint16 @24 + 8n. A SET carries n = 0 and no boxes, as the published SET helper.
 * - DEBUG (1.2): eight int32 @0..31 of data, param_type 0, not scaled.
 * - Ranges checked on unpacking: yaw +-180 degrees, pitch and roll +-90, fov 0..180 (in the wire's unit), lock_flags
 *   0..7 (three flag bits; the seed's table says 0..4), targeting_mode 0..3, crop_mode 0..2 (the table says 0..1, the
 *   text 1..2), num_user_views 0..4, lock_target 0..1; the others as the seed's tables.
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
constexpr std::size_t DATA_SIZE = 72;  ///< the largest data field (1.2); the others carry Layout::data_size bytes
constexpr std::size_t MAX_MESSAGE_SIZE = 96;
constexpr std::uint8_t VERSION = 0;
constexpr std::size_t MAX_NAME_SIZE = 16;

/// The wire formats in the field, each a published revision of msg_defs.hpp (SynclairVision/message-definitions).
enum class Format : std::uint8_t
{
  V0_5,  ///< "0.5": 80-byte messages, the seed's tables (72c80d2, 2025-10-17)
  V1_0,  ///< "1.0": 88-byte messages, interval_ms in the header, no GET_INTERVAL, replies renumbered (835b28e)
  V1_1,  ///< "1.1": 1.0 with detection_id appended to CAM_TARGETING, and a checksum helper (305a8ab, 2026-03-24)
  V1_2,  ///< "1.2": 96-byte messages, 16-character names, CAM_TARGETING 13, no crop_mode, DEBUG (1cbc39f, 2026-08-20)
};
/// Every format, oldest first.
inline constexpr Format FORMATS[] = { Format::V0_5, Format::V1_0, Format::V1_1, Format::V1_2 };
const char* toString(Format format);  ///< "0.5", "1.0", "1.1", "1.2"
/// "0.5", "1.0", "1.1" or "1.2" into \p format; false for anything else.
bool parseFormat(const std::string& text, Format& format);
/// The formats whose messages are \p size bytes, for messages: "0.5", "1.0 or 1.1", "1.2"; empty: none.
std::string formatsOfSize(std::size_t size);

/// Where a format puts the parts of a message (offsets in bytes).
struct Layout
{
  std::size_t size;
  std::size_t data_offset;
  std::size_t data_size;
  std::size_t checksum_offset;  ///< also the number of bytes the checksum covers
  std::size_t interval_offset;  ///< 0: the format has no interval_ms (and has GET_INTERVAL instead)
};
Layout layoutOf(Format format);
/// A subscription is a GET_PARAMETERS with interval_ms in the header (1.0 on), not a GET_INTERVAL (0.5).
inline bool subscribesWithGet(Format format)
{
  return layoutOf(format).interval_offset != 0;
}
/// The bytes of a stream name: 8, or 16 in 1.2 (whose packers cut longer names).
std::size_t nameSizeOf(Format format);
/// The shortest interval that subscribes: 100 ms, or 50 ms in 1.2.
std::uint32_t minIntervalOf(Format format);
/// 1.2: a GET with a shorter non-zero interval is answered once (before, the whole request is ignored).
bool shortIntervalIsOneShot(Format format);

/// The unit a format's angles and field of view travel in (times 1000, as every scaled field).
enum class AngleUnit : std::uint8_t
{
  RADIANS,
  DEGREES,
};
const char* toString(AngleUnit unit);  ///< "radians", "degrees"
bool parseAngleUnit(const std::string& text, AngleUnit& unit);
/// As each revision's own documentation gives it: radians in 0.5 and 1.0 (the seed's docs.md, published with
/// 835b28e), degrees in 1.1 (docs.md since 8d272ef, 2026-03-10, so at 305a8ab) and 1.2 (message-definitions.md at
/// 1cbc39f). The published packers only multiply by 1000: the unit is the documentation's word.
AngleUnit documentedAngleUnit(Format format);

/// What a receiver takes for a checksum.
enum class ChecksumRule : std::uint8_t
{
  REQUIRED,       ///< every message must carry its CRC
  ZERO_ACCEPTED,  ///< the peer may not fill it: a checksum byte of 0 is accepted unverified, any other must verify
};
const char* toString(ChecksumRule rule);  ///< "required", "zero_accepted"
bool parseChecksumRule(const std::string& text, ChecksumRule& rule);

/// How one side of a DigiView link reads and writes the wire. A Format alone is a Wire with its documented angle unit.
struct Wire
{
  // Not explicit on purpose: a format names its wire wherever the other two are the defaults.
  Wire(Format format = Format::V0_5, ChecksumRule checksum = ChecksumRule::REQUIRED)  // NOLINT
    : Wire(format, checksum, documentedAngleUnit(format))
  {
  }
  Wire(Format format, ChecksumRule checksum, AngleUnit angles) : format(format), checksum(checksum), angles(angles)
  {
  }

  Format format;
  ChecksumRule checksum;
  AngleUnit angles;
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
  DEBUG = 10,  ///< 1.2 only (wire 9); not a seed value
  QUIT = 255,
};

/// The parameter types: 0..12 are the wire values of 0.5, 1.0 and 1.1; 1.2 numbers them otherwise (paramToWire())
/// and adds the rest.
enum class ParamType : std::uint8_t
{
  SYSTEM_STATUS = 0,
  AI = 1,
  MODEL = 2,
  VIDEO_OUTPUT = 3,
  CAPTURE = 4,
  DETECTION = 5,
  DETECTED_ROI = 6,  ///< TRACKED_DETECTION in 1.2 (another layout)
  CAM_TARGETING = 7,
  CAM_OPTICS_AND_CONTROL = 8,
  CAM_OFFSET = 9,
  SENSOR = 10,
  CAM_DEPTH_ESTIMATION = 11,
  SINGLE_TARGET_TRACKING = 12,
  // 1.2 only:
  CALIBRATION = 13,
  NAVIGATION = 14,
  LENS = 15,
  CAM_EULER = 16,
  CAM_ZOOM = 17,
  CAM_LOCK_FLAGS = 18,
  CAM_CONTROL_MODE = 19,
};

/// The byte \p type is in \p format; false for what the format has not (GET_INTERVAL from 1.0 on, DEBUG before 1.2).
bool toWire(Format format, MessageType type, std::uint8_t& wire);
/// The message type the byte \p wire is in \p format; false if it is none.
bool fromWire(Format format, std::uint8_t wire, MessageType& type);
/// The byte \p param is in \p format; false for a parameter the format has not.
bool paramToWire(Format format, ParamType param, std::uint8_t& wire);
/// The parameter the byte \p wire is in \p format; false if it is none.
bool paramFromWire(Format format, std::uint8_t wire, ParamType& param);
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
  AngleUnit angles = AngleUnit::RADIANS;  ///< how its payload's angles read (the Wire it was packed or read with)
  std::uint64_t timestamp = 0;
  std::uint8_t version = VERSION;
  MessageType message_type = MessageType::EMPTY;
  ParamType param_type = ParamType::SYSTEM_STATUS;
  std::uint32_t interval_ms = 0;               ///< from 1.0 on: a GET with it subscribes (0.5 has no such field)
  std::array<std::uint8_t, DATA_SIZE> data{};  ///< the first layoutOf(format).data_size bytes travel

  /// The message in its format, with its checksum, padding zero. Throws std::invalid_argument for what the format
  /// cannot carry (GET_INTERVAL from 1.0 on, DEBUG or a 1.2 parameter before 1.2, an interval_ms in 0.5).
  Bytes pack() const;
  /// Checks size, checksum (by \p wire's rule), version and types; never reads outside [bytes, bytes + size).
  /// \p unverified (if given) tells whether a checksum byte of 0 was accepted without verifying.
  static UnpackError unpack(const std::uint8_t* bytes, std::size_t size, const Wire& wire, Message& message,
                            bool* unverified = nullptr);
  /// The wire it was packed or read with, checksum required.
  Wire wire() const
  {
    return Wire(format, ChecksumRule::REQUIRED, angles);
  }
};

/// Which user-controllable camera of which stream a message is about.
struct CameraId
{
  std::string stream_name;  ///< at most nameSizeOf(format) characters
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
  std::uint16_t track_id = 0;      ///< 1.2 only: the track to aim at; 0: none (use view_id)
  std::int16_t view_id = -1;       ///< 1.2 only: the displayed AI view slot; -1: no detection lock
  bool lock_target = false;        ///< 1.2 only
};

struct CamOpticsAndControl
{
  CameraId camera;
  std::int8_t zoom = 0;        ///< relative zoom step: 0 none, positive in, negative out
  double fov = 0.0;            ///< rad
  std::uint8_t crop_mode = 1;  ///< not in 1.2
};

/// SYSTEM_STATUS status values from 1.1 on (digiview_commons' app_status).
constexpr std::uint8_t APP_STATUS_RUNNING = 2;
constexpr std::uint8_t APP_STATUS_HALT = 4;
/// SYSTEM_STATUS status is app_status (0 startup .. 4 halt) from 1.1 on, the seed's (0 idle .. 3 error) before.
bool hasAppStatus(Format format);
/// What a running DigiView reports: 1 (the seed's "running") before 1.1, APP_STATUS_RUNNING from 1.1 on.
std::uint8_t runningStatus(Format format);
/// "running", "HALT", ... as \p format's documentation names \p status.
const char* describeStatus(Format format, std::uint8_t status);

struct SystemStatus
{
  std::uint8_t status = 0;  ///< see hasAppStatus()
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

/// 1.2's DEBUG message: eight integers, as they are.
using DebugValues = std::array<std::int32_t, 8>;

// Packing: build the message of the given wire and type around the payload (a Format alone: its documented unit).
Message packTargeting(const Wire& wire, MessageType type, const CamTargeting& targeting);
Message packOptics(const Wire& wire, MessageType type, const CamOpticsAndControl& optics);
Message packSystemStatus(const Wire& wire, MessageType type, const SystemStatus& status);
Message packVideoOutput(const Wire& wire, MessageType type, const VideoOutput& output);
/// A GET_PARAMETERS request for \p param about \p camera (stream_name @0, cam_id after it).
Message packGet(const Wire& wire, ParamType param, const CameraId& camera);
/// 0.5: a GET_INTERVAL (interval @12 of data); from 1.0 on: a GET_PARAMETERS with interval_ms.
Message packInterval(const Wire& wire, const IntervalRequest& request);
/// A message without payload (ACKNOWLEDGEMENT, an error, QUIT) about \p param.
Message packBare(const Wire& wire, MessageType type, ParamType param);
/// 1.2: a DEBUG message (param_type 0).
Message packDebug(const Wire& wire, const DebugValues& values);

// Unpacking the payload of an unpacked message; BAD_DATA when the param type differs or a field is out of range.
UnpackError unpackTargeting(const Message& message, CamTargeting& targeting);
UnpackError unpackOptics(const Message& message, CamOpticsAndControl& optics);
UnpackError unpackSystemStatus(const Message& message, SystemStatus& status);
UnpackError unpackVideoOutput(const Message& message, VideoOutput& output);
UnpackError unpackCamera(const Message& message, CameraId& camera);
/// A 0.5 GET_INTERVAL, or a GET_PARAMETERS of 1.0 on (whose interval_ms may be 0: a plain GET).
UnpackError unpackInterval(const Message& message, IntervalRequest& request);
/// BAD_DATA unless \p message is a DEBUG message.
UnpackError unpackDebug(const Message& message, DebugValues& values);

}  // namespace digiview
}  // namespace ptz_action_server

/**
 * \file
 * \brief Pelco-D: 7-byte frames `FF addr cmd1 cmd2 data1 data2 sum`, sum = (addr + cmd1 + cmd2 + data1 + data2) mod
 * 256, and a stream parser that resynchronises on 0xFF.
 */
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace ptz_action_server
{
namespace pelco
{
constexpr std::uint8_t SYNC = 0xFF;
constexpr std::size_t FRAME_SIZE = 7;
constexpr std::size_t GENERAL_REPLY_SIZE = 4;

/// cmd2 bits of the standard movement command.
constexpr std::uint8_t RIGHT = 0x02;
constexpr std::uint8_t LEFT = 0x04;
constexpr std::uint8_t UP = 0x08;
constexpr std::uint8_t DOWN = 0x10;
constexpr std::uint8_t ZOOM_TELE = 0x20;
constexpr std::uint8_t ZOOM_WIDE = 0x40;
/// The highest speed byte every published Pelco-D client sends. Turbo is device-specific (0x40 on some, 0xFF on
/// others, ignored by many): a setting of the backend, never sent unless configured.
constexpr std::uint8_t MAX_SPEED = 0x3F;
// The lens bits of the standard movement command: focus far in command 2, the others in command 1.
constexpr std::uint8_t FOCUS_FAR = 0x80;   ///< command 2, bit 7
constexpr std::uint8_t FOCUS_NEAR = 0x01;  ///< command 1, bit 0
constexpr std::uint8_t IRIS_OPEN = 0x02;   ///< command 1, bit 1
constexpr std::uint8_t IRIS_CLOSE = 0x04;  ///< command 1, bit 2

/// Extended commands (cmd2) and their replies.
constexpr std::uint8_t SET_PAN = 0x4B;
constexpr std::uint8_t SET_TILT = 0x4D;
constexpr std::uint8_t SET_ZOOM = 0x4F;
constexpr std::uint8_t QUERY_PAN = 0x51;
constexpr std::uint8_t QUERY_TILT = 0x53;
constexpr std::uint8_t QUERY_ZOOM = 0x55;
constexpr std::uint8_t PAN_REPLY = 0x59;
constexpr std::uint8_t TILT_REPLY = 0x5B;
constexpr std::uint8_t ZOOM_REPLY = 0x5D;
constexpr std::uint8_t SET_PRESET = 0x03;
constexpr std::uint8_t CLEAR_PRESET = 0x05;
constexpr std::uint8_t GO_TO_PRESET = 0x07;

/// Hundredths of a degree in a full turn.
constexpr int FULL_TURN = 36000;

struct Frame
{
  std::uint8_t address = 1;
  std::uint8_t command1 = 0;
  std::uint8_t command2 = 0;
  std::uint8_t data1 = 0;
  std::uint8_t data2 = 0;

  /// data1 (MSB) and data2 (LSB) as one 16-bit value.
  std::uint16_t value() const
  {
    return static_cast<std::uint16_t>((data1 << 8) | data2);
  }
  bool operator==(const Frame& other) const;
};

using Bytes = std::array<std::uint8_t, FRAME_SIZE>;

std::uint8_t checksum(const Frame& frame);
Bytes encode(const Frame& frame);

/// A frame with a 16-bit argument in data1 (MSB) / data2 (LSB).
Frame withValue(std::uint8_t address, std::uint8_t command2, std::uint16_t value);
/// Stop: all zero.
Frame stop(std::uint8_t address);
/**
 * \brief Movement: signed speeds, positive pan right, positive tilt up; zoom -1 wide, +1 tele.
 *
 * Speeds are capped at 0x3F; a pan speed above it is sent as \p pan_turbo instead when that is not 0 (the device's
 * own turbo byte). Tilt has no turbo.
 */
Frame move(std::uint8_t address, int pan_speed, int tilt_speed, int zoom_direction, std::uint8_t pan_turbo = 0);

/// How a device encodes tilt angles in 0..35999 hundredths of a degree.
/// \p frame (a standard movement command) with the lens bits: \p focus > 0 far, < 0 near; \p iris > 0 open, < 0
/// close; 0 neither. The lens moves at the device's own speed.
Frame withLens(Frame frame, int focus, int iris);

enum class TiltEncoding
{
  /// The Pelco manual's, as its published clients quote it: 0 is horizontal, "45 degrees below the horizon is 4500",
  /// "30 degrees above the horizon is 33000" (36000 - 100 a for an angle a up). The default.
  DOWN_POSITIVE,
  /// Up positive, an angle below the horizon as 36000 - 100 a: some devices count this way.
  UP_POSITIVE,
};

/// "down_positive" / "up_positive" -> \p encoding; false for anything else.
bool parseTiltEncoding(const std::string& text, TiltEncoding& encoding);
const char* toString(TiltEncoding encoding);

/// Pan in degrees (clockwise positive, any value) -> 0..35999 hundredths, clockwise from home.
std::uint16_t encodePan(double degrees);
/// 0..35999 hundredths -> pan in degrees within (-180, 180].
double decodePan(std::uint16_t value);
std::uint16_t encodeTilt(double degrees, TiltEncoding encoding);
double decodeTilt(std::uint16_t value, TiltEncoding encoding);

/// What the parser has thrown away.
struct ParserCounters
{
  std::uint64_t frames = 0;
  std::uint64_t general_replies = 0;
  std::uint64_t bad_checksum = 0;   ///< a 0xFF whose 7 (or 4) bytes do not check: dropped, resync
  std::uint64_t skipped_bytes = 0;  ///< bytes before a 0xFF (noise, the rest of a broken frame)
  std::uint64_t wrong_address = 0;  ///< valid frames for another address
};

/**
 * \brief Turns a byte stream into frames (and 4-byte general replies, when the device sends them).
 *
 * Bytes before a 0xFF are skipped; a 0xFF whose frame does not check is dropped and the search for the next 0xFF
 * goes on, so one broken frame never hides the next. Incomplete frames wait for more bytes: between two feeds the
 * buffer holds at most one frame less a byte (6 bytes), so bytes that never make a frame cost no memory.
 */
class FrameParser
{
public:
  struct Event
  {
    bool general_reply = false;  ///< a 4-byte `FF addr alarm sum` reply rather than a frame
    Frame frame;                 ///< valid when !general_reply
    std::uint8_t alarm = 0;      ///< general replies only
  };

  /// \p address: frames for other addresses are counted and dropped (0: accept any).
  explicit FrameParser(std::uint8_t address = 0, bool general_replies = false);

  void feed(const std::uint8_t* data, std::size_t size, std::vector<Event>& events);
  /// Drops a partial frame (after a reconnect or a timeout).
  void reset();
  const ParserCounters& counters() const
  {
    return counters_;
  }

private:
  void takeGeneralReply(std::vector<Event>& events);

  std::uint8_t address_;
  bool general_replies_;
  std::deque<std::uint8_t> buffer_;
  ParserCounters counters_;
};

}  // namespace pelco
}  // namespace ptz_action_server

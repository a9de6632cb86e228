/**
 * \file
 * \brief MAVLink 2 framing: `FD len incompat compat seq sysid compid msgid(3, LE) payload crc(2, LE) [signature(13)]`,
 * CRC-16/MCRF4XX with each message's CRC_EXTRA, payload truncation and zero-filling, and a stream parser that
 * resynchronises on the next 0xFD and counts every frame it drops under its reason.
 *
 * Only the messages of Gimbal Protocol v2 the gimbal backend and its emulator use are known (see mavlink_messages.h);
 * no Debian package carries the MAVLink headers.
 */
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace ptz_action_server
{
namespace mavlink
{
constexpr std::uint8_t STX_V2 = 0xFD;
constexpr std::uint8_t STX_V1 = 0xFE;
constexpr std::size_t HEADER_SIZE = 10;  ///< STX to the end of msgid
constexpr std::size_t V1_HEADER_SIZE = 6;
constexpr std::size_t CHECKSUM_SIZE = 2;
constexpr std::size_t SIGNATURE_SIZE = 13;
constexpr std::size_t MAX_PAYLOAD = 255;
constexpr std::size_t MAX_FRAME = HEADER_SIZE + MAX_PAYLOAD + CHECKSUM_SIZE + SIGNATURE_SIZE;
/// The only incompat flag there is: a 13-byte signature follows the checksum (not verified here).
constexpr std::uint8_t INCOMPAT_SIGNED = 0x01;

/// A full-length payload: fields beyond the bytes on the wire read as zero, as MAVLink 2 requires.
using Payload = std::array<std::uint8_t, MAX_PAYLOAD>;

/// What a receiver must know of a message to check and decode it.
struct MessageSpec
{
  std::uint32_t id;
  const char* name;
  std::uint8_t crc_extra;
  std::uint8_t length;  ///< with every extension field this codec knows
};

/// The spec of message \p id, or nullptr if this codec does not know it.
const MessageSpec* findMessage(std::uint32_t id);

/// CRC-16/MCRF4XX (X.25 polynomial reflected, initial 0xFFFF, no final xor): accumulates \p byte into \p crc.
inline std::uint16_t crcAccumulate(std::uint8_t byte, std::uint16_t crc)
{
  std::uint8_t mixed = static_cast<std::uint8_t>(byte ^ (crc & 0xFF));
  mixed = static_cast<std::uint8_t>(mixed ^ (mixed << 4));
  return static_cast<std::uint16_t>((crc >> 8) ^ (mixed << 8) ^ (mixed << 3) ^ (mixed >> 4));
}
std::uint16_t crc16(const std::uint8_t* data, std::size_t size, std::uint16_t crc = 0xFFFF);

/// Who sends a frame, and its sequence number.
struct FrameHeader
{
  std::uint8_t sequence = 0;
  std::uint8_t system_id = 0;
  std::uint8_t component_id = 0;
};

/// One received frame: its header, its message and the payload zero-filled to the full length.
struct Frame
{
  FrameHeader header;
  std::uint32_t message_id = 0;
  std::uint8_t incompat_flags = 0;
  std::uint8_t wire_length = 0;  ///< payload bytes on the wire (after truncation)
  Payload payload{};
};

/// An encoded frame, ready to send.
struct EncodedFrame
{
  std::array<std::uint8_t, MAX_FRAME> bytes{};
  std::size_t size = 0;

  const std::uint8_t* data() const
  {
    return bytes.data();
  }
};

/**
 * \brief Frames message \p spec with the first \p length bytes of \p payload: trailing zero bytes are cut (one byte
 * always stays), no incompat or compat flags, no signature.
 */
EncodedFrame encodeFrame(const FrameHeader& header, const MessageSpec& spec, const std::uint8_t* payload,
                         std::size_t length);

/// Why the parser dropped bytes or a frame.
enum class FrameError
{
  BAD_CHECKSUM,     ///< a known message whose checksum does not match (or noise that looked like a frame start)
  UNKNOWN_MESSAGE,  ///< a frame of a message this codec does not know, skipped whole
  BAD_INCOMPAT,     ///< incompat flags other than "signed": a frame no receiver may interpret
  MAVLINK1,         ///< a MAVLink 1 frame (0xFE), checked and skipped
  NOISE,            ///< bytes between frames that start none
};
constexpr std::size_t FRAME_ERROR_COUNT = 5;
const char* toString(FrameError error);

/// The parser's own tally.
struct ParserCounts
{
  std::uint64_t frames = 0;  ///< good frames handed out
  std::uint64_t signed_frames = 0;
  std::array<std::uint64_t, FRAME_ERROR_COUNT> errors{};  ///< indexed by FrameError
  std::uint64_t noise_bytes = 0;                          ///< bytes skipped while resynchronising
};

/**
 * \brief Cuts MAVLink 2 frames out of a byte stream (a serial line) or out of datagrams (UDP), and checks them.
 *
 * A frame that fails its check costs only its start byte: the parser looks for the next 0xFD after it, so a good
 * frame after garbage or after a damaged one is never lost. A frame of an unknown message cannot be checked; it is
 * skipped whole when the byte after it starts another frame, and treated as noise otherwise (so the parser may wait
 * for one more byte before deciding).
 */
class FrameParser
{
public:
  /// Feeds \p size bytes; calls \p on_frame(const Frame&) for every good frame, in order.
  template <class OnFrame>
  void feed(const std::uint8_t* data, std::size_t size, OnFrame&& on_frame)
  {
    for (std::size_t index = 0; index < size; ++index)
    {
      buffer_[buffered_++] = data[index];
      if (buffered_ == buffer_.size())
      {
        parseBuffered(on_frame);
      }
    }
    parseBuffered(on_frame);
  }
  /// Forgets a partial frame (the link closed).
  void reset()
  {
    buffered_ = 0;
  }
  const ParserCounts& counts() const
  {
    return counts_;
  }

private:
  /// The outcome of looking at the frame at the start of the buffer.
  enum class Step
  {
    NEED_MORE,
    FRAME,  ///< frame_ holds a good frame of consumed bytes
    SKIP,   ///< drop consumed bytes
  };

  template <class OnFrame>
  void parseBuffered(OnFrame& on_frame)
  {
    std::size_t start = 0;
    while (start < buffered_)
    {
      std::size_t consumed = 0;
      const Step step = examine(buffer_.data() + start, buffered_ - start, consumed);
      if (step == Step::NEED_MORE)
      {
        break;
      }
      if (step == Step::FRAME)
      {
        on_frame(static_cast<const Frame&>(frame_));
      }
      start += consumed;
    }
    if (start > 0)
    {
      std::copy(buffer_.begin() + static_cast<std::ptrdiff_t>(start),
                buffer_.begin() + static_cast<std::ptrdiff_t>(buffered_), buffer_.begin());
      buffered_ -= start;
    }
  }

  Step examine(const std::uint8_t* bytes, std::size_t size, std::size_t& consumed);
  Step examineV1(const std::uint8_t* bytes, std::size_t size, std::size_t& consumed);

  std::array<std::uint8_t, 2 * MAX_FRAME> buffer_{};
  std::size_t buffered_ = 0;
  Frame frame_;
  ParserCounts counts_;
};

}  // namespace mavlink
}  // namespace ptz_action_server

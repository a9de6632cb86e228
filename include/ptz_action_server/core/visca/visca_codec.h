/**
 * \file
 * \brief Sony VISCA: command packets `8x ... FF`, the replies (`z0 4y FF` ACK, `z0 5y FF` completion, `z0 50 ... FF`
 * inquiry answers, `z0 6y ee FF` errors), a stream splitter that finds packets among garbage, and VISCA over IP's
 * 8-byte header.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ptz_action_server
{
namespace visca
{
using Packet = std::vector<std::uint8_t>;

constexpr std::uint8_t TERMINATOR = 0xFF;
constexpr std::uint8_t BROADCAST = 0x88;  ///< the header byte of a broadcast (address set, IF_Clear)
constexpr std::size_t MIN_PACKET = 3;
/// VISCA's packets are 16 bytes at most, but Sony's 5 + 5 nibble models send 17: the absolute move of the
/// SRG-360SHE, ILME-FR7 and BRC-AM7 (`8x 01 06 02 vv ww` + 10 nibbles + FF), their pan-tilt limit set.
constexpr std::size_t MAX_PACKET = 17;
constexpr std::uint16_t SONY_IP_PORT = 52381;

/// The error codes of `z0 6y ee FF`.
enum ErrorCode : std::uint8_t
{
  MESSAGE_LENGTH = 0x01,
  SYNTAX = 0x02,
  BUFFER_FULL = 0x03,
  CANCELLED = 0x04,
  NO_SOCKET = 0x05,
  NOT_EXECUTABLE = 0x41,
};
/// "syntax error", "command buffer full", ... ("error 0x42" for a code VISCA does not define).
std::string errorName(std::uint8_t code);

/**
 * \brief How a model writes pan-tilt positions: 4 or 5 nibbles for pan and for tilt (two's complement, 16 or 20 bits),
 * and the speed bytes of the absolute and relative moves.
 *
 * Sony's BRC-X1000/H800 send pan as 5 nibbles and tilt as 4; the ILME-FR7, BRC-AM7 and SRG-360SHE 5 and 5; the older
 * models and most copies 4 and 4. The BRC-X400 and SRG-360SHE take one speed for both axes (`vv 00`).
 */
struct PositionLayout
{
  std::uint8_t pan_nibbles = 4;
  std::uint8_t tilt_nibbles = 4;
  bool shared_speed = false;  ///< `vv 00`: one speed byte, then 00

  /// The largest position \p nibbles nibbles hold (two's complement): 32767 or 524287.
  static std::int32_t limit(std::uint8_t nibbles)
  {
    return (std::int32_t(1) << (4 * nibbles - 1)) - 1;
  }
  /// The bytes of the position inquiry's answer between `z0 50` and FF.
  std::size_t answerSize() const
  {
    return std::size_t(pan_nibbles) + tilt_nibbles;
  }
  bool operator==(const PositionLayout& other) const
  {
    return pan_nibbles == other.pan_nibbles && tilt_nibbles == other.tilt_nibbles && shared_speed == other.shared_speed;
  }
};

// ---------------------------------------------------------------- commands (address 1..7)
Packet addressSet();  ///< `88 30 01 FF`
Packet ifClear();     ///< `88 01 00 01 FF` (broadcast)
/// `8x 01 06 01 VV WW 0Y 0Z FF`; \p pan and \p tilt in the contract's sign (> 0 right / up, 0 stop).
Packet panTiltDrive(std::uint8_t address, std::uint8_t pan_speed, std::uint8_t tilt_speed, int pan, int tilt);
/// `8x 01 06 02 VV WW 0p.. 0t.. FF` (\p relative: `.. 06 03 ..`), positions in steps, two's complement, as many
/// nibbles as \p layout says (4 + 4 by default); `VV 00` where the layout shares one speed.
Packet panTiltPosition(std::uint8_t address, std::uint8_t pan_speed, std::uint8_t tilt_speed, std::int32_t pan,
                       std::int32_t tilt, const PositionLayout& layout = PositionLayout(), bool relative = false);
Packet panTiltHome(std::uint8_t address);     ///< `8x 01 06 04 FF`
Packet panTiltInquiry(std::uint8_t address);  ///< `8x 09 06 12 FF`
Packet zoomStop(std::uint8_t address);        ///< `8x 01 04 07 00 FF`
/// `8x 01 04 07 2p FF` (tele, \p speed > 0) or `3p` (wide, < 0), p = |speed| - 1 in 0..7; 0 stops.
Packet zoomDrive(std::uint8_t address, int speed);
/// The standard (fixed speed) zoom: `8x 01 04 07 02 FF` (tele, \p direction > 0), `03` (wide, < 0); 0 stops.
Packet zoomDriveStandard(std::uint8_t address, int direction);
/// A zoom drive at a variable speed (`2p`, `3p`), which some cameras refuse with a syntax error.
bool isVariableZoomDrive(const Packet& packet);
Packet zoomDirect(std::uint8_t address, std::uint16_t position);  ///< `8x 01 04 47 0p 0q 0r 0s FF`
Packet zoomInquiry(std::uint8_t address);                         ///< `8x 09 04 47 FF`
Packet cancel(std::uint8_t address, std::uint8_t socket);         ///< `8x 2y FF`
Packet ifClearAddressed(std::uint8_t address);                    ///< `8x 01 00 01 FF` (answered `z0 50 FF`)
Packet versionInquiry(std::uint8_t address);                      ///< `8x 09 00 02 FF`
Packet powerInquiry(std::uint8_t address);                        ///< `8x 09 04 00 FF`

/// \p value as \p count nibbles, most significant first, one a byte (`0p 0p ...`), appended to \p out.
void putNibbles(Packet& out, std::uint32_t value, std::size_t count);
/// \p count nibbles from \p in (only the low nibble of each byte counts).
std::uint32_t getNibbles(const std::uint8_t* in, std::size_t count);
/// \p count nibbles from \p in as a two's complement number of 4 x \p count bits.
std::int32_t getSignedNibbles(const std::uint8_t* in, std::size_t count);

// ---------------------------------------------------------------- what a camera (or a controller) sends
/// What a packet is, read by its first bytes.
struct Reply
{
  enum class Kind
  {
    ACK,             ///< `z0 4y FF`
    COMPLETION,      ///< `z0 5y FF`, y = 1..: a command's socket is done
    ANSWER,          ///< `z0 50 ... FF`: an inquiry's answer (data holds the bytes between)
    ERROR,           ///< `z0 6y ee FF`
    ADDRESS_SET,     ///< `88 30 0w FF`: the next free address is w
    IF_CLEAR,        ///< `88 01 00 01 FF`, echoed
    NETWORK_CHANGE,  ///< `z0 38 FF`: a camera joined or left the chain
    OTHER,           ///< well formed, but none of the above
  };
  Kind kind = Kind::OTHER;
  std::uint8_t address = 0;  ///< the sender (z - 8), 0 for a broadcast
  std::uint8_t socket = 0;
  std::uint8_t error = 0;  ///< ERROR only
  Packet data;             ///< ANSWER: the bytes between `z0 50` and FF; ADDRESS_SET: w
};
/// Classifies a packet from a camera (start byte to terminator).
Reply classify(const Packet& packet);

/// An inquiry answer's position: pan and tilt in steps (signed, as many nibbles as \p layout says), or the zoom
/// position. False if the size is wrong.
bool decodePanTiltAnswer(const Reply& reply, const PositionLayout& layout, std::int32_t& pan, std::int32_t& tilt);
bool decodeZoomAnswer(const Reply& reply, std::uint16_t& position);

/// What the splitter has thrown away, and what it has read. Every byte fed is in exactly one count (or pending).
struct SplitterCounters
{
  std::uint64_t packets = 0;
  std::uint64_t packet_bytes = 0;
  std::uint64_t skipped_bytes = 0;   ///< bytes outside any packet (noise before a start byte)
  std::uint64_t broken_packets = 0;  ///< a start byte whose packet never ended (a new start came, or > 17 bytes)
  std::uint64_t broken_bytes = 0;
};

/**
 * \brief Finds VISCA packets in a byte stream: a start byte (0x80..0xFE), bytes below 0x80, the terminator FF.
 *
 * Bytes outside packets are skipped; a packet that meets a new start byte, or grows past 17 bytes, is dropped and the
 * search goes on from the new start byte, so one broken packet never hides the next. How the stream is split never
 * changes what is read.
 */
class PacketSplitter
{
public:
  void feed(const std::uint8_t* data, std::size_t size, std::vector<Packet>& packets);
  /// Drops a partial packet (after a reconnect or a timeout); its bytes count as broken.
  void reset();
  std::size_t pending() const
  {
    return partial_.size();
  }
  const SplitterCounters& counters() const
  {
    return counters_;
  }

private:
  void dropPartial();

  Packet partial_;
  SplitterCounters counters_;
};

// ---------------------------------------------------------------- VISCA over IP (Sony): the 8-byte header
constexpr std::size_t IP_HEADER_SIZE = 8;
enum PayloadType : std::uint16_t
{
  IP_COMMAND = 0x0100,
  IP_INQUIRY = 0x0110,
  IP_REPLY = 0x0111,
  IP_DEVICE_SETTING = 0x0120,  ///< the broadcasts (address set, IF_Clear), answered as IP_REPLY
  IP_CONTROL = 0x0200,
  IP_CONTROL_REPLY = 0x0201,
};
/// Control payloads: RESET (and its acknowledgement), the errors a control reply carries.
constexpr std::uint8_t CONTROL_RESET = 0x01;
constexpr std::uint8_t CONTROL_ERROR = 0x0F;
constexpr std::uint8_t CONTROL_SEQUENCE_ERROR = 0x01;  ///< `0F 01`: a sequence number out of order
constexpr std::uint8_t CONTROL_MESSAGE_ERROR = 0x02;   ///< `0F 02`: a message the camera could not read

struct IpMessage
{
  std::uint16_t type = IP_COMMAND;
  std::uint32_t sequence = 0;
  Packet payload;
};
/// Header (type, payload length, sequence, all big-endian) then the payload.
Packet encodeIp(const IpMessage& message);
/// Why a datagram is no VISCA over IP message.
enum class IpError
{
  NONE,
  TOO_SHORT,        ///< fewer than 8 + 1 bytes
  LENGTH_MISMATCH,  ///< the header's length is not the datagram's
  UNKNOWN_TYPE,
};
const char* toString(IpError error);
/// One datagram as one message. \p message keeps the header's sequence number when only the rest is wrong (a camera
/// answers an error with the sequence number of the message it refuses).
IpError decodeIp(const std::uint8_t* data, std::size_t size, IpMessage& message);
/// The control message that resets the camera's sequence number: `02 00 00 01 seq 01`.
Packet sequenceReset(std::uint32_t sequence);

/// \p bytes as "81 01 06 02 ..." (for messages).
std::string toHex(const Packet& bytes);

}  // namespace visca
}  // namespace ptz_action_server

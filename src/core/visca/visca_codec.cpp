#include "ptz_action_server/core/visca/visca_codec.h"

#include <algorithm>
#include <cstdio>

#include "ptz_action_server/core/byte_order.h"

namespace ptz_action_server
{
namespace visca
{
namespace
{
constexpr std::uint8_t COMMAND = 0x01;
constexpr std::uint8_t INQUIRY = 0x09;
constexpr std::uint8_t PAN_TILTER = 0x06;
constexpr std::uint8_t CAMERA = 0x04;

std::uint8_t header(std::uint8_t address)
{
  return static_cast<std::uint8_t>(0x80 | (address & 0x07));
}

/// VISCA's direction byte: pan 01 left, 02 right; tilt 01 up, 02 down; 03 stop.
std::uint8_t panDirection(int pan)
{
  return pan > 0 ? 0x02 : (pan < 0 ? 0x01 : 0x03);
}
std::uint8_t tiltDirection(int tilt)
{
  return tilt > 0 ? 0x01 : (tilt < 0 ? 0x02 : 0x03);
}

bool isStart(std::uint8_t byte)
{
  return byte >= 0x80 && byte != TERMINATOR;
}
}  // namespace

std::string errorName(std::uint8_t code)
{
  switch (code)
  {
    case MESSAGE_LENGTH:
      return "message length error";
    case SYNTAX:
      return "syntax error";
    case BUFFER_FULL:
      return "command buffer full";
    case CANCELLED:
      return "command cancelled";
    case NO_SOCKET:
      return "no socket";
    case NOT_EXECUTABLE:
      return "command not executable";
    default: {
      char text[16];
      std::snprintf(text, sizeof(text), "error 0x%02X", code);
      return text;
    }
  }
}

void putNibbles(Packet& out, std::uint32_t value, std::size_t count)
{
  for (std::size_t index = count; index-- > 0;)
  {
    out.push_back(static_cast<std::uint8_t>((value >> (4 * index)) & 0x0F));
  }
}

std::uint32_t getNibbles(const std::uint8_t* in, std::size_t count)
{
  std::uint32_t value = 0;
  for (std::size_t index = 0; index < count; ++index)
  {
    value = (value << 4) | (in[index] & 0x0Fu);
  }
  return value;
}

std::int32_t getSignedNibbles(const std::uint8_t* in, std::size_t count)
{
  const std::uint32_t value = getNibbles(in, count);
  const std::uint32_t sign = std::uint32_t(1) << (4 * count - 1);
  return static_cast<std::int32_t>(value & (sign - 1)) - static_cast<std::int32_t>(value & sign);
}

Packet addressSet()
{
  return { BROADCAST, 0x30, 0x01, TERMINATOR };
}

Packet ifClear()
{
  return { BROADCAST, 0x01, 0x00, 0x01, TERMINATOR };
}

Packet panTiltDrive(std::uint8_t address, std::uint8_t pan_speed, std::uint8_t tilt_speed, int pan, int tilt)
{
  return { header(address), COMMAND,           PAN_TILTER,          0x01,      pan_speed,
           tilt_speed,      panDirection(pan), tiltDirection(tilt), TERMINATOR };
}

Packet panTiltPosition(std::uint8_t address, std::uint8_t pan_speed, std::uint8_t tilt_speed, std::int32_t pan,
                       std::int32_t tilt, const PositionLayout& layout, bool relative)
{
  Packet packet{ header(address), COMMAND,
                 PAN_TILTER,      static_cast<std::uint8_t>(relative ? 0x03 : 0x02),
                 pan_speed,       static_cast<std::uint8_t>(layout.shared_speed ? 0x00 : tilt_speed) };
  putNibbles(packet, static_cast<std::uint32_t>(pan), layout.pan_nibbles);
  putNibbles(packet, static_cast<std::uint32_t>(tilt), layout.tilt_nibbles);
  packet.push_back(TERMINATOR);
  return packet;
}

Packet panTiltHome(std::uint8_t address)
{
  return { header(address), COMMAND, PAN_TILTER, 0x04, TERMINATOR };
}

Packet panTiltInquiry(std::uint8_t address)
{
  return { header(address), INQUIRY, PAN_TILTER, 0x12, TERMINATOR };
}

Packet zoomStop(std::uint8_t address)
{
  return { header(address), COMMAND, CAMERA, 0x07, 0x00, TERMINATOR };
}

Packet zoomDrive(std::uint8_t address, int speed)
{
  if (speed == 0)
  {
    return zoomStop(address);
  }
  const int p = (speed > 0 ? speed : -speed) - 1;
  const std::uint8_t step = static_cast<std::uint8_t>(p < 0 ? 0 : (p > 7 ? 7 : p));
  return { header(address), COMMAND, CAMERA, 0x07, static_cast<std::uint8_t>((speed > 0 ? 0x20 : 0x30) | step),
           TERMINATOR };
}

Packet zoomDriveStandard(std::uint8_t address, int direction)
{
  if (direction == 0)
  {
    return zoomStop(address);
  }
  return { header(address), COMMAND, CAMERA, 0x07, static_cast<std::uint8_t>(direction > 0 ? 0x02 : 0x03), TERMINATOR };
}

bool isVariableZoomDrive(const Packet& packet)
{
  return packet.size() == 6 && (packet[0] & 0xF0) == 0x80 && packet[1] == COMMAND && packet[2] == CAMERA &&
         packet[3] == 0x07 && ((packet[4] & 0xF0) == 0x20 || (packet[4] & 0xF0) == 0x30);
}

Packet zoomDirect(std::uint8_t address, std::uint16_t position)
{
  Packet packet{ header(address), COMMAND, CAMERA, 0x47 };
  putNibbles(packet, position, 4);
  packet.push_back(TERMINATOR);
  return packet;
}

Packet zoomInquiry(std::uint8_t address)
{
  return { header(address), INQUIRY, CAMERA, 0x47, TERMINATOR };
}

Packet cancel(std::uint8_t address, std::uint8_t socket)
{
  return { header(address), static_cast<std::uint8_t>(0x20 | (socket & 0x0F)), TERMINATOR };
}

Packet ifClearAddressed(std::uint8_t address)
{
  return { header(address), COMMAND, 0x00, 0x01, TERMINATOR };
}

Packet versionInquiry(std::uint8_t address)
{
  return { header(address), INQUIRY, 0x00, 0x02, TERMINATOR };
}

Packet powerInquiry(std::uint8_t address)
{
  return { header(address), INQUIRY, CAMERA, 0x00, TERMINATOR };
}

Reply classify(const Packet& packet)
{
  Reply reply;
  if (packet.size() < MIN_PACKET || packet.back() != TERMINATOR)
  {
    return reply;
  }
  const std::uint8_t first = packet[0];
  const std::uint8_t second = packet[1];
  if (first == BROADCAST)
  {
    if (packet.size() == 4 && second == 0x30)
    {
      reply.kind = Reply::Kind::ADDRESS_SET;
      reply.data = { static_cast<std::uint8_t>(packet[2] & 0x0F) };
    }
    else if (packet == ifClear())
    {
      reply.kind = Reply::Kind::IF_CLEAR;
    }
    return reply;
  }
  if ((first & 0x0F) != 0 || first < 0x90)
  {
    return reply;  // not addressed to a controller (address 0)
  }
  reply.address = static_cast<std::uint8_t>((first >> 4) - 8);
  reply.socket = second & 0x0F;
  const std::size_t size = packet.size();
  switch (second & 0xF0)
  {
    case 0x40:
      reply.kind = size == 3 ? Reply::Kind::ACK : Reply::Kind::OTHER;
      break;
    case 0x50:
      if (size == 3 && reply.socket != 0)
      {
        reply.kind = Reply::Kind::COMPLETION;
      }
      else if (reply.socket == 0)
      {
        reply.kind = Reply::Kind::ANSWER;
        reply.data.assign(packet.begin() + 2, packet.end() - 1);
      }
      break;
    case 0x60:
      if (size == 4)
      {
        reply.kind = Reply::Kind::ERROR;
        reply.error = packet[2];
      }
      break;
    case 0x30:
      reply.kind = size == 3 && second == 0x38 ? Reply::Kind::NETWORK_CHANGE : Reply::Kind::OTHER;
      break;
    default:
      break;
  }
  return reply;
}

bool decodePanTiltAnswer(const Reply& reply, const PositionLayout& layout, std::int32_t& pan, std::int32_t& tilt)
{
  if (reply.kind != Reply::Kind::ANSWER || reply.data.size() != layout.answerSize())
  {
    return false;
  }
  pan = getSignedNibbles(reply.data.data(), layout.pan_nibbles);
  tilt = getSignedNibbles(reply.data.data() + layout.pan_nibbles, layout.tilt_nibbles);
  return true;
}

bool decodeZoomAnswer(const Reply& reply, std::uint16_t& position)
{
  if (reply.kind != Reply::Kind::ANSWER || reply.data.size() != 4)
  {
    return false;
  }
  position = static_cast<std::uint16_t>(getNibbles(reply.data.data(), 4));
  return true;
}

void PacketSplitter::feed(const std::uint8_t* data, std::size_t size, std::vector<Packet>& packets)
{
  for (std::size_t index = 0; index < size; ++index)
  {
    const std::uint8_t byte = data[index];
    if (partial_.empty())
    {
      if (isStart(byte))
      {
        partial_.push_back(byte);
      }
      else
      {
        ++counters_.skipped_bytes;
      }
      continue;
    }
    if (byte == TERMINATOR)
    {
      partial_.push_back(byte);
      if (partial_.size() < MIN_PACKET)
      {
        dropPartial();  // `8x FF`: nothing VISCA sends
        continue;
      }
      ++counters_.packets;
      counters_.packet_bytes += partial_.size();
      packets.push_back(std::move(partial_));
      partial_.clear();
      continue;
    }
    if (isStart(byte) || partial_.size() + 1 >= MAX_PACKET)
    {
      // A new packet begins (or this one cannot end in time): the partial one is lost.
      dropPartial();
      if (isStart(byte))
      {
        partial_.push_back(byte);
      }
      else
      {
        ++counters_.skipped_bytes;
      }
      continue;
    }
    partial_.push_back(byte);
  }
}

void PacketSplitter::dropPartial()
{
  ++counters_.broken_packets;
  counters_.broken_bytes += partial_.size();
  partial_.clear();
}

void PacketSplitter::reset()
{
  if (!partial_.empty())
  {
    dropPartial();
  }
}

Packet encodeIp(const IpMessage& message)
{
  Packet bytes(IP_HEADER_SIZE + message.payload.size());
  putBigEndian<std::uint16_t>(bytes.data(), message.type);
  putBigEndian<std::uint16_t>(bytes.data() + 2, static_cast<std::uint16_t>(message.payload.size()));
  putBigEndian<std::uint32_t>(bytes.data() + 4, message.sequence);
  std::copy(message.payload.begin(), message.payload.end(), bytes.begin() + IP_HEADER_SIZE);
  return bytes;
}

const char* toString(IpError error)
{
  switch (error)
  {
    case IpError::NONE:
      return "none";
    case IpError::TOO_SHORT:
      return "shorter than a header and one byte";
    case IpError::LENGTH_MISMATCH:
      return "payload length does not match the datagram";
    case IpError::UNKNOWN_TYPE:
      return "unknown payload type";
  }
  return "?";
}

IpError decodeIp(const std::uint8_t* data, std::size_t size, IpMessage& message)
{
  message = IpMessage{};
  if (size >= IP_HEADER_SIZE)
  {
    message.sequence = getBigEndian<std::uint32_t>(data + 4);
  }
  if (size < IP_HEADER_SIZE + 1)
  {
    return IpError::TOO_SHORT;
  }
  const std::uint16_t type = getBigEndian<std::uint16_t>(data);
  if (getBigEndian<std::uint16_t>(data + 2) != size - IP_HEADER_SIZE)
  {
    return IpError::LENGTH_MISMATCH;
  }
  if (type != IP_COMMAND && type != IP_INQUIRY && type != IP_REPLY && type != IP_DEVICE_SETTING && type != IP_CONTROL &&
      type != IP_CONTROL_REPLY)
  {
    return IpError::UNKNOWN_TYPE;
  }
  message.type = type;
  message.payload.assign(data + IP_HEADER_SIZE, data + size);
  return IpError::NONE;
}

Packet sequenceReset(std::uint32_t sequence)
{
  return encodeIp(IpMessage{ IP_CONTROL, sequence, { CONTROL_RESET } });
}

std::string toHex(const Packet& bytes)
{
  std::string text;
  for (std::uint8_t byte : bytes)
  {
    char digits[4];
    std::snprintf(digits, sizeof(digits), "%s%02X", text.empty() ? "" : " ", byte);
    text += digits;
  }
  return text;
}

}  // namespace visca
}  // namespace ptz_action_server

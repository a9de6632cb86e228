/**
 * \file
 * \brief The DigiView base message: the CRC, pack() and unpack() (the format table is digiview_formats.cpp, the
 * payloads digiview_payloads.cpp).
 */
#include "ptz_action_server/core/digiview/digiview_codec.h"

#include <algorithm>
#include <stdexcept>

#include "ptz_action_server/core/byte_order.h"

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
}  // namespace

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
  const Layout layout = layoutOf(format);
  std::uint8_t type = 0;
  if (!toWire(format, message_type, type))
  {
    throw std::invalid_argument(std::string("DigiView format ") + toString(format) + " has no " +
                                toString(message_type));
  }
  if (layout.interval_offset == 0 && interval_ms != 0)
  {
    throw std::invalid_argument(std::string("DigiView format ") + toString(format) + " has no interval_ms");
  }
  std::uint8_t param = 0;
  if (!paramToWire(format, param_type, param))
  {
    throw std::invalid_argument(std::string("DigiView format ") + toString(format) + " has no " + toString(param_type));
  }
  Bytes bytes(layout.size, 0);
  putLittleEndian(&bytes[0], timestamp);
  bytes[8] = version;
  bytes[9] = type;
  bytes[10] = param;
  if (layout.interval_offset != 0)
  {
    putLittleEndian(&bytes[layout.interval_offset], interval_ms);
  }
  std::copy(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(layout.data_size),
            bytes.begin() + static_cast<std::ptrdiff_t>(layout.data_offset));
  bytes[layout.checksum_offset] = crc8(bytes.data(), layout.checksum_offset);
  return bytes;
}

UnpackError Message::unpack(const std::uint8_t* bytes, std::size_t size, const Wire& wire, Message& message,
                            bool* unverified)
{
  message = Message();
  if (unverified != nullptr)
  {
    *unverified = false;
  }
  const Layout layout = layoutOf(wire.format);
  if (bytes == nullptr || size != layout.size)
  {
    return UnpackError::BAD_SIZE;
  }
  const std::uint8_t checksum = bytes[layout.checksum_offset];
  const bool verified = crc8(bytes, layout.checksum_offset) == checksum;
  const bool unfilled = !verified && checksum == 0 && wire.checksum == ChecksumRule::ZERO_ACCEPTED;
  if (!verified && !unfilled)
  {
    return UnpackError::BAD_CHECKSUM;
  }
  MessageType type = MessageType::EMPTY;
  ParamType param = ParamType::SYSTEM_STATUS;
  if (bytes[8] != VERSION)
  {
    return UnpackError::BAD_VERSION;
  }
  if (!fromWire(wire.format, bytes[9], type))
  {
    return UnpackError::BAD_MESSAGE_TYPE;
  }
  if (!paramFromWire(wire.format, bytes[10], param))
  {
    return UnpackError::BAD_PARAM_TYPE;
  }
  message.format = wire.format;
  message.angles = wire.angles;
  message.timestamp = getLittleEndian<std::uint64_t>(bytes);
  message.version = bytes[8];
  message.message_type = type;
  message.param_type = param;
  if (layout.interval_offset != 0)
  {
    message.interval_ms = getLittleEndian<std::uint32_t>(bytes + layout.interval_offset);
  }
  std::copy(bytes + layout.data_offset, bytes + layout.data_offset + layout.data_size, message.data.begin());
  if (unverified != nullptr)
  {
    *unverified = unfilled;
  }
  return UnpackError::NONE;
}

}  // namespace digiview
}  // namespace ptz_action_server

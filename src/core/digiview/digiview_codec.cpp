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

const char* toString(Format format)
{
  switch (format)
  {
    case Format::V0_5:
      return "0.5";
    case Format::V1_0:
      return "1.0";
    case Format::V1_1:
      return "1.1";
  }
  return "?";
}

bool parseFormat(const std::string& text, Format& format)
{
  for (Format candidate : FORMATS)
  {
    if (text == toString(candidate))
    {
      format = candidate;
      return true;
    }
  }
  return false;
}

Layout layoutOf(Format format)
{
  return format == Format::V0_5 ? Layout{ 80, 11, 75, 0 } : Layout{ 88, 16, 80, 12 };
}

const char* toString(ChecksumRule rule)
{
  return rule == ChecksumRule::ZERO_ACCEPTED ? "zero_accepted" : "required";
}

bool parseChecksumRule(const std::string& text, ChecksumRule& rule)
{
  if (text != "required" && text != "zero_accepted")
  {
    return false;
  }
  rule = text == "required" ? ChecksumRule::REQUIRED : ChecksumRule::ZERO_ACCEPTED;
  return true;
}

bool toWire(Format format, MessageType type, std::uint8_t& wire)
{
  const auto value = static_cast<std::uint8_t>(type);
  if (format == Format::V0_5 || value < static_cast<std::uint8_t>(MessageType::GET_INTERVAL) ||
      type == MessageType::QUIT)
  {
    wire = value;
    return true;
  }
  if (type == MessageType::GET_INTERVAL)
  {
    return false;
  }
  wire = static_cast<std::uint8_t>(value - 1);  // 1.0 removed GET_INTERVAL: the replies moved down by one (1.1 too)
  return true;
}

bool fromWire(Format format, std::uint8_t wire, MessageType& type)
{
  const auto last = static_cast<std::uint8_t>(MessageType::UNKNOWN);
  if (wire == static_cast<std::uint8_t>(MessageType::QUIT) ||
      wire < static_cast<std::uint8_t>(MessageType::GET_INTERVAL))
  {
    type = static_cast<MessageType>(wire);
    return true;
  }
  if (format == Format::V0_5 && wire <= last)
  {
    type = static_cast<MessageType>(wire);
    return true;
  }
  if (format != Format::V0_5 && wire < last)
  {
    type = static_cast<MessageType>(wire + 1);
    return true;
  }
  return false;
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
  Bytes bytes(layout.size, 0);
  putLittleEndian(&bytes[0], timestamp);
  bytes[8] = version;
  bytes[9] = type;
  bytes[10] = static_cast<std::uint8_t>(param_type);
  if (layout.interval_offset != 0)
  {
    putLittleEndian(&bytes[layout.interval_offset], interval_ms);
  }
  std::copy(data.begin(), data.end(), bytes.begin() + static_cast<std::ptrdiff_t>(layout.data_offset));
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
  if (bytes[8] != VERSION)
  {
    return UnpackError::BAD_VERSION;
  }
  if (!fromWire(wire.format, bytes[9], type))
  {
    return UnpackError::BAD_MESSAGE_TYPE;
  }
  if (!isParamType(bytes[10]))
  {
    return UnpackError::BAD_PARAM_TYPE;
  }
  message.format = wire.format;
  message.timestamp = getLittleEndian<std::uint64_t>(bytes);
  message.version = bytes[8];
  message.message_type = type;
  message.param_type = static_cast<ParamType>(bytes[10]);
  if (layout.interval_offset != 0)
  {
    message.interval_ms = getLittleEndian<std::uint32_t>(bytes + layout.interval_offset);
  }
  std::copy(bytes + layout.data_offset, bytes + layout.data_offset + DATA_SIZE, message.data.begin());
  if (unverified != nullptr)
  {
    *unverified = unfilled;
  }
  return UnpackError::NONE;
}

}  // namespace digiview
}  // namespace ptz_action_server

#include "ptz_action_server/core/digiview/digiview_codec.h"

#include <algorithm>

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

}  // namespace digiview
}  // namespace ptz_action_server

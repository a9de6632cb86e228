#include "ptz_action_server/core/mavlink/mavlink_codec.h"

#include <algorithm>

#include "ptz_action_server/core/byte_order.h"
#include "ptz_action_server/core/mavlink/mavlink_messages.h"
#include "ptz_action_server/core/mavlink/mavlink_vehicle_messages.h"

namespace ptz_action_server
{
namespace mavlink
{
namespace
{
// CRC_EXTRA and full payload length (extensions included) of every message this codec checks (protocols.md §9).
// The messages no one here decodes are known for their CRC_EXTRA only; their length is the wire's.
constexpr MessageSpec MESSAGES[] = {
  { message_id::HEARTBEAT, "HEARTBEAT", 50, 9 },
  { message_id::ATTITUDE, "ATTITUDE", 39, 28 },
  { message_id::COMMAND_INT, "COMMAND_INT", 158, 0 },
  { message_id::COMMAND_LONG, "COMMAND_LONG", 152, 33 },
  { message_id::COMMAND_ACK, "COMMAND_ACK", 143, 10 },
  { message_id::MOUNT_STATUS, "MOUNT_STATUS", 134, 15 },
  { message_id::MOUNT_ORIENTATION, "MOUNT_ORIENTATION", 26, 20 },
  { message_id::GIMBAL_MANAGER_INFORMATION, "GIMBAL_MANAGER_INFORMATION", 70, 33 },
  { message_id::GIMBAL_MANAGER_STATUS, "GIMBAL_MANAGER_STATUS", 48, 13 },
  { message_id::GIMBAL_MANAGER_SET_ATTITUDE, "GIMBAL_MANAGER_SET_ATTITUDE", 123, 35 },
  { message_id::GIMBAL_DEVICE_INFORMATION, "GIMBAL_DEVICE_INFORMATION", 74, 0 },
  { message_id::GIMBAL_DEVICE_SET_ATTITUDE, "GIMBAL_DEVICE_SET_ATTITUDE", 99, 0 },
  { message_id::GIMBAL_DEVICE_ATTITUDE_STATUS, "GIMBAL_DEVICE_ATTITUDE_STATUS", 137, 49 },
  { message_id::AUTOPILOT_STATE_FOR_GIMBAL_DEVICE, "AUTOPILOT_STATE_FOR_GIMBAL_DEVICE", 210, 0 },
  { message_id::GIMBAL_MANAGER_SET_PITCHYAW, "GIMBAL_MANAGER_SET_PITCHYAW", 1, 23 },
  { message_id::GIMBAL_MANAGER_SET_MANUAL_CONTROL, "GIMBAL_MANAGER_SET_MANUAL_CONTROL", 20, 0 },
};

bool startsFrame(std::uint8_t byte)
{
  return byte == STX_V2 || byte == STX_V1;
}
}  // namespace

const MessageSpec* findMessage(std::uint32_t id)
{
  for (const MessageSpec& spec : MESSAGES)
  {
    if (spec.id == id)
    {
      return &spec;
    }
  }
  return nullptr;
}

std::uint16_t crc16(const std::uint8_t* data, std::size_t size, std::uint16_t crc)
{
  for (std::size_t index = 0; index < size; ++index)
  {
    crc = crcAccumulate(data[index], crc);
  }
  return crc;
}

EncodedFrame encodeFrame(const FrameHeader& header, const MessageSpec& spec, const std::uint8_t* payload,
                         std::size_t length)
{
  length = std::min(length, MAX_PAYLOAD);
  while (length > 1 && payload[length - 1] == 0)
  {
    --length;  // MAVLink 2 payload truncation: the receiver fills the zeros back in
  }
  length = std::max<std::size_t>(length, 1);

  EncodedFrame frame;
  std::uint8_t* out = frame.bytes.data();
  out[0] = STX_V2;
  out[1] = static_cast<std::uint8_t>(length);
  out[2] = 0;  // incompat flags
  out[3] = 0;  // compat flags
  out[4] = header.sequence;
  out[5] = header.system_id;
  out[6] = header.component_id;
  out[7] = static_cast<std::uint8_t>(spec.id);
  out[8] = static_cast<std::uint8_t>(spec.id >> 8);
  out[9] = static_cast<std::uint8_t>(spec.id >> 16);
  std::copy(payload, payload + length, out + HEADER_SIZE);
  std::uint16_t crc = crc16(out + 1, HEADER_SIZE - 1 + length);
  crc = crcAccumulate(spec.crc_extra, crc);
  putLittleEndian<std::uint16_t>(out + HEADER_SIZE + length, crc);
  frame.size = HEADER_SIZE + length + CHECKSUM_SIZE;
  return frame;
}

const char* toString(FrameError error)
{
  switch (error)
  {
    case FrameError::BAD_CHECKSUM:
      return "bad_checksum";
    case FrameError::UNKNOWN_MESSAGE:
      return "unknown_message";
    case FrameError::BAD_INCOMPAT:
      return "bad_incompat_flags";
    case FrameError::MAVLINK1:
      return "mavlink1";
    case FrameError::NOISE:
      return "noise";
  }
  return "?";
}

FrameParser::Step FrameParser::examine(const std::uint8_t* bytes, std::size_t size, std::size_t& consumed)
{
  if (bytes[0] == STX_V1)
  {
    return examineV1(bytes, size, consumed);
  }
  if (bytes[0] != STX_V2)
  {
    // Garbage between frames: skip it up to the next byte that may start one, as one NOISE event.
    consumed = 1;
    while (consumed < size && !startsFrame(bytes[consumed]))
    {
      ++consumed;
    }
    ++counts_.errors[static_cast<std::size_t>(FrameError::NOISE)];
    counts_.noise_bytes += consumed;
    return Step::SKIP;
  }
  if (size < HEADER_SIZE)
  {
    return Step::NEED_MORE;
  }
  const std::uint8_t length = bytes[1];
  const std::uint8_t incompat = bytes[2];
  if ((incompat & ~INCOMPAT_SIGNED) != 0)
  {
    ++counts_.errors[static_cast<std::size_t>(FrameError::BAD_INCOMPAT)];
    consumed = 1;
    return Step::SKIP;
  }
  const std::size_t total =
      HEADER_SIZE + length + CHECKSUM_SIZE + ((incompat & INCOMPAT_SIGNED) != 0 ? SIGNATURE_SIZE : 0);
  const std::uint32_t id = static_cast<std::uint32_t>(bytes[7]) | (static_cast<std::uint32_t>(bytes[8]) << 8) |
                           (static_cast<std::uint32_t>(bytes[9]) << 16);
  const MessageSpec* spec = findMessage(id);
  if (spec == nullptr)
  {
    // Nothing to check it by: believe the length only if another frame starts right after it.
    if (size < total + 1)
    {
      return Step::NEED_MORE;
    }
    if (startsFrame(bytes[total]))
    {
      ++counts_.errors[static_cast<std::size_t>(FrameError::UNKNOWN_MESSAGE)];
      consumed = total;
    }
    else
    {
      ++counts_.errors[static_cast<std::size_t>(FrameError::NOISE)];
      ++counts_.noise_bytes;
      consumed = 1;
    }
    return Step::SKIP;
  }
  if (size < total)
  {
    return Step::NEED_MORE;
  }
  std::uint16_t crc = crc16(bytes + 1, HEADER_SIZE - 1 + length);
  crc = crcAccumulate(spec->crc_extra, crc);
  if (crc != getLittleEndian<std::uint16_t>(bytes + HEADER_SIZE + length))
  {
    ++counts_.errors[static_cast<std::size_t>(FrameError::BAD_CHECKSUM)];
    consumed = 1;  // resynchronise on the next start byte after this one
    return Step::SKIP;
  }
  frame_.header.sequence = bytes[4];
  frame_.header.system_id = bytes[5];
  frame_.header.component_id = bytes[6];
  frame_.message_id = id;
  frame_.incompat_flags = incompat;
  frame_.wire_length = length;
  frame_.payload.fill(0);
  std::copy(bytes + HEADER_SIZE, bytes + HEADER_SIZE + length, frame_.payload.begin());
  ++counts_.frames;
  if ((incompat & INCOMPAT_SIGNED) != 0)
  {
    ++counts_.signed_frames;
  }
  consumed = total;
  return Step::FRAME;
}

FrameParser::Step FrameParser::examineV1(const std::uint8_t* bytes, std::size_t size, std::size_t& consumed)
{
  // `FE len seq sysid compid msgid payload crc`: skipped whole when its checksum proves it is one, noise otherwise.
  if (size < V1_HEADER_SIZE)
  {
    return Step::NEED_MORE;
  }
  const std::uint8_t length = bytes[1];
  const MessageSpec* spec = findMessage(bytes[5]);
  const std::size_t total = V1_HEADER_SIZE + length + CHECKSUM_SIZE;
  if (spec != nullptr)
  {
    if (size < total)
    {
      return Step::NEED_MORE;
    }
    std::uint16_t crc = crc16(bytes + 1, V1_HEADER_SIZE - 1 + length);
    crc = crcAccumulate(spec->crc_extra, crc);
    if (crc == getLittleEndian<std::uint16_t>(bytes + V1_HEADER_SIZE + length))
    {
      ++counts_.errors[static_cast<std::size_t>(FrameError::MAVLINK1)];
      consumed = total;
      return Step::SKIP;
    }
  }
  ++counts_.errors[static_cast<std::size_t>(FrameError::NOISE)];
  ++counts_.noise_bytes;
  consumed = 1;
  return Step::SKIP;
}

}  // namespace mavlink
}  // namespace ptz_action_server

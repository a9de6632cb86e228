/**
 * \file
 * \brief libFuzzer target: the MAVLink 2 frame parser on arbitrary bytes, fed whole and in arbitrary pieces, and
 * the gimbal messages decoded from whatever it hands out.
 */
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "ptz_action_server/core/mavlink/mavlink_messages.h"

using namespace ptz_action_server::mavlink;

namespace
{
void decodeKnown(const Frame& frame)
{
  switch (frame.message_id)
  {
    case message_id::HEARTBEAT:
      (void)decode<Heartbeat>(frame);
      break;
    case message_id::COMMAND_LONG:
      (void)decode<CommandLong>(frame);
      break;
    case message_id::COMMAND_ACK:
      (void)toString(decode<CommandAck>(frame).result);
      break;
    case message_id::GIMBAL_MANAGER_INFORMATION:
      (void)decode<GimbalManagerInformation>(frame);
      break;
    case message_id::GIMBAL_MANAGER_STATUS:
      (void)decode<GimbalManagerStatus>(frame);
      break;
    case message_id::GIMBAL_MANAGER_SET_ATTITUDE:
      (void)decode<GimbalManagerSetAttitude>(frame);
      break;
    case message_id::GIMBAL_DEVICE_ATTITUDE_STATUS:
      (void)panTiltFromQuaternion(decode<GimbalDeviceAttitudeStatus>(frame).q);
      break;
    case message_id::GIMBAL_MANAGER_SET_PITCHYAW:
      (void)decode<GimbalManagerSetPitchYaw>(frame);
      break;
    default:
      break;
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const std::size_t piece = 1 + data[0] % 29;
  FrameParser whole;
  FrameParser pieces;
  std::vector<Frame> from_whole;
  std::vector<Frame> from_pieces;
  whole.feed(data + 1, size - 1, [&](const Frame& frame) { from_whole.push_back(frame); });
  for (std::size_t offset = 1; offset < size; offset += piece)
  {
    pieces.feed(data + offset, std::min(piece, size - offset),
                [&](const Frame& frame) { from_pieces.push_back(frame); });
  }
  if (from_whole.size() != from_pieces.size())
  {
    std::abort();
  }
  for (std::size_t index = 0; index < from_whole.size(); ++index)
  {
    const Frame& frame = from_whole[index];
    const Frame& other = from_pieces[index];
    if (frame.message_id != other.message_id || frame.payload != other.payload ||
        frame.header.sequence != other.header.sequence || frame.wire_length != other.wire_length)
    {
      std::abort();
    }
    // Only known messages come out, zero-filled past the bytes on the wire.
    const MessageSpec* spec = findMessage(frame.message_id);
    if (spec == nullptr)
    {
      std::abort();
    }
    for (std::size_t byte = frame.wire_length; byte < frame.payload.size(); ++byte)
    {
      if (frame.payload[byte] != 0)
      {
        std::abort();
      }
    }
    decodeKnown(frame);
    // Framed again, it parses back to the same payload.
    const EncodedFrame again = encodeFrame(frame.header, *spec, frame.payload.data(), frame.wire_length);
    FrameParser check;
    std::size_t frames = 0;
    check.feed(again.data(), again.size, [&](const Frame& back) {
      ++frames;
      if (back.payload != frame.payload || back.message_id != frame.message_id)
      {
        std::abort();
      }
    });
    if (frames != 1)
    {
      std::abort();
    }
  }
  if (whole.counts().frames != from_whole.size())
  {
    std::abort();
  }
  return 0;
}

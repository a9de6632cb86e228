/**
 * \file
 * \brief libFuzzer target: the VISCA packet splitter and reply classifier on arbitrary bytes, fed in arbitrary pieces,
 * and the VISCA over IP header decoder on the same bytes.
 */
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "ptz_action_server/core/visca/visca_codec.h"

using namespace ptz_action_server::visca;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  // First byte: the piece size; the rest is the stream.
  const std::size_t piece = 1 + data[0] % 17;
  const std::uint8_t* stream = data + 1;
  const std::size_t length = size - 1;
  PacketSplitter whole;
  PacketSplitter pieces;
  std::vector<Packet> from_whole;
  std::vector<Packet> from_pieces;
  whole.feed(stream, length, from_whole);
  for (std::size_t offset = 0; offset < length; offset += piece)
  {
    pieces.feed(stream + offset, std::min(piece, length - offset), from_pieces);
  }
  // The same bytes split differently read the same.
  if (from_whole != from_pieces || whole.pending() != pieces.pending())
  {
    std::abort();
  }
  for (const Packet& packet : from_whole)
  {
    // Every packet is a start byte, bytes below 0x80, the terminator, 3..17 bytes.
    if (packet.size() < MIN_PACKET || packet.size() > MAX_PACKET || packet.front() < 0x80 ||
        packet.back() != TERMINATOR)
    {
      std::abort();
    }
    for (std::size_t index = 1; index + 1 < packet.size(); ++index)
    {
      if (packet[index] >= 0x80)
      {
        std::abort();
      }
    }
    const Reply reply = classify(packet);
    std::int32_t pan = 0;
    std::int32_t tilt = 0;
    std::uint16_t zoom = 0;
    // Every layout a model has: 4 + 4, 5 + 4, 5 + 5 nibbles; a position fits its nibbles.
    for (const PositionLayout layout :
         { PositionLayout{ 4, 4, false }, PositionLayout{ 5, 4, false }, PositionLayout{ 5, 5, true } })
    {
      if (decodePanTiltAnswer(reply, layout, pan, tilt) &&
          (reply.data.size() != layout.answerSize() || pan > PositionLayout::limit(layout.pan_nibbles) ||
           pan < -PositionLayout::limit(layout.pan_nibbles) - 1 || tilt > PositionLayout::limit(layout.tilt_nibbles) ||
           tilt < -PositionLayout::limit(layout.tilt_nibbles) - 1))
      {
        std::abort();
      }
    }
    if (decodeZoomAnswer(reply, zoom) && reply.data.size() != 4)
    {
      std::abort();
    }
    (void)errorName(reply.error);
  }
  // Every byte is accounted for: in a packet, skipped, in a broken packet, or still waiting.
  const SplitterCounters& counters = whole.counters();
  if (counters.packet_bytes + counters.skipped_bytes + counters.broken_bytes + whole.pending() != length)
  {
    std::abort();
  }
  // The same bytes as a VISCA over IP datagram: what decodes encodes back to the same bytes.
  IpMessage message;
  if (decodeIp(stream, length, message) == IpError::NONE && encodeIp(message) != Packet(stream, stream + length))
  {
    std::abort();
  }
  return 0;
}

/**
 * \file
 * \brief libFuzzer target: the Pelco-D frame parser on arbitrary bytes, fed in arbitrary pieces.
 */
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "ptz_action_server/core/pelco_d/pelco_d_codec.h"

using namespace ptz_action_server::pelco;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 2)
  {
    return 0;
  }
  // First byte: piece size and general replies on or off; second: the address to accept (0 = any).
  const std::size_t piece = 1 + data[0] % 13;
  const bool general_replies = (data[0] & 0x80) != 0;
  FrameParser whole(data[1], general_replies);
  FrameParser pieces(data[1], general_replies);
  std::vector<FrameParser::Event> from_whole;
  std::vector<FrameParser::Event> from_pieces;
  whole.feed(data + 2, size - 2, from_whole);
  for (std::size_t offset = 2; offset < size; offset += piece)
  {
    pieces.feed(data + offset, std::min(piece, size - offset), from_pieces);
  }
  if (from_whole.size() != from_pieces.size())
  {
    std::abort();
  }
  for (std::size_t index = 0; index < from_whole.size(); ++index)
  {
    const FrameParser::Event& event = from_whole[index];
    if (event.general_reply != from_pieces[index].general_reply || !(event.frame == from_pieces[index].frame))
    {
      std::abort();
    }
    // Every frame handed out checks, and is for the address asked for.
    if (!event.general_reply &&
        ((data[1] != 0 && event.frame.address != data[1]) || encode(event.frame)[6] != checksum(event.frame)))
    {
      std::abort();
    }
  }
  // Every input byte is accounted for: in a frame, a reply, a drop, or still waiting (less than a frame).
  const ParserCounters& counters = whole.counters();
  const std::uint64_t accounted = (counters.frames + counters.wrong_address) * FRAME_SIZE +
                                  counters.general_replies * GENERAL_REPLY_SIZE + counters.bad_checksum +
                                  counters.skipped_bytes;
  if (accounted > size - 2 || size - 2 - accounted >= FRAME_SIZE)
  {
    std::abort();
  }
  return 0;
}

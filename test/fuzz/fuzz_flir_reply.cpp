/**
 * \file
 * \brief libFuzzer target: the FLIR reply parser on arbitrary bytes, fed in arbitrary pieces.
 */
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "ptz_action_server/core/flir/flir_codec.h"

using ptz_action_server::flir::Reply;
using ptz_action_server::flir::ReplyParser;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  // The first byte chooses the piece size, so the same text is also split in many ways.
  const std::size_t piece = 1 + data[0] % 17;
  ReplyParser whole;
  ReplyParser pieces;
  std::vector<Reply> from_whole;
  std::vector<Reply> from_pieces;
  whole.feed(data + 1, size - 1, from_whole);
  for (std::size_t offset = 1; offset < size; offset += piece)
  {
    pieces.feed(data + offset, std::min(piece, size - offset), from_pieces);
  }
  // Splitting the stream never changes what it says.
  if (from_whole.size() != from_pieces.size())
  {
    std::abort();
  }
  for (std::size_t index = 0; index < from_whole.size(); ++index)
  {
    const Reply& a = from_whole[index];
    const Reply& b = from_pieces[index];
    if (a.kind != b.kind || a.text != b.text || a.axis != b.axis || (a.value != b.value && a.value == a.value))
    {
      std::abort();
    }
    if (a.text.size() > ReplyParser::MAX_LINE)
    {
      std::abort();
    }
  }
  return 0;
}

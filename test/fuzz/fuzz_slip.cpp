/**
 * \file
 * \brief libFuzzer target: the SLIP decoder (PanTilt on a serial line) on arbitrary bytes, whole and in pieces, and
 * every frame it hands out encoded again and decoded back.
 */
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "ptz_action_server/core/framing/slip.h"

using namespace ptz_action_server;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const std::size_t piece = 1 + data[0] % 17;
  using Frames = std::vector<std::vector<std::uint8_t>>;
  Frames whole_frames;
  Frames piece_frames;
  slip::Decoder whole(64);
  slip::Decoder pieces(64);
  whole.feed(data + 1, size - 1,
             [&](const std::uint8_t* frame, std::size_t length) { whole_frames.emplace_back(frame, frame + length); });
  for (std::size_t offset = 1; offset < size; offset += piece)
  {
    pieces.feed(data + offset, std::min(piece, size - offset), [&](const std::uint8_t* frame, std::size_t length) {
      piece_frames.emplace_back(frame, frame + length);
    });
  }
  if (whole_frames != piece_frames)
  {
    std::abort();
  }
  for (const auto& frame : whole_frames)
  {
    if (frame.empty() || frame.size() > 64)
    {
      std::abort();
    }
    std::vector<std::uint8_t> again;
    slip::encode(frame.data(), frame.size(), again);
    slip::Decoder check(64);
    Frames back;
    check.feed(again.data(), again.size(),
               [&](const std::uint8_t* out, std::size_t length) { back.emplace_back(out, out + length); });
    if (back.size() != 1 || back[0] != frame)
    {
      std::abort();
    }
  }
  return 0;
}

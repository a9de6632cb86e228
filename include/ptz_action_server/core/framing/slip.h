/**
 * \file
 * \brief SLIP (RFC 1055) framing, for protocols whose frames carry no length or sync byte (PanTilt) on a byte
 * stream: END (0xC0) closes a frame (and is sent before it too, to flush line noise), ESC (0xDB) ESC_END (0xDC)
 * stands for a 0xC0 inside it and ESC ESC_ESC (0xDD) for a 0xDB.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ptz_action_server
{
namespace slip
{
constexpr std::uint8_t END = 0xC0;
constexpr std::uint8_t ESC = 0xDB;
constexpr std::uint8_t ESC_END = 0xDC;
constexpr std::uint8_t ESC_ESC = 0xDD;

/// Appends \p size bytes as one SLIP frame (END, the escaped bytes, END) to \p out.
void encode(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out);

/// What the decoder dropped, by reason.
struct DecoderCounts
{
  std::uint64_t frames = 0;         ///< frames handed out
  std::uint64_t bad_escapes = 0;    ///< frames with ESC followed by neither ESC_END nor ESC_ESC: dropped whole
  std::uint64_t overlong = 0;       ///< frames longer than the decoder's limit: dropped whole
  std::uint64_t dropped_bytes = 0;  ///< received bytes of dropped frames (up to the next END)
};

/**
 * \brief Cuts SLIP frames out of a byte stream. Empty frames (two ENDs in a row, the leading END) are no frames.
 *
 * A damaged frame is dropped whole and counted; the next END starts afresh, so one bad byte costs one frame. The
 * buffer is the decoder's limit, allocated once: a frame that never ends is dropped past it, byte by byte, and costs
 * no memory.
 */
class Decoder
{
public:
  /// Frames longer than \p max_frame bytes (decoded) are dropped.
  explicit Decoder(std::size_t max_frame = 512) : frame_(max_frame)
  {
  }

  /// Feeds \p size bytes; calls \p on_frame(const std::uint8_t* frame, std::size_t size) for every whole frame.
  template <class OnFrame>
  void feed(const std::uint8_t* data, std::size_t size, OnFrame&& on_frame)
  {
    for (std::size_t index = 0; index < size; ++index)
    {
      const std::uint8_t byte = data[index];
      if (byte == END)
      {
        if (length_ > 0 && !damaged_)
        {
          ++counts_.frames;
          on_frame(static_cast<const std::uint8_t*>(frame_.data()), length_);
        }
        length_ = 0;
        damaged_ = false;
        escaped_ = false;
        continue;
      }
      if (damaged_)
      {
        ++counts_.dropped_bytes;
        continue;  // the rest of a dropped frame, up to the next END
      }
      if (escaped_)
      {
        escaped_ = false;
        if (byte != ESC_END && byte != ESC_ESC)
        {
          drop(counts_.bad_escapes);
          continue;
        }
        append(byte == ESC_END ? END : ESC);
      }
      else if (byte == ESC)
      {
        escaped_ = true;
      }
      else
      {
        append(byte);
      }
    }
  }
  /// Forgets a partial frame (the link closed).
  void reset()
  {
    length_ = 0;
    damaged_ = escaped_ = false;
  }
  const DecoderCounts& counts() const
  {
    return counts_;
  }

private:
  void append(std::uint8_t byte)
  {
    if (length_ == frame_.size())
    {
      drop(counts_.overlong);
      return;
    }
    frame_[length_++] = byte;
  }
  void drop(std::uint64_t& counter)
  {
    ++counter;
    counts_.dropped_bytes += length_ + 1;  // the frame so far (decoded length: near enough) and this byte
    damaged_ = true;
    length_ = 0;
  }

  std::vector<std::uint8_t> frame_;  ///< sized once: no allocation per frame
  std::size_t length_ = 0;
  bool escaped_ = false;
  bool damaged_ = false;
  DecoderCounts counts_;
};

}  // namespace slip
}  // namespace ptz_action_server

#include <gtest/gtest.h>

#include <vector>

#include "ptz_action_server/core/framing/slip.h"

using namespace ptz_action_server;
using Bytes = std::vector<std::uint8_t>;

namespace
{
Bytes encoded(const Bytes& frame)
{
  Bytes out;
  slip::encode(frame.data(), frame.size(), out);
  return out;
}

std::vector<Bytes> decodeAll(slip::Decoder& decoder, const Bytes& bytes)
{
  std::vector<Bytes> frames;
  decoder.feed(bytes.data(), bytes.size(),
               [&frames](const std::uint8_t* frame, std::size_t size) { frames.emplace_back(frame, frame + size); });
  return frames;
}
}  // namespace

TEST(Slip, EncodingEscapesEndAndEscAsRfc1055Says)
{
  EXPECT_EQ(encoded(Bytes{ 0x01, 0xC0, 0x02, 0xDB, 0x03 }),
            (Bytes{ 0xC0, 0x01, 0xDB, 0xDC, 0x02, 0xDB, 0xDD, 0x03, 0xC0 }));
  EXPECT_EQ(encoded(Bytes{}), (Bytes{ 0xC0, 0xC0 }));
}

TEST(Slip, FramesSplitAtEveryOffsetComeBackWhole)
{
  const std::vector<Bytes> frames = { { 0x01, 0xC0, 0xDB, 0x00 }, { 0xDB }, { 0x02, 0x01, 0x00, 0x00, 0xC0 } };
  Bytes stream = { 0x55, 0x66 };  // line noise before the first END: a frame of noise, not one of ours
  for (const Bytes& frame : frames)
  {
    const Bytes bytes = encoded(frame);
    stream.insert(stream.end(), bytes.begin(), bytes.end());
  }
  for (std::size_t split = 0; split <= stream.size(); ++split)
  {
    slip::Decoder decoder;
    std::vector<Bytes> got;
    auto keep = [&got](const std::uint8_t* frame, std::size_t size) { got.emplace_back(frame, frame + size); };
    decoder.feed(stream.data(), split, keep);
    decoder.feed(stream.data() + split, stream.size() - split, keep);
    ASSERT_EQ(got.size(), 4u) << "split at " << split;  // the noise, then the three frames
    EXPECT_EQ(got[0], (Bytes{ 0x55, 0x66 }));
    EXPECT_EQ(got[1], frames[0]);
    EXPECT_EQ(got[2], frames[1]);
    EXPECT_EQ(got[3], frames[2]);
  }
}

TEST(Slip, ABadEscapeDropsItsFrameOnlyAndIsCounted)
{
  Bytes stream = { 0xC0, 0x01, 0xDB, 0x42, 0x02, 0xC0 };
  const Bytes next = encoded(Bytes{ 0x07, 0x08 });
  stream.insert(stream.end(), next.begin(), next.end());
  slip::Decoder decoder;
  const std::vector<Bytes> frames = decodeAll(decoder, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0], (Bytes{ 0x07, 0x08 }));
  EXPECT_EQ(decoder.counts().bad_escapes, 1u);
}

TEST(Slip, AnOverlongFrameIsDroppedAndTheNextOneSurvives)
{
  slip::Decoder decoder(4);
  Bytes stream = encoded(Bytes{ 1, 2, 3, 4, 5 });
  const Bytes next = encoded(Bytes{ 9, 9, 9, 9 });
  stream.insert(stream.end(), next.begin(), next.end());
  const std::vector<Bytes> frames = decodeAll(decoder, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0], (Bytes{ 9, 9, 9, 9 }));
  EXPECT_EQ(decoder.counts().overlong, 1u);
  EXPECT_EQ(decoder.counts().dropped_bytes, 5u);
}

TEST(Slip, AFrameThatNeverEndsCostsNoMemoryAndIsCounted)
{
  slip::Decoder decoder(16);
  const Bytes endless(10000, 'A');
  EXPECT_TRUE(decodeAll(decoder, endless).empty());
  EXPECT_EQ(decoder.counts().overlong, 1u);
  EXPECT_EQ(decoder.counts().dropped_bytes, 10000u);  // every byte: the 16 held when it was cut, and the rest
}

TEST(Slip, ResetForgetsAPartialFrame)
{
  slip::Decoder decoder;
  Bytes partial = { 0xC0, 0x01, 0x02 };
  EXPECT_TRUE(decodeAll(decoder, partial).empty());
  decoder.reset();
  const std::vector<Bytes> frames = decodeAll(decoder, Bytes{ 0x03, 0xC0 });
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0], (Bytes{ 0x03 }));
}

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ptz_action_server/core/pelco_d/pelco_d_codec.h"

using namespace ptz_action_server;
using Bytes = std::vector<std::uint8_t>;

namespace
{
Bytes bytesOf(const pelco::Frame& frame)
{
  const pelco::Bytes encoded = pelco::encode(frame);
  return Bytes(encoded.begin(), encoded.end());
}

std::vector<pelco::FrameParser::Event> parseAll(pelco::FrameParser& parser, const Bytes& bytes)
{
  std::vector<pelco::FrameParser::Event> events;
  parser.feed(bytes.data(), bytes.size(), events);
  return events;
}
}  // namespace

// --- Pelco-D golden frames from protocols.md (address 1)

TEST(PelcoGolden, Frames)
{
  EXPECT_EQ(bytesOf(pelco::stop(1)), (Bytes{ 0xFF, 0x01, 0x00, 0x00, 0x00, 0x00, 0x01 }));
  EXPECT_EQ(bytesOf(pelco::move(1, 0x20, 0, 0)), (Bytes{ 0xFF, 0x01, 0x00, 0x02, 0x20, 0x00, 0x23 }));
  EXPECT_EQ(bytesOf(pelco::move(1, -0x3F, 0, 0)), (Bytes{ 0xFF, 0x01, 0x00, 0x04, 0x3F, 0x00, 0x44 }));
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::SET_PAN, pelco::encodePan(90.0))),
            (Bytes{ 0xFF, 0x01, 0x00, 0x4B, 0x23, 0x28, 0x97 }));
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::SET_TILT, 35000)), (Bytes{ 0xFF, 0x01, 0x00, 0x4D, 0x88, 0xB8, 0x8E }));
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::QUERY_PAN, 0)), (Bytes{ 0xFF, 0x01, 0x00, 0x51, 0x00, 0x00, 0x52 }));
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::PAN_REPLY, pelco::encodePan(180.0))),
            (Bytes{ 0xFF, 0x01, 0x00, 0x59, 0x46, 0x50, 0xF0 }));
}

TEST(PelcoGolden, MovementBitsAndSpeeds)
{
  const pelco::Frame up_left_tele = pelco::move(3, -0x10, 0x3F, 1);
  EXPECT_EQ(up_left_tele.command2, pelco::LEFT | pelco::UP | pelco::ZOOM_TELE);
  EXPECT_EQ(up_left_tele.data1, 0x10);
  EXPECT_EQ(up_left_tele.data2, 0x3F);
  const pelco::Frame down_right_wide = pelco::move(3, 0x40, -0x50, -1);
  EXPECT_EQ(down_right_wide.command2, pelco::RIGHT | pelco::DOWN | pelco::ZOOM_WIDE);
  EXPECT_EQ(down_right_wide.data1, 0x3F);  // capped: no published client sends 0x40
  EXPECT_EQ(down_right_wide.data2, 0x3F);
  const pelco::Frame turbo = pelco::move(3, 0x40, -0x50, 0, 0xFF);
  EXPECT_EQ(turbo.data1, 0xFF);                             // the device's own turbo byte, when configured
  EXPECT_EQ(turbo.data2, 0x3F);                             // tilt has no turbo
  EXPECT_EQ(pelco::move(3, 0x3F, 0, 0, 0xFF).data1, 0x3F);  // turbo only above 0x3F
}

TEST(PelcoGolden, PublishedClientsFrames)
{
  // Printed by the published clients (published-wire-facts.md section 4), address 1.
  EXPECT_EQ(bytesOf(pelco::move(1, -0x40, 0, 0)),
            (Bytes{ 0xFF, 0x01, 0x00, 0x04, 0x3F, 0x00, 0x44 }));  // panLeft(0x40)
  EXPECT_EQ(bytesOf(pelco::move(1, -0x40, 0, 0, 0xFF)),
            (Bytes{ 0xFF, 0x01, 0x00, 0x04, 0xFF, 0x00, 0x04 }));  // pelcodrs
  const auto down = pelco::TiltEncoding::DOWN_POSITIVE;
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::SET_TILT, pelco::encodeTilt(-45.0, down))),
            (Bytes{ 0xFF, 0x01, 0x00, 0x4D, 0x11, 0x94, 0xF3 }));  // "45 degrees below the horizon is 4500"
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::SET_TILT, pelco::encodeTilt(-20.0, down))),
            (Bytes{ 0xFF, 0x01, 0x00, 0x4D, 0x07, 0xD0, 0x25 }));
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::SET_TILT, pelco::encodeTilt(30.0, down))),
            (Bytes{ 0xFF, 0x01, 0x00, 0x4D, 0x80, 0xE8, 0xB6 }));  // "30 degrees above the horizon is 33000"
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::SET_PAN, pelco::encodePan(90.0))),
            (Bytes{ 0xFF, 0x01, 0x00, 0x4B, 0x23, 0x28, 0x97 }));
  EXPECT_EQ(bytesOf(pelco::withValue(1, pelco::QUERY_TILT, 0)), (Bytes{ 0xFF, 0x01, 0x00, 0x53, 0x00, 0x00, 0x54 }));
  EXPECT_DOUBLE_EQ(pelco::decodeTilt(4500, down), -45.0);
  EXPECT_DOUBLE_EQ(pelco::decodeTilt(33000, down), 30.0);
}

TEST(PelcoAngles, PanWrapsClockwiseAndTiltEncodingIsASetting)
{
  EXPECT_EQ(pelco::encodePan(-10.0), 35000);
  EXPECT_EQ(pelco::encodePan(370.0), 1000);
  EXPECT_DOUBLE_EQ(pelco::decodePan(35000), -10.0);
  EXPECT_DOUBLE_EQ(pelco::decodePan(18000), 180.0);
  EXPECT_DOUBLE_EQ(pelco::decodePan(18001), -179.99);
  // UP_POSITIVE: up positive, negative as 36000 - x.
  EXPECT_EQ(pelco::encodeTilt(-10.0, pelco::TiltEncoding::UP_POSITIVE), 35000);
  EXPECT_EQ(pelco::encodeTilt(25.5, pelco::TiltEncoding::UP_POSITIVE), 2550);
  EXPECT_DOUBLE_EQ(pelco::decodeTilt(35000, pelco::TiltEncoding::UP_POSITIVE), -10.0);
  // DOWN_POSITIVE, the manual's (and the default): down positive, up as 36000 - x.
  EXPECT_EQ(pelco::encodeTilt(-10.0, pelco::TiltEncoding::DOWN_POSITIVE), 1000);
  EXPECT_EQ(pelco::encodeTilt(10.0, pelco::TiltEncoding::DOWN_POSITIVE), 35000);
  EXPECT_DOUBLE_EQ(pelco::decodeTilt(1000, pelco::TiltEncoding::DOWN_POSITIVE), -10.0);
  pelco::TiltEncoding parsed = pelco::TiltEncoding::UP_POSITIVE;
  EXPECT_TRUE(pelco::parseTiltEncoding("down_positive", parsed));
  EXPECT_EQ(parsed, pelco::TiltEncoding::DOWN_POSITIVE);
  EXPECT_FALSE(pelco::parseTiltEncoding("wrap", parsed));
}

// --- Pelco-D parser

TEST(PelcoParser, SplitAtEveryOffsetGivesTheSameFrames)
{
  Bytes stream;
  const std::vector<pelco::Frame> frames = { pelco::withValue(1, pelco::PAN_REPLY, 18000),
                                             pelco::withValue(1, pelco::TILT_REPLY, 35000),
                                             pelco::withValue(1, pelco::ZOOM_REPLY, 0xFFFF) };
  for (const pelco::Frame& frame : frames)
  {
    const Bytes bytes = bytesOf(frame);
    stream.insert(stream.end(), bytes.begin(), bytes.end());
  }
  for (std::size_t split = 0; split <= stream.size(); ++split)
  {
    pelco::FrameParser parser(1);
    std::vector<pelco::FrameParser::Event> events = parseAll(parser, Bytes(stream.begin(), stream.begin() + split));
    const std::vector<pelco::FrameParser::Event> rest = parseAll(parser, Bytes(stream.begin() + split, stream.end()));
    events.insert(events.end(), rest.begin(), rest.end());
    ASSERT_EQ(events.size(), frames.size()) << "split at " << split;
    for (std::size_t index = 0; index < frames.size(); ++index)
    {
      EXPECT_EQ(events[index].frame, frames[index]) << "split at " << split;
    }
    EXPECT_EQ(parser.counters().bad_checksum, 0u);
  }
}

TEST(PelcoParser, DropsGarbageBadChecksumsAndPartialFramesThenResynchronises)
{
  const Bytes good = bytesOf(pelco::withValue(1, pelco::PAN_REPLY, 12345));
  Bytes bad_checksum = good;
  bad_checksum[6] ^= 0x01;
  const Bytes partial(good.begin(), good.begin() + 4);
  const Bytes other_address = bytesOf(pelco::withValue(2, pelco::PAN_REPLY, 1));
  Bytes stream = { 0x00, 0x12, 0x34 };  // noise before any frame
  for (const Bytes* piece : std::vector<const Bytes*>{ &bad_checksum, &good, &partial, &good, &other_address, &good })
  {
    stream.insert(stream.end(), piece->begin(), piece->end());
  }
  pelco::FrameParser parser(1);
  const std::vector<pelco::FrameParser::Event> events = parseAll(parser, stream);
  ASSERT_EQ(events.size(), 3u);
  for (const pelco::FrameParser::Event& event : events)
  {
    EXPECT_EQ(event.frame.value(), 12345);
  }
  EXPECT_EQ(parser.counters().frames, 3u);
  EXPECT_EQ(parser.counters().wrong_address, 1u);
  EXPECT_GE(parser.counters().bad_checksum, 2u);  // the broken frame's 0xFF and the partial frame's
  EXPECT_GE(parser.counters().skipped_bytes, 3u);
}

TEST(PelcoParser, GeneralRepliesWhenTheDeviceSendsThem)
{
  pelco::FrameParser parser(1, true);
  Bytes stream = { 0xFF, 0x01, 0x00, 0x01 };  // a general reply: FF addr alarm sum
  const Bytes reply = bytesOf(pelco::withValue(1, pelco::TILT_REPLY, 500));
  stream.insert(stream.end(), reply.begin(), reply.end());
  const std::vector<pelco::FrameParser::Event> events = parseAll(parser, stream);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_TRUE(events[0].general_reply);
  EXPECT_FALSE(events[1].general_reply);
  EXPECT_EQ(events[1].frame.value(), 500);
}

TEST(PelcoParser, AGeneralReplyIsToldFromAFrameByItsOwnFourBytes)
{
  // Found by fuzz_pelco_d: FF 01 00 01 both checks as a general reply and starts a frame that checks.
  const Bytes stream = { 0xFF, 0x01, 0x00, 0x01, 0xFF, 0x00, 0x01, 0x5B, 0x88, 0xB8, 0x9C };
  for (std::size_t split = 0; split <= stream.size(); ++split)
  {
    pelco::FrameParser parser(1, true);
    std::vector<pelco::FrameParser::Event> events = parseAll(parser, Bytes(stream.begin(), stream.begin() + split));
    const std::vector<pelco::FrameParser::Event> rest = parseAll(parser, Bytes(stream.begin() + split, stream.end()));
    events.insert(events.end(), rest.begin(), rest.end());
    ASSERT_FALSE(events.empty()) << "split at " << split;
    EXPECT_TRUE(events.front().general_reply) << "split at " << split;
  }
}

TEST(PelcoParser, RandomBytesNeverProduceAnInvalidFrame)
{
  pelco::FrameParser parser(0);
  std::uint32_t state = 12345;
  Bytes noise(20000);
  for (std::uint8_t& byte : noise)
  {
    state = state * 1664525u + 1013904223u;
    byte = static_cast<std::uint8_t>(state >> 24);
  }
  for (const pelco::FrameParser::Event& event : parseAll(parser, noise))
  {
    if (!event.general_reply)
    {
      EXPECT_EQ(pelco::checksum(event.frame), bytesOf(event.frame)[6]);
    }
  }
}

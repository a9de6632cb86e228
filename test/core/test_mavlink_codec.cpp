/**
 * \file
 * \brief The MAVLink codec: its CRC, protocols.md's golden frames, and the parser on a byte stream.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mavlink_test_frames.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using namespace mavlink_test;

namespace
{
std::uint64_t errors(const FrameParser& parser, FrameError error)
{
  return parser.counts().errors[static_cast<std::size_t>(error)];
}

// The three golden frames of protocols.md section 9 (sysid 255, compid 190).
const char* GOLDEN_HEARTBEAT = "fd09000000ffbe0000000000000006080004033d48";
const char* GOLDEN_SET_PITCHYAW = "fd16000001ffbe1f010000000000000000bf0000803e0000c07f0000c07f019a6271";
const char* GOLDEN_CONFIGURE = "fd20000002ffbe4c0000000000c0000000c0000080bf000080bf000000000000000000000000e9030101f5f"
                               "1";

CommandLong configureGolden()
{
  CommandLong command;
  command.params = { -2.0f, -2.0f, -1.0f, -1.0f, 0.0f, 0.0f, 0.0f };
  command.command = command_id::DO_GIMBAL_MANAGER_CONFIGURE;
  command.target_system = 1;
  command.target_component = 1;
  return command;
}
}  // namespace

TEST(MavlinkCrc, CheckValueOfMcrf4xx)
{
  const std::string text = "123456789";
  EXPECT_EQ(crc16(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), 0x6F91);
}

TEST(MavlinkGolden, HeartbeatOfAGroundStation)
{
  Heartbeat heartbeat;
  heartbeat.type = MAV_TYPE_GCS;
  heartbeat.autopilot = MAV_AUTOPILOT_INVALID;
  heartbeat.system_status = MAV_STATE_ACTIVE;
  EXPECT_EQ(bytesOf(encode(gcs(0), heartbeat)), fromHex(GOLDEN_HEARTBEAT));
}

TEST(MavlinkGolden, SetPitchYawWithTheTrailingZeroCut)
{
  const Bytes encoded = bytesOf(encode(gcs(1), pitchYawGolden()));
  EXPECT_EQ(encoded, fromHex(GOLDEN_SET_PITCHYAW));
  EXPECT_EQ(encoded[1], 22) << "gimbal_device_id 0 is cut";
}

TEST(MavlinkGolden, ConfigureCommandLong)
{
  EXPECT_EQ(bytesOf(encode(gcs(2), configureGolden())), fromHex(GOLDEN_CONFIGURE));
}

TEST(MavlinkGolden, GoldenFramesParseBackWithTheCutBytesZeroFilled)
{
  FrameParser parser;
  Bytes stream = fromHex(GOLDEN_HEARTBEAT);
  for (const char* hex : { GOLDEN_SET_PITCHYAW, GOLDEN_CONFIGURE })
  {
    const Bytes frame = fromHex(hex);
    stream.insert(stream.end(), frame.begin(), frame.end());
  }
  const std::vector<Frame> frames = parseAll(parser, stream);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].message_id, message_id::HEARTBEAT);
  EXPECT_EQ(decode<Heartbeat>(frames[0]).type, MAV_TYPE_GCS);
  EXPECT_EQ(frames[1].header.sequence, 1);
  EXPECT_EQ(frames[1].header.system_id, 255);
  EXPECT_EQ(frames[1].header.component_id, 190);
  const auto pitch_yaw = decode<GimbalManagerSetPitchYaw>(frames[1]);
  EXPECT_EQ(pitch_yaw.pitch, -0.5f);
  EXPECT_EQ(pitch_yaw.yaw, 0.25f);
  EXPECT_TRUE(std::isnan(pitch_yaw.pitch_rate));
  EXPECT_TRUE(std::isnan(pitch_yaw.yaw_rate));
  EXPECT_EQ(pitch_yaw.target_component, 154);
  EXPECT_EQ(pitch_yaw.gimbal_device_id, 0);
  const auto configure = decode<CommandLong>(frames[2]);
  EXPECT_EQ(configure.command, command_id::DO_GIMBAL_MANAGER_CONFIGURE);
  EXPECT_EQ(configure.params[0], -2.0f);
  EXPECT_EQ(configure.params[3], -1.0f);
  EXPECT_EQ(configure.confirmation, 0);
  EXPECT_EQ(parser.counts().frames, 3u);
}

// --- the parser on a byte stream

TEST(MavlinkParser, AStreamSplitAtEveryOffsetWithGarbageBetweenFramesYieldsEveryFrame)
{
  // Garbage that holds start bytes too: a lone 0xFD, a 0xFD followed by a plausible header, a 0xFE.
  const Bytes garbage = { 0x00, 0xFD, 0x11, 0xFE, 0x03, 0xFD, 0x02, 0x00, 0x00, 0x05, 0x01, 0x01, 0x1F, 0x01, 0x00 };
  Bytes stream;
  const char* frames_hex[] = { GOLDEN_HEARTBEAT, GOLDEN_SET_PITCHYAW, GOLDEN_CONFIGURE };
  for (const char* hex : frames_hex)
  {
    stream.insert(stream.end(), garbage.begin(), garbage.end());
    const Bytes frame = fromHex(hex);
    stream.insert(stream.end(), frame.begin(), frame.end());
  }
  stream.insert(stream.end(), garbage.begin(), garbage.end());

  for (std::size_t split = 0; split <= stream.size(); ++split)
  {
    FrameParser parser;
    std::vector<Frame> frames;
    auto keep = [&frames](const Frame& frame) { frames.push_back(frame); };
    parser.feed(stream.data(), split, keep);
    parser.feed(stream.data() + split, stream.size() - split, keep);
    ASSERT_EQ(frames.size(), 3u) << "split at " << split;
    EXPECT_EQ(frames[0].message_id, message_id::HEARTBEAT);
    EXPECT_EQ(frames[1].message_id, message_id::GIMBAL_MANAGER_SET_PITCHYAW);
    EXPECT_EQ(frames[2].message_id, message_id::COMMAND_LONG);
    EXPECT_EQ(frames[2].header.sequence, 2);
    EXPECT_GT(parser.counts().noise_bytes, 0u);
  }
}

TEST(MavlinkParser, AStreamFedByteByByteYieldsEveryFrame)
{
  Bytes stream;
  for (const char* hex : { GOLDEN_CONFIGURE, GOLDEN_HEARTBEAT, GOLDEN_SET_PITCHYAW })
  {
    const Bytes frame = fromHex(hex);
    stream.insert(stream.end(), frame.begin(), frame.end());
  }
  FrameParser parser;
  std::vector<std::uint32_t> ids;
  for (std::uint8_t byte : stream)
  {
    parser.feed(&byte, 1, [&ids](const Frame& frame) { ids.push_back(frame.message_id); });
  }
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{ message_id::COMMAND_LONG, message_id::HEARTBEAT,
                                              message_id::GIMBAL_MANAGER_SET_PITCHYAW }));
}

TEST(MavlinkParser, ADamagedFrameIsCountedAndTheNextOneSurvives)
{
  Bytes damaged = fromHex(GOLDEN_SET_PITCHYAW);
  damaged[14] ^= 0x40;  // a bit of the pitch
  Bytes stream = damaged;
  const Bytes good = fromHex(GOLDEN_HEARTBEAT);
  stream.insert(stream.end(), good.begin(), good.end());
  FrameParser parser;
  const std::vector<Frame> frames = parseAll(parser, stream);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].message_id, message_id::HEARTBEAT);
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 1u);
}

TEST(MavlinkParser, TheWrongCrcExtraFailsTheCheck)
{
  // The same bytes framed with another message's CRC_EXTRA: a receiver must refuse them.
  Payload payload{};
  pack(pitchYawGolden(), payload);
  MessageSpec wrong = *findMessage(message_id::GIMBAL_MANAGER_SET_PITCHYAW);
  wrong.crc_extra = 2;
  const EncodedFrame encoded = encodeFrame(gcs(1), wrong, payload.data(), wrong.length);
  FrameParser parser;
  EXPECT_TRUE(parseAll(parser, Bytes(encoded.data(), encoded.data() + encoded.size)).empty());
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 1u);
}

TEST(MavlinkParser, UnknownIncompatFlagsAreDroppedAndCounted)
{
  Bytes frame = fromHex(GOLDEN_HEARTBEAT);
  frame[2] = 0x02;
  FrameParser parser;
  EXPECT_TRUE(parseAll(parser, frame).empty());
  EXPECT_EQ(errors(parser, FrameError::BAD_INCOMPAT), 1u);
}

TEST(MavlinkParser, ASignedFrameIsTakenWithItsSignatureSkipped)
{
  // The signature is not verified (no key is configured); the CRC still covers the frame.
  Payload payload{};
  pack(Heartbeat(), payload);
  const MessageSpec& spec = *findMessage(message_id::HEARTBEAT);
  Bytes frame = { STX_V2, 9, INCOMPAT_SIGNED, 0, 5, 1, 1, 0, 0, 0 };
  frame.insert(frame.end(), payload.begin(), payload.begin() + 9);
  std::uint16_t crc = crcAccumulate(spec.crc_extra, crc16(frame.data() + 1, frame.size() - 1));
  frame.push_back(static_cast<std::uint8_t>(crc));
  frame.push_back(static_cast<std::uint8_t>(crc >> 8));
  frame.insert(frame.end(), SIGNATURE_SIZE, 0xAB);
  const Bytes next = fromHex(GOLDEN_HEARTBEAT);
  frame.insert(frame.end(), next.begin(), next.end());
  FrameParser parser;
  EXPECT_EQ(parseAll(parser, frame).size(), 2u);
  EXPECT_EQ(parser.counts().signed_frames, 1u);
  EXPECT_EQ(parser.counts().noise_bytes, 0u);
}

TEST(MavlinkParser, MavlinkOneFramesAreCountedAndSkippedWhole)
{
  // A MAVLink 1 HEARTBEAT: FE len seq sys comp msgid(1) payload crc. Its payload holds a 0xFD that must not start
  // a frame.
  Bytes v1 = { STX_V1, 9, 0, 1, 1, 0, 0xFD, 0x09, 0, 0, 2, 3, 0, 4, 3 };
  const std::uint16_t crc =
      crcAccumulate(findMessage(message_id::HEARTBEAT)->crc_extra, crc16(v1.data() + 1, v1.size() - 1));
  v1.push_back(static_cast<std::uint8_t>(crc));
  v1.push_back(static_cast<std::uint8_t>(crc >> 8));
  const Bytes good = fromHex(GOLDEN_HEARTBEAT);
  v1.insert(v1.end(), good.begin(), good.end());
  FrameParser parser;
  EXPECT_EQ(parseAll(parser, v1).size(), 1u);
  EXPECT_EQ(errors(parser, FrameError::MAVLINK1), 1u);
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 0u);
}

TEST(MavlinkParser, AFrameOfAnUnknownMessageIsSkippedWholeWhenAnotherFollows)
{
  // msgid 33 (GLOBAL_POSITION_INT) is nothing this codec knows; the frame after it must come through.
  Bytes unknown = { STX_V2, 4, 0, 0, 9, 1, 1, 33, 0, 0, 0xFD, 0xFD, 0xFD, 0xFD, 0x12, 0x34 };
  const Bytes good = fromHex(GOLDEN_HEARTBEAT);
  unknown.insert(unknown.end(), good.begin(), good.end());
  FrameParser parser;
  EXPECT_EQ(parseAll(parser, unknown).size(), 1u);
  EXPECT_EQ(errors(parser, FrameError::UNKNOWN_MESSAGE), 1u);
  EXPECT_EQ(errors(parser, FrameError::BAD_CHECKSUM), 0u);
}

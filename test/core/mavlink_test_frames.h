/**
 * \file
 * \brief What the MAVLink codec and message tests share: frames from hex and back, a ground station's frame header,
 * a parser run over bytes, and the GIMBAL_MANAGER_SET_PITCHYAW of protocols.md's golden frame.
 */
#pragma once

#include <string>
#include <vector>

#include "ptz_action_server/core/mavlink/mavlink_messages.h"

namespace mavlink_test
{
using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using Bytes = std::vector<std::uint8_t>;

inline Bytes fromHex(const std::string& hex)
{
  Bytes bytes;
  for (std::size_t index = 0; index + 1 < hex.size(); index += 2)
  {
    bytes.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(index, 2), nullptr, 16)));
  }
  return bytes;
}

inline Bytes bytesOf(const EncodedFrame& frame)
{
  return Bytes(frame.data(), frame.data() + frame.size);
}

/// The header of a ground station's frame (sysid 255, compid 190), as protocols.md's golden frames have it.
inline FrameHeader gcs(std::uint8_t sequence)
{
  return FrameHeader{ sequence, 255, 190 };
}

/// Every frame \p parser finds in \p bytes.
inline std::vector<Frame> parseAll(FrameParser& parser, const Bytes& bytes)
{
  std::vector<Frame> frames;
  parser.feed(bytes.data(), bytes.size(), [&frames](const Frame& frame) { frames.push_back(frame); });
  return frames;
}

/// The SET_PITCHYAW of the golden frame GOLDEN_SET_PITCHYAW (test_mavlink_codec.cpp) without its header.
inline GimbalManagerSetPitchYaw pitchYawGolden()
{
  GimbalManagerSetPitchYaw message;
  message.pitch = -0.5f;
  message.yaw = 0.25f;
  message.target_system = 1;
  message.target_component = 154;
  return message;
}
}  // namespace mavlink_test

/**
 * \file
 * \brief Private to the VISCA protocol's sources: requests travel as strings, packets as byte vectors.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/visca/visca_codec.h"

namespace ptz_action_server
{
inline std::string bytesOf(const visca::Packet& packet)
{
  return std::string(packet.begin(), packet.end());
}

inline visca::Packet packetOf(const std::string& bytes)
{
  return visca::Packet(bytes.begin(), bytes.end());
}

}  // namespace ptz_action_server

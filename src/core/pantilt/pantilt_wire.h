/**
 * \file
 * \brief Private to the PanTilt codec: little-endian fields and the frame header (type, major, minor), shared by the
 * command codec (pantilt_codec.cpp) and the params frame (pantilt_params.cpp).
 */
#pragma once

#include <cstdint>
#include <cstring>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

namespace cr
{
namespace pantilt
{
namespace detail
{
inline constexpr std::uint8_t MAJOR_VERSION = 1;

inline std::uint8_t minorVersion(WireVersion version)
{
  return version == WireVersion::V1_0 ? 0 : 1;
}

inline void writeInt32(std::uint8_t* out, std::int32_t value)
{
  const auto bits = static_cast<std::uint32_t>(value);
  for (int index = 0; index < 4; ++index)
  {
    out[index] = static_cast<std::uint8_t>(bits >> (8 * index));
  }
}

inline void writeFloat(std::uint8_t* out, float value)
{
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof(bits));
  writeInt32(out, static_cast<std::int32_t>(bits));
}

inline std::int32_t readInt32(const std::uint8_t* in)
{
  std::uint32_t bits = 0;
  for (int index = 0; index < 4; ++index)
  {
    bits |= static_cast<std::uint32_t>(in[index]) << (8 * index);
  }
  return static_cast<std::int32_t>(bits);
}

inline float readFloat(const std::uint8_t* in)
{
  const auto bits = static_cast<std::uint32_t>(readInt32(in));
  float value = 0.0f;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

inline void writeHeader(std::uint8_t* data, std::uint8_t type, WireVersion version)
{
  data[0] = type;
  data[1] = MAJOR_VERSION;
  data[2] = minorVersion(version);
}

inline bool versionMatches(const std::uint8_t* data, WireVersion version)
{
  return data[1] == MAJOR_VERSION && data[2] == minorVersion(version);
}
}  // namespace detail
}  // namespace pantilt
}  // namespace cr

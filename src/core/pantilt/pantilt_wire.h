/**
 * \file
 * \brief Private to the PanTilt codec: little-endian fields and the frame header (type, major, minor), shared by the
 * command codec (pantilt_codec.cpp) and the params frame (pantilt_params.cpp).
 */
#pragma once

#include <cstdint>

#include "ptz_action_server/core/byte_order.h"
#include "ptz_action_server/core/pantilt/pantilt_codec.h"

namespace cr
{
namespace pantilt
{
namespace detail
{
inline constexpr std::uint8_t MAJOR_VERSION = 1;

/// The minor version byte: 0 in the seed's format and in v1.0 alike.
inline std::uint8_t minorVersion(WireFormat format)
{
  return format == WireFormat::V1_1 ? 1 : 0;
}

inline void writeInt32(std::uint8_t* out, std::int32_t value)
{
  ptz_action_server::putLittleEndian(out, static_cast<std::uint32_t>(value));
}

inline void writeFloat(std::uint8_t* out, float value)
{
  ptz_action_server::putLittleEndian(out, ptz_action_server::floatBits(value));
}

inline std::int32_t readInt32(const std::uint8_t* in)
{
  return static_cast<std::int32_t>(ptz_action_server::getLittleEndian<std::uint32_t>(in));
}

inline float readFloat(const std::uint8_t* in)
{
  return ptz_action_server::floatFromBits(ptz_action_server::getLittleEndian<std::uint32_t>(in));
}

inline void writeHeader(std::uint8_t* data, std::uint8_t type, WireFormat format)
{
  data[0] = type;
  data[1] = MAJOR_VERSION;
  data[2] = minorVersion(format);
}

inline bool versionMatches(const std::uint8_t* data, WireFormat format)
{
  return data[1] == MAJOR_VERSION && data[2] == minorVersion(format);
}
}  // namespace detail
}  // namespace pantilt
}  // namespace cr

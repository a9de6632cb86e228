/**
 * \file
 * \brief Fields in wire byte order, for every codec: little-endian (PanTilt, DigiView, MAVLink) and big-endian
 * (Pelco-D, VISCA) integers, and IEEE-754 floats by their bits.
 */
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace ptz_action_server
{
/// Writes the unsigned integer \p value at \p out, least significant byte first.
template <class Unsigned>
void putLittleEndian(std::uint8_t* out, Unsigned value)
{
  static_assert(std::is_unsigned<Unsigned>::value, "an unsigned integer");
  for (std::size_t index = 0; index < sizeof(Unsigned); ++index)
  {
    out[index] = static_cast<std::uint8_t>(value >> (8 * index));
  }
}

/// Reads an unsigned integer stored least significant byte first at \p in.
template <class Unsigned>
Unsigned getLittleEndian(const std::uint8_t* in)
{
  static_assert(std::is_unsigned<Unsigned>::value, "an unsigned integer");
  Unsigned value = 0;
  for (std::size_t index = 0; index < sizeof(Unsigned); ++index)
  {
    value = static_cast<Unsigned>(value | static_cast<Unsigned>(static_cast<Unsigned>(in[index]) << (8 * index)));
  }
  return value;
}

/// Writes the unsigned integer \p value at \p out, most significant byte first.
template <class Unsigned>
void putBigEndian(std::uint8_t* out, Unsigned value)
{
  static_assert(std::is_unsigned<Unsigned>::value, "an unsigned integer");
  for (std::size_t index = 0; index < sizeof(Unsigned); ++index)
  {
    out[sizeof(Unsigned) - 1 - index] = static_cast<std::uint8_t>(value >> (8 * index));
  }
}

/// Reads an unsigned integer stored most significant byte first at \p in.
template <class Unsigned>
Unsigned getBigEndian(const std::uint8_t* in)
{
  static_assert(std::is_unsigned<Unsigned>::value, "an unsigned integer");
  Unsigned value = 0;
  for (std::size_t index = 0; index < sizeof(Unsigned); ++index)
  {
    value = static_cast<Unsigned>((value << 8) | in[index]);
  }
  return value;
}

/// The bits of a float, and back (IEEE-754 single precision on every platform this builds for).
inline std::uint32_t floatBits(float value)
{
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

inline float floatFromBits(std::uint32_t bits)
{
  float value = 0.0f;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

}  // namespace ptz_action_server

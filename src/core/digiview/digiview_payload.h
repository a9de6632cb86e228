/**
 * \file
 * \brief Private to the DigiView codec: little-endian writes and reads into a message's data field, the scales of its
 * fixed-point fields (truncated as the published packers do, angles in the wire's unit), and the camera id most
 * payloads start with (digiview_payloads.cpp).
 */
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/byte_order.h"
#include "ptz_action_server/core/digiview/digiview_codec.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace digiview
{
namespace detail
{
// Scaled fields: angles, coordinates, fov and temperature x 1000, offsets x 32767, in single precision.
inline constexpr float MILLI_SCALE = 1000.0f;
inline constexpr float OFFSET_SCALE = 32767.0f;

/// The largest yaw (and fov) and pitch (and roll) on the wire: pi and pi / 2, times 1000 in the wire's unit (in
/// milliradians rounded up).
struct AngleLimits
{
  std::int32_t half_turn;
  std::int32_t quarter_turn;
};
inline AngleLimits angleLimitsOf(AngleUnit unit)
{
  return unit == AngleUnit::DEGREES ? AngleLimits{ 180000, 90000 } : AngleLimits{ 3142, 1571 };
}

/// The value of a scaled field (in double precision: unpacking does not change the wire).
inline double unscaled(std::int64_t value, float scale)
{
  return static_cast<double>(value) / static_cast<double>(scale);
}

/// As the published packers' static_cast<Int>(value * scale) on floats: truncated toward zero; saturated at \p min
/// and \p max, where the published cast is undefined; NaN is 0.
template <class Int>
Int truncated(double value, float scale, Int min, Int max)
{
  const float product = static_cast<float>(value) * scale;
  if (std::isnan(product))
  {
    return 0;
  }
  return static_cast<Int>(std::clamp(static_cast<double>(product), static_cast<double>(min), static_cast<double>(max)));
}

/// Little-endian writes into a message's data field, by offset; names and angles as the message's wire has them.
class Payload
{
public:
  explicit Payload(Message& message)
    : data_(message.data), name_size_(nameSizeOf(message.format)), angles_(message.angles)
  {
  }
  /// Where the fields after a stream name start: 8, or 16 in 1.2.
  std::size_t afterName() const
  {
    return name_size_;
  }
  void u8(std::size_t at, std::uint8_t value)
  {
    data_[at] = value;
  }
  void u16(std::size_t at, std::uint16_t value)
  {
    putLittleEndian(&data_[at], value);
  }
  void u32(std::size_t at, std::uint32_t value)
  {
    putLittleEndian(&data_[at], value);
  }
  void scaled32(std::size_t at, double value, float scale)
  {
    const std::int32_t scaled = truncated<std::int32_t>(value, scale, std::numeric_limits<std::int32_t>::min(),
                                                        std::numeric_limits<std::int32_t>::max());
    u32(at, static_cast<std::uint32_t>(scaled));
  }
  /// An angle or field of view given in radians, on the wire in the message's unit.
  void angle(std::size_t at, double radians)
  {
    scaled32(at, angles_ == AngleUnit::DEGREES ? toDegrees(radians) : radians, MILLI_SCALE);
  }
  /// A view offset: never -32768, as the published packer with inputs in [-1, 1].
  void scaled16(std::size_t at, double value)
  {
    u16(at, static_cast<std::uint16_t>(truncated<std::int16_t>(value, OFFSET_SCALE, -32767, 32767)));
  }
  /// The name up to its first NUL, cut to the format's size, NUL-padded (a name of the full size has no NUL).
  void name(std::size_t at, const std::string& text)
  {
    const std::size_t length = std::min({ text.size(), text.find('\0'), name_size_ });
    for (std::size_t index = 0; index < name_size_; ++index)
    {
      data_[at + index] = index < length ? static_cast<std::uint8_t>(text[index]) : 0;
    }
  }
  void box(std::size_t at, const BoundingBox& box)
  {
    u16(at, box.x);
    u16(at + 2, box.y);
    u16(at + 4, box.w);
    u16(at + 6, box.h);
  }

private:
  std::array<std::uint8_t, DATA_SIZE>& data_;
  const std::size_t name_size_;
  const AngleUnit angles_;
};

/// Little-endian reads from a message's data field, by offset.
class Reader
{
public:
  explicit Reader(const Message& message)
    : data_(message.data), name_size_(nameSizeOf(message.format)), angles_(message.angles)
  {
  }
  std::size_t afterName() const
  {
    return name_size_;
  }
  AngleLimits angleLimits() const
  {
    return angleLimitsOf(angles_);
  }
  /// Radians of an angle field's raw value.
  double radians(std::int32_t raw) const
  {
    const double value = unscaled(raw, MILLI_SCALE);
    return angles_ == AngleUnit::DEGREES ? toRadians(value) : value;
  }
  std::uint8_t u8(std::size_t at) const
  {
    return data_[at];
  }
  std::uint16_t u16(std::size_t at) const
  {
    return getLittleEndian<std::uint16_t>(&data_[at]);
  }
  std::uint32_t u32(std::size_t at) const
  {
    return getLittleEndian<std::uint32_t>(&data_[at]);
  }
  std::int32_t i32(std::size_t at) const
  {
    return static_cast<std::int32_t>(u32(at));
  }
  std::int16_t i16(std::size_t at) const
  {
    return static_cast<std::int16_t>(u16(at));
  }
  /// The NUL-padded name; false if it holds a non-printable character before the first NUL.
  bool name(std::size_t at, std::string& text) const
  {
    text.clear();
    for (std::size_t index = 0; index < name_size_ && data_[at + index] != 0; ++index)
    {
      const std::uint8_t character = data_[at + index];
      if (character < 0x20 || character > 0x7E)
      {
        return false;
      }
      text.push_back(static_cast<char>(character));
    }
    return true;
  }
  BoundingBox box(std::size_t at) const
  {
    return BoundingBox{ u16(at), u16(at + 2), u16(at + 4), u16(at + 6) };
  }

private:
  const std::array<std::uint8_t, DATA_SIZE>& data_;
  const std::size_t name_size_;
  const AngleUnit angles_;
};

inline bool within(std::int64_t value, std::int64_t min, std::int64_t max)
{
  return value >= min && value <= max;
}

inline Message withPayload(const Wire& wire, MessageType type, ParamType param)
{
  Message message;
  message.format = wire.format;
  message.angles = wire.angles;
  message.message_type = type;
  message.param_type = param;
  return message;
}

/// stream_name @0, cam_id right after it.
inline void writeCamera(Payload& payload, const CameraId& camera)
{
  payload.name(0, camera.stream_name);
  payload.u8(payload.afterName(), camera.cam_id);
}

inline bool readCamera(const Reader& reader, CameraId& camera)
{
  camera.cam_id = reader.u8(reader.afterName());
  return reader.name(0, camera.stream_name) && camera.cam_id <= 3;
}
}  // namespace detail
}  // namespace digiview
}  // namespace ptz_action_server

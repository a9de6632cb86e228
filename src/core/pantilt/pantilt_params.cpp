#include "ptz_action_server/core/pantilt/pantilt_codec.h"

#include <cmath>
#include <cstring>

#include "pantilt_fields.h"
#include "pantilt_wire.h"

namespace cr
{
namespace pantilt
{
using namespace detail;

namespace
{
/// Calls \p visit(index, field) for each field of \p format's frame, in mask-bit order.
template <class Visit>
void forEachWireField(WireFormat format, Visit visit)
{
  if (format == WireFormat::SEED)
  {
    for (std::size_t index = 0; index < FIELDS_SEED.size(); ++index)
    {
      visit(index, *FIELDS_SEED[index]);
    }
  }
  else
  {
    for (std::size_t index = 0; index < FIELDS_V1.size(); ++index)
    {
      visit(index, *FIELDS_V1[index]);
    }
  }
}

std::size_t wireFieldCount(WireFormat format)
{
  return format == WireFormat::SEED ? FIELDS_SEED.size() : FIELDS_V1.size();
}

int fieldSize(FieldType type)
{
  return type == FieldType::FLAG ? 1 : 4;
}

bool maskBit(const std::uint8_t* mask, std::size_t index)
{
  return (mask[index / 8] & (0x80u >> (index % 8))) != 0;
}

/// True if the bytes at \p in hold a value \p field can have (see PanTiltParams::decode).
bool plausible(const Field& field, const std::uint8_t* in)
{
  switch (field.type)
  {
    case FieldType::INT32: {
      const std::int32_t value = readInt32(in);
      return value >= 0 && static_cast<float>(value) <= field.limit;
    }
    case FieldType::FLOAT32: {
      const float value = readFloat(in);
      if (std::isinf(field.limit))
      {
        return true;
      }
      // A small integer read as a float is subnormal: the sign of a field of another format.
      return std::fpclassify(value) != FP_SUBNORMAL && std::abs(value) <= field.limit;
    }
    case FieldType::FLAG:
      return in[0] <= 1;
  }
  return false;
}

/// Decodes \p data as a params frame of \p format alone: NONE and \p decoded filled, or why not.
DecodeError decodeParamsAs(const std::uint8_t* data, int dataSize, WireFormat format, PanTiltParams& decoded)
{
  if (data == nullptr || dataSize < PARAMS_HEADER_SIZE)
  {
    return DecodeError::BAD_SIZE;
  }
  if (data[0] != PARAMS_HEADER)
  {
    return DecodeError::BAD_HEADER;
  }
  if (!versionMatches(data, format))
  {
    return DecodeError::BAD_VERSION;
  }
  const std::uint8_t* mask = data + 3;
  for (std::size_t bit = wireFieldCount(format); bit < 16; ++bit)
  {
    if (maskBit(mask, bit))
    {
      return DecodeError::BAD_MASK;
    }
  }
  int expected = PARAMS_HEADER_SIZE;
  forEachWireField(format, [&](std::size_t index, const Field& field) {
    expected += maskBit(mask, index) ? fieldSize(field.type) : 0;
  });
  if (dataSize != expected)
  {
    return DecodeError::BAD_SIZE;
  }
  bool all_plausible = true;
  decoded = PanTiltParams();  // fields absent from the mask, and fields of the other formats, decode as 0
  int offset = PARAMS_HEADER_SIZE;
  forEachWireField(format, [&](std::size_t index, const Field& field) {
    if (!maskBit(mask, index))
    {
      return;
    }
    all_plausible = all_plausible && plausible(field, data + offset);
    switch (field.type)
    {
      case FieldType::INT32:
        decoded.*field.int_member = readInt32(data + offset);
        break;
      case FieldType::FLOAT32:
        decoded.*field.float_member = readFloat(data + offset);
        break;
      case FieldType::FLAG:
        decoded.*field.flag_member = data[offset] != 0;
        break;
    }
    offset += fieldSize(field.type);
  });
  return all_plausible ? DecodeError::NONE : DecodeError::BAD_VALUE;
}
}  // namespace

// --- PanTiltParams

PanTiltParamsMask PanTiltParamsMask::none()
{
  PanTiltParamsMask mask;
  for (const Field* field : ALL_FIELDS)
  {
    mask.*field->mask_member = false;
  }
  return mask;
}

bool PanTiltParams::operator==(const PanTiltParams& other) const
{
  for (const Field* field : ALL_FIELDS)
  {
    const bool equal =
        field->type == FieldType::INT32 ? this->*field->int_member == other.*field->int_member :
        field->type == FieldType::FLAG  ? this->*field->flag_member == other.*field->flag_member :
                                          // Bitwise, so NaN round trips compare equal too.
            std::memcmp(&(this->*field->float_member), &(other.*field->float_member), sizeof(float)) == 0;
    if (!equal)
    {
      return false;
    }
  }
  return true;
}

bool PanTiltParams::encode(std::uint8_t* data, int bufferSize, int& size, const PanTiltParamsMask* mask,
                           WireFormat format) const
{
  const PanTiltParamsMask all;
  const PanTiltParamsMask& selected = mask ? *mask : all;
  int needed = PARAMS_HEADER_SIZE;
  forEachWireField(format, [&](std::size_t, const Field& field) {
    needed += selected.*field.mask_member ? fieldSize(field.type) : 0;
  });
  size = 0;
  if (data == nullptr || bufferSize < needed)
  {
    return false;
  }
  writeHeader(data, PARAMS_HEADER, format);
  data[3] = 0;
  data[4] = 0;
  int offset = PARAMS_HEADER_SIZE;
  forEachWireField(format, [&](std::size_t index, const Field& field) {
    if (!(selected.*field.mask_member))
    {
      return;
    }
    data[3 + index / 8] |= static_cast<std::uint8_t>(0x80u >> (index % 8));
    switch (field.type)
    {
      case FieldType::INT32:
        writeInt32(data + offset, this->*field.int_member);
        break;
      case FieldType::FLOAT32:
        writeFloat(data + offset, this->*field.float_member);
        break;
      case FieldType::FLAG:
        data[offset] = this->*field.flag_member ? 1 : 0;
        break;
    }
    offset += fieldSize(field.type);
  });
  size = offset;
  return true;
}

bool PanTiltParams::decode(const std::uint8_t* data, int dataSize, WireFormat format, DecodeError* error)
{
  PanTiltParams decoded;
  DecodeError result = decodeParamsAs(data, dataSize, format, decoded);
  if (result != DecodeError::NONE)
  {
    for (WireFormat other : ALL_WIRE_FORMATS)
    {
      PanTiltParams ignored;
      if (other != format && decodeParamsAs(data, dataSize, other, ignored) == DecodeError::NONE)
      {
        result = DecodeError::FOREIGN_FORMAT;
        break;
      }
    }
  }
  if (error)
  {
    *error = result;
  }
  if (result != DecodeError::NONE)
  {
    return false;
  }
  *this = decoded;
  return true;
}

}  // namespace pantilt
}  // namespace cr

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

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
/// Calls \p visit(index, field) for each field of \p version's frame.
template <class Visit>
void forEachWireField(WireVersion version, Visit visit)
{
  if (version == WireVersion::V1_0)
  {
    for (std::size_t index = 0; index < FIELDS_V1_0.size(); ++index)
    {
      visit(index, *FIELDS_V1_0[index]);
    }
  }
  else
  {
    for (std::size_t index = 0; index < FIELDS_V1_1.size(); ++index)
    {
      visit(index, *FIELDS_V1_1[index]);
    }
  }
}

std::size_t wireFieldCount(WireVersion version)
{
  return version == WireVersion::V1_0 ? FIELDS_V1_0.size() : FIELDS_V1_1.size();
}

int fieldSize(FieldType type)
{
  return type == FieldType::FLAG ? 1 : 4;
}

bool maskBit(const std::uint8_t* mask, std::size_t index)
{
  return (mask[index / 8] & (0x80u >> (index % 8))) != 0;
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
                           WireVersion version) const
{
  const PanTiltParamsMask all;
  const PanTiltParamsMask& selected = mask ? *mask : all;
  int needed = PARAMS_HEADER_SIZE;
  forEachWireField(version, [&](std::size_t, const Field& field) {
    needed += selected.*field.mask_member ? fieldSize(field.type) : 0;
  });
  size = 0;
  if (data == nullptr || bufferSize < needed)
  {
    return false;
  }
  writeHeader(data, PARAMS_HEADER, version);
  data[3] = 0;
  data[4] = 0;
  int offset = PARAMS_HEADER_SIZE;
  forEachWireField(version, [&](std::size_t index, const Field& field) {
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

bool PanTiltParams::decode(const std::uint8_t* data, int dataSize, WireVersion version, DecodeError* error)
{
  DecodeError ignored = DecodeError::NONE;
  DecodeError& result = error ? *error : ignored;
  result = DecodeError::NONE;
  if (data == nullptr || dataSize < PARAMS_HEADER_SIZE)
  {
    result = DecodeError::BAD_SIZE;
    return false;
  }
  if (data[0] != PARAMS_HEADER)
  {
    result = DecodeError::BAD_HEADER;
    return false;
  }
  if (!versionMatches(data, version))
  {
    result = DecodeError::BAD_VERSION;
    return false;
  }
  const std::uint8_t* mask = data + 3;
  for (std::size_t bit = wireFieldCount(version); bit < 16; ++bit)
  {
    if (maskBit(mask, bit))
    {
      result = DecodeError::BAD_MASK;
      return false;
    }
  }
  int expected = PARAMS_HEADER_SIZE;
  forEachWireField(version, [&](std::size_t index, const Field& field) {
    expected += maskBit(mask, index) ? fieldSize(field.type) : 0;
  });
  if (dataSize != expected)
  {
    result = DecodeError::BAD_SIZE;
    return false;
  }
  PanTiltParams decoded;  // fields absent from the mask, and fields of the other format, decode as 0
  int offset = PARAMS_HEADER_SIZE;
  forEachWireField(version, [&](std::size_t index, const Field& field) {
    if (!maskBit(mask, index))
    {
      return;
    }
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
  *this = decoded;
  return true;
}

}  // namespace pantilt
}  // namespace cr

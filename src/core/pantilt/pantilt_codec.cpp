#include "ptz_action_server/core/pantilt/pantilt_codec.h"

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

namespace cr
{
namespace pantilt
{
namespace
{
constexpr std::uint8_t MAJOR_VERSION = 1;
constexpr const char* LIBRARY_VERSION = "1.0.0";

std::uint8_t minorVersion(WireVersion version)
{
  return version == WireVersion::V1_0 ? 0 : 1;
}

void writeInt32(std::uint8_t* out, std::int32_t value)
{
  const auto bits = static_cast<std::uint32_t>(value);
  for (int index = 0; index < 4; ++index)
  {
    out[index] = static_cast<std::uint8_t>(bits >> (8 * index));
  }
}

void writeFloat(std::uint8_t* out, float value)
{
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof(bits));
  writeInt32(out, static_cast<std::int32_t>(bits));
}

std::int32_t readInt32(const std::uint8_t* in)
{
  std::uint32_t bits = 0;
  for (int index = 0; index < 4; ++index)
  {
    bits |= static_cast<std::uint32_t>(in[index]) << (8 * index);
  }
  return static_cast<std::int32_t>(bits);
}

float readFloat(const std::uint8_t* in)
{
  const auto bits = static_cast<std::uint32_t>(readInt32(in));
  float value = 0.0f;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

// --- Params fields: one table serves both wire formats and JSON.

enum class FieldType
{
  INT32,
  FLOAT32,
  FLAG,  ///< one byte, 0 or 1
};

struct Field
{
  const char* name;
  FieldType type;
  int PanTiltParams::*int_member;
  float PanTiltParams::*float_member;
  bool PanTiltParams::*flag_member;
  bool PanTiltParamsMask::*mask_member;
};

constexpr Field intField(const char* name, int PanTiltParams::*member, bool PanTiltParamsMask::*mask)
{
  return Field{ name, FieldType::INT32, member, nullptr, nullptr, mask };
}
constexpr Field floatField(const char* name, float PanTiltParams::*member, bool PanTiltParamsMask::*mask)
{
  return Field{ name, FieldType::FLOAT32, nullptr, member, nullptr, mask };
}
constexpr Field flagField(const char* name, bool PanTiltParams::*member, bool PanTiltParamsMask::*mask)
{
  return Field{ name, FieldType::FLAG, nullptr, nullptr, member, mask };
}

const Field PAN_MOTOR_POSITION_FIELD =
    intField("panMotorPosition", &PanTiltParams::panMotorPosition, &PanTiltParamsMask::panMotorPosition);
const Field TILT_MOTOR_POSITION_FIELD =
    intField("tiltMotorPosition", &PanTiltParams::tiltMotorPosition, &PanTiltParamsMask::tiltMotorPosition);
const Field PAN_ANGLE_FIELD = floatField("panAngle", &PanTiltParams::panAngle, &PanTiltParamsMask::panAngle);
const Field TILT_ANGLE_FIELD = floatField("tiltAngle", &PanTiltParams::tiltAngle, &PanTiltParamsMask::tiltAngle);
const Field PAN_TILT_MOTOR_POSITION_FIELD =
    intField("panTiltMotorPosition", &PanTiltParams::panTiltMotorPosition, &PanTiltParamsMask::panTiltMotorPosition);
const Field PAN_TILT_ANGLE_FIELD =
    floatField("panTiltAngle", &PanTiltParams::panTiltAngle, &PanTiltParamsMask::panTiltAngle);
const Field PAN_MOTOR_SPEED_FIELD =
    floatField("panMotorSpeed", &PanTiltParams::panMotorSpeed, &PanTiltParamsMask::panMotorSpeed);
const Field TILT_MOTOR_SPEED_FIELD =
    floatField("tiltMotorSpeed", &PanTiltParams::tiltMotorSpeed, &PanTiltParamsMask::tiltMotorSpeed);
const Field PAN_TILT_MOTOR_SPEED_FIELD =
    floatField("panTiltMotorSpeed", &PanTiltParams::panTiltMotorSpeed, &PanTiltParamsMask::panTiltMotorSpeed);
const Field IS_CONNECTED_FIELD = flagField("isConnected", &PanTiltParams::isConnected, &PanTiltParamsMask::isConnected);
const Field IS_OPEN_FIELD = flagField("isOpen", &PanTiltParams::isOpen, &PanTiltParamsMask::isOpen);
const Field CUSTOM_1_FIELD = floatField("custom1", &PanTiltParams::custom1, &PanTiltParamsMask::custom1);
const Field CUSTOM_2_FIELD = floatField("custom2", &PanTiltParams::custom2, &PanTiltParamsMask::custom2);
const Field CUSTOM_3_FIELD = floatField("custom3", &PanTiltParams::custom3, &PanTiltParamsMask::custom3);

/// 1.0 frame order: the seed's class declaration.
const std::array<const Field*, 9> FIELDS_V1_0 = {
  &PAN_MOTOR_POSITION_FIELD, &TILT_MOTOR_POSITION_FIELD,     &PAN_ANGLE_FIELD,
  &TILT_ANGLE_FIELD,         &PAN_TILT_MOTOR_POSITION_FIELD, &PAN_TILT_ANGLE_FIELD,
  &PAN_MOTOR_SPEED_FIELD,    &TILT_MOTOR_SPEED_FIELD,        &PAN_TILT_MOTOR_SPEED_FIELD
};
/// 1.1 frame order: the published library's.
const std::array<const Field*, 11> FIELDS_V1_1 = { &PAN_MOTOR_POSITION_FIELD,
                                                   &TILT_MOTOR_POSITION_FIELD,
                                                   &PAN_ANGLE_FIELD,
                                                   &TILT_ANGLE_FIELD,
                                                   &PAN_MOTOR_SPEED_FIELD,
                                                   &TILT_MOTOR_SPEED_FIELD,
                                                   &IS_CONNECTED_FIELD,
                                                   &IS_OPEN_FIELD,
                                                   &CUSTOM_1_FIELD,
                                                   &CUSTOM_2_FIELD,
                                                   &CUSTOM_3_FIELD };
/// JSON: every field, in declaration order.
const std::array<const Field*, 14> ALL_FIELDS = { &PAN_MOTOR_POSITION_FIELD,
                                                  &TILT_MOTOR_POSITION_FIELD,
                                                  &PAN_ANGLE_FIELD,
                                                  &TILT_ANGLE_FIELD,
                                                  &PAN_TILT_MOTOR_POSITION_FIELD,
                                                  &PAN_TILT_ANGLE_FIELD,
                                                  &PAN_MOTOR_SPEED_FIELD,
                                                  &TILT_MOTOR_SPEED_FIELD,
                                                  &PAN_TILT_MOTOR_SPEED_FIELD,
                                                  &IS_CONNECTED_FIELD,
                                                  &IS_OPEN_FIELD,
                                                  &CUSTOM_1_FIELD,
                                                  &CUSTOM_2_FIELD,
                                                  &CUSTOM_3_FIELD };

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

// --- Id tables.

struct ParamId
{
  PanTiltParam param;
  std::int32_t id_v1_0;  ///< 0: not in 1.0
  std::int32_t id_v1_1;  ///< 0: not in 1.1
};

const std::array<ParamId, 14> PARAM_IDS = { {
    { PanTiltParam::PAN_MOTOR_POSITION, 1, 1 },
    { PanTiltParam::TILT_MOTOR_POSITION, 2, 2 },
    { PanTiltParam::PAN_ANGLE, 3, 3 },
    { PanTiltParam::TILT_ANGLE, 4, 4 },
    { PanTiltParam::PAN_TILT_MOTOR_POSITION, 5, 0 },
    { PanTiltParam::PAN_TILT_ANGLE, 6, 0 },
    { PanTiltParam::PAN_MOTOR_SPEED, 7, 5 },
    { PanTiltParam::TILT_MOTOR_SPEED, 8, 6 },
    { PanTiltParam::PAN_TILT_MOTOR_SPEED, 9, 0 },
    { PanTiltParam::IS_CONNECTED, 0, 7 },
    { PanTiltParam::IS_OPEN, 0, 8 },
    { PanTiltParam::CUSTOM_1, 0, 9 },
    { PanTiltParam::CUSTOM_2, 0, 10 },
    { PanTiltParam::CUSTOM_3, 0, 11 },
} };

constexpr std::int32_t LAST_COMMAND_V1_0 = static_cast<std::int32_t>(PanTiltCommand::GO_TO_HOME);
constexpr std::int32_t LAST_COMMAND_V1_1 = static_cast<std::int32_t>(PanTiltCommand::MOVE_PAN_TILT);

int commandSize(WireVersion version)
{
  return version == WireVersion::V1_0 ? COMMAND_SIZE_V1_0 : COMMAND_SIZE_V1_1;
}

void writeHeader(std::uint8_t* data, std::uint8_t type, WireVersion version)
{
  data[0] = type;
  data[1] = MAJOR_VERSION;
  data[2] = minorVersion(version);
}

bool versionMatches(const std::uint8_t* data, WireVersion version)
{
  return data[1] == MAJOR_VERSION && data[2] == minorVersion(version);
}
}  // namespace

bool parseWireVersion(const std::string& text, WireVersion& version)
{
  if (text == "1.0")
  {
    version = WireVersion::V1_0;
    return true;
  }
  if (text == "1.1")
  {
    version = WireVersion::V1_1;
    return true;
  }
  return false;
}

const char* toString(WireVersion version)
{
  return version == WireVersion::V1_0 ? "1.0" : "1.1";
}

const char* toString(DecodeError error)
{
  switch (error)
  {
    case DecodeError::NONE:
      return "none";
    case DecodeError::BAD_SIZE:
      return "bad size";
    case DecodeError::BAD_HEADER:
      return "bad header";
    case DecodeError::BAD_VERSION:
      return "bad version";
    case DecodeError::BAD_ID:
      return "bad id";
    case DecodeError::BAD_MASK:
      return "bad mask";
  }
  return "?";
}

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

nlohmann::json PanTiltParams::toJson() const
{
  nlohmann::json json = nlohmann::json::object();
  for (const Field* field : ALL_FIELDS)
  {
    switch (field->type)
    {
      case FieldType::INT32:
        json[field->name] = this->*field->int_member;
        break;
      case FieldType::FLOAT32:
        json[field->name] = this->*field->float_member;
        break;
      case FieldType::FLAG:
        json[field->name] = this->*field->flag_member;
        break;
    }
  }
  return json;
}

bool PanTiltParams::fromJson(const nlohmann::json& json, std::string* error)
{
  if (!json.is_object())
  {
    if (error)
    {
      *error = "params must be a JSON object";
    }
    return false;
  }
  PanTiltParams read = *this;
  for (const Field* field : ALL_FIELDS)
  {
    const auto member = json.find(field->name);
    if (member == json.end())
    {
      continue;
    }
    const bool ok = field->type == FieldType::INT32   ? member->is_number_integer() :
                    field->type == FieldType::FLOAT32 ? member->is_number() :
                                                        member->is_boolean();
    if (!ok)
    {
      if (error)
      {
        *error = std::string("field '") + field->name + "' has the wrong type";
      }
      return false;
    }
    switch (field->type)
    {
      case FieldType::INT32:
        read.*field->int_member = member->get<int>();
        break;
      case FieldType::FLOAT32:
        read.*field->float_member = member->get<float>();
        break;
      case FieldType::FLAG:
        read.*field->flag_member = member->get<bool>();
        break;
    }
  }
  *this = read;
  return true;
}

bool PanTiltParams::writeToFile(const std::string& path, const std::string& key) const
{
  std::ofstream file(path);
  if (!file)
  {
    return false;
  }
  nlohmann::json document;
  document[key] = toJson();
  file << document.dump(2) << '\n';
  return static_cast<bool>(file);
}

bool PanTiltParams::readFromFile(const std::string& path, const std::string& key, std::string* error)
{
  std::ifstream file(path);
  if (!file)
  {
    if (error)
    {
      *error = "cannot open " + path;
    }
    return false;
  }
  const nlohmann::json document = nlohmann::json::parse(file, nullptr, false);
  if (document.is_discarded() || !document.is_object() || !document.contains(key))
  {
    if (error)
    {
      *error = path + " is not JSON with a '" + key + "' object";
    }
    return false;
  }
  return fromJson(document.at(key), error);
}

// --- PanTilt

PanTilt::~PanTilt() = default;

std::string PanTilt::getVersion()
{
  return LIBRARY_VERSION;
}

std::int32_t PanTilt::wireId(PanTiltParam param, WireVersion version)
{
  for (const ParamId& entry : PARAM_IDS)
  {
    if (entry.param == param)
    {
      return version == WireVersion::V1_0 ? entry.id_v1_0 : entry.id_v1_1;
    }
  }
  return 0;
}

bool PanTilt::paramFromWireId(std::int32_t id, WireVersion version, PanTiltParam& param)
{
  for (const ParamId& entry : PARAM_IDS)
  {
    const std::int32_t entry_id = version == WireVersion::V1_0 ? entry.id_v1_0 : entry.id_v1_1;
    if (entry_id != 0 && entry_id == id)
    {
      param = entry.param;
      return true;
    }
  }
  return false;
}

bool PanTilt::commandExists(PanTiltCommand command, WireVersion version)
{
  const auto id = static_cast<std::int32_t>(command);
  return id >= 1 && id <= (version == WireVersion::V1_0 ? LAST_COMMAND_V1_0 : LAST_COMMAND_V1_1);
}

bool PanTilt::encodeSetParamCommand(std::uint8_t* data, int& size, PanTiltParam id, float value, WireVersion version)
{
  size = 0;
  const std::int32_t wire_id = wireId(id, version);
  if (data == nullptr || wire_id == 0)
  {
    return false;
  }
  writeHeader(data, SET_PARAM_HEADER, version);
  writeInt32(data + 3, wire_id);
  writeFloat(data + 7, value);
  size = SET_PARAM_SIZE;
  return true;
}

bool PanTilt::encodeCommand(std::uint8_t* data, int& size, PanTiltCommand id, WireVersion version, float arg1,
                            float arg2)
{
  size = 0;
  if (data == nullptr || !commandExists(id, version))
  {
    return false;
  }
  writeHeader(data, COMMAND_HEADER, version);
  writeInt32(data + 3, static_cast<std::int32_t>(id));
  if (version == WireVersion::V1_1)
  {
    writeFloat(data + 7, arg1);
    writeFloat(data + 11, arg2);
  }
  size = commandSize(version);
  return true;
}

int PanTilt::decodeCommand(const std::uint8_t* data, int size, PanTiltParam& paramId, PanTiltCommand& commandId,
                           float& value, WireVersion version, float* secondValue, DecodeError* error)
{
  paramId = PanTiltParam{};
  commandId = PanTiltCommand{};
  value = 0.0f;
  if (secondValue)
  {
    *secondValue = 0.0f;
  }
  DecodeError ignored = DecodeError::NONE;
  DecodeError& result = error ? *error : ignored;
  result = DecodeError::NONE;

  if (data == nullptr || size < 3)
  {
    result = DecodeError::BAD_SIZE;
    return -1;
  }
  if (data[0] != COMMAND_HEADER && data[0] != SET_PARAM_HEADER)
  {
    result = DecodeError::BAD_HEADER;
    return -1;
  }
  if (!versionMatches(data, version))
  {
    result = DecodeError::BAD_VERSION;
    return -1;
  }
  const bool is_command = data[0] == COMMAND_HEADER;
  if (size != (is_command ? commandSize(version) : SET_PARAM_SIZE))
  {
    result = DecodeError::BAD_SIZE;
    return -1;
  }
  const std::int32_t id = readInt32(data + 3);
  if (is_command)
  {
    const auto command = static_cast<PanTiltCommand>(id);
    if (!commandExists(command, version))
    {
      result = DecodeError::BAD_ID;
      return -1;
    }
    commandId = command;
    if (version == WireVersion::V1_1)
    {
      value = readFloat(data + 7);
      if (secondValue)
      {
        *secondValue = readFloat(data + 11);
      }
    }
    return 0;
  }
  PanTiltParam param{};
  if (!paramFromWireId(id, version, param))
  {
    result = DecodeError::BAD_ID;
    return -1;
  }
  paramId = param;
  value = readFloat(data + 7);
  return 1;
}

}  // namespace pantilt
}  // namespace cr

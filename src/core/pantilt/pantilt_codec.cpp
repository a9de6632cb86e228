#include "ptz_action_server/core/pantilt/pantilt_codec.h"

#include <array>

#include "pantilt_wire.h"

namespace cr
{
namespace pantilt
{
using namespace detail;

namespace
{
constexpr const char* LIBRARY_VERSION = "1.0.0";

// --- Id tables.

struct ParamId
{
  PanTiltParam param;
  std::int32_t id_seed;  ///< 0: not in the seed's format
  std::int32_t id_v1;    ///< 0: not in v1.0 and v1.1
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

constexpr std::int32_t LAST_COMMAND_SEED = static_cast<std::int32_t>(PanTiltCommand::GO_TO_HOME);
constexpr std::int32_t LAST_COMMAND_V1 = static_cast<std::int32_t>(PanTiltCommand::MOVE_PAN_TILT);

std::int32_t idIn(const ParamId& entry, WireFormat format)
{
  return format == WireFormat::SEED ? entry.id_seed : entry.id_v1;
}

/// A decoded SET_PARAM or COMMAND.
struct DecodedCommand
{
  int kind = -1;  ///< 0 COMMAND, 1 SET_PARAM, -1 none
  PanTiltParam param{};
  PanTiltCommand command{};
  float value = 0.0f;
  float second_value = 0.0f;
};

/// Decodes \p data as a frame of \p format alone; NONE and \p decoded filled, or why not.
DecodeError decodeCommandAs(const std::uint8_t* data, int size, WireFormat format, DecodedCommand& decoded)
{
  if (data == nullptr || size < 3)
  {
    return DecodeError::BAD_SIZE;
  }
  if (data[0] != COMMAND_HEADER && data[0] != SET_PARAM_HEADER)
  {
    return DecodeError::BAD_HEADER;
  }
  if (!versionMatches(data, format))
  {
    return DecodeError::BAD_VERSION;
  }
  const bool is_command = data[0] == COMMAND_HEADER;
  if (size != (is_command ? commandSize(format) : SET_PARAM_SIZE))
  {
    return DecodeError::BAD_SIZE;
  }
  const std::int32_t id = readInt32(data + 3);
  if (is_command)
  {
    const auto command = static_cast<PanTiltCommand>(id);
    if (!PanTilt::commandExists(command, format))
    {
      return DecodeError::BAD_ID;
    }
    decoded.kind = 0;
    decoded.command = command;
    if (hasCommandArguments(format))
    {
      decoded.value = readFloat(data + 7);
      decoded.second_value = readFloat(data + 11);
    }
    return DecodeError::NONE;
  }
  if (!PanTilt::paramFromWireId(id, format, decoded.param))
  {
    return DecodeError::BAD_ID;
  }
  decoded.kind = 1;
  decoded.value = readFloat(data + 7);
  return DecodeError::NONE;
}
}  // namespace

bool parseWireFormat(const std::string& text, WireFormat& format)
{
  for (WireFormat candidate : ALL_WIRE_FORMATS)
  {
    if (text == toString(candidate))
    {
      format = candidate;
      return true;
    }
  }
  return false;
}

const char* toString(WireFormat format)
{
  switch (format)
  {
    case WireFormat::SEED:
      return "seed";
    case WireFormat::V1_0:
      return "v1.0";
    case WireFormat::V1_1:
      return "v1.1";
  }
  return "?";
}

bool hasCommandArguments(WireFormat format)
{
  return format != WireFormat::SEED;
}

int commandSize(WireFormat format)
{
  return hasCommandArguments(format) ? COMMAND_SIZE_WITH_ARGUMENTS : COMMAND_SIZE_SEED;
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
    case DecodeError::BAD_VALUE:
      return "bad value";
    case DecodeError::FOREIGN_FORMAT:
      return "foreign format";
  }
  return "?";
}

// --- PanTilt

PanTilt::~PanTilt() = default;

std::string PanTilt::getVersion()
{
  return LIBRARY_VERSION;
}

std::int32_t PanTilt::wireId(PanTiltParam param, WireFormat format)
{
  for (const ParamId& entry : PARAM_IDS)
  {
    if (entry.param == param)
    {
      return idIn(entry, format);
    }
  }
  return 0;
}

bool PanTilt::paramFromWireId(std::int32_t id, WireFormat format, PanTiltParam& param)
{
  for (const ParamId& entry : PARAM_IDS)
  {
    if (idIn(entry, format) != 0 && idIn(entry, format) == id)
    {
      param = entry.param;
      return true;
    }
  }
  return false;
}

bool PanTilt::commandExists(PanTiltCommand command, WireFormat format)
{
  const auto id = static_cast<std::int32_t>(command);
  return id >= 1 && id <= (format == WireFormat::SEED ? LAST_COMMAND_SEED : LAST_COMMAND_V1);
}

bool PanTilt::encodeSetParamCommand(std::uint8_t* data, int& size, PanTiltParam id, float value, WireFormat format)
{
  size = 0;
  const std::int32_t wire_id = wireId(id, format);
  if (data == nullptr || wire_id == 0)
  {
    return false;
  }
  writeHeader(data, SET_PARAM_HEADER, format);
  writeInt32(data + 3, wire_id);
  writeFloat(data + 7, value);
  size = SET_PARAM_SIZE;
  return true;
}

bool PanTilt::encodeCommand(std::uint8_t* data, int& size, PanTiltCommand id, WireFormat format, float arg1, float arg2)
{
  size = 0;
  if (data == nullptr || !commandExists(id, format))
  {
    return false;
  }
  writeHeader(data, COMMAND_HEADER, format);
  writeInt32(data + 3, static_cast<std::int32_t>(id));
  if (hasCommandArguments(format))
  {
    writeFloat(data + 7, arg1);
    writeFloat(data + 11, arg2);
  }
  size = commandSize(format);
  return true;
}

int PanTilt::decodeCommand(const std::uint8_t* data, int size, PanTiltParam& paramId, PanTiltCommand& commandId,
                           float& value, WireFormat format, float* secondValue, DecodeError* error)
{
  DecodedCommand decoded;
  DecodeError result = decodeCommandAs(data, size, format, decoded);
  if (result != DecodeError::NONE)
  {
    decoded = DecodedCommand{};
    for (WireFormat other : ALL_WIRE_FORMATS)
    {
      DecodedCommand ignored;
      if (other != format && decodeCommandAs(data, size, other, ignored) == DecodeError::NONE)
      {
        result = DecodeError::FOREIGN_FORMAT;
        break;
      }
    }
  }
  paramId = decoded.param;
  commandId = decoded.command;
  value = decoded.value;
  if (secondValue)
  {
    *secondValue = decoded.second_value;
  }
  if (error)
  {
    *error = result;
  }
  return decoded.kind;
}

}  // namespace pantilt
}  // namespace cr

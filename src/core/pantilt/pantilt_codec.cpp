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

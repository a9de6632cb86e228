/**
 * \file
 * \brief libFuzzer target: PanTilt::decodeCommand and PanTiltParams::decode on arbitrary bytes, in every wire format
 * (seed, v1.0, v1.1).
 *
 * Beyond "no crash, no out-of-bounds read" (ASan, UBSan), it checks that a decoded command re-encodes to the same
 * bytes, that failures leave defined outputs, that decoded params survive an encode/decode round trip, and that a
 * frame is reported as another format exactly when it fails in its own format and another format takes it.
 */
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

using namespace cr::pantilt;

namespace
{
void check(bool condition)
{
  if (!condition)
  {
    std::abort();
  }
}

/// True if a format other than \p format takes the frame as a command (\p as_params: as params).
bool anotherFormatTakes(const std::uint8_t* data, int size, WireFormat format, bool as_params)
{
  for (WireFormat other : ALL_WIRE_FORMATS)
  {
    if (other == format)
    {
      continue;
    }
    PanTiltParam param{};
    PanTiltCommand command{};
    float value = 0.0f;
    PanTiltParams params;
    if (as_params ? params.decode(data, size, other) :
                    PanTilt::decodeCommand(data, size, param, command, value, other) >= 0)
    {
      return true;
    }
  }
  return false;
}

void fuzzCommand(const std::uint8_t* data, int size, WireFormat format)
{
  PanTiltParam param{};
  PanTiltCommand command{};
  float value = 0.0f;
  float second = 0.0f;
  DecodeError error = DecodeError::NONE;
  const int kind = PanTilt::decodeCommand(data, size, param, command, value, format, &second, &error);
  check((kind < 0) == (error != DecodeError::NONE));
  check((error == DecodeError::FOREIGN_FORMAT) == (kind < 0 && anotherFormatTakes(data, size, format, false)));
  std::uint8_t encoded[MAX_COMMAND_SIZE];
  int encoded_size = 0;
  if (kind == 0)
  {
    check(PanTilt::encodeCommand(encoded, encoded_size, command, format, value, second));
  }
  else if (kind == 1)
  {
    check(PanTilt::encodeSetParamCommand(encoded, encoded_size, param, value, format));
  }
  else
  {
    check(value == 0.0f && second == 0.0f && param == PanTiltParam{} && command == PanTiltCommand{});
    return;
  }
  check(encoded_size == size && std::memcmp(encoded, data, static_cast<std::size_t>(size)) == 0);
}

void fuzzParams(const std::uint8_t* data, int size, WireFormat format)
{
  PanTiltParams params;
  DecodeError error = DecodeError::NONE;
  if (!params.decode(data, size, format, &error))
  {
    check(error != DecodeError::NONE && params == PanTiltParams());
    check((error == DecodeError::FOREIGN_FORMAT) == anotherFormatTakes(data, size, format, true));
    return;
  }
  check(error == DecodeError::NONE);
  // What decodes survives a full encode and a second decode unchanged.
  std::uint8_t full[MAX_PARAMS_FRAME_SIZE];
  int full_size = 0;
  check(params.encode(full, sizeof(full), full_size, nullptr, format));
  PanTiltParams again;
  check(again.decode(full, full_size, format) && again == params);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const int length = static_cast<int>(size);
  for (WireFormat format : ALL_WIRE_FORMATS)
  {
    fuzzCommand(data, length, format);
    fuzzParams(data, length, format);
  }
  return 0;
}

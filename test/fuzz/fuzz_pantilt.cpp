/**
 * \file
 * \brief libFuzzer target: PanTilt::decodeCommand and PanTiltParams::decode on arbitrary bytes, both wire formats.
 *
 * Beyond "no crash, no out-of-bounds read" (ASan, UBSan), it checks that a decoded command re-encodes to the same
 * bytes, that failures leave defined outputs, and that decoded params survive an encode/decode round trip.
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

void fuzzCommand(const std::uint8_t* data, int size, WireVersion version)
{
  PanTiltParam param{};
  PanTiltCommand command{};
  float value = 0.0f;
  float second = 0.0f;
  DecodeError error = DecodeError::NONE;
  const int kind = PanTilt::decodeCommand(data, size, param, command, value, version, &second, &error);
  check((kind < 0) == (error != DecodeError::NONE));
  std::uint8_t encoded[COMMAND_SIZE_V1_1];
  int encoded_size = 0;
  if (kind == 0)
  {
    check(PanTilt::encodeCommand(encoded, encoded_size, command, version, value, second));
  }
  else if (kind == 1)
  {
    check(PanTilt::encodeSetParamCommand(encoded, encoded_size, param, value, version));
  }
  else
  {
    check(value == 0.0f && second == 0.0f && param == PanTiltParam{} && command == PanTiltCommand{});
    return;
  }
  check(encoded_size == size && std::memcmp(encoded, data, static_cast<std::size_t>(size)) == 0);
}

void fuzzParams(const std::uint8_t* data, int size, WireVersion version)
{
  PanTiltParams params;
  DecodeError error = DecodeError::NONE;
  if (!params.decode(data, size, version, &error))
  {
    check(error != DecodeError::NONE && params == PanTiltParams());
    return;
  }
  // What decodes survives a full encode and a second decode unchanged.
  std::uint8_t full[MAX_PARAMS_FRAME_SIZE];
  int full_size = 0;
  check(params.encode(full, sizeof(full), full_size, nullptr, version));
  PanTiltParams again;
  check(again.decode(full, full_size, version) && again == params);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const int length = static_cast<int>(size);
  for (WireVersion version : { WireVersion::V1_0, WireVersion::V1_1 })
  {
    fuzzCommand(data, length, version);
    fuzzParams(data, length, version);
  }
  return 0;
}

/**
 * \file
 * \brief libFuzzer target: DigiView Message::unpack and every payload unpack, on arbitrary bytes.
 */
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "ptz_action_server/core/digiview/digiview_codec.h"

using namespace ptz_action_server::digiview;

namespace
{
void checkUnpacked(const std::uint8_t* data, std::size_t size)
{
  Message message;
  if (Message::unpack(data, size, message) != UnpackError::NONE)
  {
    return;
  }
  // What unpacks packs back to the same 75 bytes and checksum (the padding is not checked).
  const Bytes packed = message.pack();
  if (std::memcmp(packed.data(), data, CHECKSUM_OFFSET + 1) != 0)
  {
    std::abort();
  }
  CamTargeting targeting;
  if (unpackTargeting(message, targeting) == UnpackError::NONE)
  {
    // Re-packing a valid targeting gives a valid targeting with the same values.
    Message again;
    const Bytes bytes = packTargeting(message.message_type, targeting).pack();
    CamTargeting twice;
    if (Message::unpack(bytes.data(), bytes.size(), again) != UnpackError::NONE ||
        unpackTargeting(again, twice) != UnpackError::NONE || twice.yaw != targeting.yaw ||
        twice.camera.stream_name != targeting.camera.stream_name)
    {
      std::abort();
    }
  }
  CamOpticsAndControl optics;
  SystemStatus status;
  VideoOutput output;
  CameraId camera;
  IntervalRequest request;
  (void)unpackOptics(message, optics);
  (void)unpackSystemStatus(message, status);
  (void)unpackVideoOutput(message, output);
  (void)unpackCamera(message, camera);
  (void)unpackInterval(message, request);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  checkUnpacked(data, size);
  if (size == MESSAGE_SIZE)
  {
    // The same bytes with a correct checksum, so the fuzzer reaches the payload checks, not only the CRC.
    Bytes fixed{};
    std::memcpy(fixed.data(), data, MESSAGE_SIZE);
    fixed[CHECKSUM_OFFSET] = crc8(fixed.data(), CHECKSUM_OFFSET);
    checkUnpacked(fixed.data(), fixed.size());
  }
  return 0;
}

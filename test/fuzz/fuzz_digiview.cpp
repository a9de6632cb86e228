/**
 * \file
 * \brief libFuzzer target: DigiView Message::unpack and every payload unpack, on arbitrary bytes, in every format
 * (0.5, 1.0, 1.1, 1.2), both checksum rules and both angle units.
 *
 * Beyond "no crash, no out-of-bounds read" (ASan, UBSan), it checks that a refused message leaves a default message,
 * that a checksum byte of 0 is taken unverified only where the rule allows it, that what unpacks packs back to the
 * same bytes (padding zero, checksum recomputed), and that a valid payload packs again into a valid payload with the
 * same values, within the one unit the published packers' truncation may take off.
 */
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "ptz_action_server/core/digiview/digiview_codec.h"

using namespace ptz_action_server::digiview;

namespace
{
void check(bool condition)
{
  if (!condition)
  {
    std::abort();
  }
}

/// |a - b| within one unit of a field scaled by \p scale (truncation toward zero may take one off).
bool withinOneUnit(double a, double b, double scale)
{
  return std::abs(a - b) <= 1.0 / scale + 1e-9;
}

/// The bytes \p message must pack to: the input with its padding zeroed and its checksum recomputed.
Bytes canonical(const std::uint8_t* data, Format format)
{
  const Layout layout = layoutOf(format);
  Bytes bytes(data, data + layout.size);
  if (layout.interval_offset != 0)
  {
    bytes[layout.interval_offset - 1] = 0;  // from 1.0 on: the padding byte before interval_ms
  }
  std::fill(bytes.begin() + static_cast<std::ptrdiff_t>(layout.checksum_offset) + 1, bytes.end(), 0);
  bytes[layout.checksum_offset] = crc8(bytes.data(), layout.checksum_offset);
  return bytes;
}

/// \p message's payload unpacked, packed again and unpacked again: still valid, and \p same says the values held.
template <class Payload, class Same>
void checkRepacked(const Message& message, UnpackError (*unpack)(const Message&, Payload&),
                   Message (*pack)(const Wire&, MessageType, const Payload&), Same same)
{
  Payload first;
  const UnpackError error = unpack(message, first);
  if (error != UnpackError::NONE)
  {
    check(error == UnpackError::BAD_DATA);
    return;
  }
  const Bytes bytes = pack(message.wire(), message.message_type, first).pack();
  Message again;
  Payload second;
  check(Message::unpack(bytes.data(), bytes.size(), message.wire(), again) == UnpackError::NONE);
  check(unpack(again, second) == UnpackError::NONE);
  check(same(first, second));
}

bool sameCamera(const CameraId& a, const CameraId& b)
{
  return a.stream_name == b.stream_name && a.cam_id == b.cam_id;
}

void checkPayloads(const Message& message)
{
  checkRepacked(message, &unpackTargeting, &packTargeting, [](const CamTargeting& a, const CamTargeting& b) {
    return sameCamera(a.camera, b.camera) && a.targeting_mode == b.targeting_mode && a.euler_delta == b.euler_delta &&
           a.lock_flags == b.lock_flags && withinOneUnit(a.yaw, b.yaw, 1000.0) &&
           withinOneUnit(a.pitch, b.pitch, 1000.0) && withinOneUnit(a.roll, b.roll, 1000.0) &&
           withinOneUnit(a.x_offset, b.x_offset, 32767.0) && withinOneUnit(a.y_offset, b.y_offset, 32767.0) &&
           withinOneUnit(a.target_latitude, b.target_latitude, 1000.0) &&
           withinOneUnit(a.target_longitude, b.target_longitude, 1000.0) &&
           withinOneUnit(a.target_altitude, b.target_altitude, 1000.0) && a.detection_id == b.detection_id &&
           a.track_id == b.track_id && a.view_id == b.view_id && a.lock_target == b.lock_target;
  });
  checkRepacked(message, &unpackOptics, &packOptics, [](const CamOpticsAndControl& a, const CamOpticsAndControl& b) {
    return sameCamera(a.camera, b.camera) && a.zoom == b.zoom && a.crop_mode == b.crop_mode &&
           withinOneUnit(a.fov, b.fov, 1000.0);
  });
  checkRepacked(message, &unpackSystemStatus, &packSystemStatus, [](const SystemStatus& a, const SystemStatus& b) {
    return a.status == b.status && a.error == b.error && withinOneUnit(a.jetson_temp, b.jetson_temp, 1000.0);
  });
  // A SET carries no views (as the published SET helper): only the other types keep them.
  const bool keeps_views = message.message_type != MessageType::SET_PARAMETERS;
  checkRepacked(
      message, &unpackVideoOutput, &packVideoOutput, [keeps_views](const VideoOutput& a, const VideoOutput& b) {
        const bool views = !keeps_views || (a.num_user_views == b.num_user_views &&
                                            std::memcmp(a.views.data(), b.views.data(), sizeof(a.views)) == 0 &&
                                            std::memcmp(&a.detection_overlay_box, &b.detection_overlay_box,
                                                        sizeof(a.detection_overlay_box)) == 0 &&
                                            a.single_detection_size == b.single_detection_size);
        return views && a.stream_name == b.stream_name && a.width == b.width && a.height == b.height &&
               a.fps == b.fps && a.layout_mode == b.layout_mode && a.detection_overlay_mode == b.detection_overlay_mode;
      });
  CameraId camera;
  IntervalRequest request;
  if (unpackCamera(message, camera) != UnpackError::NONE)
  {
    check(camera.stream_name.empty() && camera.cam_id == 0);
  }
  if (unpackInterval(message, request) == UnpackError::NONE)
  {
    const Bytes bytes = packInterval(message.wire(), request).pack();
    Message again;
    IntervalRequest twice;
    check(Message::unpack(bytes.data(), bytes.size(), message.wire(), again) == UnpackError::NONE);
    check(unpackInterval(again, twice) == UnpackError::NONE && twice.interval_ms == request.interval_ms &&
          twice.param == request.param && sameCamera(twice.camera, request.camera));
  }
  DebugValues values;
  if (unpackDebug(message, values) == UnpackError::NONE)  // 1.2 only
  {
    const Bytes bytes = packDebug(message.wire(), values).pack();
    Message again;
    DebugValues twice;
    check(Message::unpack(bytes.data(), bytes.size(), message.wire(), again) == UnpackError::NONE);
    check(unpackDebug(again, twice) == UnpackError::NONE && twice == values);
  }
}

void checkUnpacked(const std::uint8_t* data, std::size_t size, const Wire& wire)
{
  Message message;
  message.timestamp = 1;
  bool unverified = true;
  const UnpackError error = Message::unpack(data, size, wire, message, &unverified);
  if (error != UnpackError::NONE)
  {
    check(message.timestamp == 0 && message.interval_ms == 0 && !unverified);
    return;
  }
  const Layout layout = layoutOf(wire.format);
  check(size == layout.size && message.format == wire.format);
  check(!unverified || (wire.checksum == ChecksumRule::ZERO_ACCEPTED && data[layout.checksum_offset] == 0));
  check(message.pack() == canonical(data, wire.format));
  checkPayloads(message);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  for (Format format : FORMATS)
  {
    for (ChecksumRule rule : { ChecksumRule::REQUIRED, ChecksumRule::ZERO_ACCEPTED })
    {
      checkUnpacked(data, size, Wire{ format, rule });
    }
    checkUnpacked(data, size, Wire(format, ChecksumRule::REQUIRED, AngleUnit::RADIANS));
    checkUnpacked(data, size, Wire(format, ChecksumRule::REQUIRED, AngleUnit::DEGREES));
    // The same bytes cut or zero-padded to the format's size, with a correct checksum, so that the fuzzer reaches
    // the payload checks whatever the input's length.
    const Layout layout = layoutOf(format);
    Bytes fitted(layout.size, 0);
    std::memcpy(fitted.data(), data, std::min(size, layout.size));
    fitted[layout.checksum_offset] = crc8(fitted.data(), layout.checksum_offset);
    checkUnpacked(fitted.data(), fitted.size(), Wire{ format });
  }
  return 0;
}

/**
 * \file
 * \brief Format 1.2 (msg_defs.hpp 1cbc39f) against the frames its published helpers print (published-wire-facts.md
 * section 1.9.7): what the backend sends and reads, angles and fov in degrees, 16-byte names, the renumbered
 * parameter types, its subscriptions, DEBUG, and SYSTEM_STATUS's HALT (which 1.1 documents too).
 */
#include <gtest/gtest.h>

#include <string>

#include "digiview_golden_frames.h"
#include "ptz_action_server/core/digiview/digiview_codec.h"
#include "ptz_action_server/core/units.h"

using namespace ptz_action_server;
using namespace ptz_action_server::digiview;
using namespace ptz_action_server::digiview_golden;

namespace
{
const CameraId MAIN_0{ "main", 0 };
const CameraId MAIN_1{ "main", 1 };

Message unpackedV1_2(const char* hex, AngleUnit angles = AngleUnit::DEGREES)
{
  const Bytes bytes = fromHex(hex);
  Message message;
  EXPECT_EQ(Message::unpack(bytes.data(), bytes.size(), Wire(Format::V1_2, ChecksumRule::REQUIRED, angles), message),
            UnpackError::NONE)
      << hex;
  return message;
}

CamTargeting targetingV1_2(double yaw_degrees, double pitch_degrees)
{
  CamTargeting targeting;
  targeting.camera = MAIN_0;
  targeting.yaw = toRadians(yaw_degrees);
  targeting.pitch = toRadians(pitch_degrees);
  targeting.lock_flags = 3;
  return targeting;
}
}  // namespace

TEST(DigiViewGoldenV1_2, AimingInDegreesGivesThePublishedBytes)
{
  // What the backend sends and reads in 1.2: angles and fov in milli-degrees, names of 16 bytes, cam_id @16.
  const Wire wire(Format::V1_2);
  ASSERT_EQ(wire.angles, AngleUnit::DEGREES);  // as message-definitions.md documents them
  EXPECT_EQ(toHex(packTargeting(wire, MessageType::SET_PARAMETERS, targetingV1_2(45.5, -10.25)).pack()),
            SET_TARGETING_45_5_V1_2);
  CamTargeting delta = targetingV1_2(5.0, -2.5);
  delta.euler_delta = true;
  EXPECT_EQ(toHex(packTargeting(wire, MessageType::SET_PARAMETERS, delta).pack()), SET_TARGETING_DELTA_V1_2);
  EXPECT_EQ(toHex(packTargeting(wire, MessageType::CURRENT_PARAMETERS, targetingV1_2(-120.75, 30.125)).pack()),
            CURRENT_TARGETING_V1_2);
  EXPECT_EQ(
      toHex(packOptics(wire, MessageType::SET_PARAMETERS, CamOpticsAndControl{ MAIN_0, 0, toRadians(60.0) }).pack()),
      SET_OPTICS_FOV_60_V1_2);
  EXPECT_EQ(toHex(packOptics(wire, MessageType::SET_PARAMETERS, CamOpticsAndControl{ MAIN_0, 3, 0.0 }).pack()),
            SET_OPTICS_ZOOM_3_V1_2);
  EXPECT_EQ(
      toHex(
          packOptics(wire, MessageType::CURRENT_PARAMETERS, CamOpticsAndControl{ MAIN_0, 0, toRadians(45.0) }).pack()),
      CURRENT_OPTICS_FOV_45_V1_2);

  CamTargeting read;
  ASSERT_EQ(unpackTargeting(unpackedV1_2(CURRENT_TARGETING_V1_2), read), UnpackError::NONE);
  EXPECT_NEAR(toDegrees(read.yaw), -120.75, 1e-9);
  EXPECT_NEAR(toDegrees(read.pitch), 30.125, 1e-9);
  EXPECT_EQ(read.lock_flags, 3);
  EXPECT_EQ(read.view_id, -1);
  CamOpticsAndControl optics;
  ASSERT_EQ(unpackOptics(unpackedV1_2(CURRENT_OPTICS_FOV_45_V1_2), optics), UnpackError::NONE);
  EXPECT_NEAR(toDegrees(optics.fov), 45.0, 1e-9);
  // Read as radians, the same bytes are out of range: a yaw of -120.75 rad is no yaw.
  EXPECT_EQ(unpackTargeting(unpackedV1_2(CURRENT_TARGETING_V1_2, AngleUnit::RADIANS), read), UnpackError::BAD_DATA);
}

TEST(DigiViewGoldenV1_2, TargetingModesSubscriptionsNamesAndDebug)
{
  const Wire wire(Format::V1_2);
  CamTargeting detection;
  detection.camera = MAIN_1;
  detection.targeting_mode = 2;
  detection.lock_flags = 3;
  detection.track_id = 42;
  detection.view_id = 3;
  detection.lock_target = true;
  EXPECT_EQ(toHex(packTargeting(wire, MessageType::SET_PARAMETERS, detection).pack()), SET_TARGETING_DETECTION_V1_2);
  CamTargeting read;
  ASSERT_EQ(unpackTargeting(unpackedV1_2(SET_TARGETING_DETECTION_V1_2), read), UnpackError::NONE);
  EXPECT_EQ(read.track_id, 42);
  EXPECT_EQ(read.view_id, 3);
  EXPECT_TRUE(read.lock_target);
  CamTargeting coordinal;
  coordinal.camera = MAIN_0;
  coordinal.targeting_mode = 1;
  coordinal.target_latitude = -33.8688;
  coordinal.target_longitude = 151.2093;
  coordinal.target_altitude = -12.25;
  EXPECT_EQ(toHex(packTargeting(wire, MessageType::SET_PARAMETERS, coordinal).pack()), SET_TARGETING_COORDINAL_V1_2);

  const auto interval = [&wire](digiview::ParamType param, const CameraId& camera, std::uint32_t ms) {
    return toHex(packInterval(wire, IntervalRequest{ param, camera, ms }).pack());
  };
  EXPECT_EQ(interval(digiview::ParamType::CAM_TARGETING, MAIN_1, 100), GET_CAM_TARGETING_EVERY_100_MS_V1_2);
  EXPECT_EQ(interval(digiview::ParamType::CAM_TARGETING, MAIN_0, 50), GET_TARGETING_EVERY_50_MS_V1_2);
  EXPECT_EQ(interval(digiview::ParamType::CAM_OPTICS_AND_CONTROL, MAIN_0, 200), GET_OPTICS_EVERY_200_MS_V1_2);
  EXPECT_EQ(minIntervalOf(Format::V1_2), 50u);
  EXPECT_TRUE(shortIntervalIsOneShot(Format::V1_2));
  EXPECT_EQ(toHex(packGet(wire, digiview::ParamType::VIDEO_OUTPUT, MAIN_0).pack()), GET_VIDEO_OUTPUT_V1_2);
  EXPECT_EQ(toHex(packGet(wire, digiview::ParamType::SYSTEM_STATUS, CameraId{}).pack()),
            GET_SYSTEM_STATUS_NO_STREAM_V1_2);

  // 16 characters travel without a NUL; a longer name is cut to its first 16, as the published packers do.
  EXPECT_EQ(toHex(packGet(wire, digiview::ParamType::CAM_TARGETING, CameraId{ "pipeline_front01", 2 }).pack()),
            GET_TARGETING_16_CHARACTERS_V1_2);
  EXPECT_EQ(toHex(packGet(wire, digiview::ParamType::CAM_TARGETING, CameraId{ "pipeline_front01_extra", 2 }).pack()),
            GET_TARGETING_16_CHARACTERS_V1_2);
  CameraId camera;
  ASSERT_EQ(unpackCamera(unpackedV1_2(GET_TARGETING_16_CHARACTERS_V1_2), camera), UnpackError::NONE);
  EXPECT_EQ(camera.stream_name, "pipeline_front01");
  EXPECT_EQ(camera.cam_id, 2);

  const DebugValues values{ 1, -1, 2, 3, 4, 5, 6, 7 };
  EXPECT_EQ(toHex(packDebug(wire, values).pack()), DEBUG_V1_2);
  DebugValues debug{};
  const Message debug_message = unpackedV1_2(DEBUG_V1_2);
  EXPECT_EQ(debug_message.message_type, MessageType::DEBUG);
  ASSERT_EQ(unpackDebug(debug_message, debug), UnpackError::NONE);
  EXPECT_EQ(debug, values);
}

TEST(DigiViewGoldenV1_2, SystemStatusSaysHaltFromOneOneOn)
{
  // app_status (digiview_commons): RUNNING 2, HALT 4 from 1.1 on; the seed's 0..3 before (4 is no status there).
  for (Format format : FORMATS)
  {
    Message message = packSystemStatus(format, MessageType::CURRENT_PARAMETERS, SystemStatus{ APP_STATUS_HALT, 0, 40 });
    const Bytes bytes = message.pack();
    ASSERT_EQ(Message::unpack(bytes.data(), bytes.size(), Wire(format), message), UnpackError::NONE);
    SystemStatus status;
    EXPECT_EQ(unpackSystemStatus(message, status), hasAppStatus(format) ? UnpackError::NONE : UnpackError::BAD_DATA)
        << toString(format);
    EXPECT_EQ(std::string(describeStatus(format, APP_STATUS_HALT)), hasAppStatus(format) ? "HALT" : "?");
    EXPECT_EQ(std::string(describeStatus(format, runningStatus(format))), hasAppStatus(format) ? "RUNNING" : "running");
  }
  EXPECT_FALSE(hasAppStatus(Format::V1_0));
  EXPECT_TRUE(hasAppStatus(Format::V1_1));
}

TEST(DigiViewAngleUnit, TheDocumentedOneUnlessSet)
{
  // 0.5 and 1.0: radians (the seed's docs.md); 1.1 (docs.md at 305a8ab) and 1.2: degrees. Either unit on any format.
  EXPECT_EQ(documentedAngleUnit(Format::V0_5), AngleUnit::RADIANS);
  EXPECT_EQ(documentedAngleUnit(Format::V1_0), AngleUnit::RADIANS);
  EXPECT_EQ(documentedAngleUnit(Format::V1_1), AngleUnit::DEGREES);
  EXPECT_EQ(documentedAngleUnit(Format::V1_2), AngleUnit::DEGREES);
  CamTargeting targeting;
  targeting.camera = MAIN_1;
  targeting.yaw = 0.5;  // rad
  for (Format format : FORMATS)
  {
    for (AngleUnit unit : { AngleUnit::RADIANS, AngleUnit::DEGREES })
    {
      const Wire wire(format, ChecksumRule::REQUIRED, unit);
      const Bytes bytes = packTargeting(wire, MessageType::SET_PARAMETERS, targeting).pack();
      const std::size_t yaw_at = layoutOf(format).data_offset + nameSizeOf(format) + 3;
      const std::int32_t raw = static_cast<std::int32_t>(bytes[yaw_at] | (bytes[yaw_at + 1] << 8) |
                                                         (bytes[yaw_at + 2] << 16) | (bytes[yaw_at + 3] << 24));
      EXPECT_EQ(raw, unit == AngleUnit::DEGREES ? 28647 : 500) << toString(format) << " " << toString(unit);
      Message message;
      ASSERT_EQ(Message::unpack(bytes.data(), bytes.size(), wire, message), UnpackError::NONE);
      CamTargeting read;
      ASSERT_EQ(unpackTargeting(message, read), UnpackError::NONE);
      EXPECT_NEAR(read.yaw, 0.5, 1e-4);
    }
  }
  AngleUnit unit = AngleUnit::RADIANS;
  EXPECT_TRUE(parseAngleUnit("degrees", unit));
  EXPECT_EQ(unit, AngleUnit::DEGREES);
  EXPECT_FALSE(parseAngleUnit("mrad", unit));
}

/**
 * \file
 * \brief The DigiView codec against the golden frames (digiview_golden_frames.h: for 0.5, 1.0 and 1.2 what the
 * published implementations print, for 1.1 computed from its layout), in every format: packing gives them byte for
 * byte, unpacking reads them, and what is read packs back the same.
 */
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "digiview_golden_frames.h"
#include "digiview_test_formats.h"
#include "ptz_action_server/core/digiview/digiview_codec.h"
#include "ptz_action_server/core/units.h"

using namespace ptz_action_server;
using namespace ptz_action_server::digiview;
using namespace ptz_action_server::digiview_golden;

namespace
{
const CameraId MAIN_1{ "main", 1 };

/// The radians of an angle the goldens give in \p format's documented unit (the published caller's float).
double documented(Format format, double value)
{
  return documentedAngleUnit(format) == AngleUnit::DEGREES ? toRadians(value) : value;
}

CamTargeting goldenTargeting(Format format)
{
  CamTargeting targeting;
  targeting.camera = MAIN_1;
  targeting.yaw = documented(format, 0.5);
  targeting.pitch = documented(format, -0.25);
  targeting.lock_flags = 3;
  targeting.x_offset = 0.5;
  targeting.y_offset = -0.25;
  targeting.target_latitude = 59.3293;
  targeting.target_longitude = 18.0686;
  targeting.target_altitude = 120.5;
  return targeting;
}

VideoOutput goldenVideoOutput()
{
  VideoOutput output;
  output.stream_name = "main";
  output.fps = 30;
  output.layout_mode = 4;
  output.detection_overlay_mode = 2;
  output.num_user_views = 4;
  output.views = { BoundingBox{ 0, 0, 960, 540 }, BoundingBox{ 960, 0, 960, 540 }, BoundingBox{ 0, 540, 960, 540 },
                   BoundingBox{ 960, 540, 960, 540 } };
  output.detection_overlay_box = BoundingBox{ 1600, 0, 320, 1080 };
  output.single_detection_size = 160;
  return output;
}

/// One golden: how the published code's caller built it, and the bytes it printed in each format.
struct Golden
{
  const char* name;
  std::function<Message(Format)> build;
  std::function<UnpackError(const Message&, Message&)> reread;  ///< unpacks the payload and packs it again
  digiview_golden::Frame frame;
};

template <class Payload>
std::function<UnpackError(const Message&, Message&)>
rereading(UnpackError (*unpack)(const Message&, Payload&), Message (*pack)(const Wire&, MessageType, const Payload&))
{
  return [unpack, pack](const Message& message, Message& again) {
    Payload payload;
    const UnpackError error = unpack(message, payload);
    again = pack(message.wire(), message.message_type, payload);
    again.timestamp = message.timestamp;
    return error;
  };
}

UnpackError rereadBare(const Message& message, Message& again)
{
  again = packBare(message.wire(), message.message_type, message.param_type);
  return UnpackError::NONE;
}

const std::vector<Golden>& goldens()
{
  const auto targeting = rereading(&unpackTargeting, &packTargeting);
  const auto optics = rereading(&unpackOptics, &packOptics);
  const auto status = rereading(&unpackSystemStatus, &packSystemStatus);
  const auto output = rereading(&unpackVideoOutput, &packVideoOutput);
  const auto get = [](const Message& message, Message& again) {
    CameraId camera;
    const UnpackError error = unpackCamera(message, camera);
    again = packGet(message.wire(), message.param_type, camera);
    return error;
  };
  static const std::vector<Golden> GOLDENS = {
    { "SET CAM_TARGETING",
      [](Format format) { return packTargeting(format, MessageType::SET_PARAMETERS, goldenTargeting(format)); },
      targeting, SET_CAM_TARGETING },
    { "SET CAM_OPTICS",
      [](Format format) {
        return packOptics(format, MessageType::SET_PARAMETERS,
                          CamOpticsAndControl{ MAIN_1, 0, documented(format, 0.6), 1 });
      },
      optics, SET_CAM_OPTICS },
    { "GET CAM_TARGETING", [](Format format) { return packGet(format, digiview::ParamType::CAM_TARGETING, MAIN_1); },
      get, GET_CAM_TARGETING },
    { "CURRENT SYSTEM_STATUS",
      [](Format format) {
        // The published 1.2 golden reports RUNNING (app_status 2); the others were printed with status 1.
        const std::uint8_t status = format == Format::V1_2 ? APP_STATUS_RUNNING : 1;
        return packSystemStatus(format, MessageType::CURRENT_PARAMETERS, SystemStatus{ status, 0, 45.5 });
      },
      status, CURRENT_SYSTEM_STATUS },
    { "CURRENT VIDEO_OUTPUT",
      [](Format format) { return packVideoOutput(format, MessageType::CURRENT_PARAMETERS, goldenVideoOutput()); },
      output, CURRENT_VIDEO_OUTPUT },
    { "SET VIDEO_OUTPUT",
      [](Format format) {
        VideoOutput output;
        output.stream_name = "main";
        output.width = 1280;
        output.height = 720;
        output.fps = 30;
        output.layout_mode = 1;
        return packVideoOutput(format, MessageType::SET_PARAMETERS, output);
      },
      output, SET_VIDEO_OUTPUT },
    { "QUIT", [](Format format) { return packBare(format, MessageType::QUIT, digiview::ParamType::SYSTEM_STATUS); },
      rereadBare, QUIT },
    { "ACKNOWLEDGEMENT",
      [](Format format) { return packBare(format, MessageType::ACKNOWLEDGEMENT, digiview::ParamType::CAM_TARGETING); },
      rereadBare, ACKNOWLEDGEMENT },
  };
  return GOLDENS;
}

class DigiViewGoldens : public ::testing::TestWithParam<Format>
{
protected:
  static const char* golden(const Golden& item, Format format)
  {
    return item.frame.in(format);
  }
};
}  // namespace

TEST_P(DigiViewGoldens, PackingGivesThePublishedBytes)
{
  for (const Golden& item : goldens())
  {
    const Message message = item.build(GetParam());
    EXPECT_EQ(toHex(message.pack()), golden(item, GetParam())) << item.name;
  }
}

TEST_P(DigiViewGoldens, WhatIsReadPacksBackTheSame)
{
  for (const Golden& item : goldens())
  {
    const Bytes bytes = fromHex(golden(item, GetParam()));
    ASSERT_EQ(bytes.size(), layoutOf(GetParam()).size) << item.name;
    Message message;
    bool unverified = true;
    ASSERT_EQ(Message::unpack(bytes.data(), bytes.size(), Wire{ GetParam() }, message, &unverified), UnpackError::NONE)
        << item.name;
    EXPECT_FALSE(unverified) << item.name;  // the goldens carry the CRC
    Message again;
    ASSERT_EQ(item.reread(message, again), UnpackError::NONE) << item.name;
    EXPECT_EQ(toHex(again.pack()), golden(item, GetParam())) << item.name;
  }
}

TEST_P(DigiViewGoldens, TheFieldsReadAreThePublishedValues)
{
  const Wire wire{ GetParam() };
  auto read = [&wire](const Golden& item) {
    const Bytes bytes = fromHex(item.frame.in(GetParam()));
    Message message;
    EXPECT_EQ(Message::unpack(bytes.data(), bytes.size(), wire, message), UnpackError::NONE) << item.name;
    return message;
  };
  CamTargeting targeting;
  ASSERT_EQ(unpackTargeting(read(goldens()[0]), targeting), UnpackError::NONE);
  EXPECT_EQ(targeting.camera.stream_name, "main");
  EXPECT_EQ(targeting.camera.cam_id, 1);
  EXPECT_NEAR(targeting.yaw, documented(GetParam(), 0.5), 1e-12);
  EXPECT_NEAR(targeting.pitch, documented(GetParam(), -0.25), 1e-12);
  EXPECT_DOUBLE_EQ(targeting.x_offset, 16383 / 32767.0);  // truncated
  EXPECT_DOUBLE_EQ(targeting.y_offset, -8191 / 32767.0);
  EXPECT_DOUBLE_EQ(targeting.target_latitude, 59.329);  // 0.5: from @28, not from its copy @32
  EXPECT_DOUBLE_EQ(targeting.target_longitude, 18.068);
  EXPECT_DOUBLE_EQ(targeting.target_altitude, 120.5);
  EXPECT_EQ(targeting.detection_id, -1);  // 1.1: FF FF @40; the others carry none
  EXPECT_EQ(targeting.view_id, -1);       // 1.2: FF FF @50, no detection lock; the others carry none
  EXPECT_EQ(targeting.track_id, 0);
  EXPECT_FALSE(targeting.lock_target);

  SystemStatus status;
  ASSERT_EQ(unpackSystemStatus(read(goldens()[3]), status), UnpackError::NONE);
  EXPECT_EQ(status.status, GetParam() == Format::V1_2 ? APP_STATUS_RUNNING : 1);
  EXPECT_DOUBLE_EQ(status.jetson_temp, 45.5);  // int32 x 1000, not a float

  VideoOutput output;
  ASSERT_EQ(unpackVideoOutput(read(goldens()[4]), output), UnpackError::NONE);
  EXPECT_EQ(output.num_user_views, 4);  // its own byte @15 (@23 in 1.2)
  EXPECT_EQ(output.layout_mode, 4);
  EXPECT_EQ(output.width, 1920);
  EXPECT_EQ(output.fps, 30);
  EXPECT_EQ(output.views[3].x, 960);
  EXPECT_EQ(output.views[3].h, 540);
  EXPECT_EQ(output.detection_overlay_box.x, 1600);  // @48 after four views (@56 in 1.2)
  EXPECT_EQ(output.detection_overlay_box.h, 1080);
  EXPECT_EQ(output.single_detection_size, 160);

  const Message ack = read(goldens()[7]);
  EXPECT_EQ(ack.message_type, MessageType::ACKNOWLEDGEMENT);      // wire 5 in 0.5, 4 later
  EXPECT_EQ(ack.param_type, digiview::ParamType::CAM_TARGETING);  // wire 7, 13 in 1.2
}

TEST_P(DigiViewGoldens, AChecksumByteOfZeroIsTakenOnlyWhenTheRuleSaysSoAndIsReported)
{
  const Layout layout = layoutOf(GetParam());
  for (const Golden& item : goldens())
  {
    Bytes bytes = fromHex(golden(item, GetParam()));
    if (bytes[layout.checksum_offset] == 0)
    {
      continue;
    }
    Message message;
    bool unverified = false;
    bytes[layout.checksum_offset] = 0;  // as the published helpers leave it
    EXPECT_EQ(Message::unpack(bytes.data(), bytes.size(), Wire{ GetParam(), ChecksumRule::REQUIRED }, message),
              UnpackError::BAD_CHECKSUM)
        << item.name;
    ASSERT_EQ(Message::unpack(bytes.data(), bytes.size(), Wire{ GetParam(), ChecksumRule::ZERO_ACCEPTED }, message,
                              &unverified),
              UnpackError::NONE)
        << item.name;
    EXPECT_TRUE(unverified) << item.name;
    bytes[layout.checksum_offset] = 0x01;  // a filled checksum that is wrong stays wrong
    EXPECT_EQ(Message::unpack(bytes.data(), bytes.size(), Wire{ GetParam(), ChecksumRule::ZERO_ACCEPTED }, message),
              UnpackError::BAD_CHECKSUM)
        << item.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, DigiViewGoldens, ::testing::ValuesIn(digiview_test::FORMATS),
                         digiview_test::formatName);

TEST(DigiViewGoldenExtras, FormatSpecificFrames)
{
  // 1.0 and 1.1: a GET with interval_ms @12 in the header subscribes.
  EXPECT_EQ(
      toHex(packInterval(Format::V1_0, IntervalRequest{ digiview::ParamType::CAM_TARGETING, MAIN_1, 100 }).pack()),
      GET_CAM_TARGETING_EVERY_100_MS_V1_0);
  EXPECT_EQ(
      toHex(packInterval(Format::V1_1, IntervalRequest{ digiview::ParamType::CAM_TARGETING, MAIN_1, 100 }).pack()),
      GET_CAM_TARGETING_EVERY_100_MS_V1_1);
  // 1.1: detection_id, int16 @40 of CAM_TARGETING's data, packed and read.
  CamTargeting detection = goldenTargeting(Format::V1_1);
  detection.targeting_mode = 2;
  detection.detection_id = 1234;
  EXPECT_EQ(toHex(packTargeting(Format::V1_1, MessageType::SET_PARAMETERS, detection).pack()),
            SET_CAM_TARGETING_DETECTION_1234_V1_1);
  const Bytes detection_bytes = fromHex(SET_CAM_TARGETING_DETECTION_1234_V1_1);
  Message detection_message;
  ASSERT_EQ(Message::unpack(detection_bytes.data(), detection_bytes.size(), Wire{ Format::V1_1 }, detection_message),
            UnpackError::NONE);
  CamTargeting detection_read;
  ASSERT_EQ(unpackTargeting(detection_message, detection_read), UnpackError::NONE);
  EXPECT_EQ(detection_read.targeting_mode, 2);
  EXPECT_EQ(detection_read.detection_id, 1234);
  // The first 0.5 revision's SYSTEM_STATUS had no temperature: its zeros read as 0 degrees.
  const Bytes old_status = fromHex(CURRENT_SYSTEM_STATUS_WITHOUT_TEMPERATURE_V0_5);
  EXPECT_EQ(toHex(packSystemStatus(Format::V0_5, MessageType::CURRENT_PARAMETERS, SystemStatus{ 1, 0, 0.0 }).pack()),
            toHex(old_status));
  Message message;
  ASSERT_EQ(Message::unpack(old_status.data(), old_status.size(), Wire{}, message), UnpackError::NONE);
  SystemStatus status;
  ASSERT_EQ(unpackSystemStatus(message, status), UnpackError::NONE);
  EXPECT_EQ(status.status, 1);
  EXPECT_EQ(status.jetson_temp, 0.0);
  // Truncated toward zero: fov 1.2345 -> 1234, zoom -5.
  const Message optics = packOptics(Format::V1_0, MessageType::SET_PARAMETERS,
                                    CamOpticsAndControl{ CameraId{ "main", 0 }, -5, 1.2345, 2 });
  EXPECT_EQ(toHex(Bytes(optics.data.begin(), optics.data.begin() + 15)), "6D61696E0000000000FBD204000002");
}

TEST(DigiViewGoldenExtras, TheFormatsAreToldApartByLengthAndTheirTypeNumbers)
{
  const Golden& ack = goldens()[7];
  Message message;
  const Bytes v0_5 = fromHex(ack.frame.v0_5);
  const Bytes v1_0 = fromHex(ack.frame.v1_0);
  const Bytes v1_2 = fromHex(ack.frame.v1_2);
  EXPECT_EQ(Message::unpack(v0_5.data(), v0_5.size(), Wire{ Format::V1_0 }, message), UnpackError::BAD_SIZE);
  EXPECT_EQ(Message::unpack(v1_0.data(), v1_0.size(), Wire{ Format::V0_5 }, message), UnpackError::BAD_SIZE);
  EXPECT_EQ(Message::unpack(v1_2.data(), v1_2.size(), Wire{ Format::V1_1 }, message), UnpackError::BAD_SIZE);
  EXPECT_EQ(Message::unpack(v1_0.data(), v1_0.size(), Wire{ Format::V1_2 }, message), UnpackError::BAD_SIZE);
  EXPECT_EQ(formatsOfSize(80), "0.5");
  EXPECT_EQ(formatsOfSize(88), "1.0 or 1.1");
  EXPECT_EQ(formatsOfSize(96), "1.2");
  // Wire values: 0.5 as the seed; later formats have no GET_INTERVAL and every reply one lower.
  const std::vector<std::pair<MessageType, int>> v1_0_values = {
    { MessageType::EMPTY, 0 },          { MessageType::GET_PARAMETERS, 1 },
    { MessageType::SET_PARAMETERS, 2 }, { MessageType::CURRENT_PARAMETERS, 3 },
    { MessageType::GET_INTERVAL, -1 },  { MessageType::ACKNOWLEDGEMENT, 4 },
    { MessageType::CHECKSUM_ERROR, 5 }, { MessageType::DATA_ERROR, 6 },
    { MessageType::FORBIDDEN, 7 },      { MessageType::UNKNOWN, 8 },
    { MessageType::QUIT, 255 },
  };
  for (const auto& [type, value] : v1_0_values)
  {
    std::uint8_t wire = 0;
    MessageType back = MessageType::EMPTY;
    ASSERT_TRUE(toWire(Format::V0_5, type, wire));
    EXPECT_EQ(wire, static_cast<std::uint8_t>(type));
    for (Format renumbered : { Format::V1_0, Format::V1_1, Format::V1_2 })
    {
      EXPECT_EQ(toWire(renumbered, type, wire), value >= 0) << toString(type);
      if (value >= 0)
      {
        EXPECT_EQ(wire, value) << toString(type);
        ASSERT_TRUE(fromWire(renumbered, wire, back));
        EXPECT_EQ(back, type);
      }
    }
  }
  std::uint8_t wire = 0;
  MessageType type = MessageType::EMPTY;
  EXPECT_FALSE(fromWire(Format::V1_0, 9, type));
  EXPECT_FALSE(fromWire(Format::V1_1, 9, type));
  EXPECT_FALSE(fromWire(Format::V0_5, 10, type));
  EXPECT_FALSE(fromWire(Format::V1_2, 10, type));
  EXPECT_FALSE(toWire(Format::V1_0, MessageType::GET_INTERVAL, wire));
  // 1.2 adds DEBUG as 9; the others have none.
  ASSERT_TRUE(fromWire(Format::V1_2, 9, type));
  EXPECT_EQ(type, MessageType::DEBUG);
  ASSERT_TRUE(toWire(Format::V1_2, MessageType::DEBUG, wire));
  EXPECT_EQ(wire, 9);
  for (Format format : { Format::V0_5, Format::V1_0, Format::V1_1 })
  {
    EXPECT_FALSE(toWire(format, MessageType::DEBUG, wire)) << toString(format);
  }
  // Parameter types: the seed's numbers until 1.1; 1.2 renumbers them (CAM_TARGETING 13, CAM_OPTICS 14, 12 unused).
  const std::vector<std::tuple<digiview::ParamType, int, int>> params = {
    { digiview::ParamType::SYSTEM_STATUS, 0, 0 },
    { digiview::ParamType::VIDEO_OUTPUT, 3, 3 },
    { digiview::ParamType::DETECTED_ROI, 6, 6 },
    { digiview::ParamType::CAM_TARGETING, 7, 13 },
    { digiview::ParamType::CAM_OPTICS_AND_CONTROL, 8, 14 },
    { digiview::ParamType::SINGLE_TARGET_TRACKING, 12, 18 },
    { digiview::ParamType::CALIBRATION, -1, 19 },
    { digiview::ParamType::NAVIGATION, -1, 20 },
    { digiview::ParamType::LENS, -1, 7 },
    { digiview::ParamType::CAM_CONTROL_MODE, -1, 11 },
  };
  for (const auto& [param, before, now] : params)
  {
    digiview::ParamType back = digiview::ParamType::AI;
    for (Format format : FORMATS)
    {
      const int expected = format == Format::V1_2 ? now : before;
      EXPECT_EQ(paramToWire(format, param, wire), expected >= 0) << toString(param) << " " << toString(format);
      if (expected >= 0)
      {
        EXPECT_EQ(wire, expected) << toString(param);
        ASSERT_TRUE(paramFromWire(format, wire, back));
        EXPECT_EQ(back, param);
      }
    }
  }
  digiview::ParamType param = digiview::ParamType::AI;
  EXPECT_FALSE(paramFromWire(Format::V1_2, 12, param));  // CAM_CROP_MODE, retired
  EXPECT_FALSE(paramFromWire(Format::V1_2, 21, param));
  EXPECT_FALSE(paramFromWire(Format::V1_1, 13, param));
  // What a format cannot carry is not packed.
  EXPECT_THROW(packBare(Format::V1_0, MessageType::GET_INTERVAL, digiview::ParamType::CAM_TARGETING).pack(),
               std::invalid_argument);
  EXPECT_THROW(packBare(Format::V1_1, MessageType::GET_INTERVAL, digiview::ParamType::CAM_TARGETING).pack(),
               std::invalid_argument);
  EXPECT_THROW(packBare(Format::V1_2, MessageType::GET_INTERVAL, digiview::ParamType::CAM_TARGETING).pack(),
               std::invalid_argument);
  EXPECT_THROW(packDebug(Format::V1_1, DebugValues{}).pack(), std::invalid_argument);
  EXPECT_THROW(packGet(Format::V1_1, digiview::ParamType::NAVIGATION, MAIN_1).pack(), std::invalid_argument);
  Message with_interval = packGet(Format::V0_5, digiview::ParamType::CAM_TARGETING, MAIN_1);
  with_interval.interval_ms = 100;
  EXPECT_THROW(with_interval.pack(), std::invalid_argument);
}

TEST(DigiViewGoldenExtras, OneAndOneOneReadEachOtherButForDetectionId)
{
  // Same size, types, checksum and layout: a 1.1 frame is a valid 1.0 frame (its detection_id unread), and a 1.0
  // frame reads in 1.1 as detection_id 0, the zeros 1.0 leaves there. Nothing in a message tells them apart.
  for (const Golden& item : goldens())
  {
    EXPECT_EQ(item.frame.v1_0 == std::string(item.frame.v1_1), item.name != std::string("SET CAM_TARGETING"))
        << item.name;
  }
  const Bytes v1_1 = fromHex(SET_CAM_TARGETING.v1_1);
  const Bytes v1_0 = fromHex(SET_CAM_TARGETING.v1_0);
  Message message;
  CamTargeting as_1_0;
  ASSERT_EQ(Message::unpack(v1_1.data(), v1_1.size(), Wire{ Format::V1_0 }, message), UnpackError::NONE);
  ASSERT_EQ(unpackTargeting(message, as_1_0), UnpackError::NONE);
  EXPECT_DOUBLE_EQ(as_1_0.target_altitude, 120.5);
  EXPECT_EQ(as_1_0.detection_id, -1);  // not read: the default
  CamTargeting as_1_1;
  ASSERT_EQ(Message::unpack(v1_0.data(), v1_0.size(), Wire{ Format::V1_1 }, message), UnpackError::NONE);
  ASSERT_EQ(unpackTargeting(message, as_1_1), UnpackError::NONE);
  EXPECT_NEAR(as_1_1.yaw, documented(Format::V1_1, 0.5), 1e-12);  // the same 500, in 1.1's unit
  EXPECT_EQ(as_1_1.detection_id, 0);
}

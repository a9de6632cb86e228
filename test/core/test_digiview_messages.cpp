#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "ptz_action_server/core/digiview/digiview_codec.h"

using namespace ptz_action_server::digiview;

namespace
{
/// An independent, bit by bit CRC-8/BLUETOOTH (poly 0xA7, reflected), to check the table-driven one.
std::uint8_t bitwiseCrc(const std::uint8_t* data, std::size_t size)
{
  std::uint8_t crc = 0;
  for (std::size_t index = 0; index < size; ++index)
  {
    for (int bit = 0; bit < 8; ++bit)
    {
      const bool in = (data[index] >> bit) & 1u;  // reflected input: least significant bit first
      const bool top = crc & 0x80u;
      crc = static_cast<std::uint8_t>(crc << 1);
      if (in != top)
      {
        crc ^= 0xA7;
      }
    }
  }
  // Reflected output.
  std::uint8_t reflected = 0;
  for (int bit = 0; bit < 8; ++bit)
  {
    reflected = static_cast<std::uint8_t>(reflected | (((crc >> bit) & 1u) << (7 - bit)));
  }
  return reflected;
}

std::int32_t int32At(const Bytes& bytes, std::size_t at)
{
  std::uint32_t value = 0;
  for (std::size_t index = 0; index < 4; ++index)
  {
    value |= static_cast<std::uint32_t>(bytes[at + index]) << (8 * index);
  }
  return static_cast<std::int32_t>(value);
}

CameraId mainCamera(std::uint8_t cam_id = 0)
{
  return CameraId{ "main", cam_id };
}
}  // namespace

TEST(DigiViewCrc, CheckValueAndAgreementWithABitwiseImplementation)
{
  const std::string check = "123456789";
  EXPECT_EQ(crc8(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0x26);
  EXPECT_EQ(bitwiseCrc(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0x26);
  std::uint8_t data[75];
  for (int round = 0; round < 50; ++round)
  {
    for (std::size_t index = 0; index < sizeof(data); ++index)
    {
      data[index] = static_cast<std::uint8_t>(index * 37 + round * 101);
    }
    EXPECT_EQ(crc8(data, sizeof(data)), bitwiseCrc(data, sizeof(data)));
  }
}

TEST(DigiViewGolden, SetCamTargetingLayout)
{
  CamTargeting targeting;
  targeting.camera = mainCamera(2);
  targeting.targeting_mode = 0;
  targeting.yaw = 0.5;
  targeting.pitch = -0.2;
  targeting.lock_flags = 3;
  targeting.x_offset = 0.5;
  targeting.y_offset = -1.0;
  targeting.target_latitude = 59.3293;
  targeting.target_longitude = 18.0686;
  targeting.target_altitude = 120.0;
  Message message = packTargeting(MessageType::SET_PARAMETERS, targeting);
  message.timestamp = 0x0102030405060708ull;
  const Bytes bytes = message.pack();
  // Header.
  EXPECT_EQ((std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 11)),
            (std::vector<std::uint8_t>{ 0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01, 0x00, 0x02, 0x07 }));
  // Data at 11: stream_name[8], cam_id, targeting_mode, euler_delta, yaw, pitch, roll, lock_flags, offsets,
  // coordinates.
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&bytes[11]), 4), "main");
  EXPECT_EQ(bytes[15], 0);
  EXPECT_EQ(bytes[18], 0);
  EXPECT_EQ(bytes[11 + 8], 2);                                                           // cam_id
  EXPECT_EQ(bytes[11 + 9], 0);                                                           // directional
  EXPECT_EQ(bytes[11 + 10], 0);                                                          // absolute
  EXPECT_EQ(int32At(bytes, 11 + 11), 500);                                               // yaw, milliradians
  EXPECT_EQ(int32At(bytes, 11 + 15), -200);                                              // pitch
  EXPECT_EQ(int32At(bytes, 11 + 19), 0);                                                 // roll
  EXPECT_EQ(bytes[11 + 23], 3);                                                          // lock flags
  EXPECT_EQ(static_cast<std::int16_t>(bytes[11 + 24] | (bytes[11 + 25] << 8)), 16384);   // 0.5 x 32767, rounded
  EXPECT_EQ(static_cast<std::int16_t>(bytes[11 + 26] | (bytes[11 + 27] << 8)), -32767);  // -1.0
  EXPECT_EQ(int32At(bytes, 11 + 28), 59329);
  EXPECT_EQ(int32At(bytes, 11 + 32), 18069);
  EXPECT_EQ(int32At(bytes, 11 + 36), 120000);
  // Checksum over 0..74, padding zero.
  EXPECT_EQ(bytes[75], bitwiseCrc(bytes.data(), 75));
  EXPECT_EQ(bytes[76] | bytes[77] | bytes[78] | bytes[79], 0);
}

TEST(DigiViewGolden, OpticsIntervalAndGetLayouts)
{
  CamOpticsAndControl optics;
  optics.camera = mainCamera(1);
  optics.zoom = -3;
  optics.fov = 0.6;
  optics.crop_mode = 2;
  const Bytes packed = packOptics(MessageType::SET_PARAMETERS, optics).pack();
  EXPECT_EQ(packed[10], 8);
  EXPECT_EQ(packed[11 + 8], 1);
  EXPECT_EQ(static_cast<std::int8_t>(packed[11 + 9]), -3);
  EXPECT_EQ(int32At(packed, 11 + 10), 600);
  EXPECT_EQ(packed[11 + 14], 2);

  const Bytes interval = packInterval(IntervalRequest{ ParamType::CAM_TARGETING, mainCamera(), 100 }).pack();
  EXPECT_EQ(interval[9], 4);
  EXPECT_EQ(interval[10], 7);
  EXPECT_EQ(int32At(interval, 11 + 12), 100);  // our choice: the interval as uint32 at data[12]

  const Bytes get = packGet(ParamType::VIDEO_OUTPUT, mainCamera()).pack();
  EXPECT_EQ(get[9], 1);
  EXPECT_EQ(get[10], 3);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&get[11]), 4), "main");
}

TEST(DigiViewRoundTrip, EveryMessageAPtzClientNeeds)
{
  CamTargeting targeting;
  targeting.camera = CameraId{ "stream8c", 3 };
  targeting.targeting_mode = 1;
  targeting.euler_delta = true;
  targeting.yaw = -3.141;
  targeting.pitch = 1.57;
  targeting.roll = -0.25;
  targeting.lock_flags = 7;
  targeting.x_offset = -0.25;
  targeting.y_offset = 1.0;
  targeting.target_latitude = -90.0;
  targeting.target_longitude = 179.999;
  targeting.target_altitude = -1000.0;
  Message unpacked;
  const Bytes bytes = packTargeting(MessageType::CURRENT_PARAMETERS, targeting).pack();
  ASSERT_EQ(Message::unpack(bytes.data(), bytes.size(), unpacked), UnpackError::NONE);
  EXPECT_EQ(unpacked.message_type, MessageType::CURRENT_PARAMETERS);
  CamTargeting back;
  ASSERT_EQ(unpackTargeting(unpacked, back), UnpackError::NONE);
  EXPECT_EQ(back.camera.stream_name, "stream8c");
  EXPECT_EQ(back.camera.cam_id, 3);
  EXPECT_EQ(back.targeting_mode, 1);
  EXPECT_TRUE(back.euler_delta);
  EXPECT_DOUBLE_EQ(back.yaw, -3.141);
  EXPECT_DOUBLE_EQ(back.pitch, 1.57);
  EXPECT_DOUBLE_EQ(back.roll, -0.25);
  EXPECT_EQ(back.lock_flags, 7);
  EXPECT_NEAR(back.x_offset, -0.25, 1.0 / 32767);
  EXPECT_DOUBLE_EQ(back.y_offset, 1.0);
  EXPECT_DOUBLE_EQ(back.target_latitude, -90.0);
  EXPECT_DOUBLE_EQ(back.target_longitude, 179.999);
  EXPECT_DOUBLE_EQ(back.target_altitude, -1000.0);

  CamOpticsAndControl optics;
  optics.camera = mainCamera(2);
  optics.zoom = 127;
  optics.fov = 3.14;
  optics.crop_mode = 1;
  const Bytes optics_bytes = packOptics(MessageType::SET_PARAMETERS, optics).pack();
  ASSERT_EQ(Message::unpack(optics_bytes.data(), optics_bytes.size(), unpacked), UnpackError::NONE);
  CamOpticsAndControl optics_back;
  ASSERT_EQ(unpackOptics(unpacked, optics_back), UnpackError::NONE);
  EXPECT_EQ(optics_back.zoom, 127);
  EXPECT_DOUBLE_EQ(optics_back.fov, 3.14);
  EXPECT_EQ(optics_back.camera.cam_id, 2);

  const Bytes status_bytes = packSystemStatus(MessageType::CURRENT_PARAMETERS, SystemStatus{ 3, 0, 71.5f }).pack();
  ASSERT_EQ(Message::unpack(status_bytes.data(), status_bytes.size(), unpacked), UnpackError::NONE);
  SystemStatus status;
  ASSERT_EQ(unpackSystemStatus(unpacked, status), UnpackError::NONE);
  EXPECT_EQ(status.status, 3);
  EXPECT_FLOAT_EQ(status.jetson_temp, 71.5f);

  VideoOutput output;
  output.stream_name = "main";
  output.width = 1280;
  output.height = 720;
  output.layout_mode = 4;
  output.num_user_views = 4;
  output.detection_overlay_mode = 2;
  output.views[3] = BoundingBox{ 640, 360, 640, 360 };
  output.detection_overlay_box = BoundingBox{ 1, 2, 3, 4 };
  output.single_detection_size = 96;
  const Bytes output_bytes = packVideoOutput(MessageType::CURRENT_PARAMETERS, output).pack();
  EXPECT_EQ(output_bytes[11 + 13], 0x44);  // 4 views in the MSB, layout 4 in the LSB
  ASSERT_EQ(Message::unpack(output_bytes.data(), output_bytes.size(), unpacked), UnpackError::NONE);
  VideoOutput output_back;
  ASSERT_EQ(unpackVideoOutput(unpacked, output_back), UnpackError::NONE);
  EXPECT_EQ(output_back.num_user_views, 4);
  EXPECT_EQ(output_back.layout_mode, 4);
  EXPECT_EQ(output_back.width, 1280);
  EXPECT_EQ(output_back.views[3].x, 640);
  EXPECT_EQ(output_back.detection_overlay_box.h, 4);
  EXPECT_EQ(output_back.single_detection_size, 96);

  const Bytes interval_bytes =
      packInterval(IntervalRequest{ ParamType::CAM_OPTICS_AND_CONTROL, mainCamera(1), 250 }).pack();
  ASSERT_EQ(Message::unpack(interval_bytes.data(), interval_bytes.size(), unpacked), UnpackError::NONE);
  IntervalRequest request;
  ASSERT_EQ(unpackInterval(unpacked, request), UnpackError::NONE);
  EXPECT_EQ(request.param, ParamType::CAM_OPTICS_AND_CONTROL);
  EXPECT_EQ(request.interval_ms, 250u);
  EXPECT_EQ(request.camera.cam_id, 1);

  for (MessageType type : { MessageType::ACKNOWLEDGEMENT, MessageType::CHECKSUM_ERROR, MessageType::DATA_ERROR,
                            MessageType::FORBIDDEN, MessageType::UNKNOWN, MessageType::QUIT })
  {
    const Bytes bare = packBare(type, ParamType::CAM_TARGETING).pack();
    ASSERT_EQ(Message::unpack(bare.data(), bare.size(), unpacked), UnpackError::NONE);
    EXPECT_EQ(unpacked.message_type, type);
    EXPECT_EQ(unpacked.param_type, ParamType::CAM_TARGETING);
  }
}

TEST(DigiViewRejection, EveryMalformedMessageHasOneReasonAndLeavesDefinedOutputs)
{
  CamTargeting targeting;
  targeting.camera = mainCamera();
  const Bytes good = packTargeting(MessageType::SET_PARAMETERS, targeting).pack();
  auto with = [&](std::size_t at, std::uint8_t value, bool fix_checksum = true) {
    Bytes bytes = good;
    bytes[at] = value;
    if (fix_checksum)
    {
      bytes[75] = crc8(bytes.data(), 75);
    }
    return bytes;
  };
  auto withInt32 = [&](std::size_t at, std::int32_t value) {
    Bytes bytes = good;
    for (std::size_t index = 0; index < 4; ++index)
    {
      bytes[11 + at + index] = static_cast<std::uint8_t>(static_cast<std::uint32_t>(value) >> (8 * index));
    }
    bytes[75] = crc8(bytes.data(), 75);
    return bytes;
  };
  struct Case
  {
    const char* name;
    Bytes bytes;
    std::size_t size;
    UnpackError message_error;
    UnpackError data_error;
  };
  const std::vector<Case> cases = {
    { "79 bytes", good, 79, UnpackError::BAD_SIZE, UnpackError::NONE },
    { "bad checksum", with(75, static_cast<std::uint8_t>(good[75] ^ 0x5A), false), 80, UnpackError::BAD_CHECKSUM,
      UnpackError::NONE },
    { "a flipped data bit", with(20, static_cast<std::uint8_t>(good[20] ^ 0x01), false), 80, UnpackError::BAD_CHECKSUM,
      UnpackError::NONE },
    { "version 1", with(8, 1), 80, UnpackError::BAD_VERSION, UnpackError::NONE },
    { "message type 10", with(9, 10), 80, UnpackError::BAD_MESSAGE_TYPE, UnpackError::NONE },
    { "message type 254", with(9, 254), 80, UnpackError::BAD_MESSAGE_TYPE, UnpackError::NONE },
    { "param type 13", with(10, 13), 80, UnpackError::BAD_PARAM_TYPE, UnpackError::NONE },
    { "cam_id 4", with(11 + 8, 4), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "targeting mode 4", with(11 + 9, 4), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "euler_delta 2", with(11 + 10, 2), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "lock flags 8", with(11 + 23, 8), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "a control character in the stream name", with(11 + 1, 0x07), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "yaw 3.2 rad", withInt32(11, 3200), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "pitch -1.6 rad", withInt32(15, -1600), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "latitude 91", withInt32(28, 91000), 80, UnpackError::NONE, UnpackError::BAD_DATA },
    { "longitude 180", withInt32(32, 180000), 80, UnpackError::NONE, UnpackError::BAD_DATA },
  };
  for (const Case& item : cases)
  {
    Message message;
    message.timestamp = 42;
    EXPECT_EQ(Message::unpack(item.bytes.data(), item.size, message), item.message_error) << item.name;
    if (item.message_error != UnpackError::NONE)
    {
      EXPECT_EQ(message.timestamp, 0u) << item.name;  // defined: a default message
      continue;
    }
    CamTargeting read;
    read.yaw = 9.0;
    EXPECT_EQ(unpackTargeting(message, read), item.data_error) << item.name;
    EXPECT_EQ(read.yaw, 0.0) << item.name;
  }
  // An optics unpack of a targeting message is refused too.
  Message message;
  ASSERT_EQ(Message::unpack(good.data(), good.size(), message), UnpackError::NONE);
  CamOpticsAndControl optics;
  EXPECT_EQ(unpackOptics(message, optics), UnpackError::BAD_DATA);
  Message none;
  EXPECT_EQ(Message::unpack(nullptr, 80, none), UnpackError::BAD_SIZE);
}

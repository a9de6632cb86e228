#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "digiview_test_formats.h"
#include "ptz_action_server/core/digiview/digiview_codec.h"

using namespace ptz_action_server;
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

std::int16_t int16At(const Bytes& bytes, std::size_t at)
{
  return static_cast<std::int16_t>(bytes[at] | (bytes[at + 1] << 8));
}

CameraId mainCamera(std::uint8_t cam_id = 0)
{
  return CameraId{ "main", cam_id };
}

/// The codec tests that hold in every format. Angles in radians on the wire here, whatever the format documents, so
/// that the scaled values are the same numbers in all (test_digiview_goldens.cpp checks degrees).
class DigiViewMessages : public ::testing::TestWithParam<Format>
{
protected:
  Format format() const
  {
    return GetParam();
  }
  Wire wire() const
  {
    return Wire(GetParam(), ChecksumRule::REQUIRED, AngleUnit::RADIANS);
  }
  Layout layout() const
  {
    return layoutOf(GetParam());
  }
  /// Where the fields after the stream name start in the data: 8, or 16 in 1.2.
  std::size_t b() const
  {
    return nameSizeOf(GetParam());
  }
  std::uint8_t paramWire(digiview::ParamType param) const
  {
    std::uint8_t value = 0;
    EXPECT_TRUE(paramToWire(GetParam(), param, value));
    return value;
  }
  Message unpacked(const Bytes& bytes) const
  {
    Message message;
    EXPECT_EQ(Message::unpack(bytes.data(), bytes.size(), wire(), message), UnpackError::NONE);
    return message;
  }
};
}  // namespace

TEST(DigiViewCrc, CheckValueAndAgreementWithABitwiseImplementation)
{
  const std::string check = "123456789";
  EXPECT_EQ(crc8(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0x26);
  EXPECT_EQ(bitwiseCrc(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()), 0x26);
  std::uint8_t data[80];
  for (int round = 0; round < 50; ++round)
  {
    for (std::size_t index = 0; index < sizeof(data); ++index)
    {
      data[index] = static_cast<std::uint8_t>(index * 37 + round * 101);
    }
    EXPECT_EQ(crc8(data, sizeof(data)), bitwiseCrc(data, sizeof(data)));
  }
}

TEST_P(DigiViewMessages, HeaderChecksumAndTruncatedFields)
{
  CamTargeting targeting;
  targeting.camera = mainCamera(2);
  targeting.yaw = 1.2345;  // 1234.5 mrad: truncated, not rounded
  targeting.pitch = -0.0015;
  targeting.roll = -0.0009;  // toward zero: 0
  targeting.lock_flags = 3;
  targeting.x_offset = 0.5;
  targeting.y_offset = -1.0;
  targeting.target_latitude = -89.9999;
  targeting.target_altitude = 1e12;  // far outside int32: saturated (the published cast is undefined)
  Message message = packTargeting(wire(), MessageType::SET_PARAMETERS, targeting);
  message.timestamp = 0x0102030405060708ull;
  const Bytes bytes = message.pack();
  ASSERT_EQ(bytes.size(), layout().size);
  EXPECT_EQ((std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 11)),
            (std::vector<std::uint8_t>{ 0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01, 0x00, 0x02,
                                        paramWire(digiview::ParamType::CAM_TARGETING) }));
  const std::size_t data = layout().data_offset;
  const std::size_t after_name = data + b();
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&bytes[data]), 4), "main");
  EXPECT_EQ(bytes[data + 4] | bytes[after_name - 1], 0);  // NUL-padded
  EXPECT_EQ(bytes[after_name], 2);                        // cam_id
  EXPECT_EQ(int32At(bytes, after_name + 3), 1234);
  EXPECT_EQ(int32At(bytes, after_name + 7), -1);
  EXPECT_EQ(int32At(bytes, after_name + 11), 0);
  EXPECT_EQ(bytes[after_name + 15], 3);
  EXPECT_EQ(int16At(bytes, after_name + 16), 16383);   // 0.5 x 32767 = 16383.5, truncated
  EXPECT_EQ(int16At(bytes, after_name + 18), -32767);  // never -32768
  EXPECT_EQ(int32At(bytes, after_name + 20), -89999);
  EXPECT_EQ(int32At(bytes, after_name + (format() == Format::V0_5 ? 32 : 28)),
            std::numeric_limits<std::int32_t>::max());
  // After the altitude: 1.1's detection_id (-1 unless set: no detection), 1.2's track_id 0, view_id -1 (no lock),
  // lock_target 0; 1.0 leaves those bytes zero.
  if (format() != Format::V0_5)
  {
    EXPECT_EQ(int16At(bytes, after_name + 32), format() == Format::V1_1 ? -1 : 0);
    EXPECT_EQ(int16At(bytes, after_name + 34), format() == Format::V1_2 ? -1 : 0);
    EXPECT_EQ(bytes[after_name + 36], 0);
  }
  // The checksum covers every byte before it; padding is zero.
  EXPECT_EQ(bytes[layout().checksum_offset], bitwiseCrc(bytes.data(), layout().checksum_offset));
  for (std::size_t at = layout().checksum_offset + 1; at < bytes.size(); ++at)
  {
    EXPECT_EQ(bytes[at], 0) << at;
  }
  targeting.yaw = std::nan("");
  EXPECT_EQ(int32At(packTargeting(wire(), MessageType::SET_PARAMETERS, targeting).pack(), after_name + 3), 0);
  // In single precision, as the published packer: -0.511f x 1000 is -510.99997, so a yaw of -511 mrad read from
  // DigiView goes back as -510 (the fuzzer's round trips allow that one unit).
  targeting.yaw = -0.511;
  EXPECT_EQ(int32At(packTargeting(wire(), MessageType::SET_PARAMETERS, targeting).pack(), after_name + 3), -510);
}

TEST_P(DigiViewMessages, WhereEachFormatPutsTheSubscriptionInterval)
{
  const Bytes interval =
      packInterval(wire(), IntervalRequest{ digiview::ParamType::CAM_TARGETING, mainCamera(1), 250 }).pack();
  EXPECT_EQ(interval[10], paramWire(digiview::ParamType::CAM_TARGETING));
  if (format() == Format::V0_5)
  {
    EXPECT_EQ(interval[9], 4);                   // GET_INTERVAL
    EXPECT_EQ(int32At(interval, 11 + 12), 250);  // our choice: uint32 at data[12]
  }
  else
  {
    EXPECT_EQ(interval[9], 1);                 // a GET
    EXPECT_EQ(int32At(interval, 12), 250);     // interval_ms in the header
    EXPECT_EQ(int32At(interval, 16 + 12), 0);  // and nothing in the data
  }
  const Message message = unpacked(interval);
  IntervalRequest request;
  ASSERT_EQ(unpackInterval(message, request), UnpackError::NONE);
  EXPECT_EQ(request.param, digiview::ParamType::CAM_TARGETING);
  EXPECT_EQ(request.interval_ms, 250u);
  EXPECT_EQ(request.camera.cam_id, 1);
  // A plain GET: a subscription request with interval 0 from 1.0 on (a one-shot GET), none in 0.5.
  const Message get = unpacked(packGet(wire(), digiview::ParamType::CAM_TARGETING, mainCamera()).pack());
  EXPECT_EQ(unpackInterval(get, request), subscribesWithGet(format()) ? UnpackError::NONE : UnpackError::BAD_DATA);
  EXPECT_EQ(request.interval_ms, 0u);
}

TEST_P(DigiViewMessages, RoundTripOfEveryMessageAPtzClientNeeds)
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
  targeting.detection_id = -32768;
  targeting.track_id = 65535;
  targeting.view_id = -32768;
  targeting.lock_target = true;
  Message message = unpacked(packTargeting(wire(), MessageType::CURRENT_PARAMETERS, targeting).pack());
  EXPECT_EQ(message.message_type, MessageType::CURRENT_PARAMETERS);
  EXPECT_EQ(message.format, format());
  CamTargeting back;
  ASSERT_EQ(unpackTargeting(message, back), UnpackError::NONE);
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
  EXPECT_EQ(back.detection_id, format() == Format::V1_1 ? -32768 : -1);  // only 1.1 carries it
  EXPECT_EQ(back.track_id, format() == Format::V1_2 ? 65535 : 0);        // only 1.2 carries these
  EXPECT_EQ(back.view_id, format() == Format::V1_2 ? -32768 : -1);
  EXPECT_EQ(back.lock_target, format() == Format::V1_2);

  message = unpacked(
      packOptics(wire(), MessageType::SET_PARAMETERS, CamOpticsAndControl{ mainCamera(2), 127, 3.14, 2 }).pack());
  CamOpticsAndControl optics;
  ASSERT_EQ(unpackOptics(message, optics), UnpackError::NONE);
  EXPECT_EQ(optics.zoom, 127);
  EXPECT_DOUBLE_EQ(optics.fov, 3.14);
  EXPECT_EQ(optics.camera.cam_id, 2);
  EXPECT_EQ(optics.crop_mode, format() == Format::V1_2 ? 1 : 2);  // 1.2 has none: the default

  message = unpacked(packSystemStatus(wire(), MessageType::CURRENT_PARAMETERS, SystemStatus{ 3, 0, 71.5 }).pack());
  SystemStatus status;
  ASSERT_EQ(unpackSystemStatus(message, status), UnpackError::NONE);
  EXPECT_EQ(status.status, 3);
  EXPECT_DOUBLE_EQ(status.jetson_temp, 71.5);

  // Two views: the overlay box follows them @32, the size @40.
  VideoOutput output;
  output.stream_name = "main";
  output.width = 1280;
  output.height = 720;
  output.layout_mode = 2;
  output.num_user_views = 2;
  output.detection_overlay_mode = 2;
  output.views[1] = BoundingBox{ 640, 0, 640, 720 };
  output.views[2] = BoundingBox{ 9, 9, 9, 9 };  // not one of the two: not sent
  output.detection_overlay_box = BoundingBox{ 1, 2, 3, 4 };
  output.single_detection_size = 96;
  const Bytes output_bytes = packVideoOutput(wire(), MessageType::CURRENT_PARAMETERS, output).pack();
  const std::size_t after_name = layout().data_offset + b();
  EXPECT_EQ(output_bytes[after_name + 5], 2);  // the layout, alone in its byte
  EXPECT_EQ(output_bytes[after_name + 7], 2);  // num_user_views
  EXPECT_EQ(int16At(output_bytes, after_name + 24), 1);
  EXPECT_EQ(int16At(output_bytes, after_name + 32), 96);
  VideoOutput output_back;
  ASSERT_EQ(unpackVideoOutput(unpacked(output_bytes), output_back), UnpackError::NONE);
  EXPECT_EQ(output_back.num_user_views, 2);
  EXPECT_EQ(output_back.layout_mode, 2);
  EXPECT_EQ(output_back.width, 1280);
  EXPECT_EQ(output_back.views[1].x, 640);
  EXPECT_EQ(output_back.views[2].x, 0);
  EXPECT_EQ(output_back.detection_overlay_box.h, 4);
  EXPECT_EQ(output_back.single_detection_size, 96);

  for (MessageType type : { MessageType::ACKNOWLEDGEMENT, MessageType::CHECKSUM_ERROR, MessageType::DATA_ERROR,
                            MessageType::FORBIDDEN, MessageType::UNKNOWN, MessageType::QUIT })
  {
    message = unpacked(packBare(wire(), type, digiview::ParamType::CAM_TARGETING).pack());
    EXPECT_EQ(message.message_type, type);
    EXPECT_EQ(message.param_type, digiview::ParamType::CAM_TARGETING);
  }
}

TEST_P(DigiViewMessages, EveryMalformedMessageHasOneReasonAndLeavesDefinedOutputs)
{
  const std::size_t data = layout().data_offset;
  const std::size_t after_name = data + b();
  const std::size_t checksum = layout().checksum_offset;
  CamTargeting targeting;
  targeting.camera = mainCamera();
  const Bytes good = packTargeting(wire(), MessageType::SET_PARAMETERS, targeting).pack();
  auto with = [&](std::size_t at, std::uint8_t value, bool fix_checksum = true) {
    Bytes bytes = good;
    bytes[at] = value;
    if (fix_checksum)
    {
      bytes[checksum] = crc8(bytes.data(), checksum);
    }
    return bytes;
  };
  auto withInt32 = [&](std::size_t at, std::int32_t value) {
    Bytes bytes = good;
    for (std::size_t index = 0; index < 4; ++index)
    {
      bytes[after_name + at + index] = static_cast<std::uint8_t>(static_cast<std::uint32_t>(value) >> (8 * index));
    }
    bytes[checksum] = crc8(bytes.data(), checksum);
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
  const std::size_t size = layout().size;
  const std::vector<Case> cases = {
    { "one byte short", good, size - 1, UnpackError::BAD_SIZE, UnpackError::NONE },
    { "bad checksum", with(checksum, static_cast<std::uint8_t>(good[checksum] ^ 0x5A), false), size,
      UnpackError::BAD_CHECKSUM, UnpackError::NONE },
    { "a flipped data bit", with(after_name + 1, static_cast<std::uint8_t>(good[after_name + 1] ^ 0x01), false), size,
      UnpackError::BAD_CHECKSUM, UnpackError::NONE },
    { "version 1", with(8, 1), size, UnpackError::BAD_VERSION, UnpackError::NONE },
    { "message type 10", with(9, 10), size, UnpackError::BAD_MESSAGE_TYPE, UnpackError::NONE },
    { "message type 254", with(9, 254), size, UnpackError::BAD_MESSAGE_TYPE, UnpackError::NONE },
    { "a param type the format has not", with(10, format() == Format::V1_2 ? 12 : 13), size,
      UnpackError::BAD_PARAM_TYPE, UnpackError::NONE },
    { "param type 21", with(10, 21), size, UnpackError::BAD_PARAM_TYPE, UnpackError::NONE },
    { "cam_id 4", with(after_name, 4), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "targeting mode 4", with(after_name + 1, 4), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "euler_delta 2", with(after_name + 2, 2), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "lock flags 8", with(after_name + 15, 8), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "a control character in the stream name", with(data + 1, 0x07), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "yaw 3.2 rad", withInt32(3, 3200), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "pitch -1.6 rad", withInt32(7, -1600), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "latitude 91", withInt32(20, 91000), size, UnpackError::NONE, UnpackError::BAD_DATA },
    { "longitude 180", withInt32(format() == Format::V0_5 ? 28 : 24, 180000), size, UnpackError::NONE,
      UnpackError::BAD_DATA },
    { "lock_target 2 (1.2; unused bytes before)", with(after_name + 36, 2), size, UnpackError::NONE,
      format() == Format::V1_2 ? UnpackError::BAD_DATA : UnpackError::NONE },
  };
  for (const Case& item : cases)
  {
    Message message;
    message.timestamp = 42;
    EXPECT_EQ(Message::unpack(item.bytes.data(), item.size, wire(), message), item.message_error) << item.name;
    if (item.message_error != UnpackError::NONE)
    {
      EXPECT_EQ(message.timestamp, 0u) << item.name;  // defined: a default message
      continue;
    }
    CamTargeting read;
    read.yaw = 9.0;
    EXPECT_EQ(unpackTargeting(message, read), item.data_error) << item.name;
    if (item.data_error != UnpackError::NONE)
    {
      EXPECT_EQ(read.yaw, 0.0) << item.name;
    }
  }
  // In degrees the limits are +-180 and +-90: 179.999 is a yaw, 180.001 is not.
  const Wire degrees(format(), ChecksumRule::REQUIRED, AngleUnit::DEGREES);
  for (const auto& [raw, error] :
       { std::make_pair(179999, UnpackError::NONE), std::make_pair(180001, UnpackError::BAD_DATA) })
  {
    const Bytes bytes = withInt32(3, raw);
    Message message;
    ASSERT_EQ(Message::unpack(bytes.data(), bytes.size(), degrees, message), UnpackError::NONE);
    CamTargeting read;
    EXPECT_EQ(unpackTargeting(message, read), error) << raw;
  }
  // An optics unpack of a targeting message is refused too; so is a VIDEO_OUTPUT with more than four views.
  const Message message = unpacked(good);
  CamOpticsAndControl optics;
  EXPECT_EQ(unpackOptics(message, optics), UnpackError::BAD_DATA);
  Message output = packVideoOutput(wire(), MessageType::CURRENT_PARAMETERS, VideoOutput{});
  output.data[b() + 7] = 5;
  VideoOutput read;
  EXPECT_EQ(unpackVideoOutput(output, read), UnpackError::BAD_DATA);
  Message none;
  EXPECT_EQ(Message::unpack(nullptr, size, wire(), none), UnpackError::BAD_SIZE);
}

INSTANTIATE_TEST_SUITE_P(Formats, DigiViewMessages, ::testing::ValuesIn(digiview_test::FORMATS),
                         digiview_test::formatName);

// The rviz panel's image view: images converted for display by cv_bridge, with the header a pixel goal carries.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include <boost/make_shared.hpp>
#include <sensor_msgs/Image.h>

#include "ptz_action_server/panel/image_frame.h"

using namespace ptz_action_server::panel;

namespace
{
/// A `width` x `height` image of `bytes` per pixel, rows padded to `step` bytes, pixel i's bytes from `pixel(i)`.
template <class PixelBytes>
sensor_msgs::ImagePtr makeImage(const std::string& encoding, int width, int height, int bytes, std::uint32_t step,
                                PixelBytes pixel)
{
  auto image = boost::make_shared<sensor_msgs::Image>();
  image->header.seq = 7;
  image->header.stamp.sec = 1234;
  image->header.stamp.nsec = 500000000;
  image->header.frame_id = "ptz_camera_optical";
  image->encoding = encoding;
  image->width = width;
  image->height = height;
  image->step = step;
  image->data.assign(static_cast<std::size_t>(step) * height, 0xEE);  // the padding: never shown
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      const std::vector<std::uint8_t> value = pixel(row * width + column);
      for (int b = 0; b < bytes; ++b)
      {
        image->data[row * step + column * bytes + b] = value[b];
      }
    }
  }
  return image;
}

/// R, G, B of pixel i of the test pattern.
std::vector<std::uint8_t> rgbOf(int i)
{
  return { static_cast<std::uint8_t>(10 + i), static_cast<std::uint8_t>(100 + i), static_cast<std::uint8_t>(200 - i) };
}

void expectPattern(const ImageFrame& frame, int width, int height)
{
  ASSERT_EQ(frame.width, width);
  ASSERT_EQ(frame.height, height);
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      const std::vector<std::uint8_t> want = rgbOf(row * width + column);
      const std::uint8_t* got = frame.pixel(column, row);
      EXPECT_EQ((std::vector<std::uint8_t>{ got[0], got[1], got[2] }), want) << column << ", " << row;
    }
  }
}
}  // namespace

TEST(PanelModelFrame, ShowsRgbWithoutACopyAndKeepsTheHeader)
{
  sensor_msgs::ImageConstPtr image = makeImage("rgb8", 5, 3, 3, 17, rgbOf);
  const std::uint8_t* memory = image->data.data();
  ImageFrame frame;
  ASSERT_EQ(toFrame(image, frame), "");
  expectPattern(frame, 5, 3);
  EXPECT_EQ(frame.rgb.ptr<std::uint8_t>(0), memory) << "rgb8 is shown from the message's own memory";
  EXPECT_EQ(frame.seq, 7u);
  EXPECT_EQ(frame.stamp_sec, 1234u);
  EXPECT_EQ(frame.stamp_nsec, 500000000u);
  EXPECT_DOUBLE_EQ(frame.stamp(), 1234.5);
  EXPECT_EQ(frame.frame_id, "ptz_camera_optical");
  image.reset();  // the frame keeps the message alive
  expectPattern(frame, 5, 3);
}

TEST(PanelModelFrame, ConvertsBgrAlphaGreyAndDeepImages)
{
  const auto swapped = [](int i) {
    const auto c = rgbOf(i);
    return std::vector<std::uint8_t>{ c[2], c[1], c[0], 7 };
  };
  for (const auto& [encoding, bytes] : { std::pair{ "bgr8", 3 }, std::pair{ "bgra8", 4 } })
  {
    ImageFrame frame;
    EXPECT_EQ(toFrame(makeImage(encoding, 5, 3, bytes, 5 * bytes + 4, swapped), frame), "") << encoding;
    expectPattern(frame, 5, 3);
  }
  // Grey: the same value in R, G and B.
  ImageFrame frame;
  ASSERT_EQ(
      toFrame(makeImage("mono8", 4, 2, 1, 4, [](int i) { return std::vector<std::uint8_t>{ std::uint8_t(i * 30) }; }),
              frame),
      "");
  EXPECT_EQ(frame.pixel(3, 1)[0], 7 * 30);
  EXPECT_EQ(frame.pixel(3, 1)[2], 7 * 30);
  // 16 bits: brighter stays brighter in 8.
  ASSERT_EQ(toFrame(makeImage("mono16", 2, 1, 2, 4,
                              [](int i) {
                                return std::vector<std::uint8_t>{ 0, std::uint8_t(i ? 200 : 20) };
                              }),
                    frame),
            "");
  EXPECT_GT(frame.pixel(1, 0)[0], frame.pixel(0, 0)[0]);
}

TEST(PanelModelFrame, RefusesWhatItCannotShowAndKeepsTheFrame)
{
  ImageFrame frame;
  ASSERT_EQ(toFrame(makeImage("rgb8", 4, 2, 3, 12, rgbOf), frame), "");

  const std::string unknown = toFrame(makeImage("no_such_encoding", 4, 2, 3, 12, rgbOf), frame);
  EXPECT_NE(unknown.find("encoding 'no_such_encoding' cannot be shown"), std::string::npos) << unknown;
  sensor_msgs::ImagePtr truncated = makeImage("rgb8", 4, 2, 3, 12, rgbOf);
  truncated->data.resize(20);
  const std::string short_data = toFrame(truncated, frame);
  EXPECT_NE(short_data.find("has only 20 bytes"), std::string::npos) << short_data;
  sensor_msgs::ImagePtr empty = makeImage("rgb8", 4, 2, 3, 12, rgbOf);
  empty->width = 0;
  EXPECT_NE(toFrame(empty, frame).find("an empty image"), std::string::npos);
  expectPattern(frame, 4, 2);  // the last image shown is still there
}

// The rviz panel's image view: images converted for display, from each encoding it reads, into memory it reuses.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "ptz_action_server/panel/image_frame.h"

using namespace ptz_action_server::panel;

namespace
{
/// A `width` x `height` image of `bytes` per pixel, rows padded to `step`, pixel i's bytes from `pixel(i)`.
template <class PixelBytes>
std::vector<std::uint8_t> makeImage(int width, int height, int bytes, std::size_t step, PixelBytes pixel)
{
  std::vector<std::uint8_t> data(step * height, 0xEE);  // the padding: never shown
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      const std::vector<std::uint8_t> value = pixel(row * width + column);
      for (int b = 0; b < bytes; ++b)
      {
        data[row * step + column * bytes + b] = value[b];
      }
    }
  }
  return data;
}

ImageData dataOf(const std::string& encoding, int width, int height, std::size_t step,
                 const std::vector<std::uint8_t>& bytes)
{
  ImageData image;
  image.encoding = encoding;
  image.width = width;
  image.height = height;
  image.step = step;
  image.data = bytes.data();
  image.size = bytes.size();
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

TEST(PanelModelFrame, ReadsRgbBgrAndTheirAlphaFormsWithPaddedRows)
{
  constexpr int WIDTH = 5, HEIGHT = 3;
  const auto rgb = makeImage(WIDTH, HEIGHT, 3, 17, rgbOf);
  const auto bgr = makeImage(WIDTH, HEIGHT, 3, 16, [](int i) {
    const auto c = rgbOf(i);
    return std::vector<std::uint8_t>{ c[2], c[1], c[0] };
  });
  const auto rgba = makeImage(WIDTH, HEIGHT, 4, 24, [](int i) {
    const auto c = rgbOf(i);
    return std::vector<std::uint8_t>{ c[0], c[1], c[2], 7 };
  });
  const auto bgra = makeImage(WIDTH, HEIGHT, 4, 20, [](int i) {
    const auto c = rgbOf(i);
    return std::vector<std::uint8_t>{ c[2], c[1], c[0], 7 };
  });
  for (const auto& [encoding, bytes, step] :
       { std::tuple{ "rgb8", rgb, 17 }, std::tuple{ "bgr8", bgr, 16 }, std::tuple{ "rgba8", rgba, 24 },
         std::tuple{ "bgra8", bgra, 20 } })
  {
    ImageFrame frame;
    EXPECT_EQ(convertImage(dataOf(encoding, WIDTH, HEIGHT, step, bytes), frame), "") << encoding;
    expectPattern(frame, WIDTH, HEIGHT);
    EXPECT_EQ(frame.stride % 4, 0) << "QImage's rows start at 4-byte boundaries";
    EXPECT_GE(frame.stride, WIDTH * 3);
  }
}

TEST(PanelModelFrame, ReadsGreyAndYuv)
{
  // mono8: grey.
  const auto mono = makeImage(4, 2, 1, 4, [](int i) { return std::vector<std::uint8_t>{ static_cast<std::uint8_t>(i * 30) }; });
  ImageFrame frame;
  ASSERT_EQ(convertImage(dataOf("mono8", 4, 2, 4, mono), frame), "");
  EXPECT_EQ(frame.pixel(3, 1)[0], 7 * 30);
  EXPECT_EQ(frame.pixel(3, 1)[2], 7 * 30);

  // mono16: the high byte, in the message's byte order.
  const std::vector<std::uint8_t> little = { 0x34, 0x12, 0xFF, 0xAB };  // 0x1234, 0xABFF
  ASSERT_EQ(convertImage(dataOf("mono16", 2, 1, 4, little), frame), "");
  EXPECT_EQ(frame.pixel(0, 0)[1], 0x12);
  EXPECT_EQ(frame.pixel(1, 0)[1], 0xAB);
  ImageData big = dataOf("mono16", 2, 1, 4, little);
  big.big_endian = true;  // 0x3412, 0xFFAB
  ASSERT_EQ(convertImage(big, frame), "");
  EXPECT_EQ(frame.pixel(0, 0)[0], 0x34);
  EXPECT_EQ(frame.pixel(1, 0)[0], 0xFF);

  // yuv422 (U Y V Y) and yuv422_yuy2 (Y U Y V) of neutral chroma: the luma as grey, in BT.601's video range (Y 16 is
  // black, 235 white).
  const auto grey = [](int luma) { return 255.0 * (luma - 16) / (235 - 16); };
  const std::vector<std::uint8_t> uyvy = { 128, 60, 128, 200 };
  ASSERT_EQ(convertImage(dataOf("yuv422", 2, 1, 4, uyvy), frame), "");
  EXPECT_NEAR(frame.pixel(0, 0)[0], grey(60), 1.0);
  EXPECT_NEAR(frame.pixel(1, 0)[2], grey(200), 1.0);
  const std::vector<std::uint8_t> yuyv = { 60, 128, 200, 128 };
  ASSERT_EQ(convertImage(dataOf("yuv422_yuy2", 2, 1, 4, yuyv), frame), "");
  EXPECT_NEAR(frame.pixel(0, 0)[1], grey(60), 1.0);
  EXPECT_NEAR(frame.pixel(1, 0)[1], grey(200), 1.0);
}

TEST(PanelModelFrame, RefusesWhatItCannotShowAndKeepsTheFrame)
{
  const auto rgb = makeImage(4, 2, 3, 12, rgbOf);
  ImageFrame frame;
  ASSERT_EQ(convertImage(dataOf("rgb8", 4, 2, 12, rgb), frame), "");
  const std::vector<std::uint8_t> before = frame.rgb;

  const std::string bayer = convertImage(dataOf("bayer_rggb8", 4, 2, 4, rgb), frame);
  EXPECT_NE(bayer.find("'bayer_rggb8' is not shown"), std::string::npos) << bayer;
  EXPECT_NE(bayer.find("rgb8, bgr8"), std::string::npos) << bayer;
  const std::string short_step = convertImage(dataOf("rgb8", 4, 2, 10, rgb), frame);
  EXPECT_NE(short_step.find("rows of 12 bytes"), std::string::npos) << short_step;
  const std::string short_data = convertImage(dataOf("rgb8", 4, 3, 12, rgb), frame);
  EXPECT_NE(short_data.find("24 bytes"), std::string::npos) << short_data;
  EXPECT_NE(convertImage(dataOf("yuv422", 3, 1, 6, rgb), frame), "") << "an odd width";
  EXPECT_NE(convertImage(dataOf("rgb8", 0, 2, 12, rgb), frame), "");
  EXPECT_EQ(frame.width, 4);
  EXPECT_EQ(frame.rgb, before);
}

TEST(PanelModelFrame, ReusesItsMemoryFromOneImageToTheNext)
{
  const auto big = makeImage(64, 36, 3, 192, rgbOf);
  const auto small = makeImage(32, 18, 3, 96, rgbOf);
  ImageFrame frame;
  ASSERT_EQ(convertImage(dataOf("rgb8", 64, 36, 192, big), frame), "");
  const std::uint8_t* memory = frame.rgb.data();
  for (int i = 0; i < 10; ++i)
  {
    ASSERT_EQ(convertImage(dataOf(i % 2 == 0 ? "rgb8" : "bgr8", 64, 36, 192, big), frame), "");
    ASSERT_EQ(convertImage(dataOf("rgb8", 32, 18, 96, small), frame), "");  // smaller: fits
  }
  EXPECT_EQ(frame.rgb.data(), memory) << "no allocation for images of a size seen before";
  expectPattern(frame, 32, 18);
}

#include "ptz_action_server/panel/image_frame.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace ptz_action_server::panel
{
namespace
{
/// How an encoding converts: the source's OpenCV type and bytes per pixel, and the cvtColor code (-1: copied as is).
struct Conversion
{
  const char* encoding;
  int type;
  int bytes;
  int code;
};

constexpr int COPY = -1;
constexpr int MONO16 = -2;  ///< the high byte of each pixel, by hand (its byte order is the message's)

const Conversion CONVERSIONS[] = {
  { "rgb8", CV_8UC3, 3, COPY },
  { "bgr8", CV_8UC3, 3, cv::COLOR_BGR2RGB },
  { "rgba8", CV_8UC4, 4, cv::COLOR_RGBA2RGB },
  { "bgra8", CV_8UC4, 4, cv::COLOR_BGRA2RGB },
  { "mono8", CV_8UC1, 1, cv::COLOR_GRAY2RGB },
  { "8UC1", CV_8UC1, 1, cv::COLOR_GRAY2RGB },
  { "8UC3", CV_8UC3, 3, COPY },
  { "mono16", CV_16UC1, 2, MONO16 },
  { "16UC1", CV_16UC1, 2, MONO16 },
  { "yuv422", CV_8UC2, 2, cv::COLOR_YUV2RGB_UYVY },
  { "yuv422_yuy2", CV_8UC2, 2, cv::COLOR_YUV2RGB_YUYV },
};
}  // namespace

std::string convertImage(const ImageData& image, ImageFrame& frame)
{
  const Conversion* conversion = nullptr;
  for (const Conversion& candidate : CONVERSIONS)
  {
    if (image.encoding == candidate.encoding)
    {
      conversion = &candidate;
    }
  }
  if (conversion == nullptr)
  {
    return "encoding '" + image.encoding + "' is not shown (" + SHOWN_ENCODINGS + ")";
  }
  const std::string size = std::to_string(image.width) + " x " + std::to_string(image.height) + " px";
  if (image.width <= 0 || image.height <= 0)
  {
    return "an empty image (" + size + ")";
  }
  if ((conversion->code == cv::COLOR_YUV2RGB_UYVY || conversion->code == cv::COLOR_YUV2RGB_YUYV) &&
      image.width % 2 != 0)
  {
    return image.encoding + " with an odd width (" + size + ")";
  }
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * conversion->bytes;
  if (image.step < row_bytes || image.data == nullptr ||
      image.size < image.step * static_cast<std::size_t>(image.height - 1) + row_bytes)
  {
    return "a " + image.encoding + " image of " + size + " needs rows of " + std::to_string(row_bytes) +
           " bytes: it has a step of " + std::to_string(image.step) + " and " + std::to_string(image.size) + " bytes";
  }

  frame.width = image.width;
  frame.height = image.height;
  frame.stride = (image.width * 3 + 3) / 4 * 4;
  frame.rgb.resize(static_cast<std::size_t>(frame.stride) * frame.height);  // within its capacity: no allocation
  // OpenCV writes into the frame's own memory: a header over it of the right size and type is never reallocated.
  cv::Mat out(frame.height, frame.width, CV_8UC3, frame.rgb.data(), frame.stride);
  // Only read: cv::Mat has no header over const memory.
  const cv::Mat in(image.height, image.width, conversion->type, const_cast<std::uint8_t*>(image.data), image.step);
  if (conversion->code == COPY)
  {
    in.copyTo(out);
  }
  else if (conversion->code == MONO16)
  {
    const int high = image.big_endian ? 0 : 1;
    for (int row = 0; row < image.height; ++row)
    {
      const std::uint8_t* source = image.data + row * image.step;
      std::uint8_t* target = out.ptr<std::uint8_t>(row);
      for (int column = 0; column < image.width; ++column, source += 2, target += 3)
      {
        target[0] = target[1] = target[2] = source[high];
      }
    }
  }
  else
  {
    cv::cvtColor(in, out, conversion->code);
  }
  return "";
}

}  // namespace ptz_action_server::panel

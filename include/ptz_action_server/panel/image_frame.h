/**
 * \file
 * \brief An image as the panel's view draws it: packed 8-bit RGB rows, converted once per image from the encodings
 * cameras publish, into memory reused from one image to the next. No Qt, no ROS (test_core tests it).
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ptz_action_server::panel
{
/// One image converted for display, with the header fields a pixel goal on it carries.
struct ImageFrame
{
  std::uint32_t seq = 0;         ///< the image header's
  std::uint32_t stamp_sec = 0;   ///< the image header's stamp
  std::uint32_t stamp_nsec = 0;  ///< ns
  std::string frame_id;          ///< the image header's
  int width = 0;                 ///< px
  int height = 0;                ///< px
  int stride = 0;                ///< bytes per row: width * 3 rounded up to a multiple of 4, as QImage wants
  std::vector<std::uint8_t> rgb;  ///< height rows of `stride` bytes, R, G, B per pixel

  /// The stamp in seconds.
  double stamp() const
  {
    return stamp_sec + stamp_nsec * 1e-9;
  }
  /// The pixel (column, row) as R, G, B.
  const std::uint8_t* pixel(int column, int row) const
  {
    return rgb.data() + static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(column) * 3;
  }
};

/// The encodings convertImage reads, in words for the view's message.
inline constexpr const char* SHOWN_ENCODINGS = "rgb8, bgr8, rgba8, bgra8, mono8, mono16, yuv422, yuv422_yuy2";

/// One image as sensor_msgs/Image has it.
struct ImageData
{
  std::string encoding;  ///< sensor_msgs/image_encodings' name
  bool big_endian = false;
  int width = 0;   ///< px
  int height = 0;  ///< px
  std::size_t step = 0;  ///< bytes per row
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;  ///< bytes at data
};

/// Converts `image` into `frame`'s size and pixels (its header fields untouched), reusing `frame`'s memory whenever it
/// is large enough: rgb8, bgr8, rgba8, bgra8, mono8, mono16 (the high byte), yuv422 (UYVY) and yuv422_yuy2 (YUYV).
/// Returns "" or why the image cannot be shown (another encoding, a row step or a data size too short for the size);
/// `frame` is then left as it was.
std::string convertImage(const ImageData& image, ImageFrame& frame);

}  // namespace ptz_action_server::panel

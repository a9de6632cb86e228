/**
 * \file
 * \brief An image as the panel's view draws it: 8-bit RGB, converted once per image by cv_bridge's
 * cvtColorForDisplay (any encoding it reads: colour, grey, Bayer, YUV, 16-bit and float depths scaled), with the
 * header fields a pixel goal on it carries. No Qt (test_core tests it).
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core.hpp>
#include <sensor_msgs/Image.h>

namespace ptz_action_server::panel
{
/// One image converted for display.
struct ImageFrame
{
  std::uint32_t seq = 0;         ///< the image header's
  std::uint32_t stamp_sec = 0;   ///< the image header's stamp
  std::uint32_t stamp_nsec = 0;  ///< ns
  std::string frame_id;          ///< the image header's
  int width = 0;                 ///< px
  int height = 0;                ///< px
  /// CV_8UC3, R, G, B; may point into the message's memory (an rgb8 image is not copied).
  cv::Mat rgb;
  /// Keeps the memory rgb points into alive (cv_bridge's image, which holds the message).
  std::shared_ptr<const void> owner;

  /// The stamp in seconds.
  double stamp() const
  {
    return stamp_sec + stamp_nsec * 1e-9;
  }
  /// The pixel (column, row) as R, G, B.
  const std::uint8_t* pixel(int column, int row) const
  {
    return rgb.ptr<std::uint8_t>(row) + static_cast<std::size_t>(column) * 3;
  }
};

/// Converts `image` for display into `frame` (its header fields, size and pixels). Returns "" or why the image cannot
/// be shown (an encoding cv_bridge does not read, an empty image, a data size too short for its size); `frame` is
/// then left as it was.
std::string toFrame(const sensor_msgs::ImageConstPtr& image, ImageFrame& frame);

}  // namespace ptz_action_server::panel

/**
 * \file
 * \brief Finds blobs of one colour in an image: the core of ptz_blob_detector, plain C++ and OpenCV without ROS.
 */
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace ptz_action_server
{
/// The colour a blob is made of: an RGB colour give or take a tolerance per channel, or a range of hue, saturation
/// and value.
struct BlobColour
{
  bool hsv = false;                           ///< false: rgb and tolerance; true: the hue, saturation, value range
  std::array<int, 3> rgb{ { 255, 0, 255 } };  ///< 0..255 each (the sim's first marker colour, magenta)
  int tolerance = 40;                         ///< 0..255: how far each channel may be off rgb
  double hue_min = 0.0;                       ///< degrees in [0, 360]; hue_min > hue_max wraps through 0 (reds)
  double hue_max = 360.0;
  double saturation_min = 0.0;  ///< [0, 1]
  double saturation_max = 1.0;
  double value_min = 0.0;  ///< [0, 1]
  double value_max = 1.0;
};

/// How BlobFinder finds blobs.
struct BlobFinderSettings
{
  BlobColour colour;
  int min_area = 4;            ///< px: smaller blobs are noise
  std::size_t max_blobs = 10;  ///< the largest this many are kept
};

/// "" or what is wrong with \p settings (a channel, tolerance or range out of bounds), naming the setting.
std::string findBadBlobSettings(const BlobFinderSettings& settings);

/// The order of an image's colour channels.
enum class ChannelOrder
{
  RGB,  ///< rgb8, rgba8
  BGR,  ///< bgr8, bgra8
};

/// One blob: its pixels 8-connected, all of the colour. Pixels as camera_info's K: (0, 0) the centre of the top-left
/// pixel.
struct Blob
{
  double u = 0.0;  ///< px, the centroid of its pixels
  double v = 0.0;
  int left = 0;  ///< px, its bounding box: the first column, row, and how many columns and rows
  int top = 0;
  int width = 0;
  int height = 0;
  int area = 0;  ///< pixels
};

/**
 * \brief Finds the blobs of a colour in 8-bit colour images (3 or 4 channels), largest first.
 *
 * A mask of the pixels of the colour (cv::inRange, on the image itself for RGB, on its HSV conversion for a hue
 * range), then its 8-connected components with their areas, boxes and centroids (cv::connectedComponentsWithStats).
 * The buffers are kept from one image to the next. Not thread-safe.
 */
class BlobFinder
{
public:
  /// Throws std::invalid_argument with findBadBlobSettings()'s text.
  explicit BlobFinder(const BlobFinderSettings& settings);

  /// The blobs of \p image (CV_8UC3 or CV_8UC4, channels in \p order; an alpha channel is not looked at), largest
  /// first, at least min_area pixels, at most max_blobs. Throws std::invalid_argument for another type of image.
  const std::vector<Blob>& find(const cv::Mat& image, ChannelOrder order);

  const BlobFinderSettings& settings() const
  {
    return settings_;
  }

private:
  /// mask_ from a 3-channel \p image in \p order.
  void maskOf(const cv::Mat& image, ChannelOrder order);

  const BlobFinderSettings settings_;
  cv::Mat colour_;  ///< a 4-channel image without its alpha
  cv::Mat hsv_;
  cv::Mat mask_;
  cv::Mat wrapped_;  ///< a hue range through 0: its second half
  cv::Mat labels_;
  cv::Mat stats_;
  cv::Mat centroids_;
  std::vector<Blob> blobs_;
};

}  // namespace ptz_action_server

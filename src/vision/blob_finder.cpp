#include "ptz_action_server/vision/blob_finder.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
namespace blob_finder
{
/// OpenCV's 8-bit hue (COLOR_*2HSV_FULL: 256 steps a turn) of \p degrees.
int hueStep(double degrees)
{
  return std::min(255, static_cast<int>(std::lround(degrees * 256.0 / 360.0)));
}

int eightBit(double fraction)
{
  return static_cast<int>(std::lround(fraction * 255.0));
}

bool within(double value, double min, double max)
{
  return value >= min && value <= max;  // false for NaN
}
}  // namespace blob_finder

std::string findBadBlobSettings(const BlobFinderSettings& settings)
{
  const BlobColour& colour = settings.colour;
  std::ostringstream problem;
  if (!colour.hsv)
  {
    for (const int channel : colour.rgb)
    {
      if (channel < 0 || channel > 255)
      {
        problem << "the colour's channels must be in [0, 255], not " << channel;
        return problem.str();
      }
    }
    if (colour.tolerance < 0 || colour.tolerance > 255)
    {
      problem << "the tolerance must be in [0, 255], not " << colour.tolerance;
      return problem.str();
    }
  }
  else if (!blob_finder::within(colour.hue_min, 0.0, 360.0) || !blob_finder::within(colour.hue_max, 0.0, 360.0))
  {
    problem << "the hue range [" << colour.hue_min << ", " << colour.hue_max << "] must be within [0, 360] degrees";
    return problem.str();
  }
  else if (!blob_finder::within(colour.saturation_min, 0.0, colour.saturation_max) ||
           !blob_finder::within(colour.saturation_max, colour.saturation_min, 1.0) ||
           !blob_finder::within(colour.value_min, 0.0, colour.value_max) ||
           !blob_finder::within(colour.value_max, colour.value_min, 1.0))
  {
    problem << "the saturation range [" << colour.saturation_min << ", " << colour.saturation_max
            << "] and the value range [" << colour.value_min << ", " << colour.value_max
            << "] must be rising within [0, 1]";
    return problem.str();
  }
  if (settings.min_area < 1)
  {
    problem << "min_area must be at least 1 px, not " << settings.min_area;
    return problem.str();
  }
  if (settings.max_blobs < 1)
  {
    return "max_blobs must be at least 1";
  }
  return "";
}

BlobFinder::BlobFinder(const BlobFinderSettings& settings) : settings_(settings)
{
  const std::string problem = findBadBlobSettings(settings);
  if (!problem.empty())
  {
    throw ConfigError(problem);
  }
  blobs_.reserve(settings.max_blobs + 1);
}

const std::vector<Blob>& BlobFinder::find(const cv::Mat& image, ChannelOrder order)
{
  if (image.depth() != CV_8U || (image.channels() != 3 && image.channels() != 4))
  {
    throw std::invalid_argument("a blob is found in an 8-bit image of 3 or 4 channels, not of type " +
                                cv::typeToString(image.type()));
  }
  const cv::Mat* colour = &image;
  if (image.channels() == 4)
  {
    cv::cvtColor(image, colour_, order == ChannelOrder::RGB ? cv::COLOR_RGBA2RGB : cv::COLOR_BGRA2BGR);
    colour = &colour_;
  }
  maskOf(*colour, order);
  const int labels = cv::connectedComponentsWithStats(mask_, labels_, stats_, centroids_, 8, CV_32S);
  blobs_.clear();
  for (int label = 1; label < labels; ++label)  // 0 is the background
  {
    const int area = stats_.at<int>(label, cv::CC_STAT_AREA);
    if (area < settings_.min_area)
    {
      continue;
    }
    Blob blob;
    blob.u = centroids_.at<double>(label, 0);
    blob.v = centroids_.at<double>(label, 1);
    blob.left = stats_.at<int>(label, cv::CC_STAT_LEFT);
    blob.top = stats_.at<int>(label, cv::CC_STAT_TOP);
    blob.width = stats_.at<int>(label, cv::CC_STAT_WIDTH);
    blob.height = stats_.at<int>(label, cv::CC_STAT_HEIGHT);
    blob.area = area;
    blobs_.push_back(blob);
  }
  std::stable_sort(blobs_.begin(), blobs_.end(), [](const Blob& a, const Blob& b) { return a.area > b.area; });
  if (blobs_.size() > settings_.max_blobs)
  {
    blobs_.resize(settings_.max_blobs);
  }
  return blobs_;
}

void BlobFinder::maskOf(const cv::Mat& image, ChannelOrder order)
{
  const BlobColour& colour = settings_.colour;
  if (!colour.hsv)
  {
    const int tolerance = colour.tolerance;
    const int first = order == ChannelOrder::RGB ? colour.rgb[0] : colour.rgb[2];
    const int last = order == ChannelOrder::RGB ? colour.rgb[2] : colour.rgb[0];
    cv::inRange(image, cv::Scalar(first - tolerance, colour.rgb[1] - tolerance, last - tolerance),
                cv::Scalar(first + tolerance, colour.rgb[1] + tolerance, last + tolerance), mask_);
    return;
  }
  cv::cvtColor(image, hsv_, order == ChannelOrder::RGB ? cv::COLOR_RGB2HSV_FULL : cv::COLOR_BGR2HSV_FULL);
  const cv::Scalar low_sv(0, blob_finder::eightBit(colour.saturation_min), blob_finder::eightBit(colour.value_min));
  const cv::Scalar high_sv(255, blob_finder::eightBit(colour.saturation_max), blob_finder::eightBit(colour.value_max));
  const int hue_min = blob_finder::hueStep(colour.hue_min);
  const int hue_max = blob_finder::hueStep(colour.hue_max);
  if (colour.hue_min <= colour.hue_max)
  {
    cv::inRange(hsv_, cv::Scalar(hue_min, low_sv[1], low_sv[2]), cv::Scalar(hue_max, high_sv[1], high_sv[2]), mask_);
    return;
  }
  // Through 0 (reds): [hue_min, 360] and [0, hue_max].
  cv::inRange(hsv_, cv::Scalar(hue_min, low_sv[1], low_sv[2]), high_sv, mask_);
  cv::inRange(hsv_, low_sv, cv::Scalar(hue_max, high_sv[1], high_sv[2]), wrapped_);
  cv::bitwise_or(mask_, wrapped_, mask_);
}

}  // namespace ptz_action_server

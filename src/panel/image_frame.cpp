#include "ptz_action_server/panel/image_frame.h"

#include <exception>

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>

namespace ptz_action_server::panel
{
std::string toFrame(const sensor_msgs::ImageConstPtr& image, ImageFrame& frame)
{
  const std::string size = std::to_string(image->width) + " x " + std::to_string(image->height) + " px";
  if (image->width == 0 || image->height == 0)
  {
    return "an empty image (" + size + ")";
  }
  // cv_bridge trusts step and data: a message that lies about them must not be read past its end.
  if (image->step == 0 || image->data.size() < static_cast<std::size_t>(image->step) * image->height)
  {
    return "a " + image->encoding + " image of " + size + " with a step of " + std::to_string(image->step) +
           " bytes has only " + std::to_string(image->data.size()) + " bytes";
  }
  cv_bridge::CvImageConstPtr shown;
  try
  {
    shown = cv_bridge::cvtColorForDisplay(cv_bridge::toCvShare(image), sensor_msgs::image_encodings::RGB8);
  }
  catch (const std::exception& error)  // cv_bridge::Exception and cv::Exception
  {
    return "encoding '" + image->encoding + "' cannot be shown: " + error.what();
  }
  if (shown->image.type() != CV_8UC3 || shown->image.cols != static_cast<int>(image->width) ||
      shown->image.rows != static_cast<int>(image->height))
  {
    return "encoding '" + image->encoding + "' did not convert to rgb8 (" + size + ")";
  }
  frame.seq = image->header.seq;
  frame.stamp_sec = image->header.stamp.sec;
  frame.stamp_nsec = image->header.stamp.nsec;
  frame.frame_id = image->header.frame_id;
  frame.width = shown->image.cols;
  frame.height = shown->image.rows;
  frame.rgb = shown->image;
  frame.owner = std::shared_ptr<const void>(shown.get(), [shown](const void*) {});
  return "";
}

}  // namespace ptz_action_server::panel

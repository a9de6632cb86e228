#include "ptz_action_server/ros/image_clicks.h"

#include <utility>

#include <image_transport/camera_common.h>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
void LatestImage::set(const ros::Time& stamp, std::uint32_t width, std::uint32_t height)
{
  std::lock_guard<std::mutex> lock(mutex_);
  known_ = true;
  stamp_ = stamp;
  width_ = width;
  height_ = height;
}

bool LatestImage::get(ros::Time& stamp, std::uint32_t& width, std::uint32_t& height) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  stamp = stamp_;
  width = width_;
  height = height_;
  return known_;
}

ImageClicks::ImageClicks(const ros::NodeHandle& node_handle, const std::string& image_topic,
                         std::shared_ptr<LatestImage> local_images, Handler centre)
  : centre_(std::move(centre)), images_(std::move(local_images))
{
  ros::NodeHandle handle(node_handle);
  const std::string resolved = handle.resolveName(image_topic);
  click_topic_ = resolved + "_mouse_left";
  if (!images_)
  {
    images_ = std::make_shared<LatestImage>();
    info_topic_ = image_transport::getCameraInfoTopic(resolved);
    info_subscriber_ = handle.subscribe(info_topic_, 1, &ImageClicks::onCameraInfo, this);
  }
  click_subscriber_ = handle.subscribe(click_topic_, 10, &ImageClicks::onClick, this);
  ROS_INFO("centring the pixels clicked on %s (%s), as rqt_image_view publishes them", resolved.c_str(),
           click_topic_.c_str());
}

void ImageClicks::onCameraInfo(const sensor_msgs::CameraInfo::ConstPtr& info)
{
  images_->set(info->header.stamp, info->width, info->height);
}

void ImageClicks::onClick(const geometry_msgs::Point::ConstPtr& click)
{
  ros::Time stamp;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  if (!images_->get(stamp, width, height))
  {
    const std::string source = info_topic_.empty() ? "" : " (its stamp and size come from " + info_topic_ + ")";
    ROS_WARN("%s: click at (%g, %g) ignored: no image seen yet%s", click_topic_.c_str(), click->x, click->y,
             source.c_str());
    return;
  }
  PixelGoal goal;
  pixelOfMouseClick(*click, goal.u, goal.v);
  goal.image_width = static_cast<int>(width);
  goal.image_height = static_cast<int>(height);
  centre_(stamp, goal);
}

std::string describePixel(const PixelGoal& goal, const ros::Time& stamp)
{
  return formatText("pixel (%.1f, %.1f) of the %d x %d image at %.3f s", goal.u, goal.v, goal.image_width,
                    goal.image_height, stamp.toSec());
}

}  // namespace ptz_action_server

/**
 * \file
 * \brief Clicks on an image as rqt_image_view publishes them (`<image topic>_mouse_left`): each centres the pixel.
 */
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include <geometry_msgs/Point.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/pixel_aim.h"

namespace ptz_action_server
{
/// The header stamp and size of the latest image of a topic: what a click on that topic's picture needs. Thread-safe;
/// never allocates.
class LatestImage
{
public:
  void set(const ros::Time& stamp, std::uint32_t width, std::uint32_t height);
  /// False while no image came.
  bool get(ros::Time& stamp, std::uint32_t& width, std::uint32_t& height) const;

private:
  mutable std::mutex mutex_;
  bool known_ = false;
  ros::Time stamp_;
  std::uint32_t width_ = 0;
  std::uint32_t height_ = 0;
};

/**
 * \brief rqt_image_view's click (`geometry_msgs/Point` on `<image topic>_mouse_left`) as a pixel of camera_info's
 * convention.
 *
 * rqt_image_view publishes `round(x / widget width * image width)` (the same for y): the click's distance from the
 * image's left (top) outer edge in image pixels, rounded to a whole pixel, 0 to the image's size. camera_info's pixel
 * (0, 0) is the centre of the top-left pixel, half a pixel in from those edges: (x - 0.5, y - 0.5).
 */
inline void pixelOfMouseClick(const geometry_msgs::Point& click, double& u, double& v)
{
  u = click.x - 0.5;
  v = click.y - 0.5;
}

/**
 * \brief Subscribes to `<image topic>_mouse_left` (as rqt_image_view publishes clicks on an image) and hands each click
 * on, as a pixel goal on the latest image of the topic, to be centred.
 *
 * A click carries no stamp: it belongs to the latest image of the topic, whose stamp and size come from the topic's
 * sibling camera_info (image_transport's `<namespace>/camera_info`: small, and the image itself is never subscribed
 * for this), or, for the simulated camera's own picture, from its publisher (\p local_images) without a subscription.
 * A click before any image is dropped, with a warning. Runs on \p node_handle's queue (the node's main thread).
 */
class ImageClicks
{
public:
  /// Centres \p goal's pixel of the image stamped \p stamp.
  using Handler = std::function<void(const ros::Time& stamp, const PixelGoal& goal)>;

  /// \p image_topic is resolved in \p node_handle's namespace; \p local_images, if not null, is what the simulated
  /// camera publishes on it.
  ImageClicks(const ros::NodeHandle& node_handle, const std::string& image_topic,
              std::shared_ptr<LatestImage> local_images, Handler centre);

  /// The clicks' topic, resolved.
  const std::string& clickTopic() const
  {
    return click_topic_;
  }

private:
  void onClick(const geometry_msgs::Point::ConstPtr& click);
  void onCameraInfo(const sensor_msgs::CameraInfo::ConstPtr& info);

  const Handler centre_;
  std::shared_ptr<LatestImage> images_;
  std::string click_topic_;
  std::string info_topic_;  ///< "" with local images
  ros::Subscriber click_subscriber_;
  ros::Subscriber info_subscriber_;
};

/// "pixel (319.5, 179.5) of the 640 x 360 image at 12.345 s".
std::string describePixel(const PixelGoal& goal, const ros::Time& stamp);

}  // namespace ptz_action_server

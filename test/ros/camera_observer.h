/**
 * \file
 * \brief What the rostest clients see of the simulated camera: its images, camera_info and field_of_view, and its
 * markers found by colour.
 */
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "../core/wait_until.h"
#include "node_test.h"
#include "ptz_action_server/FieldOfView.h"

namespace ptz_action_server
{
/// Every image's stamp, the latest image, every camera_info and the latest field_of_view.
class CameraObserver
{
public:
  CameraObserver()
  {
    ros::NodeHandle node_handle;
    image_subscriber_ = node_handle.subscribe("image_raw", 5, &CameraObserver::onImage, this);
    info_subscriber_ = node_handle.subscribe("camera_info", 5, &CameraObserver::onInfo, this);
    view_subscriber_ = node_handle.subscribe("field_of_view", 5, &CameraObserver::onView, this);
  }

  /// Waits for an image stamped after \p after, and its camera_info (same stamp); false after the deadline.
  bool waitForImage(const ros::Time& after, sensor_msgs::Image& image, sensor_msgs::CameraInfo& info)
  {
    return waitForImage(
        after, [](const sensor_msgs::Image&) { return true; }, image, info);
  }

  /// Waits for an image stamped after \p after that \p wanted accepts, and its camera_info; false after the deadline.
  bool waitForImage(const ros::Time& after, const std::function<bool(const sensor_msgs::Image&)>& wanted,
                    sensor_msgs::Image& image, sensor_msgs::CameraInfo& info)
  {
    ros::Time last_looked_at;
    return waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          if (image_.header.stamp <= after)
          {
            return false;
          }
          for (const sensor_msgs::CameraInfo& candidate : infos_)
          {
            if (candidate.header.stamp == image_.header.stamp && image_.header.stamp != last_looked_at)
            {
              last_looked_at = image_.header.stamp;
              if (!wanted(image_))
              {
                return false;
              }
              image = image_;
              info = candidate;
              return true;
            }
          }
          return false;
        },
        GOAL_WAIT);
  }
  std::vector<ros::Time> stamps() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return stamps_;
  }
  bool waitForView(ptz_action_server::FieldOfView& view)
  {
    return waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          view = view_;
          return view_.horizontal > 0.0;
        },
        GOAL_WAIT);
  }

private:
  void onImage(const sensor_msgs::Image::ConstPtr& image)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    image_ = *image;
    stamps_.push_back(image->header.stamp);
  }
  void onInfo(const sensor_msgs::CameraInfo::ConstPtr& info)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    infos_.push_back(*info);
    if (infos_.size() > 20)
    {
      infos_.erase(infos_.begin());
    }
  }
  void onView(const ptz_action_server::FieldOfView::ConstPtr& view)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    view_ = *view;
  }

  mutable std::mutex mutex_;
  sensor_msgs::Image image_;
  std::vector<ros::Time> stamps_;
  std::vector<sensor_msgs::CameraInfo> infos_;
  ptz_action_server::FieldOfView view_;
  ros::Subscriber image_subscriber_;
  ros::Subscriber info_subscriber_;
  ros::Subscriber view_subscriber_;
};

/// The centroid of \p image's pixels of exactly \p colour; false if there are none.
inline bool centroidOf(const sensor_msgs::Image& image, const std::uint8_t (&colour)[3], double& u, double& v)
{
  double sum_u = 0.0;
  double sum_v = 0.0;
  int pixels = 0;
  for (std::uint32_t row = 0; row < image.height; ++row)
  {
    const std::uint8_t* pixel = &image.data[row * image.step];
    for (std::uint32_t column = 0; column < image.width; ++column, pixel += 3)
    {
      if (pixel[0] == colour[0] && pixel[1] == colour[1] && pixel[2] == colour[2])
      {
        sum_u += column;
        sum_v += row;
        ++pixels;
      }
    }
  }
  if (pixels == 0)
  {
    return false;
  }
  u = sum_u / pixels;
  v = sum_v / pixels;
  return true;
}

/// The smallest box holding \p image's pixels of exactly \p colour (columns and rows, inclusive); false if none.
inline bool boundingBoxOf(const sensor_msgs::Image& image, const std::uint8_t (&colour)[3], int& min_column,
                          int& max_column, int& min_row, int& max_row)
{
  min_column = static_cast<int>(image.width);
  min_row = static_cast<int>(image.height);
  max_column = -1;
  max_row = -1;
  for (int row = 0; row < static_cast<int>(image.height); ++row)
  {
    const std::uint8_t* pixel = &image.data[row * image.step];
    for (int column = 0; column < static_cast<int>(image.width); ++column, pixel += 3)
    {
      if (pixel[0] == colour[0] && pixel[1] == colour[1] && pixel[2] == colour[2])
      {
        min_column = std::min(min_column, column);
        max_column = std::max(max_column, column);
        min_row = std::min(min_row, row);
        max_row = std::max(max_row, row);
      }
    }
  }
  return max_column >= 0;
}

}  // namespace ptz_action_server

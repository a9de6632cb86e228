/**
 * \file
 * \brief One tf broadcaster for every camera in a process, and one latched /tf_static that holds all their fixed
 * joints.
 */
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include "ptz_action_server/ros/listened_publisher.h"

namespace ptz_action_server
{
/**
 * \brief The process's tf publishers, shared by its cameras.
 *
 * roscpp keeps one publication per topic in a process, and a latched topic keeps only the last message sent on it.
 * So when several cameras in one nodelet manager each had a tf2_ros::StaticTransformBroadcaster, a subscriber that
 * came later (rviz started after the cameras) got only the fixed joints of the camera that published last. Here
 * every camera's fixed joints go into one latched message, kept per owner, and republished whole whenever a camera
 * comes or goes. Thread-safe.
 */
class SharedTransforms
{
public:
  /// The process's instance, created by the first caller; it goes with the last holder.
  static std::shared_ptr<SharedTransforms> shared();

  SharedTransforms();

  /// True while /tf has a subscriber.
  bool listened() const
  {
    return publisher_.listened();
  }
  /// Sends moving joints on /tf (nothing while nobody listens); returns whether it sent them.
  bool send(const std::vector<geometry_msgs::TransformStamped>& transforms);
  /// Replaces the fixed joints of \p owner and republishes every owner's on the latched /tf_static.
  void setStatic(const void* owner, const std::vector<geometry_msgs::TransformStamped>& transforms);
  /// Drops the fixed joints of \p owner from what /tf_static holds for later subscribers.
  void removeStatic(const void* owner);

private:
  void publishStaticLocked();

  ros::NodeHandle node_handle_;
  ListenedPublisher publisher_;  ///< /tf, only while someone listens
  tf2_msgs::TFMessage message_;  ///< guarded by send_mutex_, reused
  std::mutex send_mutex_;
  std::mutex mutex_;
  ros::Publisher static_publisher_;
  std::map<const void*, std::vector<geometry_msgs::TransformStamped>> statics_;  ///< guarded by mutex_
  tf2_msgs::TFMessage static_message_;                                           ///< guarded by mutex_
};

}  // namespace ptz_action_server

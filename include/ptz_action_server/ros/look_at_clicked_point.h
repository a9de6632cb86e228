/**
 * \file
 * \brief "Look here" from rviz: the look_at_clicked_point switch, and a clicked point as a goal of the supervisor.
 */
#pragma once

#include <functional>
#include <string>

#include <geometry_msgs/PointStamped.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// The node's ~look_at_clicked_point and ~clicked_point_topic.
struct LookAtClickedPointConfig
{
  bool enabled = false;                  ///< the switch's value at start
  std::string topic = "/clicked_point";  ///< geometry_msgs/PointStamped, as rviz's Publish Point tool sends

  /// Reads ~look_at_clicked_point and ~clicked_point_topic.
  static LookAtClickedPointConfig load(const ParamReader& params);
};

/**
 * \brief The switch: the service look_at_clicked_point (std_srvs/SetBool) turns it on and off, the latched topic
 * look_at_clicked_point/enabled (std_msgs/Bool) says where it is, and while it is on every point on the clicked point
 * topic goes to the handler. While it is off the node does not even subscribe.
 *
 * One thread: the node handle's queue (the node's main thread), where the handler runs too.
 */
class LookAtClickedPoint
{
public:
  using Handler = std::function<void(const geometry_msgs::PointStamped&)>;

  /// Advertises the service and the latched topic in \p node_handle's namespace and publishes the start value.
  LookAtClickedPoint(const ros::NodeHandle& node_handle, const LookAtClickedPointConfig& config, Handler aim);

  bool enabled() const
  {
    return enabled_;
  }
  /// Subscribes to the clicked point topic (or stops) and publishes the new value.
  void setEnabled(bool enabled);

private:
  bool onSwitch(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);

  ros::NodeHandle node_handle_;
  const LookAtClickedPointConfig config_;
  const Handler aim_;
  bool enabled_ = false;
  ros::Publisher enabled_publisher_;
  ros::ServiceServer switch_service_;
  ros::Subscriber point_subscriber_;  ///< only while enabled
};

/// "(1.000, -2.000, 0.500) in 'map'".
std::string describePoint(const geometry_msgs::PointStamped& point);

}  // namespace ptz_action_server

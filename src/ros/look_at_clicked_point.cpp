#include "ptz_action_server/ros/look_at_clicked_point.h"

#include <utility>

#include <std_msgs/Bool.h>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
LookAtClickedPointConfig LookAtClickedPointConfig::load(const ParamReader& params)
{
  LookAtClickedPointConfig config;
  config.enabled = params.flag("look_at_clicked_point", config.enabled);
  config.topic = params.text("clicked_point_topic", config.topic);
  if (config.topic.empty())
  {
    throw ConfigError("parameter " + params.resolve("clicked_point_topic") + " is empty: name a PointStamped topic");
  }
  return config;
}

LookAtClickedPoint::LookAtClickedPoint(const ros::NodeHandle& node_handle, const LookAtClickedPointConfig& config,
                                       Handler aim)
  : node_handle_(node_handle), config_(config), aim_(std::move(aim))
{
  enabled_publisher_ = node_handle_.advertise<std_msgs::Bool>("look_at_clicked_point/enabled", 1, true);
  switch_service_ = node_handle_.advertiseService("look_at_clicked_point", &LookAtClickedPoint::onSwitch, this);
  setEnabled(config_.enabled);
}

void LookAtClickedPoint::setEnabled(bool enabled)
{
  if (enabled && !point_subscriber_)
  {
    point_subscriber_ = node_handle_.subscribe<geometry_msgs::PointStamped>(
        config_.topic, 1, [this](const geometry_msgs::PointStamped::ConstPtr& point) {
          if (enabled_)
          {
            aim_(*point);
          }
        });
    ROS_INFO("look_at_clicked_point on: aiming at the points on %s", point_subscriber_.getTopic().c_str());
  }
  else if (!enabled && point_subscriber_)
  {
    point_subscriber_.shutdown();
    ROS_INFO("look_at_clicked_point off");
  }
  enabled_ = enabled;
  std_msgs::Bool message;
  message.data = enabled_;
  enabled_publisher_.publish(message);
}

bool LookAtClickedPoint::onSwitch(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response)
{
  setEnabled(request.data);
  response.success = true;
  response.message = std::string("look_at_clicked_point is ") + (enabled_ ? "on" : "off");
  return true;
}

std::string describePoint(const geometry_msgs::PointStamped& point)
{
  return formatText("(%.3f, %.3f, %.3f) in '%s'", point.point.x, point.point.y, point.point.z,
                    point.header.frame_id.c_str());
}

}  // namespace ptz_action_server

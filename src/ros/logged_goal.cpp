#include "ptz_action_server/ros/logged_goal.h"

#include <utility>

#include <ros/console.h>

namespace ptz_action_server
{
// Rejections: a clicked point in an unknown frame, one the camera cannot aim at or outside the limits; a click with a
// stamp outside the pose history, with no field of view, or off the image.
const LoggedGoalWording CLICKED_POINT_GOAL{ "look_at_clicked_point", "aiming at", "aimed at" };
const LoggedGoalWording IMAGE_CLICK_GOAL{ "image_click", "centring", "centred" };

LoggedGoal::LoggedGoal(const LoggedGoalWording& wording, std::string id, std::string where)
  : wording_(wording), action_(wording.action), id_(std::move(id)), where_(std::move(where))
{
}

void LoggedGoal::accept(const std::string& text)
{
  ROS_INFO("%s: %s %s%s%s", wording_.action, wording_.doing, where_.c_str(), text.empty() ? "" : ": ", text.c_str());
}

void LoggedGoal::reject(const std::string& text)
{
  ROS_WARN("%s: not %s %s: %s", wording_.action, wording_.doing, where_.c_str(), text.c_str());
}

void LoggedGoal::succeed(const std::string& text)
{
  ROS_DEBUG("%s: %s %s: %s", wording_.action, wording_.done, where_.c_str(), text.c_str());
}

void LoggedGoal::abort(const std::string& text)
{
  ROS_WARN("%s: %s %s aborted: %s", wording_.action, wording_.doing, where_.c_str(), text.c_str());
}

void LoggedGoal::preempt(const std::string& text)
{
  ROS_DEBUG("%s: %s %s preempted: %s", wording_.action, wording_.doing, where_.c_str(), text.c_str());
}

}  // namespace ptz_action_server

// ptz_aim_marker against the running sim node (the same rostest as the panel, ptz_panel.test): no display needed.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <mutex>

#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>

#include "../core/wait_until.h"
#include "panel_test.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/panel/panel_model.h"

namespace
{
/// ptz_aim_marker, fed the feedback rviz sends when an operator drags the marker: no display needed.
TEST(AimMarker, ADragSendsAPositionGoalAndTheMarkerFollowsTheCamera)
{
  Observer observer;
  ros::NodeHandle node("/ptz");
  ros::Publisher feedback = node.advertise<visualization_msgs::InteractiveMarkerFeedback>("aim_marker/feedback", 10);
  const auto until = [](const std::function<bool()>& done) { return ptz_action_server::waitUntil(done, WAIT); };
  ASSERT_TRUE(until([&] { return feedback.getNumSubscribers() > 0; }));
  ASSERT_TRUE(until([&] {
    std::lock_guard<std::mutex> lock(observer.mutex);
    return observer.has_state && observer.marker_aim.has_value();
  }));

  visualization_msgs::InteractiveMarkerFeedback drag;
  drag.client_id = "/rviz/InteractiveMarkers";
  drag.marker_name = "aim";
  drag.control_name = "pan";
  drag.header.frame_id = "ptz_base_link";
  const ptz_action_server::panel::Quaternion q = ptz_action_server::panel::orientationOfAim({ 0.4, 0.2 });
  drag.pose.orientation.x = q.x;
  drag.pose.orientation.y = q.y;
  drag.pose.orientation.z = q.z;
  drag.pose.orientation.w = q.w;
  drag.event_type = visualization_msgs::InteractiveMarkerFeedback::MOUSE_DOWN;
  feedback.publish(drag);
  drag.event_type = visualization_msgs::InteractiveMarkerFeedback::MOUSE_UP;
  feedback.publish(drag);
  EXPECT_TRUE(until([&] {
    std::lock_guard<std::mutex> lock(observer.mutex);
    return !observer.absolute_goals.empty() && std::abs(observer.absolute_goals.back().pan - 0.4) < 1e-4 &&
           std::abs(observer.absolute_goals.back().tilt - 0.2) < 1e-4 && std::abs(observer.state.pan - 0.4) < 0.006 &&
           std::abs(observer.state.tilt - 0.2) < 0.006;
  }));

  // Another client moves the camera: the marker follows ptz_state.
  actionlib::SimpleActionClient<ptz_action_server::PtzAction> client(node, "move_ptz/position_abs", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(WAIT)));
  ptz_action_server::PtzGoal goal;
  goal.pan = -0.3f;
  goal.tilt = 0.1f;
  goal.zoom = 1.0f;
  client.sendGoal(goal);
  EXPECT_TRUE(until([&] {
    std::lock_guard<std::mutex> lock(observer.mutex);
    return observer.marker_aim && std::abs(observer.marker_aim->pan + 0.3) < 0.006 &&
           std::abs(observer.marker_aim->tilt - 0.1) < 0.006;
  }));
}

}  // namespace

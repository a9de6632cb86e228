#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_broadcaster.h>

#include "figures.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/text.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;

constexpr double CIRCLE_RATE = 0.5;     ///< rad/s the frame circles the camera at
constexpr double CIRCLE_RADIUS = 4.0;   ///< m
constexpr double START_ANGLE = -2.4;    ///< rad of pan where the frame starts; it ends at +2.4, inside +-pi
constexpr double TRACK_SECONDS = 9.6;   ///< s of tracking
constexpr double SETTLE_SECONDS = 1.0;  ///< s after the goal not judged (the issue's "after the first second")
constexpr double FRAME_RATE = 50.0;     ///< Hz the frame is published at
const char* const TARGET_FRAME = "bench_target";

/// Where the frame is at \p seconds after the start, in the pan base frame: around the pan axis at camera height,
/// at the pan angle START_ANGLE + CIRCLE_RATE * seconds (pan is clockwise seen from above).
Eigen::Vector3d targetAt(double seconds, double camera_height)
{
  const double angle = START_ANGLE + CIRCLE_RATE * seconds;
  return { CIRCLE_RADIUS * std::cos(angle), -CIRCLE_RADIUS * std::sin(angle), camera_height };
}

Eigen::Vector3d opticalAxis(const PtzKinematics& kinematics, double pan, double tilt)
{
  return kinematics.cameraInBase(pan, tilt).linear() * Eigen::Vector3d::UnitX();
}
}  // namespace

Row trackFigure(ros::NodeHandle& node_handle)
{
  std::string urdf;
  ros::param::get(std::string(NODE_NAMESPACE) + "/robot_description", urdf);
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(urdf);
  const double camera_height = kinematics.cameraInBase(0.0, 0.0).translation().z();

  // The angular error of each joint state, measured against where the frame truly was at that state's stamp.
  std::mutex mutex;
  std::vector<double> errors;
  ros::Time judged_from;
  ros::Time started;
  const ros::Subscriber states = node_handle.subscribe<sensor_msgs::JointState>(
      "joint_states", 100, [&](const sensor_msgs::JointState::ConstPtr& state) {
        std::lock_guard<std::mutex> lock(mutex);
        if (judged_from.isZero() || state->header.stamp < judged_from || state->position.size() < 2)
        {
          return;
        }
        const Eigen::Vector3d target = targetAt((state->header.stamp - started).toSec(), camera_height);
        double pan = 0.0;
        double tilt = 0.0;
        kinematics.aimAt(target, pan, tilt);
        const double cosine =
            opticalAxis(kinematics, state->position[0], state->position[1]).dot(opticalAxis(kinematics, pan, tilt));
        errors.push_back(std::acos(std::min(1.0, cosine)));
      });

  // The camera starts on the frame, so the figure is about following, not about the first slew.
  actionlib::SimpleActionClient<PtzFrameAction> client(node_handle, "move_ptz/track_frame", true);
  client.waitForServer(ros::Duration(10.0));
  tf2_ros::TransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped transform;
  transform.header.frame_id = kinematics.baseFrame();
  transform.child_frame_id = TARGET_FRAME;
  transform.transform.rotation.w = 1.0;
  auto publishAt = [&](const ros::Time& stamp) {
    const Eigen::Vector3d target = targetAt((stamp - started).toSec(), camera_height);
    transform.header.stamp = stamp;
    transform.transform.translation.x = target.x();
    transform.transform.translation.y = target.y();
    transform.transform.translation.z = target.z();
    broadcaster.sendTransform(transform);
  };
  {
    std::lock_guard<std::mutex> lock(mutex);
    started = ros::Time::now();
  }
  ros::Rate rate(FRAME_RATE);
  // The frame waits at the start for 2 s (the goal's first slew), then the clock of the circle starts.
  const ros::WallTime hold_until = ros::WallTime::now() + ros::WallDuration(2.0);
  ptz_action_server::PtzFrameGoal goal;
  goal.frame_id = TARGET_FRAME;
  goal.zoom = 1.0;
  bool sent = false;
  while (ros::WallTime::now() < hold_until)
  {
    {
      std::lock_guard<std::mutex> lock(mutex);
      started = ros::Time::now();
    }
    publishAt(ros::Time::now());
    if (!sent)
    {
      client.sendGoal(goal);
      sent = true;
    }
    rate.sleep();
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    started = ros::Time::now();
    judged_from = started + ros::Duration(SETTLE_SECONDS);
  }
  const ros::Time end = started + ros::Duration(TRACK_SECONDS);
  while (ros::Time::now() < end && ros::ok())
  {
    publishAt(ros::Time::now());
    rate.sleep();
  }
  client.cancelGoal();
  client.waitForResult(ros::Duration(5.0));
  std::lock_guard<std::mutex> lock(mutex);
  std::vector<double> sorted = errors;
  std::sort(sorted.begin(), sorted.end());
  if (sorted.empty())
  {
    return { "track_frame: angular error (frame circling at 0.5 rad/s)", "no joint states", "p95 <= 0.02 rad" };
  }
  return { "track_frame: angular error (frame circling at 0.5 rad/s, after 1 s)",
           formatText("p50 %.4f rad, p95 %.4f rad, max %.4f rad (%zu states)", sorted[sorted.size() / 2],
                      sorted[sorted.size() * 95 / 100], sorted.back(), sorted.size()),
           "p95 <= 0.02 rad" };
}

}  // namespace ptz_bench

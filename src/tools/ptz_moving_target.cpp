// ptz_moving_target: a target moving around the camera, for trying tracking without hardware. Publishes the tf frame
// `frame` under `parent` on a path at a constant angular speed around the parent's origin; list the frame in the
// simulated camera's ~camera/frames and the camera draws it (the first of the list in magenta, which
// ptz_blob_detector looks for by default).
//
// Parameters (private, read once; a bad one exits 1 naming it):
//   frame (ptz_moving_target), parent (ptz_base_link): the frame published and the one it moves in.
//   path (sweep): "sweep", back and forth between centre - amplitude and centre + amplitude; "circle", all the way
//     round; "still", at centre.
//   angular_speed (0.2 rad/s): in azimuth, positive to the right (clockwise from above, as pan); a sweep turns round
//     at its ends.
//   centre (0 rad), amplitude (0.5 rad): the azimuths of the path (the contract's pan that looks there).
//   elevation (0.1 rad), distance (10 m): the path's height as an angle seen from the parent's origin, and its radius.
//   rate (30 Hz): transforms a second.
//   visible_for (0 s: for ever): after this long the target leaves: it goes 1 km below the parent's origin, out of a
//     camera's view unless it looks straight down, and a tracker loses it.
// See doc/tracking-detections.md.
#include <cmath>
#include <string>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/types.h"
#include "ptz_action_server/ros/param_reader.h"

namespace
{
using ptz_action_server::ParamReader;

constexpr double GONE_BELOW = 1000.0;  ///< m below the parent's origin where a target that left is

/// The path's settings.
struct TargetPath
{
  std::string path = "sweep";
  double angular_speed = 0.2;  ///< rad/s
  double centre = 0.0;         ///< rad
  double amplitude = 0.5;      ///< rad
  double elevation = 0.1;      ///< rad
  double distance = 10.0;      ///< m

  static TargetPath load(const ParamReader& params)
  {
    TargetPath target;
    target.path = params.choice("path", target.path, { "sweep", "circle", "still" });
    target.angular_speed = params.number("angular_speed", target.angular_speed, -10.0, 10.0);
    target.centre = params.number("centre", target.centre, -2.0 * M_PI, 2.0 * M_PI);
    target.amplitude = params.number("amplitude", target.amplitude, 0.0, M_PI);
    target.elevation = params.number("elevation", target.elevation, -M_PI / 2.0, M_PI / 2.0);
    target.distance = params.number("distance", target.distance, 0.5, 1e5);
    return target;
  }

  /// The azimuth \p t s after the start: a sweep starts at the centre going the way of the speed's sign.
  double azimuthAt(double t) const
  {
    if (path == "still")
    {
      return centre;
    }
    if (path == "circle" || amplitude == 0.0)
    {
      return std::remainder(centre + angular_speed * t, 2.0 * M_PI);
    }
    // A triangle wave of the speed's slope: from the centre to one end, to the other, and back.
    const double travel = std::fmod(std::abs(angular_speed) * t + amplitude, 4.0 * amplitude);
    const double offset = travel < 2.0 * amplitude ? travel - amplitude : 3.0 * amplitude - travel;
    return centre + (angular_speed < 0.0 ? -offset : offset);
  }
};

class MovingTarget
{
public:
  MovingTarget(ros::NodeHandle& node, const ParamReader& params)
    : path_(TargetPath::load(params))
    , frame_(params.text("frame", "ptz_moving_target"))
    , parent_(params.text("parent", "ptz_base_link"))
    , visible_for_(params.number("visible_for", 0.0, 0.0, 1e9))
  {
    const double rate = params.number("rate", 30.0, 0.1, 1000.0);
    message_.header.frame_id = parent_;
    message_.child_frame_id = frame_;
    message_.transform.rotation.w = 1.0;
    ROS_INFO("ptz_moving_target: %s in %s, path %s at %g rad/s around azimuth %g rad (amplitude %g rad), "
             "elevation %g rad, %g m away, visible for %g s (0: for ever)",
             frame_.c_str(), parent_.c_str(), path_.path.c_str(), path_.angular_speed, path_.centre, path_.amplitude,
             path_.elevation, path_.distance, visible_for_);
    timer_ = node.createTimer(ros::Duration(1.0 / rate), &MovingTarget::publish, this);
  }

private:
  void publish(const ros::TimerEvent& event)
  {
    if (start_.isZero())
    {
      start_ = event.current_real;
    }
    const double t = (event.current_real - start_).toSec();
    Eigen::Vector3d position(0.0, 0.0, -GONE_BELOW);
    if (visible_for_ <= 0.0 || t < visible_for_)
    {
      position = path_.distance * ptz_action_server::directionOf(path_.azimuthAt(t), path_.elevation);
    }
    else if (!left_)
    {
      left_ = true;
      ROS_INFO("ptz_moving_target: %s leaves after %.1f s", frame_.c_str(), t);
    }
    message_.header.stamp = ros::Time::now();
    message_.transform.translation.x = position.x();
    message_.transform.translation.y = position.y();
    message_.transform.translation.z = position.z();
    broadcaster_.sendTransform(message_);
  }

  const TargetPath path_;
  const std::string frame_;
  const std::string parent_;
  const double visible_for_;
  tf2_ros::TransformBroadcaster broadcaster_;
  geometry_msgs::TransformStamped message_;
  ros::Timer timer_;
  ros::Time start_;
  bool left_ = false;
};

}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_moving_target");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try
  {
    MovingTarget target(node, ParamReader(private_node));
    ros::spin();
  }
  catch (const ptz_action_server::ConfigError& error)
  {
    ROS_FATAL("ptz_moving_target: %s", error.what());
    return 1;
  }
  return 0;
}

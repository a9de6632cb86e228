#include "ptz_action_server/ros/frame_tracking.h"

#include <tf2/exceptions.h>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
constexpr double LISTEN_RENEWAL = 1.0;  ///< s between restarts of the tf listener's countdown while tracking
}  // namespace

FrameTracking::FrameTracking(const ros::NodeHandle& node_handle, const PtzKinematics& kinematics,
                             const Capabilities& limits, const FrameTrackerConfig& config, GoalSupervisor& supervisor,
                             FrameListener& frame_listener, const PtzBackend& backend)
  : node_handle_(node_handle)
  , kinematics_(kinematics)
  , limits_(limits)
  , config_(config)
  , supervisor_(supervisor)
  , frame_listener_(frame_listener)
  , backend_(backend)
  , timer_(node_handle_.getCallbackQueue(), [this] { steer(); })
{
}

void FrameTracking::start(const std::string& action, const std::string& id, const std::string& frame_id, double zoom)
{
  frame_listener_.listen();
  target_.emplace(Target{ action, id, frame_id, FrameTracker(kinematics_, limits_, config_, zoom),
                          ros::SteadyTime::now(), clock_.now() });
  timer_.startPeriodic(1.0 / config_.rate);
  steer();
}

void FrameTracking::stop()
{
  target_.reset();
  timer_.stop();
}

void FrameTracking::steer()
{
  if (!target_ || !supervisor_.isRunning(target_->action, target_->id))
  {
    stop();  // the goal ended: preempted, cancelled or aborted
    return;
  }
  Target& target = *target_;
  const ros::SteadyTime now = ros::SteadyTime::now();
  if ((now - target.last_listen).toSec() >= LISTEN_RENEWAL)
  {
    frame_listener_.listen();  // keeps the listener on for as long as the goal lasts
    target.last_listen = now;
  }
  if (frame_listener_.listening())
  {
    try
    {
      // Time 0: the latest transform, without waiting.
      const geometry_msgs::TransformStamped transform =
          frame_listener_.buffer().lookupTransform(kinematics_.baseFrame(), target.frame_id, ros::Time(0));
      const Eigen::Vector3d origin(transform.transform.translation.x, transform.transform.translation.y,
                                   transform.transform.translation.z);
      const std::string problem = target.tracker.observe(origin, transform.header.stamp.toSec(), clock_.now());
      if (!problem.empty())
      {
        ROS_WARN_THROTTLE(1.0, "track_frame '%s': %s", target.frame_id.c_str(), problem.c_str());
      }
    }
    catch (const tf2::TransformException& error)
    {
      ROS_WARN_THROTTLE(1.0, "track_frame: %s", error.what());
    }
  }
  const TimePoint last_new = target.tracker.hasPosition() ? target.tracker.lastNewPositionAt() : target.started_at;
  const double silent_for = secondsBetween(last_new, clock_.now());
  if (silent_for > config_.timeout)
  {
    supervisor_.abort(target.action, target.id,
                      formatText("frame '%s' has not been updated in tf for %.2f s (track_timeout %.2f s)",
                                 target.frame_id.c_str(), silent_for, config_.timeout));
    stop();
    return;
  }
  if (!target.tracker.hasPosition())
  {
    return;
  }
  AxisValues aim{};
  const GoalCommand command = target.tracker.command(backend_.sample(), ros::Time::now().toSec(), aim);
  supervisor_.steer(target.action, target.id, command, aim);
}

}  // namespace ptz_action_server

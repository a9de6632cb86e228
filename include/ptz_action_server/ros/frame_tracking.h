/**
 * \file
 * \brief The move_ptz/track_frame loop: looks the tracked frame up in tf and steers the active tracking goal.
 */
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <ros/ros.h>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/motion/frame_tracker.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/ros/frame_listener.h"
#include "ptz_action_server/ros/queue_timer.h"

namespace ptz_action_server
{
/**
 * \brief Steers one tracking goal at a time at FrameTrackerConfig::rate, on the main queue.
 *
 * Each step looks the frame's latest transform up without waiting (other goals are never held up by tf), feeds a new
 * position to the FrameTracker and hands its command to the supervisor. A frame whose transform has not changed for
 * the timeout aborts the goal; a goal that ended (succeeded, preempted, cancelled, aborted) stops the loop.
 */
class FrameTracking
{
public:
  /// Everything referenced must outlive the loop (the PtzActionServer owns all of them).
  FrameTracking(const ros::NodeHandle& node_handle, const PtzKinematics& kinematics, const Capabilities& limits,
                const FrameTrackerConfig& config, GoalSupervisor& supervisor, FrameListener& frame_listener,
                const PtzBackend& backend);

  /// Starts steering the running goal \p id of \p action toward the origin of \p frame_id at \p zoom, replacing any
  /// goal it steered before.
  void start(const std::string& action, const std::string& id, const std::string& frame_id, double zoom);

  const FrameTrackerConfig& config() const
  {
    return config_;
  }

private:
  struct Target
  {
    std::string action;
    std::string id;
    std::string frame_id;
    FrameTracker tracker;
    ros::SteadyTime last_listen;  ///< when the tf listener's countdown was last restarted
    TimePoint started_at;         ///< the timeout counts from here until the frame's first position
  };

  void steer();
  void stop();

  ros::NodeHandle node_handle_;
  const PtzKinematics& kinematics_;
  const Capabilities limits_;
  const FrameTrackerConfig config_;
  GoalSupervisor& supervisor_;
  FrameListener& frame_listener_;
  const PtzBackend& backend_;
  SystemClock clock_;
  std::optional<Target> target_;
  QueueTimer timer_;  ///< steers at track/rate while a goal tracks
};

}  // namespace ptz_action_server

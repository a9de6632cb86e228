/**
 * \file
 * \brief The move_ptz/track_detections loop: a detector's boxes, on the goal's topic, steer the active goal through
 * the DetectionTracker; a lost target holds the camera or sends it to a preset.
 */
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <actionlib/server/action_server.h>
#include <ros/ros.h>

#include "ptz_action_server/Detections.h"
#include "ptz_action_server/PtzTrackDetectionsAction.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/goal/goal_monitor.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/detection_tracker.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/motion/pose_history.h"
#include "ptz_action_server/ros/detection_goal_handle.h"
#include "ptz_action_server/ros/goal_handle_adapter.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/ros/pixel_goals.h"
#include "ptz_action_server/ros/pose_recorder.h"
#include "ptz_action_server/ros/preset_services.h"
#include "ptz_action_server/ros/queue_timer.h"

namespace ptz_action_server
{
/// The node's settings for track_detections goals (beside ~track/rate, gain and feed_forward, which it shares with
/// track_frame).
struct DetectionTrackingSettings
{
  /// s without a matching detection before the target is lost, for goals whose lost_timeout is 0: a detector skips
  /// images more often than tf skips a frame, so longer than track_timeout.
  double lost_timeout = 2.0;
  /// true: each detection is seen from the camera's pose when its image was taken (the pose history). false, for
  /// benchmarks and debugging only: from the pose when the detection arrives, as a tracker without the history would.
  bool pose_history = true;

  /// Reads ~track/lost_timeout and ~track/pose_history.
  static DetectionTrackingSettings load(const ParamReader& params);
};

/**
 * \brief Runs the track_detections goals: converts each goal, submits it to the supervisor and, while it is the
 * active goal, subscribes to its detections topic (on the main queue), feeds each message to its DetectionTracker and
 * steers the device at FrameTrackerConfig::rate with the tracker's commands, publishing its errors as feedback.
 *
 * A lost target ends the goal (aborted, the outcome "lost: ..."): the device stops and holds, or with a lost_preset
 * first goes there (the goal still active, its detections no longer read) and the goal ends once it is there
 * ("...; at preset 'home'"). A goal that ended otherwise (preempted by any other goal, cancelled, aborted by the
 * supervisor) stops the loop and its subscription. One goal at a time, on the main queue.
 */
class DetectionTracking
{
public:
  using Handle = actionlib::ServerGoalHandle<PtzTrackDetectionsAction>;

  /// What the loop works with; everything referenced must outlive it (the PtzActionServer owns all of them).
  struct Parts
  {
    const PtzKinematics& kinematics;
    const Capabilities& limits;  ///< the node's
    const FrameTrackerConfig& steering;
    const DetectionTrackingSettings& settings;
    const GoalMonitorConfig& monitor;  ///< how arrival at the lost preset is judged
    const PixelConfig& pixel;          ///< the picture's lens and orientation
    PixelGoals::CalibrationSource calibration;
    GoalSupervisor& supervisor;
    const PtzBackend& backend;
    const PoseRecorder& poses;
    const PresetServices& presets;
  };

  DetectionTracking(const ros::NodeHandle& node_handle, const Parts& parts);
  ~DetectionTracking();

  DetectionTracking(const DetectionTracking&) = delete;
  DetectionTracking& operator=(const DetectionTracking&) = delete;

  /// Converts the goal of \p handle against the device's \p current state and submits it to the supervisor (which
  /// rejects it, or preempts the active goal and accepts it); once it runs, follows its detections. \p post_status
  /// runs its status changes.
  void submit(const Handle& handle, const StatusPoster& post_status, const PtzSample& current);

private:
  struct Goal;

  /// The tracker's settings from \p goal and the node's.
  DetectionTrackerConfig configOf(const PtzTrackDetectionsGoal& goal) const;
  /// The goal's first aim (where the camera is), or why it is refused.
  ConvertedGoal convert(const PtzTrackDetectionsGoal& goal, const DetectionTrackerConfig& config,
                        const PtzSample& current) const;
  /// The picture's pixels: the lens, the calibrated camera_info if any, the image's orientation.
  PixelCamera camera() const;
  void start(const PtzTrackDetectionsGoal& goal, const DetectionTrackerConfig& config,
             std::shared_ptr<DetectionGoalState> state);
  void onDetections(const Detections::ConstPtr& message);
  /// At the tracking rate: the tracker's step, or the way to the lost preset.
  void steer();
  /// The target is lost for \p reason: hold, or go to the lost preset.
  void lose(const std::string& reason, const PtzSample& current);
  /// Ends the goal once the device is at the lost preset.
  void judgeReturn(const PtzSample& current);
  /// Aborts the goal with \p text as its outcome and stops the loop.
  void end(const std::string& text);
  void stop();

  ros::NodeHandle node_handle_;
  const PtzKinematics& kinematics_;
  const Capabilities limits_;
  const FrameTrackerConfig steering_;
  const DetectionTrackingSettings settings_;
  const GoalMonitorConfig monitor_;
  const PixelConfig pixel_;  ///< owns the lens the goals' trackers point at
  const PixelGoals::CalibrationSource calibration_;
  GoalSupervisor& supervisor_;
  const PtzBackend& backend_;
  const PoseRecorder& poses_;
  const PresetServices& presets_;
  SystemClock clock_;

  std::unique_ptr<Goal> goal_;  ///< the goal being followed, or null
  ros::Subscriber detections_;  ///< its topic, while it tracks
  ImageDetections image_;       ///< each message's detections, its buffers reused
  PoseHistory arrival_pose_;    ///< without the pose history: the pose when the message arrived
  QueueTimer timer_;            ///< steers at the tracking rate while a goal runs
};

}  // namespace ptz_action_server

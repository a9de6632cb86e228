/**
 * \file
 * \brief The ROS node: its action servers around one backend, its GoalSupervisor and its StatePublisher.
 */
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>

#include <actionlib/server/action_server.h>
#include <geometry_msgs/PointStamped.h>
#include <ros/ros.h>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/goal/status_hold.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/ros/action_kind.h"
#include "ptz_action_server/ros/action_servers.h"
#include "ptz_action_server/ros/detection_tracking.h"
#include "ptz_action_server/ros/frame_goal_hold.h"
#include "ptz_action_server/ros/frame_listener.h"
#include "ptz_action_server/ros/frame_tracking.h"
#include "ptz_action_server/ros/goal_handle_adapter.h"
#include "ptz_action_server/ros/goal_translator.h"
#include "ptz_action_server/ros/image_clicks.h"
#include "ptz_action_server/ros/lens_interface.h"
#include "ptz_action_server/ros/look_at_clicked_point.h"
#include "ptz_action_server/ros/node_config.h"
#include "ptz_action_server/ros/operator_controls.h"
#include "ptz_action_server/ros/pixel_goals.h"
#include "ptz_action_server/ros/pose_recorder.h"
#include "ptz_action_server/ros/preset_services.h"
#include "ptz_action_server/ros/queue_timer.h"
#include "ptz_action_server/ros/tick_costs.h"
#include "ptz_action_server/ros/tour_goals.h"
#include "ptz_action_server/ros/tour_services.h"

namespace ptz_action_server
{
class StatePublisher;

/**
 * \brief The ptz_action_server node around one backend.
 *
 * It wires ROS to the core: a goal goes from its action callback (through the FrameGoalHold if it must wait for tf)
 * to the GoalTranslator, which converts it into a command against the device's current state, and then to the
 * GoalSupervisor, which checks it and commands the backend; the goal handle's status changes go through the
 * StatusHold. Every state sample it takes (the tick's and the backend's own reports) goes into the pose history that
 * pixel goals look the image's pose up in. ActionServers holds the action servers (one row each in NODE_ACTIONS); the
 * StatePublisher runs the 10 Hz state tick.
 *
 * Threads: the node handle's queue (the main thread) runs every action callback and the supervisor; the state tick
 * runs on the process's TimerThread and hands each sample to the main thread for the goal's feedback and verdict.
 * The backend is shared by both and is thread-safe by contract.
 */
class PtzActionServer
{
public:
  PtzActionServer(const ros::NodeHandle& node_handle, const NodeConfig& config, const PtzKinematics& kinematics,
                  std::shared_ptr<PtzBackend> backend);
  ~PtzActionServer();

  PtzActionServer(const PtzActionServer&) = delete;
  PtzActionServer& operator=(const PtzActionServer&) = delete;

  /// Starts the backend, then the state timer, then the action servers (last, so no goal meets a half-built node).
  /// Throws BackendError or ConfigError.
  void start();

  /// Lets the benchmark measure the state tick's parts into \p costs (see TickCosts); before start().
  void setTickCosts(TickCosts* costs)
  {
    tick_costs_ = costs;
  }

  /// Lets clicks on the simulated camera's picture (\p topic, resolved) take its images' stamps and sizes from
  /// \p images, which its publisher fills, instead of from its camera_info topic; before start().
  void setLocalImages(std::shared_ptr<LatestImage> images, const std::string& topic)
  {
    local_images_ = std::move(images);
    local_image_topic_ = topic;
  }

  /// The pose history's feed, for the simulated camera to record the pose of each image; built by start().
  std::shared_ptr<PoseRecorder> poseRecorder() const
  {
    return poses_;
  }

  /// Limits goals are checked against: the backend's capabilities narrowed by the URDF joint limits.
  const Capabilities& limits() const
  {
    return limits_;
  }

private:
  template <class Action>
  void onGoal(actionlib::ServerGoalHandle<Action> handle, ActionKind kind);
  template <class Action>
  void onCancel(actionlib::ServerGoalHandle<Action> handle, ActionKind kind);
  /// A tour goal goes to TourGoals, whose moves are goals of their own.
  void onGoal(actionlib::ServerGoalHandle<PtzTourAction> handle, ActionKind kind);
  void onCancel(actionlib::ServerGoalHandle<PtzTourAction> handle, ActionKind kind);
  /// Converts a goal against the device's current state and hands it to the supervisor, which checks and runs it.
  template <class Action>
  void submit(actionlib::ServerGoalHandle<Action> handle, ActionKind kind);
  /// Aims the optical axis at a clicked point, as a frame goal aims it at a frame's origin: it waits for tf the same
  /// way, then preempts the active goal (or is rejected, moving nothing, with the reason in the log).
  void lookAt(const geometry_msgs::PointStamped& point);
  /// Centres a pixel clicked on an image (ImageClicks) as a pixel goal does: it preempts the active goal (or is
  /// rejected, moving nothing, with the reason in the log).
  void centrePixel(const ros::Time& stamp, const PixelGoal& goal);

  /// Runs \p change (a goal's status change) through the status hold, arming its release timer if it is held.
  void postStatus(StatusHold::Change change);
  /// How the goal handles reach postStatus().
  StatusPoster statusPoster();
  /// Arms the one-shot timer that releases the held status changes at \p due (none if TimePoint::max()).
  void armStatusRelease(TimePoint due);
  /// On the main queue when the release timer fires: runs the held changes that are due, then arms it again.
  void releaseHeldStatuses();
  /// On the backend's thread when its state may have changed: records the pose, and queues one early verdict check on
  /// the main thread.
  void onBackendSample();

  ros::NodeHandle node_handle_;  ///< the node's namespace: actions and topics; the main callback queue
  NodeConfig config_;
  PtzKinematics kinematics_;
  std::shared_ptr<PtzBackend> backend_;
  Capabilities limits_;

  ros::Publisher capabilities_publisher_;            ///< latched: what the device can do, once started
  std::unique_ptr<GoalSupervisor> supervisor_;       ///< the goal state machine, on the main thread; built by start()
  std::unique_ptr<StatePublisher> state_publisher_;  ///< the 10 Hz tick, on its own thread; built by start()
  SystemClock clock_;
  StatusHold status_hold_;           ///< goal status changes after a new goal wait here (main thread)
  QueueTimer status_release_timer_;  ///< one-shot, armed while changes are held (no roscpp timer, no thread of its own)
  bool status_release_armed_ = false;
  std::atomic<bool> supervising_{ false };  ///< supervisor_ is built: backend reports may be judged
  /// What the backend's listener reaches this server through; the destructor cuts it (the backend may outlive us).
  struct ListenerTarget
  {
    std::mutex mutex;
    PtzActionServer* server = nullptr;
  };
  std::shared_ptr<ListenerTarget> listener_target_;
  std::atomic<bool> verdict_check_queued_{ false };  ///< an early verdict check waits on the main queue
  TickCosts* tick_costs_ = nullptr;                  ///< the benchmark's, or null

  // Frame lookups for position_abs_tf and frame goals; the listener feeds the buffer from the main queue.
  std::unique_ptr<FrameListener> frame_listener_;
  std::unique_ptr<FrameGoalHold> frame_hold_;   ///< a frame goal waiting for tf; built by start()
  std::shared_ptr<PoseRecorder> poses_;         ///< the pose history; built by start(), before supervising_
  std::unique_ptr<PixelGoals> pixel_goals_;     ///< pixels to commands; built by start()
  std::unique_ptr<GoalTranslator> translator_;  ///< goals to commands; built by start()

  ActionServers servers_;                                      ///< one per action; started by start()
  std::unique_ptr<FrameTracking> frame_tracking_;              ///< steers track_frame goals; built by start()
  std::unique_ptr<DetectionTracking> detection_tracking_;      ///< runs track_detections goals; built by start()
  std::unique_ptr<PresetServices> presets_;                    ///< the preset services and lookups; built by start()
  std::unique_ptr<LensInterface> lens_;                        ///< focus and iris; built by start()
  std::unique_ptr<LookAtClickedPoint> look_at_clicked_point_;  ///< the switch; built by start()
  std::uint64_t clicked_points_ = 0;                           ///< clicked points so far, for their ids
  std::shared_ptr<LatestImage> local_images_;                  ///< the simulated camera's, or null
  std::string local_image_topic_;                              ///< its image topic, resolved
  std::unique_ptr<ImageClicks> image_clicks_;                  ///< with ~image_topic only; built by start()
  std::uint64_t image_clicks_count_ = 0;                       ///< clicks on the image so far, for their ids
  std::unique_ptr<TourServices> tour_services_;                ///< the tour services; built by start()
  std::unique_ptr<TourGoals> tours_;            ///< tour goals and the idle return; built by start(), destroyed first
  std::unique_ptr<OperatorControls> controls_;  ///< ~default_speed and `controls`; built by start()
  std::unique_ptr<VelocityTopic> velocity_topic_;  ///< cmd/velocity; built by start()
};

}  // namespace ptz_action_server

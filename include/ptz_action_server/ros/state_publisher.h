/**
 * \file
 * \brief The node's fixed 10 Hz state tick: PtzState, joint_states, tf and diagnostics, on their own thread.
 */
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/update_functions.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/timer_thread.h"
#include "ptz_action_server/ros/field_of_view_publisher.h"
#include "ptz_action_server/ros/listened_publisher.h"
#include "ptz_action_server/ros/pose_recorder.h"
#include "ptz_action_server/ros/shared_transforms.h"
#include "ptz_action_server/ros/tick_costs.h"

namespace ptz_action_server
{
/**
 * \brief Publishes the device's state at 10 Hz, whatever the backend does, and hands the samples on.
 *
 * Each tick runs on the process's TimerThread, which ticks every camera of a nodelet manager together, on one grid of
 * the period (one thread and one wake-up instead of a timer and a spinner thread per camera): it takes one backend
 * sample, publishes PtzState (with the supervisor's mode), joint_states and the pan and tilt transforms, updates the
 * diagnostics (backend status, measured ptz_state rate), and while a goal is active passes the sample to the handler.
 * The messages are built once in start() and reused, so a tick allocates nothing of its own; a topic nobody listens to
 * costs the tick nothing but the check. Each sample's pose also goes to the pose history (setPoseRecorder()), stamped
 * as joint_states is.
 *
 * An axis whose device reports no position (AxisCapability::feedback false) is published as NaN in PtzState and is
 * left out of joint_states and tf: its pose is unknown, and a made-up one would mislead rviz and the clients.
 */
class StatePublisher
{
public:
  /// Called on the state thread (the TimerThread) with each sample taken while a goal is active.
  using SampleHandler = std::function<void(const GoalSample&)>;

  /// \p supervisor must outlive the publisher; only its thread-safe sample(), mode() and goalActive() are used.
  /// \p limits are the node's (the device's capabilities within the URDF's limits). \p node_name is the node's
  /// private namespace (/left/ptz_action_server): it names the diagnostics, whether the node is a process or a nodelet.
  StatePublisher(const ros::NodeHandle& node_handle, const std::string& node_name, const PtzKinematics& kinematics,
                 std::shared_ptr<PtzBackend> backend, const GoalSupervisor& supervisor, const Capabilities& limits,
                 bool publish_tf, SampleHandler hand_over);
  /// Stops the tick: once it returns, the handler and the tick hook are not called any more.
  ~StatePublisher();

  StatePublisher(const StatePublisher&) = delete;
  StatePublisher& operator=(const StatePublisher&) = delete;

  /// Publishes field_of_view on each tick (the zoomed camera_info is served on the node handle's queue). Before
  /// start().
  void addFieldOfView(const FieldOfViewSettings& settings);

  /// The field_of_view publisher (and the camera_info calibration it keeps), or null without one.
  const FieldOfViewPublisher* fieldOfView() const
  {
    return field_of_view_.get();
  }

  /// Records each tick's sample in \p poses (which must outlive the publisher), and tells it when ROS time went back.
  /// Before start().
  void setPoseRecorder(PoseRecorder* poses)
  {
    poses_ = poses;
  }

  /// Calls \p hook on the state thread at the end of every tick; it returns how many messages it sent (the action
  /// status lists). Before start().
  void setTickHook(std::function<int()> hook)
  {
    tick_hook_ = std::move(hook);
  }

  /// Measures each part of every tick into \p costs while its \c enabled is set (the benchmark's instrumented mode);
  /// \p costs must outlive the publisher. Before start().
  void setTickCosts(TickCosts* costs)
  {
    tick_costs_ = costs;
  }

  /// Advertises the topics, publishes the static transforms once (with tf on), then starts the tick.
  void start();

private:
  void onTick();
  void publishStaticTransforms();
  /// The URDF joint of pan or tilt.
  const JointModel& joint(Axis axis) const;
  /// What PtzState carries for \p axis: its position, or NaN when the device does not report it.
  float reported(Axis axis, const PtzSample& sample) const;
  void diagnoseBackend(diagnostic_updater::DiagnosticStatusWrapper& status);
  /// Logs the backend's new warnings (ROS_WARN) and keeps them for the diagnostics.
  void takeWarnings();

  ros::NodeHandle node_handle_;  ///< the node's namespace, on the node's queue
  const std::string node_name_;  ///< the node's private namespace
  PtzKinematics kinematics_;
  std::shared_ptr<PtzBackend> backend_;
  const GoalSupervisor& supervisor_;
  const Capabilities limits_;
  std::vector<Axis> reported_joints_;  ///< pan and tilt, those the device reports, in joint_states and tf
  const bool publish_tf_;
  const SampleHandler hand_over_;
  std::function<int()> tick_hook_;
  TickCosts* tick_costs_ = nullptr;  ///< the benchmark's, or null
  PoseRecorder* poses_ = nullptr;    ///< the pose history's, or null
  SystemClock clock_;

  // Only the state thread touches these after start().
  ListenedPublisher state_publisher_;
  ListenedPublisher joint_state_publisher_;
  PtzState state_message_;
  sensor_msgs::JointState joint_state_message_;
  std::vector<geometry_msgs::TransformStamped> joint_transforms_;  ///< of reported_joints_, reused every tick
  TimePoint last_transform_stamp_{};                               ///< of the state the joint tf was last sent for
  std::shared_ptr<SharedTransforms> transforms_;                   ///< null with tf off
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  double state_rate_min_ = 0.0;
  double state_rate_max_ = 0.0;
  std::unique_ptr<diagnostic_updater::FrequencyStatus> state_rate_;
  std::unique_ptr<FieldOfViewPublisher> field_of_view_;                 ///< null without a configured field of view
  std::vector<std::string> warnings_;                                   ///< every warning of the backend so far
  std::vector<std::pair<std::string, std::string>> capability_values_;  ///< the "can: ..." diagnostics, from start()
  std::shared_ptr<TimerThread> timer_;
  TimerThread::Id tick_ = 0;
};

}  // namespace ptz_action_server

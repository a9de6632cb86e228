/**
 * \file
 * \brief The ROS node: action servers, PtzState, joint_states, tf and diagnostics around one backend.
 */
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <actionlib/server/action_server.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/update_functions.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzRelToAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/goal_supervisor.h"
#include "ptz_action_server/core/kinematics.h"
#include "ptz_action_server/core/limits.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// The node's own settings (the backend reads its own under ~<backend>/).
struct NodeConfig
{
  std::string backend = "sim";       ///< plugin name; "sim" means "ptz_action_server/sim"
  bool clamp_goals = false;          ///< clamp out-of-range goals instead of rejecting them
  bool publish_tf = true;            ///< false: leave tf to robot_state_publisher (joint_states still published)
  KinematicsNames names;             ///< URDF joint and link names
  GoalMonitorConfig monitor;         ///< tolerances, stall and timeout rules
  int action_queue_size = 2000;      ///< actionlib goal/cancel subscriber and publisher queues
  double status_list_timeout = 1.0;  ///< s a finished goal stays in actionlib's status list (actionlib: 5)

  /// Reads ~backend, ~clamp_goals, ~publish_tf, ~pan_joint, ~tilt_joint, ~camera_link, ~tolerance/*, ~stall_timeout,
  /// ~goal_timeout, ~goal_timeout_scale, ~goal_timeout_margin, ~stop_timeout, ~action_queue_size,
  /// ~status_list_timeout.
  static NodeConfig load(const ParamReader& params);
};

/// One of the five actions, for names and messages.
enum class ActionKind
{
  POSITION_ABS,
  POSITION_REL,
  VELOCITY,
  POSITION_ABS_TF,
  FRAME,
};

const char* actionName(ActionKind kind);

/**
 * \brief The ptz_action_server node around one backend.
 *
 * Threads: the node handle's queue (the main thread) runs every action callback and the goal state machine; the
 * 10 Hz state timer runs on its own queue and spinner, publishes PtzState, joint_states, tf and diagnostics, and
 * hands each sample to the main thread for the goal's feedback and verdict. The backend is shared by both and is
 * thread-safe by contract.
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

  /// Limits goals are checked against: the backend's capabilities narrowed by the URDF joint limits.
  const Capabilities& limits() const
  {
    return limits_;
  }

  /// Pan and tilt limits and speeds from the URDF (the core's urdfLimits(), kept here for its callers).
  static Capabilities urdfLimits(const PtzKinematics& kinematics)
  {
    return ptz_action_server::urdfLimits(kinematics);
  }

private:
  using PtzServer = actionlib::ActionServer<PtzAction>;
  using PtzRelToServer = actionlib::ActionServer<PtzRelToAction>;
  using PtzFrameServer = actionlib::ActionServer<PtzFrameAction>;

  template <class Action>
  void onGoal(actionlib::ServerGoalHandle<Action> handle, ActionKind kind);
  template <class Action>
  void onCancel(actionlib::ServerGoalHandle<Action> handle, ActionKind kind);

  /// Converts a goal into what to command (a GoalConverter); returns "" or the reason to reject it.
  std::string toCommand(const PtzGoal& goal, ActionKind kind, const PtzSample& sample, GoalCommand& command) const;
  std::string toCommand(const PtzRelToGoal& goal, ActionKind kind, const PtzSample& sample, GoalCommand& command) const;
  std::string toCommand(const PtzFrameGoal& goal, ActionKind kind, const PtzSample& sample, GoalCommand& command) const;
  /// The transform from \p frame_id to the base frame, looked up once without waiting; "" or the reason.
  std::string lookupFrame(const std::string& frame_id, Eigen::Isometry3d& frame_in_base) const;

  void onStateTick();
  void publishStaticTransforms();
  void diagnoseBackend(diagnostic_updater::DiagnosticStatusWrapper& status);
  ros::Time toRosTime(TimePoint stamp) const;

  ros::NodeHandle node_handle_;        ///< the node's namespace: actions and topics; the main callback queue
  ros::NodeHandle state_node_handle_;  ///< same namespace on state_queue_
  NodeConfig config_;
  PtzKinematics kinematics_;
  std::shared_ptr<PtzBackend> backend_;
  SystemClock clock_;
  Capabilities limits_;

  std::unique_ptr<GoalSupervisor> supervisor_;  ///< the goal state machine, on the main thread; built by start()

  // State publishing: only the state thread touches these after start().
  ros::CallbackQueue state_queue_;
  std::unique_ptr<ros::AsyncSpinner> state_spinner_;
  ros::SteadyTimer state_timer_;
  ros::Publisher state_publisher_;
  ros::Publisher joint_state_publisher_;
  PtzState state_message_;
  sensor_msgs::JointState joint_state_message_;
  std::vector<geometry_msgs::TransformStamped> joint_transforms_;  ///< pan and tilt, reused every tick
  std::unique_ptr<tf2_ros::TransformBroadcaster> transform_broadcaster_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  double state_rate_min_ = 0.0;
  double state_rate_max_ = 0.0;
  std::unique_ptr<diagnostic_updater::FrequencyStatus> state_rate_;

  // Frame lookups for position_abs_tf and frame goals; the listener feeds the buffer from the main queue.
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;

  std::unique_ptr<PtzServer> position_abs_server_;
  std::unique_ptr<PtzServer> position_rel_server_;
  std::unique_ptr<PtzServer> velocity_server_;
  std::unique_ptr<PtzRelToServer> position_abs_tf_server_;
  std::unique_ptr<PtzFrameServer> frame_server_;
};

}  // namespace ptz_action_server

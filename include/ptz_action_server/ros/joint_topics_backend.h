/**
 * \file
 * \brief The joint_topics backend: pan-tilts driven through per-joint position controllers (Gazebo, ros_control,
 * Dynamixel servos): a std_msgs/Float64 command topic per joint, sensor_msgs/JointState back.
 *
 * It lives in the ROS layer because its device is reached through ROS topics.
 */
#pragma once

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/device/link_supervisor.h"
#include "ptz_action_server/core/motion/motion_estimator.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

namespace ptz_action_server
{
/// Settings of the joint_topics backend (read from ~joint_topics/ by its plugin).
struct JointTopicsConfig
{
  /// Float64 position command topic of the pan and tilt controllers, relative to the node's namespace.
  std::array<std::string, 2> command_topics{ { "pan_position_controller/command", "tilt_position_controller/"
                                                                                  "command" } };
  /// JointState topic the controllers (or joint_state_controller) publish, relative to the node's namespace.
  std::string state_topic = "device_joint_states";
  /// Names of the pan and tilt joints in that JointState.
  std::array<std::string, 2> joint_names{ { "ptz_pan_joint", "ptz_tilt_joint" } };
  /// The moving setpoint: limits, max speeds and accelerations of pan and tilt (zoom absent, no quantisation).
  SimDeviceConfig setpoint;
  double command_rate = 50.0;     ///< Hz at which setpoints are published while the setpoint moves
  double state_timeout = 0.5;     ///< s without joint states before the link counts as lost
  double startup_timeout = 10.0;  ///< s start() waits for the first joint states
  double settle_window = 0.1;     ///< s a still position must last to count as settled
};

/**
 * \brief Drives position controllers with a setpoint that moves as the node's goals ask.
 *
 * Position controllers take a position only and move to it as fast as their gains let them, so the backend never
 * sends a goal's target at once: it runs a setpoint through the shared trapezoidal motion model (SimDeviceModel) at
 * the configured speeds and accelerations and publishes it at command_rate while it moves. goTo() retargets it,
 * moveAtVelocity() runs it at the rate towards the limit, stop() brakes it. When the setpoint rests, the next command
 * starts it from the measured position (so the joints never jump back to an old setpoint).
 *
 * The state is the latest JointState that names both joints; velocity and "settled" are estimated from the
 * positions (the setpoint still moving also counts as moving). The link is up while such states come within
 * state_timeout (LinkSupervisor, as for every device backend); after a loss the first state holds the joints where
 * they are.
 *
 * Threads: the backend's own thread serves its callback queue (joint states, and the commands, which the PtzBackend
 * calls post there) and publishes the setpoints; sample() and diagnostics() read the snapshot under the mutex.
 */
class JointTopicsBackend : public PtzBackend
{
public:
  /// \p node_handle: topics are resolved in its namespace (the node's).
  JointTopicsBackend(const JointTopicsConfig& config, const ros::NodeHandle& node_handle,
                     std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~JointTopicsBackend() override;

  std::string name() const override
  {
    return "joint_topics";
  }
  Capabilities capabilities() const override;
  /// Subscribes, advertises and waits up to startup_timeout for joint states naming both joints.
  void start() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  PtzSample sample() const override;
  std::string lastFault() const override
  {
    return {};  // position controllers never refuse a command
  }
  std::string lastLinkLoss() const override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;
  /// Called after each joint state naming both joints.
  bool setSampleListener(SampleListener listener) override
  {
    listener_ = std::move(listener);
    return true;
  }

private:
  /// What a command does to the setpoint model; runs on the backend's thread.
  using Command = std::function<void(SimDeviceModel&, TimePoint)>;

  void post(Command command);
  void run();
  void onJointState(const sensor_msgs::JointState::ConstPtr& message);
  /// Takes a joint state's pan and tilt into the snapshot (and brings the link up).
  void recordJointState(const std::array<double, 2>& positions);
  /// A setpoint model resting at the measured position; call with mutex_ held.
  SimDeviceModel restingAtMeasured(TimePoint now) const;
  /// Publishes the setpoint if due (or \p now_anyway); returns the seconds until the next one is due.
  double publishSetpoints(TimePoint now, bool now_anyway);
  /// "joint states naming <pan> and <tilt> on <topic>"
  std::string stateSource() const;

  const JointTopicsConfig config_;
  const std::shared_ptr<const Clock> clock_;
  ros::CallbackQueue queue_;     ///< declared before node_handle_: the subscription registers on it
  ros::NodeHandle node_handle_;  ///< the node's namespace, on queue_
  std::array<ros::Publisher, 2> command_publishers_;
  ros::Subscriber state_subscriber_;
  std::atomic<bool> running_{ false };
  std::thread thread_;
  SampleListener listener_;  ///< set before start(); called on thread_

  mutable std::mutex mutex_;  ///< guards everything below
  SimDeviceModel setpoint_;
  bool setpoint_moving_ = false;
  TimePoint next_setpoint_at_{};
  MotionEstimator estimator_;
  AxisValues measured_{ { 0.0, 0.0, 1.0 } };
  /// The state deadline, losses and the start-up wait. Mutable: sample() counts a silence the thread missed.
  mutable LinkSupervisor supervisor_;
  std::uint64_t states_received_ = 0;
  std::uint64_t states_without_joints_ = 0;
  std::uint64_t setpoints_published_ = 0;
};

}  // namespace ptz_action_server

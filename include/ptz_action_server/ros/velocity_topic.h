/**
 * \file
 * \brief `cmd/velocity`: pan, tilt and zoom velocities streamed on a topic, each change a velocity goal, with a
 * dead-man timeout.
 */
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <ros/ros.h>

#include "ptz_action_server/PtzGoal.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/ros/queue_timer.h"

namespace ptz_action_server
{
/// ~cmd_velocity/...
struct VelocityTopicConfig
{
  bool enabled = true;   ///< ~cmd_velocity/enabled: subscribe cmd/velocity
  double timeout = 0.5;  ///< ~cmd_velocity/timeout: s without a message after which the device stops

  static VelocityTopicConfig load(const ParamReader& params);
};

/**
 * \brief Subscribes `cmd/velocity` (ptz_action_server/PtzGoal: the velocity goal's own message, pan and tilt in
 * rad/s, zoom in X/s) and runs the stream as velocity goals of the GoalSupervisor named "cmd_velocity".
 *
 * A message with a new velocity is a new velocity goal (validated, clamped or rejected like one; it preempts the active
 * goal); the same velocity again only keeps the stream alive. When no message came for the timeout, the stream's goal
 * is cancelled: the device decelerates to rest. A goal of another action preempts the stream's; the stream then waits
 * until it pauses for the timeout (or sends another velocity) before it moves the device again, as after a limit ended
 * its goal, and a stream of zeros never takes the device from another goal. Rejections are logged (throttled), as a
 * velocity goal's client would hear.
 *
 * Threads: the node's main queue (the subscription and the timer), the supervisor's thread.
 */
class VelocityTopic
{
public:
  /// The action name of the stream's goals in the supervisor and the log.
  static constexpr const char* ACTION = "cmd_velocity";
  /// What converts a velocity into a goal, against the device's state (the ROS layer's translator).
  using Converter = std::function<ConvertedGoal(const PtzGoal& velocity, PtzSample& current)>;

  VelocityTopic(const ros::NodeHandle& node_handle, const VelocityTopicConfig& config, GoalSupervisor& supervisor,
                Converter convert);
  ~VelocityTopic();
  VelocityTopic(const VelocityTopic&) = delete;
  VelocityTopic& operator=(const VelocityTopic&) = delete;

private:
  class StreamGoal;

  void onVelocity(const PtzGoal& velocity);
  /// The timer: no message for the timeout.
  void onSilence();
  /// From each of the stream's goals as it ends.
  void onGoalEnded(const std::string& id);

  const VelocityTopicConfig config_;
  GoalSupervisor& supervisor_;
  const Converter convert_;
  ros::Subscriber subscriber_;
  QueueTimer silence_timer_;
  std::shared_ptr<VelocityTopic*> self_;  ///< what the goals reach the topic through; cleared by the destructor
  std::uint64_t goals_ = 0;               ///< goals so far, for their ids
  std::string goal_id_;                   ///< the stream's latest goal ("" before the first)
  PtzGoal last_{};                        ///< its velocity
  /// The latest goal ended without the stream (another goal took the device, a limit): wait for a pause or a new
  /// velocity.
  bool yielded_ = false;
};

}  // namespace ptz_action_server

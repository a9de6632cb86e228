/**
 * \file
 * \brief Focus and iris from ROS: the lens topics and services, lens_capabilities and lens_state.
 */
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>

#include "ptz_action_server/PtzLensCapabilities.h"
#include "ptz_action_server/PtzLensState.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/lens_commander.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/ros/queue_timer.h"

namespace ptz_action_server
{
/// The lens interface's settings.
struct LensInterfaceConfig
{
  double velocity_timeout = 0.5;  ///< s a cmd/focus (cmd/iris) velocity runs without a new message
  double state_rate = 10.0;       ///< Hz of lens_state while someone listens

  /// Reads ~lens/velocity_timeout and ~lens/state_rate.
  static LensInterfaceConfig load(const ParamReader& params);
};

/// \p lens of backend \p backend as the latched lens_capabilities message.
PtzLensCapabilities toLensMessage(const std::string& backend, const LensCapabilities& lens);

/**
 * \brief The lens topics and services of a node (doc/interface.md): cmd/focus and cmd/iris (std_msgs/Float64,
 * a velocity -1..1 of the top speed, stopped when its stream stops for velocity_timeout), cmd/focus_position and
 * cmd/iris_position (Float64, 0..1 of the range), focus/set_auto and iris/set_auto (std_srvs/SetBool), focus/one_push
 * (std_srvs/Trigger); lens_capabilities (latched) and lens_state.
 *
 * Everything runs on the node handle's queue (the main thread) and only hands commands to the backend, which sends
 * them from its own thread: no callback waits on the device. A command the device cannot take is refused with the
 * reason (a service's answer; a warning for a topic) and nothing is sent. PtzState is left as it is.
 */
class LensInterface
{
public:
  LensInterface(const ros::NodeHandle& node_handle, std::shared_ptr<PtzBackend> backend, const LensCapabilities& lens,
                const std::string& backend_name, const LensInterfaceConfig& config);
  /// Stops the timers: once it returns, none of its callbacks runs.
  ~LensInterface();

  LensInterface(const LensInterface&) = delete;
  LensInterface& operator=(const LensInterface&) = delete;

private:
  /// Sends \p command; "" or why it was refused.
  std::string send(const LensCommand& command);
  /// A topic's command: refused ones are logged (once a second at most).
  void sendFromTopic(const LensCommand& command);
  bool setAuto(LensFunction function, std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool onePush(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  void expire();
  void publishState();
  /// Runs the state timer while lens_state has a subscriber, stops it when the last one leaves (on the node's queue).
  void followListeners();

  ros::NodeHandle node_handle_;
  std::shared_ptr<PtzBackend> backend_;
  const LensCapabilities lens_;
  const std::string backend_name_;
  LensCommander commander_;
  SystemClock clock_;
  ros::Publisher capabilities_publisher_;
  ros::Publisher state_publisher_;
  ros::Subscriber focus_velocity_;
  ros::Subscriber iris_velocity_;
  ros::Subscriber focus_position_;
  ros::Subscriber iris_position_;
  ros::ServiceServer focus_auto_;
  ros::ServiceServer iris_auto_;
  ros::ServiceServer one_push_;
  PtzLensState state_message_;  ///< reused for every publication
  bool state_published_ = false;
  QueueTimer deadman_timer_;   ///< the next velocity's end
  QueueTimer state_timer_;     ///< lens_state, while someone listens
  const double state_period_;  ///< s
  std::mutex state_timer_mutex_;
  bool state_timer_running_ = false;  ///< under state_timer_mutex_
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief The operator's controls that change at run time: dynamic_reconfigure's Controls (the default speed of
 * position goals) and the latched `controls` topic that shows them with how each axis takes a speed.
 */
#pragma once

#include <memory>
#include <string>

#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include "ptz_action_server/ControlsConfig.h"
#include "ptz_action_server/PtzControls.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// \p limits' speed of position goals and the \p default_speed, as the `controls` message of backend \p backend.
PtzControls toControlsMessage(const std::string& backend, const Capabilities& limits, double default_speed);

/**
 * \brief Serves dynamic_reconfigure's Controls under the node's private namespace (~default_speed, also read at
 * start) and publishes `controls` (latched) at start and after every change.
 *
 * Threads: the reconfigure callbacks run on \p node_handle's queue, the node's main thread, which is the supervisor's.
 */
class OperatorControls
{
public:
  /// Controls of \p supervisor's goals on the device of \p limits; `controls` under \p node_handle, the server under
  /// \p private_namespace (on \p node_handle's queue).
  OperatorControls(const ros::NodeHandle& node_handle, const std::string& private_namespace, std::string backend,
                   const Capabilities& limits, GoalSupervisor& supervisor);

  OperatorControls(const OperatorControls&) = delete;
  OperatorControls& operator=(const OperatorControls&) = delete;

private:
  void reconfigure(ControlsConfig& config, uint32_t level);

  const std::string backend_;
  const Capabilities limits_;
  GoalSupervisor& supervisor_;
  ros::Publisher publisher_;
  boost::recursive_mutex mutex_;  ///< dynamic_reconfigure's, around its config
  std::unique_ptr<dynamic_reconfigure::Server<ControlsConfig>> server_;
};

}  // namespace ptz_action_server

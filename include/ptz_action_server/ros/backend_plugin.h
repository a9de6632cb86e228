/**
 * \file
 * \brief The pluginlib entry point of a backend: reads its parameters and builds the core backend.
 *
 * A package adds a device by exporting a BackendPlugin (see backend_plugins.xml); the node loads it by name, so this
 * package need not change.
 */
#pragma once

#include <array>
#include <memory>
#include <string>

#include <ros/node_handle.h>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// What the node knows before the backend exists.
struct BackendContext
{
  /// Pan and tilt limits and speeds from the URDF joints; zoom is left at its defaults (the URDF has none).
  Capabilities urdf_limits;
  /// The URDF's pan and tilt joint names (the node's ~pan_joint, ~tilt_joint).
  std::array<std::string, 2> joint_names;
  /// The node's namespace, where a backend that talks over ROS topics puts them.
  ros::NodeHandle node_namespace;
  /// Clock the backend should run on.
  std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>();
};

/**
 * \brief Factory for one kind of backend, loaded by name through pluginlib.
 *
 * create() runs once on the node's main thread. It converts the parameters under the backend's namespace (e.g.
 * ~sim/...) into the backend's config struct, throwing ConfigError on a bad value, and may advertise
 * backend-specific ROS interfaces (the sim's fault service) on \p params' node handle. It must not start I/O:
 * the node calls PtzBackend::start() afterwards.
 */
class BackendPlugin
{
public:
  virtual ~BackendPlugin() = default;

  virtual std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) = 0;
};

}  // namespace ptz_action_server

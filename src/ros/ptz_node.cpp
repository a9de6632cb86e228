#include "ptz_action_server/ros/ptz_node.h"

#include <string>

namespace ptz_action_server
{
PtzNode::~PtzNode()
{
  server_.reset();  // stops using the backend before it goes
  backend_.reset();
}

void PtzNode::start(const ros::NodeHandle& node_handle, const ros::NodeHandle& private_handle,
                    const BackendWrapper& wrap)
{
  const ParamReader params(private_handle);
  const NodeConfig config = NodeConfig::load(params);
  std::string urdf;
  if (!node_handle.getParam("robot_description", urdf))
  {
    throw ConfigError("parameter " + node_handle.resolveName("robot_description") +
                      " is not set: load the URDF first (the launch file does)");
  }
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(urdf, config.names);
  // The mount maps device angles to the contract's, under everything else (goals, limits, state, tf).
  backend_ = applyMount(loader_.load(config.backend, params, kinematics, config.mount), config.mount);
  if (wrap)
  {
    backend_ = wrap(backend_);
  }
  server_ = std::make_unique<PtzActionServer>(node_handle, config, kinematics, backend_);
  server_->start();
}

}  // namespace ptz_action_server

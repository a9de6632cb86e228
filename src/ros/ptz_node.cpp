#include "ptz_action_server/ros/ptz_node.h"

#include <string>

#include <ros/callback_queue.h>

#include "ptz_action_server/core/closed_loop_backend.h"
#include "ptz_action_server/ros/sim_camera_publisher.h"

namespace ptz_action_server
{
PtzNode::PtzNode() = default;

PtzNode::~PtzNode()
{
  camera_.reset();  // each stops using the backend before it goes
  server_.reset();
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
  // The picture is the simulated camera's by default; another backend (joint_topics, for a simulator without a camera
  // of its own) draws it when ~camera/enabled asks.
  const std::string backend_name = config.backend.substr(config.backend.rfind('/') + 1);
  const SimCameraSettings camera =
      SimCameraSettings::load(params.child("camera"), backend_name == "sim", kinematics, config.field_of_view.model);
  // Position goals on a device that only moves at a speed are steered on its state, in the device's own angles; the
  // mount maps those to the contract's, under everything else (goals, limits, state, tf).
  backend_ = applyMount(
      withClosedLoop(loader_.load(config.backend, params, kinematics, config.mount), config.monitor.tolerance),
      config.mount);
  if (wrap)
  {
    backend_ = wrap(backend_);
  }
  server_ = std::make_unique<PtzActionServer>(node_handle, config, kinematics, backend_);
  server_->setTickCosts(tick_costs_);
  server_->start();
  if (camera.enabled)
  {
    camera_ = std::make_unique<SimCameraPublisher>(node_handle, camera, kinematics, backend_);
  }
}

void spinUntilShutdown()
{
  // ros::spin() waits at most 0.1 s at a time to look at ros::ok(). The wait here is long: ros::shutdown() (from
  // SIGINT through roscpp's poll thread, or from any thread) disables the queue, which wakes it at once; the timeout
  // is only a backstop.
  constexpr double WAIT = 5.0;  // s
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  while (ros::ok() && queue.isEnabled())  // a disabled queue returns at once: shutdown is under way
  {
    queue.callAvailable(ros::WallDuration(WAIT));
  }
}

}  // namespace ptz_action_server

#include "ptz_action_server/ros/operator_controls.h"

namespace ptz_action_server
{
namespace
{
PtzAxisSpeed toAxisSpeed(const Capabilities& limits, Axis axis)
{
  const AxisCapability& capability = limits.axes[axis];
  PtzAxisSpeed message;
  if (!capability.present || !capability.absolute || !capability.feedback)
  {
    message.control = PtzAxisSpeed::NONE;
    return message;
  }
  switch (limits.speed.control[axis])
  {
    case SpeedControl::DEVICE:
      message.control = PtzAxisSpeed::DEVICE;
      break;
    case SpeedControl::STEERED:
      message.control = PtzAxisSpeed::STEERED;
      break;
    case SpeedControl::OWN:
      message.control = PtzAxisSpeed::OWN;
      break;
    case SpeedControl::NODE:
      message.control = PtzAxisSpeed::NODE;
      break;
  }
  message.min_speed = limits.speed.min_speed[axis];
  message.max_speed = capability.max_speed;
  return message;
}
}  // namespace

PtzControls toControlsMessage(const std::string& backend, const Capabilities& limits, double default_speed)
{
  PtzControls message;
  message.backend = backend;
  message.speed.pan = toAxisSpeed(limits, PAN);
  message.speed.tilt = toAxisSpeed(limits, TILT);
  message.speed.zoom = toAxisSpeed(limits, ZOOM);
  message.speed.default_speed = default_speed;
  return message;
}

OperatorControls::OperatorControls(const ros::NodeHandle& node_handle, const std::string& private_namespace,
                                   std::string backend, const Capabilities& limits, GoalSupervisor& supervisor)
  : backend_(std::move(backend)), limits_(limits), supervisor_(supervisor)
{
  ros::NodeHandle node(node_handle);
  publisher_ = node.advertise<PtzControls>("controls", 1, true);
  ros::NodeHandle private_handle(private_namespace);
  private_handle.setCallbackQueue(node_handle.getCallbackQueue());
  // The server reads ~default_speed (or the .cfg's default) and calls reconfigure() once before it returns.
  server_ = std::make_unique<dynamic_reconfigure::Server<ControlsConfig>>(mutex_, private_handle);
  server_->setCallback([this](ControlsConfig& config, uint32_t level) { reconfigure(config, level); });
}

void OperatorControls::reconfigure(ControlsConfig& config, uint32_t)
{
  const std::string refused = supervisor_.setDefaultSpeed(config.default_speed);
  if (!refused.empty())
  {
    ROS_WARN("%s: %s; keeping %g", backend_.c_str(), refused.c_str(), supervisor_.defaultSpeed());
    config.default_speed = supervisor_.defaultSpeed();
  }
  publisher_.publish(toControlsMessage(backend_, limits_, supervisor_.defaultSpeed()));
}

}  // namespace ptz_action_server

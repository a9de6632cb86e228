#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "plugin_params.h"
#include "ptz_action_server/ros/backend_plugin.h"
#include "ptz_action_server/ros/joint_topics_backend.h"

namespace ptz_action_server
{
/// Builds the joint_topics backend from ~joint_topics/... parameters; topics resolve in the node's namespace.
class JointTopicsBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    JointTopicsConfig config;
    config.command_topics[PAN] = params.text("pan_command_topic", config.command_topics[PAN]);
    config.command_topics[TILT] = params.text("tilt_command_topic", config.command_topics[TILT]);
    config.state_topic = params.text("state_topic", config.state_topic);
    // The device's joints are the URDF's unless the controllers call them otherwise.
    config.joint_names[PAN] = params.text("pan_joint", context.joint_names[PAN]);
    config.joint_names[TILT] = params.text("tilt_joint", context.joint_names[TILT]);
    config.command_rate = params.number("command_rate", config.command_rate, 1.0, 1000.0);
    config.state_timeout = params.number("state_timeout", config.state_timeout, 0.05, 60.0);
    config.startup_timeout = params.number("startup_timeout", config.startup_timeout, 0.1, 600.0);
    config.settle_window = params.number("settle_window", config.settle_window, 0.0, 5.0);

    config.setpoint = SimDeviceConfig::defaults();
    readSetpointAxis(params.child("pan"), context.urdf_limits.axes[PAN], M_PI, config.setpoint.axes[PAN]);
    readSetpointAxis(params.child("tilt"), context.urdf_limits.axes[TILT], M_PI / 2.0, config.setpoint.axes[TILT]);
    config.setpoint.axes[ZOOM].present = false;
    return std::make_shared<JointTopicsBackend>(config, context.node_namespace, context.clock);
  }

private:
  /// Limits, max_speed (the URDF's velocity limit by default) and acceleration of one axis of the setpoint.
  static void readSetpointAxis(const ParamReader& params, const AxisCapability& urdf, double bound, SimAxisConfig& axis)
  {
    AxisCapability capability;
    capability.max_speed = urdf.max_speed > 0.0 ? urdf.max_speed : axis.motion.max_speed;
    capability.acceleration = axis.motion.acceleration;
    readAxis(params, urdf.range, bound, capability);
    if (capability.acceleration <= 0.0)
    {
      throw ConfigError("parameter " + params.resolve("acceleration") + " must be above 0: the setpoint ramps at it");
    }
    axis.range = capability.range;
    axis.motion.max_speed = capability.max_speed;
    axis.motion.acceleration = capability.acceleration;
    axis.resolution = 0.0;  // a setpoint is continuous
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::JointTopicsBackendPlugin, ptz_action_server::BackendPlugin)

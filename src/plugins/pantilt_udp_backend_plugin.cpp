#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "ptz_action_server/core/pantilt/pantilt_udp_backend.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// Builds the pantilt_udp backend from ~pantilt_udp/... parameters.
class PanTiltUdpBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    PanTiltUdpConfig config;
    config.device_host = params.text("device_host", config.device_host);
    config.device_port = static_cast<std::uint16_t>(params.integer("device_port", config.device_port, 1, 65535));
    config.local_host = params.text("local_host", config.local_host);
    config.local_port = static_cast<std::uint16_t>(params.integer("local_port", config.local_port, 0, 65535));
    const std::string version = params.choice("wire_version", "1.0", { "1.0", "1.1" });
    cr::pantilt::parseWireVersion(version, config.version);
    config.state_timeout = params.number("state_timeout", config.state_timeout, 0.05, 60.0);
    config.state_request_period = params.number("state_request_period", config.state_request_period, 0.01, 10.0);
    config.settle_window = params.number("settle_window", config.settle_window, 0.0, 1.0);
    config.pan_speed = params.number("pan_speed", config.pan_speed, 1.0, 100.0);
    config.tilt_speed = params.number("tilt_speed", config.tilt_speed, 1.0, 100.0);
    const char* axis_names[] = { "pan", "tilt" };
    for (Axis axis : { PAN, TILT })
    {
      const ParamReader axis_params = params.child(axis_names[axis]);
      AxisCapability& capability = config.axes[axis];
      const AxisRange& urdf = context.urdf_limits.axes[axis].range;
      const double bound = axis == PAN ? M_PI : M_PI / 2.0;  // the PanTilt angle range: +-180 and +-90 degrees
      capability.range.min = axis_params.number("min", std::max(urdf.min, -bound), -bound, bound);
      capability.range.max = axis_params.number("max", std::min(urdf.max, bound), capability.range.min, bound);
      capability.max_speed = axis_params.number("max_speed", capability.max_speed, 1e-3, 100.0);
      capability.acceleration = axis_params.number("acceleration", capability.acceleration, 0.0, 1e4);
    }
    return std::make_shared<PanTiltUdpBackend>(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::PanTiltUdpBackendPlugin, ptz_action_server::BackendPlugin)

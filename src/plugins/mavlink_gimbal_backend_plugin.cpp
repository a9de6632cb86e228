#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>
#include <ros/console.h>

#include "plugin_params.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// Builds the mavlink_gimbal backend from ~mavlink_gimbal/... parameters.
class MavlinkGimbalBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    MavlinkGimbalConfig config;
    LinkConfig& link = config.link;
    if (params.choice("transport", "udp", { "udp", "serial" }) == "udp")
    {
      link.host = params.text("host", link.host);
      link.port = static_cast<std::uint16_t>(params.integer("port", link.port, 1, 65535));
      link.local_port = static_cast<std::uint16_t>(params.integer("local_port", 0, 0, 65535));
      readReconnect(params, link);
    }
    else
    {
      readSerialLink(params, "serial_port", link);
    }
    config.session.state_timeout = params.number("state_timeout", config.session.state_timeout, 0.1, 60.0);
    readSessionTiming(params, config.session);

    MavlinkGimbalSettings& gimbal = config.gimbal;
    auto id = [&params](const char* name, int value, int min) {
      return static_cast<std::uint8_t>(params.integer(name, value, min, 255));
    };
    gimbal.system_id = id("system_id", gimbal.system_id, 1);
    gimbal.component_id = id("component_id", gimbal.component_id, 1);
    gimbal.target_system = id("target_system", gimbal.target_system, 0);
    gimbal.target_component = id("target_component", gimbal.target_component, 0);
    gimbal.gimbal_device_id = id("gimbal_device_id", gimbal.gimbal_device_id, 0);
    gimbal.yaw_lock = params.choice("yaw_frame", "vehicle", { "vehicle", "north" }) == "north";
    gimbal.heartbeat_period = params.number("heartbeat_period", gimbal.heartbeat_period, 0.1, 5.0);
    gimbal.discovery_time = params.number("discovery_time", gimbal.discovery_time, 0.0, 30.0);
    gimbal.attitude_interval = params.number("attitude_interval", gimbal.attitude_interval, 0.005, 1.0);
    gimbal.rate_period = params.number("rate_period", gimbal.rate_period, 0.01, 1.0);
    gimbal.resend_period = params.number("resend_period", gimbal.resend_period, 0.05, 10.0);
    readAxis(params.child("pan"), context.urdf_limits.axes[PAN].range, M_PI, gimbal.pan);
    readAxis(params.child("tilt"), context.urdf_limits.axes[TILT].range, M_PI / 2.0, gimbal.tilt);
    return makeMavlinkGimbalBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::MavlinkGimbalBackendPlugin, ptz_action_server::BackendPlugin)

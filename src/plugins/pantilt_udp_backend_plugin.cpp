#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "plugin_params.h"
#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/core/types.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// Builds the pantilt_udp backend from ~pantilt_udp/... parameters.
class PanTiltUdpBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    PanTiltConfig config;
    LinkConfig& link = config.link;
    link.host = params.text("device_host", link.host);
    link.port = static_cast<std::uint16_t>(params.integer("device_port", link.port, 1, 65535));
    link.local_host = params.text("local_host", link.local_host);
    link.local_port = static_cast<std::uint16_t>(params.integer("local_port", link.local_port, 0, 65535));
    readReconnect(params, link);
    config.session.state_timeout = params.number("state_timeout", config.session.state_timeout, 0.05, 60.0);
    readSessionTiming(params, config.session);

    PanTiltSettings& pantilt = config.pantilt;
    if (params.has("wire_version"))
    {
      // "1.0" named two formats that share their version bytes (the seed's and PanTilt 1.0.x): no guessing.
      throw ConfigError("parameter " + params.resolve("wire_version") + " is replaced by " + params.resolve("format") +
                        ": format: seed for what wire_version 1.0 meant, v1.1 for 1.1, v1.0 for a PanTilt 1.0.x "
                        "device");
    }
    cr::pantilt::parseWireFormat(params.choice("format", "seed", { "seed", "v1.0", "v1.1" }), pantilt.format);
    pantilt.state_request_period = params.number("state_request_period", pantilt.state_request_period, 0.01, 10.0);
    pantilt.pan_speed = params.number("pan_speed", pantilt.pan_speed, 1.0, 100.0);
    pantilt.tilt_speed = params.number("tilt_speed", pantilt.tilt_speed, 1.0, 100.0);
    // The PanTilt angle range: +-180 and +-90 degrees.
    readAxis(params.child("pan"), context.urdf_limits.axes[PAN].range, M_PI, pantilt.axes[PAN]);
    readAxis(params.child("tilt"), context.urdf_limits.axes[TILT].range, M_PI / 2.0, pantilt.axes[TILT]);
    return makePanTiltBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::PanTiltUdpBackendPlugin, ptz_action_server::BackendPlugin)

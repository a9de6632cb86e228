#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "plugin_params.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// Builds the axis backend from ~axis/... parameters.
class AxisBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    AxisConfig config;  // the node intersects the camera's limits with the URDF's
    readHttpLink(params, config.link);
    config.session.state_timeout = params.number("state_timeout", config.session.state_timeout, 0.15, 60.0);
    config.session.poll_period = params.number("poll_period", config.session.poll_period, 0.02, 1.0);
    readSessionTiming(params, config.session);

    AxisSettings& axis = config.axis;
    axis.camera = params.integer("camera", axis.camera, 1, 64);
    axis.speed = params.integer("speed", axis.speed, 1, 100);
    axis.pan_max_speed = params.number("pan/max_speed", axis.pan_max_speed, 1e-3, 100.0);
    axis.tilt_max_speed = params.number("tilt/max_speed", axis.tilt_max_speed, 1e-3, 100.0);
    axis.zoom_max_rate = params.number("zoom/max_rate", axis.zoom_max_rate, 1e-3, 1000.0);
    axis.acceleration = params.number("acceleration", axis.acceleration, 0.0, 1e4);
    axis.zoom_table = params.text("zoom_table", axis.zoom_table);
    return makeAxisBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::AxisBackendPlugin, ptz_action_server::BackendPlugin)

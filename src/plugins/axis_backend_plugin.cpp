#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>
#include <ros/console.h>

#include "plugin_params.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/text.h"
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
    if (!axis.zoom_table.empty())
    {
      vapix::ZoomTable table;
      const std::string problem = vapix::ZoomTable::parse(axis.zoom_table, table);
      if (!problem.empty())
      {
        throw ConfigError("parameter " + params.resolve("zoom_table") + " = '" + axis.zoom_table + "': " + problem +
                          " (VALUE:X,VALUE:X,..., VAPIX zoom 1..19999 to X, both increasing)");
      }
    }
    axis.zoom_max_factor = params.number("zoom_max_factor", axis.zoom_max_factor, 0.0, 1000.0);
    if (axis.zoom_max_factor != 0.0 && axis.zoom_max_factor <= 1.0)
    {
      throw ConfigError("parameter " + params.resolve("zoom_max_factor") + " = " +
                        formatText("%g", axis.zoom_max_factor) +
                        " must be above 1 (the camera's optical zoom, X at VAPIX zoom 9999), or 0 to find it out");
    }
    if (axis.zoom_max_factor != 0.0 && !axis.zoom_table.empty())
    {
      throw ConfigError("parameters " + params.resolve("zoom_table") + " and " + params.resolve("zoom_max_factor") +
                        " are both set: set one (the table, or the optical zoom for a linear one)");
    }
    axis.zoom_guess = params.flag("zoom_guess", axis.zoom_guess);
    return makeAxisBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::AxisBackendPlugin, ptz_action_server::BackendPlugin)

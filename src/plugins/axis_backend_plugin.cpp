#include "device_plugin.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
/// An Axis PTZ camera over VAPIX: ~axis/..., over http or https.
struct AxisPlugin
{
  using Protocol = AxisProtocol;
  static constexpr const char* NAME = "axis";

  static LinkChoices links()
  {
    return { { { LinkKind::HTTP } }, 0.15, 0.02 };
  }

  static void read(const DeviceParams& device, const BackendContext& /*context*/, DeviceConfig<AxisProtocol>& config)
  {
    const ParamReader& params = device.own;
    AxisSettings& axis = config.settings;
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
    const std::string queue = params.choice("control_queue", "auto", { "auto", "on", "off" });
    axis.control_queue = queue == "on"  ? AxisControlQueue::ON :
                         queue == "off" ? AxisControlQueue::OFF :
                                          AxisControlQueue::AUTO;
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(AxisPlugin, AxisBackendPlugin)

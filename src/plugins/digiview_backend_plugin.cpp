#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "ptz_action_server/core/digiview/digiview_backend.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// Builds the digiview backend from ~digiview/... parameters.
class DigiViewBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    DigiViewConfig config;
    config.host = params.text("host", config.host);
    config.port = static_cast<std::uint16_t>(params.integer("port", config.port, 1, 65535));
    config.transport =
        params.choice("transport", "tcp", { "tcp", "udp" }) == "tcp" ? DigiViewTransport::TCP : DigiViewTransport::UDP;
    config.stream_name = params.text("stream_name", config.stream_name);
    if (config.stream_name.empty() || config.stream_name.size() > digiview::NAME_SIZE)
    {
      throw ConfigError("parameter " + params.resolve("stream_name") + " must have 1 to 8 characters");
    }
    config.cam_id = static_cast<std::uint8_t>(params.integer("cam_id", config.cam_id, 0, 3));
    config.fov_wide = params.number("fov_wide", config.fov_wide, 0.1, 3.14);
    config.zoom_max = params.number("zoom_max", config.zoom_max, 0.0, 1000.0);
    config.lock_flags = static_cast<std::uint8_t>(params.integer("lock_flags", config.lock_flags, 0, 7));
    config.crop_mode = static_cast<std::uint8_t>(params.integer("crop_mode", config.crop_mode, 0, 2));
    config.slew_rate = params.number("slew_rate", config.slew_rate, 1e-3, 100.0);
    config.acceleration = params.number("acceleration", config.acceleration, 0.0, 1e4);
    config.state_timeout = params.number("state_timeout", config.state_timeout, 0.15, 60.0);
    config.velocity_period = params.number("velocity_period", config.velocity_period, 0.02, 5.0);
    config.settle_window = params.number("settle_window", config.settle_window, 0.0, 5.0);
    config.startup_timeout = params.number("startup_timeout", config.startup_timeout, 0.1, 600.0);
    config.reconnect_min = params.number("reconnect_min", config.reconnect_min, 0.01, 10.0);
    config.reconnect_max = params.number("reconnect_max", config.reconnect_max, config.reconnect_min, 60.0);
    return std::make_shared<DigiViewBackend>(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::DigiViewBackendPlugin, ptz_action_server::BackendPlugin)

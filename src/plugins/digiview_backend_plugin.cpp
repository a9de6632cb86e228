#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "plugin_params.h"
#include "ptz_action_server/core/digiview/digiview_protocol.h"
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
    LinkConfig& link = config.link;
    link.host = params.text("host", link.host);
    link.port = static_cast<std::uint16_t>(params.integer("port", link.port, 1, 65535));
    link.kind = params.choice("transport", "tcp", { "tcp", "udp" }) == "tcp" ? LinkKind::TCP : LinkKind::UDP;
    readReconnect(params, link);
    config.session.state_timeout = params.number("state_timeout", config.session.state_timeout, 0.15, 60.0);
    readSessionTiming(params, config.session);

    DigiViewSettings& digiview = config.digiview;
    digiview::parseFormat(params.choice("format", "0.5", { "0.5", "1.0", "1.1" }), digiview.wire.format);
    digiview::parseChecksumRule(params.choice("checksum", "required", { "required", "zero_accepted" }),
                                digiview.wire.checksum);
    digiview.stream_name = params.text("stream_name", digiview.stream_name);
    if (digiview.stream_name.empty() || digiview.stream_name.size() > digiview::NAME_SIZE)
    {
      throw ConfigError("parameter " + params.resolve("stream_name") + " must have 1 to 8 characters");
    }
    digiview.cam_id = static_cast<std::uint8_t>(params.integer("cam_id", digiview.cam_id, 0, 3));
    digiview.fov_wide = params.number("fov_wide", digiview.fov_wide, 0.1, 3.14);
    digiview.zoom_max = params.number("zoom_max", digiview.zoom_max, 0.0, 1000.0);
    digiview.lock_flags = static_cast<std::uint8_t>(params.integer("lock_flags", digiview.lock_flags, 0, 7));
    digiview.crop_mode = static_cast<std::uint8_t>(params.integer("crop_mode", digiview.crop_mode, 0, 2));
    digiview.slew_rate = params.number("slew_rate", digiview.slew_rate, 1e-3, 100.0);
    digiview.acceleration = params.number("acceleration", digiview.acceleration, 0.0, 1e4);
    digiview.velocity_period = params.number("velocity_period", digiview.velocity_period, 0.02, 5.0);
    return makeDigiViewBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::DigiViewBackendPlugin, ptz_action_server::BackendPlugin)

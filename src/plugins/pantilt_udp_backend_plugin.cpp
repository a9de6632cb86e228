#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "pantilt_settings.h"
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

    readPanTiltSettings(params, context, config.pantilt);
    return makePanTiltBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::PanTiltUdpBackendPlugin, ptz_action_server::BackendPlugin)

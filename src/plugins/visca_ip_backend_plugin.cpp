#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "plugin_params.h"
#include "visca_params.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/**
 * \brief Builds the visca_ip backend from ~visca_ip/... parameters: a VISCA camera on the network, over UDP (Sony's
 * VISCA over IP on port 52381 by default, or raw VISCA) or TCP (raw VISCA).
 */
class ViscaIpBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    ViscaConfig config;
    LinkConfig& link = config.link;
    link.kind = params.choice("transport", "udp", { "udp", "tcp" }) == "udp" ? LinkKind::UDP : LinkKind::TCP;
    link.host = params.text("host", link.host);
    link.port = static_cast<std::uint16_t>(
        params.integer("port", link.kind == LinkKind::UDP ? visca::SONY_IP_PORT : 5678, 1, 65535));
    link.local_host = params.text("local_host", link.local_host);
    link.local_port = static_cast<std::uint16_t>(params.integer("local_port", link.local_port, 0, 65535));
    link.connect_timeout = params.number("connect_timeout", link.connect_timeout, 0.1, 60.0);
    readReconnect(params, link);
    config.session.state_timeout = params.number("state_timeout", config.session.state_timeout, 0.02, 60.0);
    config.session.poll_period = params.number("poll_period", config.session.poll_period, 0.005, 1.0);
    readSessionTiming(params, config.session);

    config.visca.backend_name = "visca_ip";
    readViscaSettings(params, config.visca);
    config.visca.framing = readViscaFraming(params, link.kind);
    config.visca.reply_timeout = params.number("reply_timeout", 0.0, 0.0, 10.0);
    return makeViscaBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::ViscaIpBackendPlugin, ptz_action_server::BackendPlugin)

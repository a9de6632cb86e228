#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>
#include <ros/console.h>

#include "plugin_params.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
namespace
{
/// scale (rad of x = 1), offset (rad) and sign (+1 / -1) of one axis' generic space under \p params.
void readGenericAxis(const ParamReader& params, GenericAxisMapping& mapping)
{
  mapping.scale = params.number("scale", mapping.scale, 1e-3, 2.0 * M_PI);
  mapping.offset = params.number("offset", mapping.offset, -M_PI, M_PI);
  mapping.sign = params.integer("sign", 1, -1, 1) < 0 ? -1.0 : 1.0;
}
}  // namespace

/// Builds the onvif backend from ~onvif/... parameters.
class OnvifBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    OnvifConfig config;  // the node intersects the camera's ranges with the URDF's
    readHttpLink(params, config.link);
    config.session.state_timeout = params.number("state_timeout", config.session.state_timeout, 0.15, 60.0);
    config.session.poll_period = params.number("poll_period", config.session.poll_period, 0.02, 1.0);
    readSessionTiming(params, config.session);

    OnvifSettings& onvif = config.onvif;
    onvif.device_path = params.text("device_path", onvif.device_path);
    onvif.profile = params.text("profile", onvif.profile);
    // WS-Security takes the HTTP credentials: one user and password for the camera.
    onvif.username = config.link.http.username;
    onvif.password = config.link.http.password;
    onvif.prefer_degrees = params.flag("prefer_degrees", onvif.prefer_degrees);
    readGenericAxis(params.child("pan"), onvif.pan);
    readGenericAxis(params.child("tilt"), onvif.tilt);
    onvif.velocity_sign_pan = params.integer("pan/velocity_sign", 1, -1, 1) < 0 ? -1.0 : 1.0;
    onvif.velocity_sign_tilt = params.integer("tilt/velocity_sign", 1, -1, 1) < 0 ? -1.0 : 1.0;
    onvif.pan_max_speed = params.number("pan/max_speed", onvif.pan_max_speed, 1e-3, 100.0);
    onvif.tilt_max_speed = params.number("tilt/max_speed", onvif.tilt_max_speed, 1e-3, 100.0);
    onvif.zoom_max = params.number("zoom/max", onvif.zoom_max, 1.01, 1000.0);
    onvif.zoom_max_rate = params.number("zoom/max_rate", onvif.zoom_max_rate, 1e-3, 1000.0);
    onvif.acceleration = params.number("acceleration", onvif.acceleration, 0.0, 1e4);
    onvif.velocity_timeout = params.integer("velocity_timeout", onvif.velocity_timeout, 1, 3600);
    // What the camera contradicts itself in (a listed range its own status leaves): once, also in diagnostics.
    return makeOnvifBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::OnvifBackendPlugin, ptz_action_server::BackendPlugin)

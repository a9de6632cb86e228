#include "device_plugin.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"

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

/// An ONVIF PTZ camera: ~onvif/..., over http or https (SOAP 1.2, WS-Security, optionally HTTP Digest).
struct OnvifPlugin
{
  using Protocol = OnvifProtocol;
  static constexpr const char* NAME = "onvif";

  static LinkChoices links()
  {
    return { { { LinkKind::HTTP } }, 0.15, 0.02 };
  }

  static void read(const DeviceParams& device, const BackendContext& /*context*/, DeviceConfig<OnvifProtocol>& config)
  {
    const ParamReader& params = device.own;
    OnvifSettings& onvif = config.settings;
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
    // A camera whose axes have not begun this long after an AbsoluteMove answered it does not move (0: never judged).
    onvif.move_start_timeout = params.number("move_start_timeout", onvif.move_start_timeout, 0.0, 10.0);
    // What the camera contradicts itself in (a listed range its own status leaves): once, also in diagnostics.
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(OnvifPlugin, OnvifBackendPlugin)

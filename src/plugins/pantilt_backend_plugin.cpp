#include "device_plugin.h"
#include "ptz_action_server/core/pantilt/pantilt_protocol.h"

namespace ptz_action_server
{
/**
 * \brief A PanTilt device controller: ~pantilt/..., over UDP (port 5000), or its frames in SLIP (RFC 1055) on a
 * serial port or over TCP (port 4002).
 */
struct PanTiltPlugin
{
  using Protocol = PanTiltProtocol;
  static constexpr const char* NAME = "pantilt";

  static LinkChoices links()
  {
    return { { { LinkKind::UDP, 5000 }, { LinkKind::SERIAL }, { LinkKind::TCP, 4002 } }, 0.05 };
  }

  static void read(const ParamReader& params, const BackendContext& context, DeviceConfig<PanTiltProtocol>& config)
  {
    PanTiltSettings& pantilt = config.settings;
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
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(PanTiltPlugin, PanTiltBackendPlugin)

#include "device_plugin.h"
#include "ptz_action_server/core/flir/flir_protocol.h"

namespace ptz_action_server
{
/// A FLIR / Directed Perception PTU (D46, E46, E-series): ~flir/..., on a serial port or over TCP (port 4000).
struct FlirPlugin
{
  using Protocol = FlirProtocol;
  static constexpr const char* NAME = "flir";

  static LinkChoices links()
  {
    return { { { LinkKind::SERIAL }, { LinkKind::TCP, 4000 } } };
  }

  static void read(const ParamReader& flir, const BackendContext& /*context*/, DeviceConfig<FlirProtocol>& config)
  {
    config.settings.pan_speed = flir.number("pan_speed", config.settings.pan_speed, 1e-3, 10.0);
    config.settings.tilt_speed = flir.number("tilt_speed", config.settings.tilt_speed, 1e-3, 10.0);
    config.settings.acceleration = flir.number("acceleration", config.settings.acceleration, 0.0, 1e4);
    config.settings.reply_timeout = flir.number("reply_timeout", 0.0, 0.0, 10.0);
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(FlirPlugin, FlirBackendPlugin)

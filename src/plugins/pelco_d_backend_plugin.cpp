#include <xmlrpcpp/XmlRpcValue.h>

#include "device_plugin.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"

namespace ptz_action_server
{
namespace
{
/// `set_position`: auto, or true / false (as YAML's booleans or as words).
PelcoSetPosition readSetPosition(const ParamReader& pelco)
{
  XmlRpc::XmlRpcValue value;
  if (pelco.get("set_position", value) && value.getType() == XmlRpc::XmlRpcValue::TypeBoolean)
  {
    return static_cast<bool>(value) ? PelcoSetPosition::YES : PelcoSetPosition::NO;
  }
  const std::string choice = pelco.choice("set_position", "auto", { "auto", "true", "false" });
  return choice == "auto" ? PelcoSetPosition::AUTO : (choice == "true" ? PelcoSetPosition::YES : PelcoSetPosition::NO);
}
}  // namespace

/// A Pelco-D camera or pan-tilt unit: ~pelco_d/..., on a serial port or over TCP to a serial-to-Ethernet server.
struct PelcoDPlugin
{
  using Protocol = PelcoProtocol;
  static constexpr const char* NAME = "pelco_d";

  static LinkChoices links()
  {
    return { { { LinkKind::SERIAL }, { LinkKind::TCP, 4001 } } };
  }

  static void read(const ParamReader& pelco, const BackendContext& context, DeviceConfig<PelcoProtocol>& config)
  {
    PelcoSettings& settings = config.settings;
    settings.reply_timeout = pelco.number("reply_timeout", 0.0, 0.0, 10.0);
    settings.address = static_cast<std::uint8_t>(pelco.integer("address", settings.address, 1, 255));
    pelco::parseTiltEncoding(pelco.choice("tilt_encoding", "down_positive", { "down_positive", "up_positive" }),
                             settings.tilt_encoding);
    settings.general_reply = pelco.flag("general_reply", settings.general_reply);
    settings.set_position = readSetPosition(pelco);
    settings.set_position_wait = pelco.number("set_position_wait", settings.set_position_wait, 0.05, 10.0);
    settings.focus = pelco.flag("focus", settings.focus);
    settings.iris = pelco.flag("iris", settings.iris);
    settings.zoom_position_max =
        static_cast<std::uint16_t>(pelco.integer("zoom_position_max", settings.zoom_position_max, 1, 0xFFFF));
    readAxis(pelco.child("pan"), context.urdf_limits.axes[PAN].range, M_PI, settings.axes[PAN]);
    readAxis(pelco.child("tilt"), context.urdf_limits.axes[TILT].range, M_PI / 2.0, settings.axes[TILT]);
    const ParamReader zoom = pelco.child("zoom");
    AxisCapability& zoom_capability = settings.axes[ZOOM];
    zoom_capability.present = zoom.flag("present", true);
    zoom_capability.range.min = zoom.number("min", zoom_capability.range.min, 1.0, 1000.0);
    zoom_capability.range.max = zoom.number("max", zoom_capability.range.max, zoom_capability.range.min, 1000.0);
    zoom_capability.max_speed = zoom.number("rate", zoom_capability.max_speed, 1e-3, 1000.0);
    zoom_capability.acceleration = zoom.number("acceleration", zoom_capability.acceleration, 0.0, 1e4);
    // Turbo is device-specific: off unless the device's byte is given (and faster than 0x3F's speed).
    settings.turbo_byte = static_cast<std::uint8_t>(pelco.integer("turbo_byte", 0, 0, 255));
    if (settings.turbo_byte != 0)
    {
      if (settings.turbo_byte <= pelco::MAX_SPEED)
      {
        throw ConfigError("parameter " + pelco.resolve("turbo_byte") +
                          " must be above 0x3F (63), the highest ordinary speed, or 0 for no turbo");
      }
      settings.turbo_speed = pelco.number("turbo_speed", 0.0, settings.axes[PAN].max_speed + 1e-6, 100.0);
    }
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(PelcoDPlugin, PelcoDBackendPlugin)

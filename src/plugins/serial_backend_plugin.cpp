#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "pantilt_settings.h"
#include "plugin_params.h"
#include "visca_params.h"
#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/**
 * \brief Builds the serial backend from ~serial/... parameters: `protocol: flir`, `pelco_d`, `visca` or `pantilt`, on a
 * serial port (`transport: serial`) or over TCP (`transport: tcp`: FLIR E-series on port 4000, a Pelco-D camera behind
 * a serial-to-Ethernet server, a VISCA camera taking raw VISCA); VISCA also over UDP (`transport: udp`).
 */
class SerialBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    const std::string protocol = params.choice("protocol", "flir", { "flir", "pelco_d", "visca", "pantilt" });
    const std::string transport = params.choice("transport", "serial", { "serial", "tcp", "udp" });
    LinkConfig link;
    if (transport == "serial")
    {
      readSerialLink(params, "port", link);
    }
    else if (transport == "tcp")
    {
      link.kind = LinkKind::TCP;
      const int default_port =
          protocol == "flir" ? 4000 : (protocol == "visca" ? 5678 : (protocol == "pantilt" ? 4002 : 4001));
      link.host = params.text("host", link.host);
      link.port = static_cast<std::uint16_t>(params.integer("tcp_port", default_port, 1, 65535));
      link.connect_timeout = params.number("connect_timeout", link.connect_timeout, 0.1, 60.0);
      readReconnect(params, link);
    }
    else
    {
      if (protocol != "visca")
      {
        throw ConfigError("parameter " + params.resolve("transport") + " = udp is for protocol: visca only");
      }
      link.kind = LinkKind::UDP;
      link.host = params.text("host", link.host);
      link.port = static_cast<std::uint16_t>(params.integer("udp_port", visca::SONY_IP_PORT, 1, 65535));
      link.local_host = params.text("local_host", link.local_host);
      readReconnect(params, link);
    }
    DeviceSessionConfig session{ 0.25, 0.05, 10.0, 0.1, 0.5 };
    session.state_timeout = params.number("transaction_deadline", session.state_timeout, 0.02, 10.0);
    session.poll_period = params.number("poll_period", session.poll_period, 0.005, 1.0);
    readSessionTiming(params, session);
    const double reply_timeout = params.number("reply_timeout", 0.0, 0.0, 10.0);

    if (protocol == "pantilt")
    {
      // PanTilt frames in SLIP (RFC 1055) on the byte stream; the device reports as over UDP.
      PanTiltConfig config;
      config.link = link;
      const ParamReader pantilt = params.child("pantilt");
      config.session.state_timeout = pantilt.number("state_timeout", config.session.state_timeout, 0.05, 60.0);
      readSessionTiming(params, config.session);
      readPanTiltSettings(pantilt, context, config.pantilt);
      return makePanTiltBackend(config, context.clock);
    }
    if (protocol == "visca")
    {
      ViscaConfig config;
      config.link = link;
      config.session = session;
      const ParamReader visca = params.child("visca");
      readViscaSettings(visca, config.visca);
      config.visca.framing = readViscaFraming(visca, link.kind);
      config.visca.reply_timeout = reply_timeout;
      return makeViscaBackend(config, context.clock);
    }
    if (protocol == "flir")
    {
      FlirConfig config;
      config.link = link;
      config.session = session;
      const ParamReader flir = params.child("flir");
      config.flir.pan_speed = flir.number("pan_speed", config.flir.pan_speed, 1e-3, 10.0);
      config.flir.tilt_speed = flir.number("tilt_speed", config.flir.tilt_speed, 1e-3, 10.0);
      config.flir.acceleration = flir.number("acceleration", config.flir.acceleration, 0.0, 1e4);
      config.flir.reply_timeout = reply_timeout;
      return makeFlirBackend(config, context.clock);
    }

    PelcoConfig config;
    config.link = link;
    config.session = session;
    PelcoSettings& pelco_settings = config.pelco;
    pelco_settings.reply_timeout = reply_timeout;
    const ParamReader pelco = params.child("pelco_d");
    pelco_settings.address = static_cast<std::uint8_t>(pelco.integer("address", pelco_settings.address, 1, 255));
    pelco::parseTiltEncoding(pelco.choice("tilt_encoding", "down_positive", { "down_positive", "up_positive" }),
                             pelco_settings.tilt_encoding);
    pelco_settings.general_reply = pelco.flag("general_reply", pelco_settings.general_reply);
    pelco_settings.zoom_position_max =
        static_cast<std::uint16_t>(pelco.integer("zoom_position_max", pelco_settings.zoom_position_max, 1, 0xFFFF));
    readAxis(pelco.child("pan"), context.urdf_limits.axes[PAN].range, M_PI, pelco_settings.axes[PAN]);
    readAxis(pelco.child("tilt"), context.urdf_limits.axes[TILT].range, M_PI / 2.0, pelco_settings.axes[TILT]);
    const ParamReader zoom = pelco.child("zoom");
    AxisCapability& zoom_capability = pelco_settings.axes[ZOOM];
    zoom_capability.present = zoom.flag("present", true);
    zoom_capability.range.min = zoom.number("min", zoom_capability.range.min, 1.0, 1000.0);
    zoom_capability.range.max = zoom.number("max", zoom_capability.range.max, zoom_capability.range.min, 1000.0);
    zoom_capability.max_speed = zoom.number("rate", zoom_capability.max_speed, 1e-3, 1000.0);
    // Turbo is device-specific: off unless the device's byte is given (and faster than 0x3F's speed).
    pelco_settings.turbo_byte = static_cast<std::uint8_t>(pelco.integer("turbo_byte", 0, 0, 255));
    if (pelco_settings.turbo_byte != 0)
    {
      if (pelco_settings.turbo_byte <= pelco::MAX_SPEED)
      {
        throw ConfigError("parameter " + pelco.resolve("turbo_byte") +
                          " must be above 0x3F (63), the highest ordinary speed, or 0 for no turbo");
      }
      pelco_settings.turbo_speed = pelco.number("turbo_speed", 0.0, pelco_settings.axes[PAN].max_speed + 1e-6, 100.0);
    }
    return makePelcoBackend(config, context.clock);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::SerialBackendPlugin, ptz_action_server::BackendPlugin)

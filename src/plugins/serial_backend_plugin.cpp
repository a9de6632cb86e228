#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "ptz_action_server/core/serial/flir_backend.h"
#include "ptz_action_server/core/serial/pelco_backend.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// Builds the serial backend from ~serial/... parameters: `protocol: flir` or `protocol: pelco_d`.
class SerialBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    const std::string protocol = params.choice("protocol", "flir", { "flir", "pelco_d" });
    SerialBackendConfig serial;
    serial.link.path = params.text("port", "/dev/ttyUSB0");
    const int baud = params.integer("baud", 9600, 1200, 921600);
    if (!standardBaud(baud))
    {
      throw ConfigError("parameter " + params.resolve("baud") + " = " + std::to_string(baud) +
                        " is not a standard rate (1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400, "
                        "460800, 921600)");
    }
    serial.link.baud = static_cast<unsigned>(baud);
    serial.link.reconnect_min = params.number("reconnect_min", serial.link.reconnect_min, 0.01, 10.0);
    serial.link.reconnect_max =
        params.number("reconnect_max", serial.link.reconnect_max, serial.link.reconnect_min, 60.0);
    serial.transaction_deadline = params.number("transaction_deadline", serial.transaction_deadline, 0.02, 10.0);
    serial.reply_timeout = params.number("reply_timeout", serial.reply_timeout, 0.0, 10.0);
    serial.poll_period = params.number("poll_period", serial.poll_period, 0.005, 1.0);
    serial.startup_timeout = params.number("startup_timeout", serial.startup_timeout, 0.1, 600.0);
    serial.settle_window = params.number("settle_window", serial.settle_window, 0.0, 2.0);

    if (protocol == "flir")
    {
      FlirConfig config;
      config.serial = serial;
      const ParamReader flir = params.child("flir");
      config.pan_speed = flir.number("pan_speed", config.pan_speed, 1e-3, 10.0);
      config.tilt_speed = flir.number("tilt_speed", config.tilt_speed, 1e-3, 10.0);
      config.acceleration = flir.number("acceleration", config.acceleration, 0.0, 1e4);
      return std::make_shared<FlirBackend>(config, context.clock);
    }

    PelcoConfig config;
    config.serial = serial;
    const ParamReader pelco = params.child("pelco_d");
    config.address = static_cast<std::uint8_t>(pelco.integer("address", config.address, 1, 255));
    config.tilt_encoding = pelco.choice("tilt_encoding", "wrap", { "wrap", "inverted_wrap" }) == "wrap" ?
                               pelco::TiltEncoding::WRAP :
                               pelco::TiltEncoding::INVERTED_WRAP;
    config.general_reply = pelco.flag("general_reply", config.general_reply);
    config.zoom_position_max =
        static_cast<std::uint16_t>(pelco.integer("zoom_position_max", config.zoom_position_max, 1, 0xFFFF));
    const char* names[] = { "pan", "tilt" };
    for (Axis axis : { PAN, TILT })
    {
      const ParamReader axis_params = pelco.child(names[axis]);
      AxisCapability& capability = config.axes[axis];
      const AxisRange& urdf = context.urdf_limits.axes[axis].range;
      const double bound = axis == PAN ? M_PI : M_PI / 2.0;
      capability.range.min = axis_params.number("min", std::max(urdf.min, -bound), -bound, bound);
      capability.range.max = axis_params.number("max", std::min(urdf.max, bound), capability.range.min, bound);
      capability.max_speed = axis_params.number("max_speed", capability.max_speed, 1e-3, 100.0);
      capability.acceleration = axis_params.number("acceleration", capability.acceleration, 0.0, 1e4);
    }
    const ParamReader zoom = pelco.child("zoom");
    AxisCapability& zoom_capability = config.axes[ZOOM];
    zoom_capability.present = zoom.flag("present", true);
    zoom_capability.range.min = zoom.number("min", zoom_capability.range.min, 1.0, 1000.0);
    zoom_capability.range.max = zoom.number("max", zoom_capability.range.max, zoom_capability.range.min, 1000.0);
    zoom_capability.max_speed = zoom.number("rate", zoom_capability.max_speed, 1e-3, 1000.0);
    return std::make_shared<PelcoBackend>(config, context.clock);
  }

private:
  static bool standardBaud(int baud)
  {
    for (int rate : { 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600 })
    {
      if (rate == baud)
      {
        return true;
      }
    }
    return false;
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::SerialBackendPlugin, ptz_action_server::BackendPlugin)

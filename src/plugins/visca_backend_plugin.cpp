#include <cstdlib>
#include <cstring>
#include <sstream>

#include "device_plugin.h"
#include "ptz_action_server/core/visca/visca_protocol.h"

namespace ptz_action_server
{
namespace
{
/// "0x0000:1, 0x4000:18" (zoom position, decimal or hex, then X) -> \p table; false if it does not read.
bool parseZoomTable(const std::string& text, std::vector<visca::ZoomPoint>& table)
{
  std::vector<visca::ZoomPoint> rows;
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ','))
  {
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos)
    {
      return false;
    }
    const std::string position_text = item.substr(0, colon);
    const std::string zoom_text = item.substr(colon + 1);
    char* end = nullptr;
    const long position = std::strtol(position_text.c_str(), &end, 0);
    if (end == position_text.c_str() || position < 0 || position > 0xFFFF || *(end + std::strspn(end, " ")) != '\0')
    {
      return false;
    }
    const double zoom = std::strtod(zoom_text.c_str(), &end);
    if (end == zoom_text.c_str() || *(end + std::strspn(end, " ")) != '\0')
    {
      return false;
    }
    rows.push_back(visca::ZoomPoint{ static_cast<std::uint16_t>(position), zoom });
  }
  table = rows;
  return true;
}

/// address, model (a preset) and its overrides (pan/..., tilt/..., zoom/...) under \p params.
void readViscaSettings(const ParamReader& params, ViscaSettings& visca)
{
  visca.address = static_cast<std::uint8_t>(params.integer("address", visca.address, 1, 7));
  const std::string model = params.choice("model", "ptzoptics", { "evi_d70", "evi_d30", "ptzoptics" });
  visca::ViscaModel::preset(model, visca.model);
  for (Axis axis : { PAN, TILT })
  {
    const ParamReader axis_params = params.child(axisName(axis));
    visca::ViscaAxis& units = visca.model.axes[axis];
    units.steps_per_degree = axis_params.number("steps_per_degree", units.steps_per_degree, 0.01, 1000.0);
    units.min_degrees = axis_params.number("min_degrees", units.min_degrees, -180.0, 180.0);
    units.max_degrees = axis_params.number("max_degrees", units.max_degrees, units.min_degrees, 180.0);
    units.max_speed_byte =
        static_cast<std::uint8_t>(axis_params.integer("max_speed_byte", units.max_speed_byte, 1, 0x7F));
    units.max_speed = axis_params.number("max_speed", units.max_speed, 0.1, 1000.0);
  }
  visca.model.acceleration = params.number("acceleration", visca.model.acceleration, 0.0, 1e4);
  const ParamReader zoom = params.child("zoom");
  visca.model.has_zoom = zoom.flag("present", visca.model.has_zoom);
  visca.model.zoom_rate = zoom.number("rate", visca.model.zoom_rate, 1e-3, 1000.0);
  if (zoom.has("table"))
  {
    const std::string table = zoom.text("table", "");
    if (!parseZoomTable(table, visca.model.zoom_table))
    {
      throw ConfigError("parameter " + zoom.resolve("table") + " = '" + table +
                        "' is not a list of 'position:X' rows, e.g. '0x0000:1, 0x4000:18'");
    }
  }
  const std::string problem = visca.model.check();
  if (!problem.empty())
  {
    throw ConfigError("VISCA model '" + visca.model.name + "' under " + params.resolve("") + ": " + problem);
  }
}

/// framing under \p params: sony_ip by default on UDP, raw otherwise; sony_ip on anything but UDP is an error.
ViscaFraming readViscaFraming(const ParamReader& params, LinkKind kind)
{
  ViscaFraming framing = ViscaFraming::RAW;
  parseViscaFraming(params.choice("framing", kind == LinkKind::UDP ? "sony_ip" : "raw", { "raw", "sony_ip" }), framing);
  if (framing == ViscaFraming::SONY_IP && kind != LinkKind::UDP)
  {
    throw ConfigError("parameter " + params.resolve("framing") +
                      " = sony_ip needs transport: udp (Sony's VISCA over IP is UDP); use raw on " + toString(kind));
  }
  return framing;
}
}  // namespace

/**
 * \brief A VISCA camera: ~visca/..., on a serial port, or over TCP (raw VISCA, port 5678) or UDP (Sony's VISCA over
 * IP on port 52381 by default, or raw VISCA).
 */
struct ViscaPlugin
{
  using Protocol = ViscaProtocol;
  static constexpr const char* NAME = "visca";

  static LinkChoices links()
  {
    return { { { LinkKind::SERIAL }, { LinkKind::TCP, 5678 }, { LinkKind::UDP, visca::SONY_IP_PORT } } };
  }

  static void read(const DeviceParams& device, const BackendContext& /*context*/, DeviceConfig<ViscaProtocol>& config)
  {
    // Diagnostics keep the name the backend was loaded by.
    config.settings.backend_name =
        device.old_plugin == "serial" ? "serial/visca" : (device.old_plugin.empty() ? NAME : device.old_plugin);
    readViscaSettings(device.own, config.settings);
    config.settings.framing = readViscaFraming(device.own, config.link.kind);
    config.settings.reply_timeout = device.params.number("reply_timeout", 0.0, 0.0, 10.0);
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(ViscaPlugin, ViscaBackendPlugin)

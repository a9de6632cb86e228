#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <ros/console.h>

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

/// "1.1, 1.3, 60" -> \p speeds (deg/s of the bytes 1, 2, ...); false if it does not read.
bool parseSpeedTable(const std::string& text, std::vector<double>& speeds)
{
  std::vector<double> rows;
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ','))
  {
    char* end = nullptr;
    const double speed = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *(end + std::strspn(end, " ")) != '\0')
    {
      return false;
    }
    rows.push_back(speed);
  }
  speeds = rows;
  return !rows.empty();
}

/// pan/... or tilt/...: the model's units of one axis, each overridable.
void readViscaAxis(const ParamReader& axis_params, visca::ViscaAxis& units, std::uint8_t& nibbles)
{
  units.steps_per_degree = axis_params.number("steps_per_degree", units.steps_per_degree, 0.01, 10000.0);
  units.min_degrees = axis_params.number("min_degrees", units.min_degrees, -360.0, 360.0);
  units.max_degrees = axis_params.number("max_degrees", units.max_degrees, units.min_degrees, 360.0);
  units.reversed = axis_params.flag("reversed", units.reversed);
  nibbles = static_cast<std::uint8_t>(axis_params.integer("nibbles", nibbles, 4, 5));
  if (axis_params.has("speed_table"))
  {
    const std::string table = axis_params.text("speed_table", "");
    if (!parseSpeedTable(table, units.speed_table))
    {
      throw ConfigError("parameter " + axis_params.resolve("speed_table") + " = '" + table +
                        "' is not a list of deg/s, one per speed byte from 01h, e.g. '1.1, 1.3, 1.6'");
    }
    units.max_speed_byte = static_cast<std::uint8_t>(std::min<std::size_t>(units.speed_table.size(), 0x7F));
    units.max_speed = units.speed_table.back();
  }
  if (axis_params.has("max_speed_byte") || axis_params.has("max_speed"))
  {
    units.speed_table.clear();  // speeds in proportion to the byte, up to the given top
  }
  units.max_speed_byte =
      static_cast<std::uint8_t>(axis_params.integer("max_speed_byte", units.max_speed_byte, 1, 0x7F));
  units.max_speed = axis_params.number("max_speed", units.max_speed, 0.1, 1000.0);
}

/// address, model (a preset) and its overrides (pan/..., tilt/..., zoom/...), and the dialect, under \p params.
void readViscaSettings(const ParamReader& params, ViscaSettings& visca)
{
  visca.address = static_cast<std::uint8_t>(params.integer("address", visca.address, 1, 7));
  const std::string model = params.choice("model", "ptzoptics", visca::ViscaModel::presets());
  visca::ViscaModel::preset(model, visca.model);
  readViscaAxis(params.child("pan"), visca.model.axes[PAN], visca.model.layout.pan_nibbles);
  readViscaAxis(params.child("tilt"), visca.model.axes[TILT], visca.model.layout.tilt_nibbles);
  visca.model.layout.shared_speed = params.flag("shared_speed", visca.model.layout.shared_speed);
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
    visca.model.zoom_table_known = true;
  }
  parseViscaZoomDrive(zoom.choice("drive", toString(visca.zoom_drive), { "auto", "variable", "standard" }),
                      visca.zoom_drive);
  visca.inquiries = params.flag("inquiries", visca.inquiries);
  const ParamReader focus = params.child("focus");
  visca.lens.focus = focus.flag("present", visca.lens.focus);
  visca.lens.focus_near = static_cast<std::uint16_t>(focus.integer("near", visca.lens.focus_near, 0, 0xFFFF));
  visca.lens.focus_far = static_cast<std::uint16_t>(focus.integer("far", visca.lens.focus_far, 0, 0xFFFF));
  const ParamReader iris = params.child("iris");
  visca.lens.iris = iris.flag("present", visca.lens.iris);
  visca.lens.iris_closed = static_cast<std::uint8_t>(iris.integer("closed", visca.lens.iris_closed, 0, 0xFF));
  visca.lens.iris_open = static_cast<std::uint8_t>(iris.integer("open", visca.lens.iris_open, 0, 0xFF));
  visca.lens.poll_period = params.child("lens").number("poll_period", visca.lens.poll_period, 0.0, 60.0);
  visca.sequence_cycle = static_cast<std::uint32_t>(params.integer("sequence_cycle", 0, 0, 1 << 30));
  const std::string problem = visca.model.check();
  if (!problem.empty())
  {
    throw ConfigError("VISCA model '" + visca.model.name + "' under " + params.resolve("") + ": " + problem);
  }
}

/// True if a UDP socket can be bound to \p host:\p port now.
bool udpPortFree(const std::string& host, std::uint16_t port)
{
  boost::system::error_code failure;
  const auto address = boost::asio::ip::make_address(host, failure);
  if (failure)
  {
    return true;  // the link will name the bad address
  }
  boost::asio::io_context context;
  boost::asio::ip::udp::socket probe(context);
  probe.open(address.is_v4() ? boost::asio::ip::udp::v4() : boost::asio::ip::udp::v6(), failure);
  if (!failure)
  {
    probe.bind(boost::asio::ip::udp::endpoint(address, port), failure);
  }
  return !failure;
}

/**
 * \brief The local port of Sony's VISCA over IP when none is set: 52381. Sony cameras send their replies to UDP
 * 52381 whatever port the request came from (libvisca-ip reports it), so a client on another port never hears them.
 * Where another program (or another camera of this node) holds 52381, any free port, with a warning.
 */
void chooseSonyLocalPort(const ParamReader& params, LinkConfig& link)
{
  if (params.has("local_port"))
  {
    return;
  }
  if (udpPortFree(link.local_host, visca::SONY_IP_PORT))
  {
    link.local_port = visca::SONY_IP_PORT;
    return;
  }
  link.local_port = 0;
  boost::system::error_code failure;
  const auto camera = boost::asio::ip::make_address(link.host, failure);
  if (!failure && camera.is_loopback())
  {
    // A camera on this machine is an emulator (on 52381 itself, as config/visca.yaml's port): it answers the sender.
    ROS_INFO_STREAM("visca: udp " << link.local_host << ":" << visca::SONY_IP_PORT
                                  << " is taken (the emulated camera's?): listening on any free port");
    return;
  }
  ROS_WARN_STREAM("visca: udp " << link.local_host << ":" << visca::SONY_IP_PORT
                                << " is taken (another controller, or another camera of this node): listening on any "
                                   "free port, where Sony cameras that send their replies to 52381 are not heard; set "
                                << params.resolve("local_port"));
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

  static void read(const ParamReader& params, const BackendContext& /*context*/, DeviceConfig<ViscaProtocol>& config)
  {
    readViscaSettings(params, config.settings);
    config.settings.framing = readViscaFraming(params, config.link.kind);
    config.settings.reply_timeout = params.number("reply_timeout", 0.0, 0.0, 10.0);
    // A network link reaches one camera, whatever address it answers from; a serial chain has several.
    if (params.has("any_reply_address"))
    {
      config.settings.any_reply_address = params.flag("any_reply_address", false);
    }
    if (config.settings.framing == ViscaFraming::SONY_IP)
    {
      chooseSonyLocalPort(params, config.link);
    }
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(ViscaPlugin, ViscaBackendPlugin)

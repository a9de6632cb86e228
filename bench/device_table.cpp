#include "device_table.h"

#include <cstdio>
#include <cstdlib>

namespace ptz_bench
{
namespace
{
using PortKind = ptz_action_server::DevicePortConfig::Kind;

BenchParam value(const std::string& name, const XmlRpc::XmlRpcValue& value)
{
  return BenchParam{ name, value, BenchParam::Source::VALUE };
}

BenchParam emulatorPort(const std::string& name)
{
  return BenchParam{ name, XmlRpc::XmlRpcValue(), BenchParam::Source::EMULATOR_PORT };
}

BenchParam emulatorLink(const std::string& name)
{
  return BenchParam{ name, XmlRpc::XmlRpcValue(), BenchParam::Source::EMULATOR_LINK };
}

/// ~<protocol>/... on the emulator's pseudo-terminal at \p baud, or over TCP (\p baud 0).
std::vector<BenchParam> serialParams(const std::string& protocol, unsigned baud)
{
  if (baud == 0)
  {
    return { value(protocol + "/transport", "tcp"), value(protocol + "/host", "127.0.0.1"),
             emulatorPort(protocol + "/port") };
  }
  return { value(protocol + "/transport", "serial"), emulatorLink(protocol + "/port"),
           value(protocol + "/baud", static_cast<int>(baud)) };
}

DeviceRow serialRow(const char* protocol, unsigned baud)
{
  const PortKind kind = baud == 0 ? PortKind::TCP : PortKind::PTY;
  DeviceRow row;
  row.name = std::string(protocol) + (baud == 0 ? "_tcp" : "_serial_" + std::to_string(baud));
  row.plugin = protocol;
  row.params = serialParams(protocol, baud);
  row.emulator = std::string(protocol) == "flir" ? flirEmulator(kind, baud) : pelcoEmulator(kind, baud);
  row.goals = baud == 0 ? 1000 : 300;
  return row;
}

/// A parameter's value as --list shows it: the emulator's, or YAML-like (strings that read as numbers quoted).
std::string show(const BenchParam& param)
{
  switch (param.source)
  {
    case BenchParam::Source::EMULATOR_PORT:
      return "(the emulator's port)";
    case BenchParam::Source::EMULATOR_LINK:
      return "(the emulator's pty link)";
    case BenchParam::Source::VALUE:
      break;
  }
  XmlRpc::XmlRpcValue copy = param.value;
  if (copy.getType() == XmlRpc::XmlRpcValue::TypeString)
  {
    const std::string text = copy;
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    return end != text.c_str() && *end == '\0' ? "\"" + text + "\"" : text;
  }
  if (copy.getType() == XmlRpc::XmlRpcValue::TypeInt)
  {
    return std::to_string(static_cast<int>(copy));
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%g", static_cast<double>(copy));
  return text;
}
}  // namespace

const std::vector<DeviceRow>& deviceTable()
{
  static const std::vector<DeviceRow> rows = [] {
    std::vector<DeviceRow> table;
    DeviceRow sim;
    sim.name = "sim";
    sim.plugin = "sim";
    // A field of view, so a tick publishes everything a camera can: ptz_state, joint_states, tf, field_of_view.
    sim.params = { value("field_of_view/horizontal", 1.0), value("field_of_view/vertical", 0.6) };
    table.push_back(sim);

    DeviceRow pantilt;
    pantilt.name = "pantilt_udp";
    pantilt.plugin = "pantilt";
    pantilt.params = { value("pantilt/transport", "udp"), value("pantilt/host", "127.0.0.1"),
                       emulatorPort("pantilt/port"), value("pantilt/local_host", "127.0.0.1"),
                       value("pantilt/format", "seed") };
    pantilt.emulator = panTiltEmulator();
    table.push_back(pantilt);

    DeviceRow digiview;
    digiview.name = "digiview_tcp";
    digiview.plugin = "digiview";
    digiview.params = { value("digiview/transport", "tcp"), value("digiview/host", "127.0.0.1"),
                        emulatorPort("digiview/port"), value("digiview/acceleration", 4.0) };
    digiview.emulator = digiViewEmulator();
    table.push_back(digiview);

    DeviceRow gimbal;
    gimbal.name = "mavlink_gimbal_udp";
    gimbal.plugin = "mavlink_gimbal";
    gimbal.params = { value("mavlink_gimbal/transport", "udp"), value("mavlink_gimbal/host", "127.0.0.1"),
                      emulatorPort("mavlink_gimbal/port") };
    gimbal.emulator = mavlinkGimbalEmulator();
    table.push_back(gimbal);
    DeviceRow axis;
    axis.name = "axis_http";
    axis.plugin = "axis";
    axis.params = { value("axis/host", "127.0.0.1"), emulatorPort("axis/port"), value("axis/username", "root"),
                    value("axis/password", "pass") };
    axis.emulator = axisEmulator();
    table.push_back(axis);

    DeviceRow onvif;
    onvif.name = "onvif_http";
    onvif.plugin = "onvif";
    onvif.params = { value("onvif/host", "127.0.0.1"), emulatorPort("onvif/port"), value("onvif/username", "admin"),
                     value("onvif/password", "admin") };
    onvif.emulator = onvifEmulator();
    table.push_back(onvif);

    for (const char* protocol : { "flir", "pelco_d" })
    {
      for (unsigned baud : { 9600u, 115200u, 0u })
      {
        table.push_back(serialRow(protocol, baud));
      }
    }

    DeviceRow visca_serial;
    visca_serial.name = "visca_serial_9600";
    visca_serial.plugin = "visca";
    visca_serial.params = serialParams("visca", 9600);
    visca_serial.emulator = viscaEmulator(PortKind::PTY, 9600);
    visca_serial.goals = 300;
    table.push_back(visca_serial);

    DeviceRow visca_udp;
    visca_udp.name = "visca_udp";
    visca_udp.plugin = "visca";
    visca_udp.params = { value("visca/transport", "udp"), value("visca/host", "127.0.0.1"), emulatorPort("visca/port"),
                         value("visca/local_host", "127.0.0.1"), value("visca/framing", "sony_ip") };
    visca_udp.emulator = viscaEmulator(PortKind::UDP, 0);
    table.push_back(visca_udp);
    return table;
  }();
  return rows;
}

const DeviceRow* findDevice(const std::string& name)
{
  for (const DeviceRow& row : deviceTable())
  {
    if (row.name == name)
    {
      return &row;
    }
  }
  return nullptr;
}

std::string deviceNames()
{
  std::string names;
  for (const DeviceRow& row : deviceTable())
  {
    names += (names.empty() ? "" : ", ") + row.name;
  }
  return names;
}

void printDeviceTable()
{
  std::printf("| device | plugin | emulator | parameters under ~ | goal commands | stop | goals |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const DeviceRow& row : deviceTable())
  {
    std::string params = "backend: " + row.plugin;
    for (const BenchParam& param : row.params)
    {
      params += ", " + param.name + ": " + show(param);
    }
    const EmulatorSpec& emulator = row.emulator;
    const bool emulated = static_cast<bool>(emulator.start);
    std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", row.name.c_str(), row.plugin.c_str(),
                emulated ? emulator.summary.c_str() : "none (the backend is the simulation)", params.c_str(),
                emulated ? emulator.goal_items.c_str() : "the backend's goTo / moveAtVelocity / stop calls",
                emulated ? emulator.stop_items.c_str() : "the backend's stop() call",
                emulated ? std::to_string(row.goals).c_str() : "-");
  }
  std::fflush(stdout);
}

}  // namespace ptz_bench

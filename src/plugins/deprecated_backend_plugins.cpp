/**
 * \file
 * \brief The old plugin names: `serial` with `protocol:`, `pantilt_udp` and `visca_ip`. Each reads its old
 * parameter namespaces and builds the backend of today's plugin, with one deprecation line naming it.
 */
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <pluginlib/class_list_macros.hpp>

#include "device_plugin.h"

namespace ptz_action_server
{
namespace
{
std::map<std::string, DeviceFactory>& factories()
{
  static std::map<std::string, DeviceFactory> registered;
  return registered;
}
}  // namespace

bool registerDevice(const std::string& name, DeviceFactory factory)
{
  factories()[name] = factory;
  return true;
}

DeviceFactory findDevice(const std::string& name)
{
  const auto found = factories().find(name);
  if (found == factories().end())
  {
    throw ConfigError("no device plugin '" + name + "' in this library");
  }
  return found->second;
}

/**
 * \brief `serial` with `protocol: flir | pelco_d | visca | pantilt`: the link and session under ~serial/ (the
 * device path in port, the TCP port in tcp_port, the UDP port in udp_port, the state deadline in
 * transaction_deadline), the protocol's settings under ~serial/PROTOCOL/.
 */
class SerialBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    const std::string protocol = params.choice("protocol", "flir", { "flir", "pelco_d", "visca", "pantilt" });
    DeviceParams::warnDeprecated("backend 'serial' (" + params.resolve("protocol") + ": " + protocol + ")",
                                 "backend '" + protocol + "' with its parameters under ~" + protocol +
                                     "/ (those of ~serial/" + protocol +
                                     "/ one level up; port is the device path or the port number, state_timeout the "
                                     "state deadline)");
    DeviceParams device(params, protocol);
    device.own = params.child(protocol);
    device.old_plugin = "serial";
    device.default_transport = "serial";
    device.transports = { "serial", "tcp" };
    if (protocol == "visca")
    {
      device.transports.push_back("udp");
    }
    if (protocol == "pantilt")
    {
      // PanTilt's state deadline was ~serial/pantilt/state_timeout, never transaction_deadline.
      device.old_names = { { "host", "device_host" }, { "state_timeout", "pantilt/state_timeout" } };
    }
    return findDevice(protocol)(device, context);
  }
};

/// `pantilt_udp`: ~pantilt_udp/... with the device's address in device_host and device_port.
class PanTiltUdpBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    DeviceParams::warnDeprecated("backend 'pantilt_udp'", "backend 'pantilt' with its parameters under ~pantilt/ "
                                                          "(device_host and device_port are host and port there)");
    DeviceParams device(params, "pantilt");
    device.old_plugin = "pantilt_udp";
    device.transports = { "udp" };
    return findDevice("pantilt")(device, context);
  }
};

/// `visca_ip`: ~visca_ip/..., over UDP (the default) or TCP.
class ViscaIpBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    DeviceParams::warnDeprecated("backend 'visca_ip'", "backend 'visca' with its parameters under ~visca/ (and "
                                                       "transport: udp, its default being serial there)");
    DeviceParams device(params, "visca");
    device.old_plugin = "visca_ip";
    device.default_transport = "udp";
    device.transports = { "udp", "tcp" };
    return findDevice("visca")(device, context);
  }
};

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::SerialBackendPlugin, ptz_action_server::BackendPlugin)
PLUGINLIB_EXPORT_CLASS(ptz_action_server::PanTiltUdpBackendPlugin, ptz_action_server::BackendPlugin)
PLUGINLIB_EXPORT_CLASS(ptz_action_server::ViscaIpBackendPlugin, ptz_action_server::BackendPlugin)

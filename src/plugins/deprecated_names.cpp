/**
 * \file
 * \brief The old names (deprecated_names.h): the parameter renaming table every device plugin applies before it
 * reads, and the old plugin names `serial` with `protocol:`, `pantilt_udp` and `visca_ip`, each building the backend
 * of today's plugin from its old parameter namespaces with one deprecation line naming it.
 */
#include "deprecated_names.h"

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pluginlib/class_list_macros.hpp>
#include <ros/console.h>

namespace ptz_action_server
{
namespace
{
/// A parameter's old name, read in the place of today's name when only the old one is set.
struct OldName
{
  const char* name;      ///< today's ("port")
  const char* old_name;  ///< relative to the namespace the link is read in ("tcp_port", "pantilt/state_timeout")
  const char* transport = nullptr;  ///< the transport it applies to ("tcp", "network": tcp or udp); null: any
};

/// Every device plugin's old names, each looked for in this order when today's name is not set.
const std::vector<OldName>& commonOldNames()
{
  static const std::vector<OldName> names = {
    { "host", "device_host" },                    // pantilt_udp
    { "port", "serial_port", "serial" },          // mavlink_gimbal
    { "port", "device_port", "network" },         // pantilt_udp
    { "port", "tcp_port", "tcp" },                // serial
    { "port", "udp_port", "udp" },                // serial
    { "state_timeout", "transaction_deadline" },  // serial
    { "tls_verify", "verify_peer" },              // axis, onvif
  };
  return names;
}

/// The link and session parameters the `serial` plugin read under ~serial/, its protocol's own under ~serial/NAME/.
const char* const SERIAL_LINK_NAMES[] = {
  "transport",       "host",          "port",          "baud",          "local_host",  "local_port",
  "connect_timeout", "reconnect_min", "reconnect_max", "state_timeout", "poll_period", "startup_timeout",
  "settle_window",   "reply_timeout"
};

std::map<std::string, DeviceEntry>& devices()
{
  static std::map<std::string, DeviceEntry> registered;
  return registered;
}

DeviceEntry findDevice(const std::string& name)
{
  const auto found = devices().find(name);
  if (found == devices().end())
  {
    throw ConfigError("no device plugin '" + name + "' in this library");
  }
  return found->second;
}

void warnDeprecated(const std::string& old_text, const std::string& new_text)
{
  ROS_WARN("%s is deprecated: use %s", old_text.c_str(), new_text.c_str());
}

/// \p choices' transports \p kinds, in that order (the first is the default).
LinkChoices only(LinkChoices choices, const std::vector<LinkKind>& kinds)
{
  std::vector<TransportChoice> kept;
  for (LinkKind kind : kinds)
  {
    for (const TransportChoice& choice : choices.transports)
    {
      if (choice.kind == kind)
      {
        kept.push_back(choice);
      }
    }
  }
  choices.transports = kept;
  return choices;
}

/**
 * \brief What the parameters of today of the plugin \p plugin are read from, where the link's are under \p link
 * (~flir/, or the old ~serial/): \p old_names for each name of today that is not set (or, for port, not of its
 * transport's type); with \p own_namespace (~serial/flir/ for `serial`), the link's names under \p link too, and a
 * port path on a network transport ignored (the old serial YAML holds port: /dev/ttyUSB0 whatever the transport).
 */
ParamRenames renames(const ParamReader& link, const std::string& plugin, const LinkChoices& choices,
                     const std::vector<OldName>& old_names, bool own_namespace)
{
  const std::string transport = link.text("transport", transportName(choices.transports.front().kind));
  const bool network = transport == "tcp" || transport == "udp";
  XmlRpc::XmlRpcValue port;
  const bool port_set = link.get("port", port);
  const bool port_fits =
      port_set && port.getType() == (network ? XmlRpc::XmlRpcValue::TypeInt : XmlRpc::XmlRpcValue::TypeString);
  ParamRenames renamed;
  for (const OldName& old : old_names)
  {
    const std::string name = old.name;
    const bool applies =
        old.transport == nullptr || transport == old.transport || (std::string(old.transport) == "network" && network);
    const bool set = name == "port" ? port_fits : link.has(name);
    if (applies && !set && renamed.count(name) == 0 && link.has(old.old_name))
    {
      const std::string parameter = link.resolve(old.old_name);
      renamed[name] = { parameter, "parameter " + parameter + " is deprecated: use ~" + plugin + "/" + name };
    }
  }
  if (own_namespace)
  {
    if (network && port_set && !port_fits && renamed.count("port") == 0)
    {
      renamed["port"] = { "", "" };
    }
    for (const char* name : SERIAL_LINK_NAMES)
    {
      renamed.insert({ name, { link.resolve(name), "" } });
    }
  }
  return renamed;
}
}  // namespace

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
    warnDeprecated("backend 'serial' (" + params.resolve("protocol") + ": " + protocol + ")",
                   "backend '" + protocol + "' with its parameters under ~" + protocol + "/ (those of ~serial/" +
                       protocol +
                       "/ one level up; port is the device path or the port number, state_timeout the state deadline)");
    const DeviceEntry device = findDevice(protocol);
    std::vector<LinkKind> kinds = { LinkKind::SERIAL, LinkKind::TCP };
    if (protocol == "visca")
    {
      kinds.push_back(LinkKind::UDP);
    }
    const LinkChoices choices = only(device.links(), kinds);
    std::vector<OldName> old_names = commonOldNames();
    for (OldName& old : old_names)
    {
      if (protocol == "pantilt" && std::string(old.name) == "state_timeout")
      {
        old.old_name = "pantilt/state_timeout";  // PanTilt's state deadline, never transaction_deadline
      }
    }
    const ParamReader own = params.child(protocol).renamed(renames(params, protocol, choices, old_names, true));
    return device.create(own, choices, context);
  }
};

/// A plugin renamed: today's plugin over some of its transports, its parameters under the old name's namespace.
class RenamedBackendPlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    warnDeprecated("backend '" + old_name_ + "'",
                   "backend '" + plugin_ + "' with its parameters under ~" + plugin_ + "/ (" + advice_ + ")");
    const DeviceEntry device = findDevice(plugin_);
    const LinkChoices choices = only(device.links(), kinds_);
    return device.create(withOldNames(params, plugin_, choices), choices, context);
  }

protected:
  /// \p kinds: the transports the old name took, the first its default.
  RenamedBackendPlugin(std::string old_name, std::string plugin, std::string advice, std::vector<LinkKind> kinds)
    : old_name_(std::move(old_name)), plugin_(std::move(plugin)), advice_(std::move(advice)), kinds_(std::move(kinds))
  {
  }

private:
  std::string old_name_;
  std::string plugin_;
  std::string advice_;  ///< what else changed, for the deprecation line
  std::vector<LinkKind> kinds_;
};

/// `pantilt_udp`: ~pantilt_udp/... with the device's address in device_host and device_port.
class PanTiltUdpBackendPlugin : public RenamedBackendPlugin
{
public:
  PanTiltUdpBackendPlugin()
    : RenamedBackendPlugin("pantilt_udp", "pantilt", "device_host and device_port are host and port there",
                           { LinkKind::UDP })
  {
  }
};

/// `visca_ip`: ~visca_ip/..., over UDP (the default) or TCP.
class ViscaIpBackendPlugin : public RenamedBackendPlugin
{
public:
  ViscaIpBackendPlugin()
    : RenamedBackendPlugin("visca_ip", "visca", "and transport: udp, its default being serial there",
                           { LinkKind::UDP, LinkKind::TCP })
  {
  }
};

ParamReader withOldNames(const ParamReader& params, const std::string& plugin, const LinkChoices& choices)
{
  return params.renamed(renames(params, plugin, choices, commonOldNames(), false));
}

bool registerDevice(const std::string& name, DeviceEntry entry)
{
  devices()[name] = entry;
  return true;
}

}  // namespace ptz_action_server

PLUGINLIB_EXPORT_CLASS(ptz_action_server::SerialBackendPlugin, ptz_action_server::BackendPlugin)
PLUGINLIB_EXPORT_CLASS(ptz_action_server::PanTiltUdpBackendPlugin, ptz_action_server::BackendPlugin)
PLUGINLIB_EXPORT_CLASS(ptz_action_server::ViscaIpBackendPlugin, ptz_action_server::BackendPlugin)

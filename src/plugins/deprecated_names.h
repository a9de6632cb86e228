/**
 * \file
 * \brief The old names, all in one place: the old plugin names (`serial` with `protocol:`, `pantilt_udp`,
 * `visca_ip`, in deprecated_names.cpp) and the old parameter names, mapped to today's before anything is read, each
 * with one deprecation line (doc/backends/link-parameters.md#old-names).
 *
 * Removing them one day is deleting this file and deprecated_names.cpp (and its line in CMakeLists.txt), the two
 * lines of device_plugin.h that call withOldNames() and registerDevice(), launch/deprecated_names.launch (and its
 * include and the protocol argument in ptz_action_server.launch), config/serial.yaml, pantilt_udp.yaml and
 * visca_ip.yaml, the three deprecated classes of backend_plugins.xml, and the rostests that start the old names
 * (deprecated_names.test, pantilt_udp_node.test, visca_ip_node.test, serial_pelco_node.test). ParamReader::renamed()
 * then has no caller left.
 */
#pragma once

#include <memory>
#include <string>

#include "plugin_params.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/ros/backend_plugin.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/**
 * \brief \p params (~NAME/ of the plugin \p plugin, e.g. ~flir/) reading each parameter of today from its old name
 * where only the old one is set: `device_host` (host), `device_port`, `tcp_port`, `udp_port`, `serial_port` (port),
 * `transaction_deadline` (state_timeout), `verify_peer` (tls_verify). The first read of an old name prints one
 * warning naming its new spelling under ~NAME/.
 */
ParamReader withOldNames(const ParamReader& params, const std::string& plugin, const LinkChoices& choices);

/// How a deprecated plugin name builds the backend of today's plugin: its links, and the backend from its reader.
struct DeviceEntry
{
  LinkChoices (*links)() = nullptr;
  std::shared_ptr<PtzBackend> (*create)(const ParamReader&, const LinkChoices&, const BackendContext&) = nullptr;
};

/// Makes the plugin of today \p name ("flir") findable by the deprecated plugin names. Returns true.
bool registerDevice(const std::string& name, DeviceEntry entry);

}  // namespace ptz_action_server

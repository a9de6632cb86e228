/**
 * \file
 * \brief The one wiring of every device plugin: a protocol's plugin file is its settings reader and one
 * PTZ_DEVICE_PLUGIN line.
 *
 * A protocol's plugin is a struct with
 * - `using Protocol = ...;` its DeviceProtocol (its config is DeviceConfig<Protocol>: link, session, settings),
 * - `static constexpr const char* NAME`, the plugin name and parameter namespace ("flir": ~flir/...),
 * - `static LinkChoices links()`, the transports it runs over and their default ports,
 * - `static void read(const DeviceParams&, const BackendContext&, DeviceConfig<Protocol>&)`, its own settings.
 *
 * The link and session parameters are read once for all (plugin_params.h), before read().
 */
#pragma once

#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "plugin_params.h"
#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// The backend of \p Plugin from \p device's parameters: link, session, then the protocol's own settings.
template <class Plugin>
std::shared_ptr<PtzBackend> createDevice(const DeviceParams& device, const BackendContext& context)
{
  DeviceConfig<typename Plugin::Protocol> config;
  const LinkChoices choices = Plugin::links();
  readLink(device, choices, config.link);
  readSession(device, choices, config.session);
  Plugin::read(device, context, config);
  return makeDeviceBackend<typename Plugin::Protocol>(config, context.clock);
}

/// The pluginlib class of \p Plugin: reads ~NAME/...
template <class Plugin>
class DevicePlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    return createDevice<Plugin>(DeviceParams(params, Plugin::NAME), context);
  }
};

using DeviceFactory = std::shared_ptr<PtzBackend> (*)(const DeviceParams&, const BackendContext&);

/// Makes \p factory findable by \p name for the deprecated plugin names (serial with protocol:). Returns true.
bool registerDevice(const std::string& name, DeviceFactory factory);

/// The factory registered under \p name; throws ConfigError if there is none.
DeviceFactory findDevice(const std::string& name);

}  // namespace ptz_action_server

/// Exports DevicePlugin<Plugin> as ptz_action_server::PluginClass (backend_plugins.xml's type).
#define PTZ_DEVICE_PLUGIN(Plugin, PluginClass)                                                                         \
  namespace ptz_action_server                                                                                          \
  {                                                                                                                    \
  using PluginClass = DevicePlugin<Plugin>;                                                                            \
  namespace                                                                                                            \
  {                                                                                                                    \
  const bool PluginClass##_registered = registerDevice(Plugin::NAME, &createDevice<Plugin>);                           \
  }                                                                                                                    \
  }                                                                                                                    \
  PLUGINLIB_EXPORT_CLASS(ptz_action_server::PluginClass, ptz_action_server::BackendPlugin)

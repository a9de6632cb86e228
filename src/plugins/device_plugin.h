/**
 * \file
 * \brief The one wiring of every device plugin: a protocol's plugin file is its settings reader and one
 * PTZ_DEVICE_PLUGIN line.
 *
 * A protocol's plugin is a struct with
 * - `using Protocol = ...;` its DeviceProtocol (its config is DeviceConfig<Protocol>: link, session, settings),
 * - `static constexpr const char* NAME`, the plugin name and parameter namespace ("flir": backend:=flir, ~flir/...),
 *   which is also the protocol's name() in messages and diagnostics,
 * - `static LinkChoices links()`, the transports it runs over and their default ports,
 * - `static void read(const ParamReader&, const BackendContext&, DeviceConfig<Protocol>&)`, its own settings.
 *
 * The link and session parameters are read once for all (plugin_params.h), before read().
 */
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "deprecated_names.h"
#include "plugin_params.h"
#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// The backend of \p Plugin from \p params (~NAME/): link (one of \p choices), session, then its own settings.
template <class Plugin>
std::shared_ptr<PtzBackend> createDevice(const ParamReader& params, const LinkChoices& choices,
                                         const BackendContext& context)
{
  DeviceConfig<typename Plugin::Protocol> config;
  readLink(params, choices, config.link);
  readSession(params, choices, config.session);
  Plugin::read(params, context, config);
  std::shared_ptr<PtzBackend> backend = makeDeviceBackend<typename Plugin::Protocol>(config, context.clock);
  // One name for one thing: messages and diagnostics name the backend as backend:= does (a protocol's name() that
  // is not its plugin's fails its first node test here).
  if (backend->name() != Plugin::NAME)
  {
    throw std::logic_error("the protocol of plugin '" + std::string(Plugin::NAME) + "' calls itself '" +
                           backend->name() + "'");
  }
  return backend;
}

/// The pluginlib class of \p Plugin: reads ~NAME/...
template <class Plugin>
class DevicePlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    const LinkChoices choices = Plugin::links();
    return createDevice<Plugin>(withOldNames(params, Plugin::NAME, choices), choices, context);
  }
};

}  // namespace ptz_action_server

/// Exports DevicePlugin<Plugin> as ptz_action_server::PluginClass (backend_plugins.xml's type).
#define PTZ_DEVICE_PLUGIN(Plugin, PluginClass)                                                                         \
  namespace ptz_action_server                                                                                          \
  {                                                                                                                    \
  using PluginClass = DevicePlugin<Plugin>;                                                                            \
  namespace                                                                                                            \
  {                                                                                                                    \
  const bool PluginClass##_registered = registerDevice(Plugin::NAME, { &Plugin::links, &createDevice<Plugin> });       \
  }                                                                                                                    \
  }                                                                                                                    \
  PLUGINLIB_EXPORT_CLASS(ptz_action_server::PluginClass, ptz_action_server::BackendPlugin)

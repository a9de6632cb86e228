/**
 * \file
 * \brief The one wiring of every device plugin: a protocol's plugin file is its settings reader and one
 * PTZ_DEVICE_PLUGIN line.
 *
 * A protocol's plugin is a struct with
 * - `using Config = ...;` its core config (with `link`, `session` and the protocol's settings),
 * - `static constexpr const char* NAME`, the plugin name and parameter namespace ("flir": ~flir/...),
 * - `static LinkChoices links()`, the transports it runs over and their default ports,
 * - `static void read(const DeviceParams&, const BackendContext&, Config&)`, its own settings,
 * - `static std::unique_ptr<DeviceBackend> make(const Config&, std::shared_ptr<const Clock>)`.
 *
 * The link and session parameters are read once for all (plugin_params.h), before read().
 */
#pragma once

#include <memory>
#include <string>

#include <pluginlib/class_list_macros.hpp>

#include "plugin_params.h"
#include "ptz_action_server/ros/backend_plugin.h"

namespace ptz_action_server
{
/// The backend of \p Protocol from \p device's parameters: link, session, then the protocol's own settings.
template <class Protocol>
std::shared_ptr<PtzBackend> createDevice(const DeviceParams& device, const BackendContext& context)
{
  typename Protocol::Config config;
  const LinkChoices choices = Protocol::links();
  readLink(device, choices, config.link);
  readSession(device, choices, config.session);
  Protocol::read(device, context, config);
  return Protocol::make(config, context.clock);
}

/// The pluginlib class of \p Protocol: reads ~NAME/...
template <class Protocol>
class DevicePlugin : public BackendPlugin
{
public:
  std::shared_ptr<PtzBackend> create(const ParamReader& params, const BackendContext& context) override
  {
    return createDevice<Protocol>(DeviceParams(params, Protocol::NAME), context);
  }
};

using DeviceFactory = std::shared_ptr<PtzBackend> (*)(const DeviceParams&, const BackendContext&);

/// Makes \p factory findable by \p name for the deprecated plugin names (serial with protocol:). Returns true.
bool registerDevice(const std::string& name, DeviceFactory factory);

/// The factory registered under \p name; throws ConfigError if there is none.
DeviceFactory findDevice(const std::string& name);

}  // namespace ptz_action_server

/// Exports DevicePlugin<Protocol> as ptz_action_server::PluginClass (backend_plugins.xml's type).
#define PTZ_DEVICE_PLUGIN(Protocol, PluginClass)                                                                       \
  namespace ptz_action_server                                                                                          \
  {                                                                                                                    \
  using PluginClass = DevicePlugin<Protocol>;                                                                          \
  namespace                                                                                                            \
  {                                                                                                                    \
  const bool PluginClass##_registered = registerDevice(Protocol::NAME, &createDevice<Protocol>);                       \
  }                                                                                                                    \
  }                                                                                                                    \
  PLUGINLIB_EXPORT_CLASS(ptz_action_server::PluginClass, ptz_action_server::BackendPlugin)

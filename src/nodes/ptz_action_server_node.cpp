/**
 * \file
 * \brief main() of the ptz_action_server node: parameters, URDF, backend plugin, then spin.
 */
#include <memory>
#include <string>

#include <pluginlib/class_loader.hpp>
#include <ros/ros.h>

#include "ptz_action_server/ros/backend_plugin.h"
#include "ptz_action_server/ros/ptz_action_server.h"

namespace
{
/// "sim" -> "ptz_action_server/sim"; a name with a package prefix is used as it is.
std::string pluginName(const std::string& backend)
{
  return backend.find('/') == std::string::npos ? "ptz_action_server/" + backend : backend;
}

std::string knownBackends(pluginlib::ClassLoader<ptz_action_server::BackendPlugin>& loader)
{
  std::string names;
  for (const std::string& name : loader.getDeclaredClasses())
  {
    names += (names.empty() ? "" : ", ") + name;
  }
  return names.empty() ? "(none)" : names;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_action_server");
  ros::NodeHandle node_handle;
  ros::NodeHandle private_handle("~");
  using namespace ptz_action_server;

  // The loader must outlive the plugin and the backend: their code lives in the plugin library.
  pluginlib::ClassLoader<BackendPlugin> loader("ptz_action_server", "ptz_action_server::BackendPlugin");
  boost::shared_ptr<BackendPlugin> plugin;
  std::shared_ptr<PtzBackend> backend;
  std::unique_ptr<PtzActionServer> server;
  try
  {
    const ParamReader params(private_handle);
    const NodeConfig config = NodeConfig::load(params);

    std::string urdf;
    if (!node_handle.getParam("robot_description", urdf))
    {
      throw ConfigError("parameter " + node_handle.resolveName("robot_description") +
                        " is not set: load the URDF first (the launch file does)");
    }
    const PtzKinematics kinematics = PtzKinematics::fromUrdf(urdf, config.names);

    const std::string name = pluginName(config.backend);
    if (!loader.isClassAvailable(name))
    {
      throw ConfigError("unknown backend '" + config.backend + "'; known backends: " + knownBackends(loader));
    }
    try
    {
      plugin = loader.createInstance(name);
    }
    catch (const pluginlib::PluginlibException& error)
    {
      throw ConfigError("backend '" + name + "' could not be loaded: " + error.what());
    }
    BackendContext context;
    context.urdf_limits = PtzActionServer::urdfLimits(kinematics);
    const std::string backend_namespace = name.substr(name.find('/') + 1);
    backend = plugin->create(params.child(backend_namespace), context);

    server = std::make_unique<PtzActionServer>(node_handle, config, kinematics, backend);
    server->start();
  }
  catch (const ConfigError& error)
  {
    ROS_FATAL("configuration error: %s", error.what());
    return 1;
  }
  catch (const BackendError& error)
  {
    ROS_FATAL("backend error: %s", error.what());
    return 2;
  }

  ros::spin();
  server.reset();
  backend.reset();
  plugin.reset();
  return 0;
}

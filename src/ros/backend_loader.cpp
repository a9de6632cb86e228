#include "ptz_action_server/ros/backend_loader.h"

#include <ros/names.h>

#include "ptz_action_server/core/limits.h"

namespace ptz_action_server
{
namespace
{
/// "sim" -> "ptz_action_server/sim"; a name with a package prefix is used as it is.
std::string pluginName(const std::string& backend)
{
  return backend.find('/') == std::string::npos ? "ptz_action_server/" + backend : backend;
}
}  // namespace

BackendLoader::BackendLoader() : loader_("ptz_action_server", "ptz_action_server::BackendPlugin")
{
}

BackendLoader::~BackendLoader()
{
  // The plugins' code lives in the libraries loader_ unloads.
  plugins_.clear();
}

std::string BackendLoader::knownBackends()
{
  std::string names;
  for (const std::string& name : loader_.getDeclaredClasses())
  {
    names += (names.empty() ? "" : ", ") + name;
  }
  return names.empty() ? "(none)" : names;
}

std::shared_ptr<PtzBackend> BackendLoader::load(const std::string& backend, const ParamReader& params,
                                                const PtzKinematics& kinematics, const MountConfig& mount)
{
  const std::string name = pluginName(backend);
  if (!loader_.isClassAvailable(name))
  {
    throw ConfigError("unknown backend '" + backend + "'; known backends: " + knownBackends());
  }
  boost::shared_ptr<BackendPlugin> plugin;
  try
  {
    plugin = loader_.createInstance(name);
  }
  catch (const pluginlib::PluginlibException& error)
  {
    throw ConfigError("backend '" + name + "' could not be loaded: " + error.what());
  }
  plugins_.push_back(plugin);
  BackendContext context;
  context.urdf_limits = deviceLimits(urdfLimits(kinematics), mount);
  context.joint_names = { { kinematics.panJoint().name, kinematics.tiltJoint().name } };
  // The private namespace's parent is the node's namespace.
  context.node_namespace = ros::NodeHandle(ros::names::parentNamespace(params.nodeHandle().getNamespace()));
  const std::string backend_namespace = name.substr(name.find('/') + 1);
  return plugin->create(params.child(backend_namespace), context);
}

}  // namespace ptz_action_server

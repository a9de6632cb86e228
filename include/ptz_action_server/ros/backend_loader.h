/**
 * \file
 * \brief Loading a backend by name through pluginlib: what the node and the benchmark share.
 */
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <boost/shared_ptr.hpp>
#include <pluginlib/class_loader.hpp>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/mounted_backend.h"
#include "ptz_action_server/ros/backend_plugin.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/**
 * \brief Creates backends through the BackendPlugins pluginlib finds, and keeps their libraries loaded.
 *
 * The code of a plugin and of every backend it creates lives in the plugin's library, which stays loaded as long as
 * the loader: destroy every backend before the loader. One thread (the node's main thread).
 */
class BackendLoader
{
public:
  BackendLoader();
  ~BackendLoader();
  BackendLoader(const BackendLoader&) = delete;
  BackendLoader& operator=(const BackendLoader&) = delete;

  /**
   * \brief Creates the backend named \p backend ("sim" means "ptz_action_server/sim") from the parameters under the
   * plugin's short name in \p params (~sim/..., ~flir/...), with the URDF's pan and tilt limits as its context,
   * in the device's own angles through \p mount (a backend whose limits default to the URDF's gets them right side up).
   *
   * The backend is not started. Throws ConfigError for an unknown backend ("unknown backend 'x'; known backends:
   * ..."), a plugin that cannot be loaded, or a bad parameter; whatever the plugin throws otherwise passes through.
   */
  std::shared_ptr<PtzBackend> load(const std::string& backend, const ParamReader& params,
                                   const PtzKinematics& kinematics, const MountConfig& mount = MountConfig());

  /// The declared backends ("ptz_action_server/sim, ..."), or "(none)".
  std::string knownBackends();

private:
  pluginlib::ClassLoader<BackendPlugin> loader_;
  std::vector<boost::shared_ptr<BackendPlugin>> plugins_;  ///< after loader_: released first
};

}  // namespace ptz_action_server

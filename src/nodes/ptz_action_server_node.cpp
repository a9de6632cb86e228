/**
 * \file
 * \brief main() of the ptz_action_server node: parameters, URDF, backend plugin, then spin.
 */
#include <memory>
#include <string>

#include <ros/ros.h>

#include "ptz_action_server/ros/backend_loader.h"
#include "ptz_action_server/ros/ptz_action_server.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_action_server");
  ros::NodeHandle node_handle;
  ros::NodeHandle private_handle("~");
  using namespace ptz_action_server;

  // The loader must outlive the backend: its code lives in the plugin library.
  BackendLoader loader;
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
    backend = loader.load(config.backend, params, kinematics);

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
  return 0;
}

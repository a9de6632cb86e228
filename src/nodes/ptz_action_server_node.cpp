/**
 * \file
 * \brief main() of the ptz_action_server node: parameters, URDF, backend plugin, then spin.
 */
#include <ros/ros.h>

#include "ptz_action_server/ros/ptz_node.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_action_server");
  using namespace ptz_action_server;
  // Held for the whole run: when the last node handle goes, roscpp shuts down (and would drop the fatal message).
  const ros::NodeHandle node_handle;
  const ros::NodeHandle private_handle("~");
  MainSpinner spinner;  // before the node: its timers run on this thread
  PtzNode node;
  try
  {
    node.start(node_handle, private_handle);
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
  spinner.spinUntilShutdown();
  return 0;
}

/**
 * \file
 * \brief main() of the ptz_teleop node: a joystick (sensor_msgs/Joy on joy) drives the camera in its namespace.
 */
#include <ros/ros.h>

#include "ptz_action_server/ros/ptz_teleop.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_teleop");
  using namespace ptz_action_server;
  const ros::NodeHandle node_handle;
  std::unique_ptr<PtzTeleop> teleop;
  try
  {
    teleop = std::make_unique<PtzTeleop>(node_handle, loadTeleopConfig(ParamReader(ros::NodeHandle("~"))));
  }
  catch (const ConfigError& error)
  {
    ROS_FATAL("configuration error: %s", error.what());
    return 1;
  }
  ros::spin();
  return 0;
}

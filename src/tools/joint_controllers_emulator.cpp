/**
 * \file
 * \brief joint_controllers_emulator: plays a pan-tilt's per-joint position controllers, as Gazebo's or ros_control's
 * would, for the joint_topics backend.
 *
 * It follows the std_msgs/Float64 position commands on ~pan_command_topic and ~tilt_command_topic with the shared sim
 * motion model (a servo with a top speed and acceleration, faster than the backend's setpoint so it can follow it)
 * and publishes sensor_msgs/JointState on ~state_topic at ~rate. ~set_faults (ptz_action_server/SetSimFaults) stalls
 * a joint, adds command lag, or silences it (no joint states, commands lost), so tests can break it on purpose.
 *
 * Topics resolve in the node's namespace; the defaults are the joint_topics backend's.
 */
#include <algorithm>
#include <array>
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>

#include "ptz_action_server/SetSimFaults.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

namespace
{
using namespace ptz_action_server;

class JointControllersEmulator
{
public:
  JointControllersEmulator() : private_handle_("~"), model_(deviceConfig(private_handle_), clock_.now())
  {
    joint_states_.name = { private_handle_.param<std::string>("pan_joint", "ptz_pan_joint"),
                           private_handle_.param<std::string>("tilt_joint", "ptz_tilt_joint") };
    joint_states_.position.assign(2, 0.0);
    joint_states_.velocity.assign(2, 0.0);
    const std::array<std::string, 2> command_topics{ { private_handle_.param<std::string>("pan_command_topic", "pan_"
                                                                                                               "positio"
                                                                                                               "n_"
                                                                                                               "control"
                                                                                                               "ler/"
                                                                                                               "comman"
                                                                                                               "d"),
                                                       private_handle_.param<std::string>("tilt_command_topic",
                                                                                          "tilt_position_controller/"
                                                                                          "command") } };
    for (Axis axis : { PAN, TILT })
    {
      command_subscribers_[axis] = node_handle_.subscribe<std_msgs::Float64>(
          command_topics[axis], 10, [this, axis](const std_msgs::Float64::ConstPtr& command) {
            if (!silent_)
            {
              model_.goToAxis(axis, command->data, clock_.now());
            }
          });
    }
    state_publisher_ = node_handle_.advertise<sensor_msgs::JointState>(
        private_handle_.param<std::string>("state_topic", "device_joint_states"), 10);
    fault_service_ = private_handle_.advertiseService("set_faults", &JointControllersEmulator::setFaults, this);
    const double rate = private_handle_.param("rate", 50.0);
    timer_ = node_handle_.createSteadyTimer(ros::WallDuration(1.0 / rate),
                                            [this](const ros::SteadyTimerEvent&) { publishState(); });
    ROS_INFO("joint_controllers_emulator: %s and %s on %s and %s, joint states on %s at %.0f Hz",
             joint_states_.name[0].c_str(), joint_states_.name[1].c_str(), command_subscribers_[PAN].getTopic().c_str(),
             command_subscribers_[TILT].getTopic().c_str(), state_publisher_.getTopic().c_str(), rate);
  }

private:
  /// A servo pan-tilt: +-pi and +-pi/2, ~max_speed (3 rad/s) and ~acceleration (10 rad/s^2), continuous positions.
  static SimDeviceConfig deviceConfig(const ros::NodeHandle& private_handle)
  {
    SimDeviceConfig config = SimDeviceConfig::defaults();
    for (Axis axis : { PAN, TILT })
    {
      config.axes[axis].motion.max_speed = private_handle.param("max_speed", 3.0);
      config.axes[axis].motion.acceleration = private_handle.param("acceleration", 10.0);
      config.axes[axis].resolution = 0.0;
    }
    config.axes[ZOOM].present = false;
    return config;
  }

  void publishState()
  {
    if (silent_)
    {
      return;
    }
    const PtzSample sample = model_.sample(clock_.now());
    joint_states_.header.stamp = ros::Time::now();
    for (Axis axis : { PAN, TILT })
    {
      joint_states_.position[axis] = sample.position[axis];
      joint_states_.velocity[axis] = sample.velocity[axis];
    }
    state_publisher_.publish(joint_states_);
  }

  bool setFaults(SetSimFaults::Request& request, SetSimFaults::Response& response)
  {
    SimFaults faults;
    faults.stalled = { { request.stall_pan != 0, request.stall_tilt != 0, false } };
    faults.lag = std::max(0.0, request.lag);
    model_.setFaults(faults, clock_.now());
    silent_ = request.dropout != 0;
    response.success = true;
    response.message = "faults set";
    return true;
  }

  ros::NodeHandle node_handle_;
  ros::NodeHandle private_handle_;
  SystemClock clock_;
  SimDeviceModel model_;  ///< only the main thread's callbacks touch it
  bool silent_ = false;
  sensor_msgs::JointState joint_states_;
  std::array<ros::Subscriber, 2> command_subscribers_;
  ros::Publisher state_publisher_;
  ros::ServiceServer fault_service_;
  ros::SteadyTimer timer_;
};
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "joint_controllers_emulator");
  JointControllersEmulator emulator;
  ros::spin();
  return 0;
}

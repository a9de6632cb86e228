#include <string>
#include <thread>
#include <vector>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/Joy.h>

#include "figures.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/ros/ptz_teleop.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;

constexpr int ROUNDS = 200;  ///< stick deflections timed
/// Joy messages (0.1 s apart) the teleop may need before it drives the node: its action client connects and the
/// capabilities arrive in a few seconds on a busy machine (5 s was not always enough).
constexpr int WARM_UP_TRIES = 300;

/// Waits up to \p timeout s for \p counter to pass \p before.
bool countPassed(const std::atomic<std::uint64_t>& counter, std::uint64_t before, double timeout)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (counter <= before && ros::WallTime::now() < deadline)
  {
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  return counter > before;
}

/// The default gamepad mapping's Joy: the dead-man (LB) held or not, the left stick at \p pan_axis.
sensor_msgs::Joy joy(const TeleopConfig& config, bool deadman, float pan_axis)
{
  sensor_msgs::Joy message;
  message.axes.assign(8, 0.0f);
  message.buttons.assign(11, 0);
  message.axes[config.pan.axis] = pan_axis;
  message.buttons[config.deadman_button] = deadman ? 1 : 0;
  message.header.stamp = ros::Time::now();
  return message;
}
}  // namespace

Row teleopFigure(SharedCounters* counters)
{
  const int rounds = ROUNDS;
  // stdout carries only the figures: the teleop's "driving /ptz" goes.
  if (ros::console::set_logger_level(ROSCONSOLE_DEFAULT_NAME, ros::console::levels::Warn))
  {
    ros::console::notifyLoggerLevelsChanged();
  }
  // The teleop as the ptz_teleop node runs it, on a queue and thread of its own, with the default mapping.
  ros::CallbackQueue queue;
  ros::NodeHandle teleop_handle(NODE_NAMESPACE);
  teleop_handle.setCallbackQueue(&queue);
  const TeleopConfig config;
  PtzTeleop teleop(teleop_handle, config);
  ros::AsyncSpinner spinner(1, &queue);
  spinner.start();
  ros::NodeHandle node_handle(NODE_NAMESPACE);
  ros::Publisher publisher = node_handle.advertise<sensor_msgs::Joy>("joy", 10);

  // Until the teleop has the capabilities and its goals reach the node.
  bool driving = false;
  for (int attempt = 0; attempt < WARM_UP_TRIES && !driving; ++attempt)
  {
    const std::uint64_t before = counters->commands;
    publisher.publish(joy(config, true, 0.5f));
    driving = countPassed(counters->commands, before, 0.1);
  }
  publisher.publish(joy(config, false, 0.0f));
  if (!driving)
  {
    return { "joystick -> first backend command",
             formatText("the teleop never drove the node in %.0f s", WARM_UP_TRIES * 0.1), "p99 <= 5 ms" };
  }
  ros::WallDuration(0.5).sleep();

  // Each round: the stick deflected (alternately left and right) with the dead-man, then released.
  std::vector<double> command_ms;
  for (int round = 0; round < rounds; ++round)
  {
    const std::uint64_t commands_before = counters->commands;
    const std::int64_t sent_ns = monotonicNanoseconds();
    publisher.publish(joy(config, true, round % 2 == 0 ? 0.5f : -0.5f));
    if (countPassed(counters->commands, commands_before, 1.0))
    {
      command_ms.push_back((counters->last_command_ns - sent_ns) / 1e6);
    }
    const std::uint64_t stops_before = counters->stops;
    publisher.publish(joy(config, false, 0.0f));
    countPassed(counters->stops, stops_before, 1.0);
    ros::WallDuration(0.02).sleep();
  }
  return { "joystick (Joy) -> first backend command",
           formatText("%s (%zu of %d; Joy in-process, goal over TCP)", percentiles(command_ms).c_str(),
                      command_ms.size(), rounds),
           "p99 <= 5 ms" };
}

}  // namespace ptz_bench

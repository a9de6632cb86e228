/**
 * \file
 * \brief What roscpp costs on this machine before the node does anything: a process that only calls ros::init() and
 * waits on its queue as the node does (TOPICS 0), or that also publishes a small message on each of TOPICS topics
 * every 100 ms from a thread of its own, as the state tick does. bench/roscpp_floor measures it.
 * Usage: bench_roscpp_floor [TOPICS]
 */
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "roscpp_floor");
  ros::NodeHandle node_handle("~");
  const int topics = argc > 1 ? std::atoi(argv[1]) : 0;
  std::vector<ros::Publisher> publishers;
  for (int index = 0; index < topics; ++index)
  {
    publishers.push_back(node_handle.advertise<sensor_msgs::JointState>("topic" + std::to_string(index), 10));
  }
  std::thread ticker;
  if (topics > 0)
  {
    ticker = std::thread([&publishers] {
      sensor_msgs::JointState state;
      state.name = { "ptz_pan_joint", "ptz_tilt_joint" };
      state.position = { 0.1, 0.2 };
      state.velocity = { 0.0, 0.0 };
      auto next = std::chrono::steady_clock::now();
      while (ros::ok())
      {
        next += std::chrono::milliseconds(100);
        std::this_thread::sleep_until(next);
        state.header.stamp = ros::Time::now();
        for (const ros::Publisher& publisher : publishers)
        {
          publisher.publish(state);
        }
      }
    });
  }
  while (ros::ok())  // as the node's MainSpinner: no wake-up until a callback comes
  {
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(5.0));
  }
  if (ticker.joinable())
  {
    ticker.join();
  }
  return 0;
}

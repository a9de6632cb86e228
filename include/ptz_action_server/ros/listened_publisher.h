/**
 * \file
 * \brief A publisher that knows, without asking roscpp, whether anyone listens.
 */
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include <ros/ros.h>

namespace ptz_action_server
{
/**
 * \brief Publishes only while the topic has subscribers, counted from roscpp's connect and disconnect callbacks.
 *
 * roscpp looks a topic up among every publication of the process on each publish, subscribers or not: 64 cameras in
 * one nodelet manager have about 1,600 publications and publish their state, joint states and tf 1,920 times a
 * second, mostly to nobody. A subscriber that connects gets the next message after roscpp's connect callback has
 * run (on the advertising handle's queue). Thread-safe: publish() from any thread.
 */
class ListenedPublisher
{
public:
  template <class Message>
  void advertise(ros::NodeHandle& node_handle, const std::string& topic, std::uint32_t queue_size)
  {
    publisher_ = node_handle.advertise<Message>(
        topic, queue_size, [this](const ros::SingleSubscriberPublisher&) { ++listeners_; },
        [this](const ros::SingleSubscriberPublisher&) { --listeners_; });
  }

  /// True while the topic has a subscriber.
  bool listened() const
  {
    return listeners_ > 0;
  }

  /// Publishes \p message if the topic has a subscriber; returns whether it did.
  template <class Message>
  bool publish(const Message& message) const
  {
    if (!listened())
    {
      return false;
    }
    publisher_.publish(message);
    return true;
  }

private:
  std::atomic<int> listeners_{ 0 };
  ros::Publisher publisher_;  ///< last: its callbacks (which roscpp removes as it goes) count listeners_
};

}  // namespace ptz_action_server

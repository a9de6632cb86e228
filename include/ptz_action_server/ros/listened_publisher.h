/**
 * \file
 * \brief A publisher that knows, without asking roscpp, whether anyone listens.
 */
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
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
  /// Advertises \p topic; \p on_connect, if set, runs after each new subscriber is counted (on the handle's queue).
  /// A topic the process already advertises keeps its publication's queue and latching, and is counted all the same.
  template <class Message>
  void advertise(ros::NodeHandle& node_handle, const std::string& topic, std::uint32_t queue_size, bool latch = false,
                 std::function<void()> on_connect = {})
  {
    on_connect_ = std::move(on_connect);
    publisher_ = node_handle.advertise<Message>(
        topic, queue_size,
        [this](const ros::SingleSubscriberPublisher&) {
          ++listeners_;
          if (on_connect_)
          {
            on_connect_();
          }
        },
        [this](const ros::SingleSubscriberPublisher&) { --listeners_; }, ros::VoidConstPtr(), latch);
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

  /// Publishes \p message whether or not anyone listens (a latched topic's message for later subscribers).
  template <class Message>
  void publishAlways(const Message& message) const
  {
    publisher_.publish(message);
  }

private:
  std::atomic<int> listeners_{ 0 };
  std::function<void()> on_connect_;
  ros::Publisher publisher_;  ///< last: its callbacks (which roscpp removes as it goes) count listeners_
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief actionlib's ActionServer with its goal status list published by the node: the periodic list only to
 * listeners, and one list for a batch of status changes.
 */
#pragma once

#include <cstddef>
#include <string>

#include <actionlib/server/action_server.h>
#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/ros.h>

#include "ptz_action_server/ros/listened_publisher.h"

namespace ptz_action_server
{
/// A NodeActionServer of any action type, as the node's table of servers (ActionServers) sees it.
class NodeActionServerBase
{
public:
  virtual ~NodeActionServerBase() = default;
  /// actionlib's ActionServer::start(): subscribes to goals and cancels, advertises the topics.
  virtual void startServer() = 0;
  /// The periodic list: published if the status topic has a subscriber; returns whether it was.
  virtual bool publishStatusIfListened() = 0;
  /// Transitions from now on publish their list at releaseStatus(). Holds nest.
  virtual void holdStatus() = 0;
  /// Ends a holdStatus(); the last one publishes the list if a transition wanted it since.
  virtual void releaseStatus() = 0;
};

/**
 * \brief An actionlib server whose status list the node publishes instead of a ros::Timer of its own.
 *
 * The state tick publishes the list at actionlib_status_frequency (publishStatusIfListened()): only while someone
 * listens, since the topic is latched and roscpp hands every latched message to its poll thread, subscribers or not
 * (64 idle cameras in one nodelet manager sent 2,240 lists a second to nobody). Every goal transition still publishes
 * the list, as actionlib does, so the latched list is never behind a transition; a new listener is sent a fresh one
 * at once. Between holdStatus() and releaseStatus() the transitions' lists are held back to one, published at the
 * release: a goal that preempts another makes one list, not one for each goal.
 *
 * The list is built as actionlib's ActionServer::publishStatus() builds it (finished goals leave it
 * status_list_timeout after their handles go), on a publisher of the same topic. Thread-safe as actionlib is: under
 * the server's lock.
 */
template <class Action>
class NodeActionServer : public actionlib::ActionServer<Action>, public NodeActionServerBase
{
public:
  using GoalHandle = typename actionlib::ActionServer<Action>::GoalHandle;
  using Callback = boost::function<void(GoalHandle)>;

  /// Not started (actionlib's auto_start false): start() it.
  NodeActionServer(const ros::NodeHandle& node_handle, const std::string& name, Callback goal, Callback cancel)
    : actionlib::ActionServer<Action>(node_handle, name, goal, cancel, false), handle_(node_handle, name)
  {
  }

  void startServer() override
  {
    this->start();
  }

  bool publishStatusIfListened() override
  {
    if (!status_.listened())
    {
      return false;
    }
    publishStatus();
    return true;
  }

  void holdStatus() override
  {
    boost::recursive_mutex::scoped_lock lock(this->lock_);
    ++holds_;
  }

  void releaseStatus() override
  {
    boost::recursive_mutex::scoped_lock lock(this->lock_);
    if (--holds_ == 0 && held_)
    {
      held_ = false;
      publishStatus();
    }
  }

private:
  /// actionlib calls this (under its lock) for every transition and at start().
  void publishStatus() override
  {
    boost::recursive_mutex::scoped_lock lock(this->lock_);
    if (holds_ > 0)
    {
      held_ = true;
      return;
    }
    if (!advertised_)
    {
      // start() has advertised actionlib's own publisher: this one joins its publication (latched, its queue).
      advertised_ = true;
      status_.advertise<actionlib_msgs::GoalStatusArray>(handle_, "status", 1, true, [this] { publishStatus(); });
    }
    status_array_.header.stamp = ros::Time::now();
    // Entries are assigned over the last list's, not cleared and copied anew: their strings keep their buffers (a
    // storm's list of some hundred goals was a few hundred allocations and frees per list).
    auto& list = status_array_.status_list;
    std::size_t count = 0;
    for (auto it = this->status_list_.begin(); it != this->status_list_.end(); ++count)
    {
      if (count < list.size())
      {
        list[count] = it->status_;
      }
      else
      {
        list.push_back(it->status_);
      }
      if (it->handle_destruction_time_ != ros::Time() &&
          it->handle_destruction_time_ + this->status_list_timeout_ < status_array_.header.stamp)
      {
        it = this->status_list_.erase(it);
      }
      else
      {
        ++it;
      }
    }
    list.resize(count);
    status_.publishAlways(status_array_);
  }

  ros::NodeHandle handle_;  ///< the action's namespace
  ListenedPublisher status_;
  actionlib_msgs::GoalStatusArray status_array_;  ///< reused (under the lock)
  bool advertised_ = false;
  int holds_ = 0;
  bool held_ = false;  ///< a transition wanted the list during a hold
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief actionlib's ActionServer with its goal status list published by the node: the periodic list only to
 * listeners, and one list for a batch of status changes.
 */
#pragma once

#include <cstdint>
#include <list>
#include <string>
#include <utility>

#include <actionlib/server/action_server.h>
#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/ros.h>

#include "ptz_action_server/core/goal/ended_goal_list.h"
#include "ptz_action_server/ros/listened_publisher.h"
#include "ptz_action_server/ros/status_list_message.h"

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
 * The list says what actionlib's ActionServer::publishStatus() would (finished goals leave it status_list_timeout
 * after their handles go), but an ended goal whose handles are gone leaves actionlib's list for an EndedGoalList:
 * actionlib scans its list for every goal that arrives, and the list went out copied entry by entry, each a few
 * hundred entries long under a storm of goals. A goal sent again with the id of such a goal is rejected (actionlib
 * would ignore it while the id is in its list); a cancel of it changes nothing, as in actionlib. Thread-safe as
 * actionlib is: under the server's lock.
 */
template <class Action>
class NodeActionServer : public actionlib::ActionServer<Action>, public NodeActionServerBase
{
public:
  using GoalHandle = typename actionlib::ActionServer<Action>::GoalHandle;
  using Callback = boost::function<void(GoalHandle)>;

  /// Not started (actionlib's auto_start false): start() it.
  NodeActionServer(const ros::NodeHandle& node_handle, const std::string& name, Callback goal, Callback cancel)
    : actionlib::ActionServer<Action>(
          node_handle, name, [this](GoalHandle handle) { onGoal(handle); }, cancel, false)
    , handle_(node_handle, name)
    , goal_(std::move(goal))
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
  using StatusList = StatusListMessage<std::list<actionlib::StatusTracker<Action>>>;

  void onGoal(GoalHandle handle)
  {
    const std::string id = handle.getGoalID().id;
    {
      boost::recursive_mutex::scoped_lock lock(this->lock_);
      if (ended_.contains(id))
      {
        // Its entry gives way to this goal's, so the list names the id once.
        ended_.remove(id);
        const std::string text = "the goal id " + id +
                                 " is that of a goal that ended less than status_list_timeout ago: a new goal needs "
                                 "an id of its own";
        ROS_WARN_THROTTLE(1.0, "%s: goal rejected: %s", handle_.getNamespace().c_str(), text.c_str());
        handle.setRejected(typename actionlib::ActionServer<Action>::Result(), text);
        return;
      }
    }
    goal_(handle);
  }

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
    const ros::Time now = ros::Time::now();
    ended_.expire(now.toSec());
    for (auto it = this->status_list_.begin(); it != this->status_list_.end();)
    {
      if (it->status_.status == actionlib_msgs::GoalStatus::RECALLING && it->handle_tracker_.expired() &&
          ended_.contains(it->status_.goal_id.id))
      {
        // A cancel of a goal that has ended (a client cancelling as its goal ends): not finding the goal in its
        // list, actionlib kept the cancel for a goal yet to come, with no end. The goal is here; the cancel changes
        // nothing, as actionlib's own cancel of an ended goal in its list does.
        it = this->status_list_.erase(it);
        continue;
      }
      const ros::Time gone = it->handle_destruction_time_;  // zero while the goal has a handle
      if (gone == ros::Time())
      {
        ++it;
        continue;
      }
      const ros::Time expires = gone + this->status_list_timeout_;
      if (expires >= now)
      {
        if (!isTerminal(it->status_.status))
        {
          ++it;  // left without a handle before it ended: stays in actionlib's list, as actionlib keeps it
          continue;
        }
        entry_.resize(ros::serialization::serializationLength(it->status_));
        ros::serialization::OStream stream(reinterpret_cast<uint8_t*>(&entry_[0]), entry_.size());
        ros::serialization::serialize(stream, it->status_);
        ended_.add(it->status_.goal_id.id, entry_, expires.toSec());
      }
      it = this->status_list_.erase(it);
    }
    StatusList list;
    list.header.stamp = now;
    list.ended = &ended_;
    list.live = &this->status_list_;
    status_.publishAlways(list);
  }

  static bool isTerminal(uint8_t status)
  {
    using actionlib_msgs::GoalStatus;
    return status == GoalStatus::PREEMPTED || status == GoalStatus::SUCCEEDED || status == GoalStatus::ABORTED ||
           status == GoalStatus::REJECTED || status == GoalStatus::RECALLED || status == GoalStatus::LOST;
  }

  ros::NodeHandle handle_;  ///< the action's namespace
  Callback goal_;
  ListenedPublisher status_;
  EndedGoalList ended_;  ///< ended goals whose handles are gone (under the lock)
  std::string entry_;    ///< one entry being serialized, reused (under the lock)
  bool advertised_ = false;
  int holds_ = 0;
  bool held_ = false;  ///< a transition wanted the list during a hold
};

}  // namespace ptz_action_server

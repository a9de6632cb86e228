/**
 * \file
 * \brief A goal on a tf frame held back, neither accepted nor rejected, while the frame listener that has just
 * started hears tf.
 */
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <ros/ros.h>

#include "ptz_action_server/ros/action_kind.h"
#include "ptz_action_server/ros/frame_listener.h"
#include "ptz_action_server/ros/queue_timer.h"

namespace ptz_action_server
{
/**
 * \brief Holds at most one goal until tf has its frame or the listener's wait is over, without holding up anything
 * else; a new goal supersedes it, a cancel ends it. One thread: the node's main queue.
 */
class FrameGoalHold
{
public:
  /// What to do with the held goal when it goes on, is superseded or is cancelled.
  struct Goal
  {
    std::string id;        ///< actionlib goal id, for a cancel
    std::string frame_id;  ///< the frame it waits for
    std::function<void()> submit;
    std::function<void(const std::string&)> reject;
    std::function<void(const std::string&)> cancel;
  };

  /// \p frames must outlive the hold. \p base_frame is the camera's base.
  FrameGoalHold(const ros::NodeHandle& node_handle, FrameListener& frames, std::string base_frame);

  /// Starts listening to tf (a goal on a frame is coming); true when \p frame_id cannot be looked up yet and the goal
  /// must wait for it (hold()).
  bool mustWait(const std::string& frame_id);
  /// Holds \p goal until its frame is known or the wait is over, then submits it.
  void hold(Goal goal);
  /// Rejects the held goal, if any, because a \p kind goal came after it.
  void supersede(ActionKind kind);
  /// Cancels the held goal if its id is \p id; false if no held goal has it.
  bool cancel(const std::string& id);

private:
  /// The held goal, which waits no more (there must be one).
  Goal take();
  /// Submits the held goal once its frame is known or the wait is over.
  void check();

  ros::NodeHandle node_handle_;
  FrameListener& frames_;
  const std::string base_frame_;
  std::optional<Goal> goal_;
  QueueTimer timer_;  ///< checks the held goal's frame while one waits
};

}  // namespace ptz_action_server

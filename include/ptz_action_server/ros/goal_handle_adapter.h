/**
 * \file
 * \brief actionlib's server goal handle seen through the GoalSupervisor's GoalHandle, its status changes run through
 * the status hold.
 */
#pragma once

#include <functional>
#include <string>
#include <utility>

#include <actionlib/server/action_server.h>
#include <ros/console.h>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/goal/status_hold.h"
#include "ptz_action_server/ros/action_kind.h"

namespace ptz_action_server
{
/// Runs a goal status change now or later (see StatusHold), and says whether changes are being held.
struct StatusPoster
{
  std::function<void(StatusHold::Change)> post;
  std::function<bool()> holding;
};

/// actionlib's goal handle of any of the node's action types, seen through the supervisor's GoalHandle.
template <class Action>
class GoalHandleAdapter : public GoalHandle
{
public:
  using Handle = actionlib::ServerGoalHandle<Action>;
  using Result = typename Action::_action_result_type::_result_type;
  using Feedback = typename Action::_action_feedback_type::_feedback_type;

  /// \p post_status runs or holds each status change (PtzActionServer::postStatus).
  GoalHandleAdapter(const Handle& handle, ActionKind kind, StatusPoster post_status)
    : handle_(handle), action_(actionName(kind)), id_(handle.getGoalID().id), post_status_(std::move(post_status))
  {
  }
  const std::string& action() const override
  {
    return action_;
  }
  const std::string& id() const override
  {
    return id_;
  }
  void accept(const std::string& text) override
  {
    post_status_.post([handle = handle_, text]() mutable { handle.setAccepted(text); });
  }
  void reject(const std::string& text) override
  {
    ROS_WARN_THROTTLE(1.0, "%s goal rejected: %s", action_.c_str(), text.c_str());
    post_status_.post([handle = handle_, text]() mutable { handle.setRejected(result(false), text); });
  }
  void publishFeedback(const AxisValues& remaining) override
  {
    feedback_.pan_remaining = static_cast<float>(remaining[PAN]);
    feedback_.tilt_remaining = static_cast<float>(remaining[TILT]);
    feedback_.zoom_remaining = static_cast<float>(remaining[ZOOM]);
    if (post_status_.holding())
    {
      // Feedback never overtakes the goal's held acceptance (clients would not know the goal yet).
      post_status_.post([handle = handle_, feedback = feedback_]() mutable { handle.publishFeedback(feedback); });
      return;
    }
    handle_.publishFeedback(feedback_);
  }
  void succeed(const std::string& text) override
  {
    ROS_DEBUG("%s goal succeeded: %s", action_.c_str(), text.c_str());
    post_status_.post([handle = handle_, text]() mutable { handle.setSucceeded(result(true), text); });
  }
  void abort(const std::string& text) override
  {
    ROS_WARN("%s goal aborted: %s", action_.c_str(), text.c_str());
    post_status_.post([handle = handle_, text]() mutable { handle.setAborted(result(false), text); });
  }
  void preempt(const std::string& text) override
  {
    ROS_DEBUG("%s goal preempted: %s", action_.c_str(), text.c_str());
    post_status_.post([handle = handle_, text]() mutable { handle.setCanceled(result(false), text); });
  }

private:
  static Result result(bool success)
  {
    Result result;
    result.success = success;
    return result;
  }

  Handle handle_;
  std::string action_;
  std::string id_;
  StatusPoster post_status_;
  Feedback feedback_;
};

}  // namespace ptz_action_server

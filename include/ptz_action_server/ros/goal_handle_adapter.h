/**
 * \file
 * \brief actionlib's server goal handle seen through the GoalSupervisor's GoalHandle, its status changes run through
 * the status hold.
 */
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

#include <actionlib/server/action_server.h>
#include <ros/console.h>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/PtzPixelAction.h"
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

  /// \p post_status runs or holds each status change (PtzActionServer::postStatus). Every result the goal ends with
  /// is \p result with its `success` set (a pixel goal's also says where it aimed).
  GoalHandleAdapter(const Handle& handle, ActionKind kind, StatusPoster post_status, Result result = Result())
    : handle_(handle)
    , action_(actionName(kind))
    , id_(handle.getGoalID().id)
    , post_status_(std::move(post_status))
    , result_(std::move(result))
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
    post_status_.post(
        [handle = handle_, text, outcome = result(false)]() mutable { handle.setRejected(outcome, text); });
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
  /// A goal the device aimed itself: a pixel goal's result says where it ended (NaN: not reached, or not known).
  void ended(const AxisValues& position) override
  {
    if constexpr (std::is_same_v<Result, PtzPixelResult>)
    {
      result_.pan = static_cast<float>(position[PAN]);
      result_.tilt = static_cast<float>(position[TILT]);
      result_.zoom = static_cast<float>(position[ZOOM]);
    }
  }
  void succeed(const std::string& text) override
  {
    ROS_DEBUG("%s goal succeeded: %s", action_.c_str(), text.c_str());
    post_status_.post(
        [handle = handle_, text, outcome = result(true)]() mutable { handle.setSucceeded(outcome, text); });
  }
  void abort(const std::string& text) override
  {
    ROS_WARN("%s goal aborted: %s", action_.c_str(), text.c_str());
    post_status_.post(
        [handle = handle_, text, outcome = result(false)]() mutable { handle.setAborted(outcome, text); });
  }
  void preempt(const std::string& text) override
  {
    ROS_DEBUG("%s goal preempted: %s", action_.c_str(), text.c_str());
    post_status_.post(
        [handle = handle_, text, outcome = result(false)]() mutable { handle.setCanceled(outcome, text); });
  }

private:
  Result result(bool success) const
  {
    Result outcome = result_;
    outcome.success = success;
    return outcome;
  }

  Handle handle_;
  std::string action_;
  std::string id_;
  StatusPoster post_status_;
  Result result_;  ///< what every result says besides `success`
  Feedback feedback_;
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief A move_ptz/track_detections goal seen through the GoalSupervisor's GoalHandle: its result's outcome is the
 * text it ends with, and its feedback comes from the tracking loop (DetectionTracking), not from the supervisor.
 */
#pragma once

#include <memory>
#include <string>
#include <utility>

#include <actionlib/server/action_server.h>
#include <ros/console.h>

#include "ptz_action_server/PtzTrackDetectionsAction.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/detection_tracker.h"
#include "ptz_action_server/ros/action_kind.h"
#include "ptz_action_server/ros/goal_handle_adapter.h"

namespace ptz_action_server
{
/// What a track_detections goal's handle (owned by the supervisor) and its tracking loop share. Main thread only.
struct DetectionGoalState
{
  actionlib::ServerGoalHandle<PtzTrackDetectionsAction> handle;
  StatusPoster post_status;
  /// "lost: ..." once the target is lost and the camera goes to the lost preset: the outcome starts with it, whatever
  /// ends the goal then (arrival, a preempting goal, a cancel).
  std::string lost;
  PtzTrackDetectionsFeedback feedback;  ///< reused for each feedback

  /// Publishes \p tracking as the goal's feedback (held back with the goal's acceptance while status changes wait).
  void publishFeedback(const TrackingFeedback& tracking)
  {
    feedback.pan_error = static_cast<float>(tracking.pan_error);
    feedback.tilt_error = static_cast<float>(tracking.tilt_error);
    feedback.u_error = static_cast<float>(tracking.u_error);
    feedback.v_error = static_cast<float>(tracking.v_error);
    feedback.detection_age = static_cast<float>(tracking.detection_age);
    feedback.target_id = tracking.target_id;
    if (post_status.holding())
    {
      post_status.post([handle = handle, copy = feedback]() mutable { handle.publishFeedback(copy); });
      return;
    }
    handle.publishFeedback(feedback);
  }
};

/**
 * \brief The supervisor's view of a track_detections goal. Every end sets the result's `outcome` to its text (after
 * DetectionGoalState::lost when the target was lost); `success` is false unless a goal succeeds, which a tracking goal
 * never does on its own. The supervisor's feedback (the remaining distance to the aim) is not this action's: the
 * tracking loop publishes the errors instead.
 */
class DetectionGoalHandle : public GoalHandle
{
public:
  using Result = PtzTrackDetectionsResult;

  explicit DetectionGoalHandle(std::shared_ptr<DetectionGoalState> state)
    : state_(std::move(state)), action_(actionName(ActionKind::TRACK_DETECTIONS)), id_(state_->handle.getGoalID().id)
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
    state_->post_status.post([handle = state_->handle, text]() mutable { handle.setAccepted(text); });
  }
  void reject(const std::string& text) override
  {
    ROS_WARN_THROTTLE(1.0, "%s goal rejected: %s", action_.c_str(), text.c_str());
    state_->post_status.post(
        [handle = state_->handle, text, result = result(false, text)]() mutable { handle.setRejected(result, text); });
  }
  void publishFeedback(const AxisValues&) override
  {
  }
  void succeed(const std::string& text) override
  {
    const std::string outcome = outcomeOf(text);
    state_->post_status.post([handle = state_->handle, outcome, result = result(true, outcome)]() mutable {
      handle.setSucceeded(result, outcome);
    });
  }
  void abort(const std::string& text) override
  {
    const std::string outcome = outcomeOf(text);
    ROS_WARN("%s goal ended: %s", action_.c_str(), outcome.c_str());
    state_->post_status.post([handle = state_->handle, outcome, result = result(false, outcome)]() mutable {
      handle.setAborted(result, outcome);
    });
  }
  void preempt(const std::string& text) override
  {
    const std::string outcome = outcomeOf(text);
    ROS_DEBUG("%s goal preempted: %s", action_.c_str(), outcome.c_str());
    state_->post_status.post([handle = state_->handle, outcome, result = result(false, outcome)]() mutable {
      handle.setCanceled(result, outcome);
    });
  }

private:
  std::string outcomeOf(const std::string& text) const
  {
    return state_->lost.empty() ? text : state_->lost + "; " + text;
  }
  static Result result(bool success, const std::string& outcome)
  {
    Result result;
    result.success = success;
    result.outcome = outcome;
    return result;
  }

  std::shared_ptr<DetectionGoalState> state_;
  std::string action_;
  std::string id_;
};

}  // namespace ptz_action_server

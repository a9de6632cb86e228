/**
 * \file
 * \brief ptz_move's goal runner: sends one goal, shows its feedback, cancels on Ctrl-C or --for, prints the result.
 */
#pragma once

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <type_traits>

#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>

#include "ptz_action_server/PtzTrackDetectionsAction.h"
#include "ptz_move.h"

namespace ptz_action_server::ptz_move
{
/// Prints \p feedback on one line: the remaining distance, or a tracking goal's errors.
template <class Feedback>
void printFeedback(const Feedback& feedback, double scale, const char* unit)
{
  if constexpr (std::is_same_v<Feedback, PtzTrackDetectionsFeedback>)
  {
    std::printf("\r  error: pan %+8.4f %s  tilt %+8.4f %s  (%+6.1f, %+6.1f) px  age %5.3f s  %s   ",
                feedback.pan_error * scale, unit, feedback.tilt_error * scale, unit, feedback.u_error, feedback.v_error,
                feedback.detection_age, feedback.target_id.c_str());
  }
  else
  {
    std::printf("\r  remaining: pan %+9.4f %s  tilt %+9.4f %s  zoom %+7.2f   ", feedback.pan_remaining * scale, unit,
                feedback.tilt_remaining * scale, unit, feedback.zoom_remaining);
  }
  std::fflush(stdout);
}

/// Sends \p goal, prints each feedback on one line, cancels on Ctrl-C or after --for, prints the final state (and
/// what \p describe_result says of the result, if given); returns the exit code.
template <class Action, class Goal>
int run(const Options& options, const std::string& action, const Goal& goal,
        const std::function<void(const typename Action::_action_result_type::_result_type&)>& describe_result = {})
{
  actionlib::SimpleActionClient<Action> client(options.ns + "/move_ptz/" + action, true);
  if (!client.waitForServer(ros::Duration(options.wait)))
  {
    std::fprintf(stderr, "ptz_move: no action server at %s/move_ptz/%s (is the node running?)\n", options.ns.c_str(),
                 action.c_str());
    return 1;
  }
  const double scale = options.degrees ? 180.0 / M_PI : 1.0;
  const char* unit = options.degrees ? "deg" : "rad";
  client.sendGoal(goal, typename actionlib::SimpleActionClient<Action>::SimpleDoneCallback(),
                  typename actionlib::SimpleActionClient<Action>::SimpleActiveCallback(),
                  [&](const typename Action::_action_feedback_type::_feedback_type::ConstPtr& feedback) {
                    printFeedback(*feedback, scale, unit);
                  });
  const ros::WallTime started = ros::WallTime::now();
  bool cancelled = false;
  while (ros::ok() && !client.getState().isDone())
  {
    const bool expired = options.cancel_after > 0.0 && (ros::WallTime::now() - started).toSec() >= options.cancel_after;
    if (!cancelled && (interrupted || expired))
    {
      std::printf("\n  cancelling...\n");
      client.cancelGoal();
      cancelled = true;
    }
    ros::WallDuration(0.02).sleep();
  }
  const actionlib::SimpleClientGoalState state = client.getState();
  const auto result = client.getResult();
  std::printf("\n%s: %s%s%s (success = %s, %.2f s)\n", action.c_str(), state.toString().c_str(),
              state.getText().empty() ? "" : ": ", state.getText().c_str(),
              result && result->success ? "true" : "false", (ros::WallTime::now() - started).toSec());
  if (result && describe_result)
  {
    describe_result(*result);
  }
  return state == actionlib::SimpleClientGoalState::SUCCEEDED ||
                 (cancelled && state == actionlib::SimpleClientGoalState::PREEMPTED) ?
             0 :
             1;
}

}  // namespace ptz_action_server::ptz_move

/**
 * \file
 * \brief The tour action (move_ptz/tour) and the idle return: the core's TourRunner wired to actionlib, the
 * GoalSupervisor and a timer.
 */
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <actionlib/server/action_server.h>
#include <ros/ros.h>

#include "ptz_action_server/PtzTourAction.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/tours/tour_runner.h"
#include "ptz_action_server/ros/goal_handle_adapter.h"
#include "ptz_action_server/ros/preset_services.h"
#include "ptz_action_server/ros/queue_timer.h"
#include "ptz_action_server/ros/tour_services.h"

namespace ptz_action_server
{
/**
 * \brief Runs tour goals and the idle return through the GoalSupervisor.
 *
 * Each move (a stop, the idle return) is a goal of its own in the supervisor, under the action name "tour" or
 * "idle_return", so any other goal preempts it as it preempts any goal, and a move is judged (reached, stalled, timed
 * out) as a preset goal is. The supervisor's activity listener tells the TourRunner of the other goals and of idle
 * time; a timer on the main queue wakes it at its deadlines (and each second of a dwell or a pause, for feedback).
 * What the runner orders is done on the main queue, never from inside the supervisor's calls.
 *
 * One thread: the node's main queue.
 */
class TourGoals
{
public:
  using Handle = actionlib::ServerGoalHandle<PtzTourAction>;

  /// \p supervisor, \p presets and \p tours must outlive it; \p post_status runs the goal's status changes;
  /// \p batch runs a change of goal statuses as one status list (ActionServers::batch()).
  TourGoals(const ros::NodeHandle& node_handle, const TourSettings& settings, GoalSupervisor& supervisor,
            std::shared_ptr<PtzBackend> backend, const PresetServices& presets, const TourServices& tours,
            StatusPoster post_status, std::function<void(const std::function<void()>&)> batch);
  ~TourGoals();

  TourGoals(const TourGoals&) = delete;
  TourGoals& operator=(const TourGoals&) = delete;

  /// A tour goal: rejected if its tour is unknown, else replaces the running one and starts.
  void onGoal(Handle handle);
  /// Cancels the tour goal \p handle if it is the running one.
  void onCancel(const Handle& handle);
  /// Aborts the running tour goal with \p reason (the node shuts down).
  void shutdown(const std::string& reason);

private:
  class MoveGoal;
  struct Link;

  /// The supervisor accepted \p goal, or (null) has no goal any more.
  void onActivity(const GoalHandle* goal);
  /// A tour move's news: \p id its goal's, \p kind what happened.
  enum class MoveEvent
  {
    REACHED,
    FAILED,
    PREEMPTED,
    FEEDBACK,
  };
  void onMove(const std::string& id, MoveEvent event, const std::string& text);
  /// Does what the runner ordered, then publishes feedback and arms the timer.
  void apply(const TourOrder& order);
  /// The move to preset \p preset as \p action's goal \p id at \p speed; false (logged) if there is no such preset.
  bool submitMove(const char* action, const std::string& id, const std::string& preset, double speed);
  /// Ends the running tour goal with \p order's outcome.
  void endGoal(const TourOrder& order);
  void publishFeedback();
  void armTimer();
  void onTimer();

  ros::NodeHandle node_handle_;
  GoalSupervisor& supervisor_;
  std::shared_ptr<PtzBackend> backend_;
  const PresetServices& presets_;
  const TourServices& tours_;
  StatusPoster post_status_;
  std::function<void(const std::function<void()>&)> batch_;
  SystemClock clock_;
  TourRunner runner_;
  std::optional<Handle> goal_;  ///< the running tour goal
  std::string move_id_;         ///< the supervisor goal id of the tour's current move
  unsigned moves_ = 0;          ///< moves so far, for their ids
  std::shared_ptr<Link> link_;  ///< what the move goals reach this through; cut by the destructor
  QueueTimer timer_;
};

}  // namespace ptz_action_server

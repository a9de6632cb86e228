/**
 * \file
 * \brief The node's actions in one table, one row each, and their servers, whose status lists the state tick
 * publishes instead of a timer each.
 */
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <tuple>

#include <ros/ros.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzPixelAction.h"
#include "ptz_action_server/PtzPresetAction.h"
#include "ptz_action_server/PtzRelToAction.h"
#include "ptz_action_server/PtzTrackDetectionsAction.h"
#include "ptz_action_server/PtzTourAction.h"
#include "ptz_action_server/PtzSpeedAction.h"
#include "ptz_action_server/ros/action_kind.h"
#include "ptz_action_server/ros/node_action_server.h"

namespace ptz_action_server
{
/// One of the node's actions: its kind, its name under move_ptz/ and its actionlib action type (Action).
template <class ActionType>
struct ActionRow
{
  using Action = ActionType;
  ActionKind kind;
  const char* name;
};

/**
 * \brief The node's actions, one row each, in the order of ActionKind (a test at compile time checks it).
 *
 * Adding an action is its value of ActionKind, its row here and the conversion of its goal
 * (GoalTranslator::convert(), and GoalTranslator::frameOf() if the goal waits for a tf frame; for a result with more
 * than `success`, GoalTranslator::fillResult()). track_detections, whose result and feedback are not Ptz's, is
 * converted and handled by DetectionTracking.
 */
inline constexpr std::tuple NODE_ACTIONS{
  ActionRow<PtzAction>{ ActionKind::POSITION_ABS, "position_abs" },
  ActionRow<PtzAction>{ ActionKind::POSITION_REL, "position_rel" },
  ActionRow<PtzAction>{ ActionKind::VELOCITY, "velocity" },
  ActionRow<PtzRelToAction>{ ActionKind::POSITION_ABS_TF, "position_abs_tf" },
  ActionRow<PtzFrameAction>{ ActionKind::FRAME, "frame" },
  ActionRow<PtzFrameAction>{ ActionKind::TRACK_FRAME, "track_frame" },
  ActionRow<PtzPresetAction>{ ActionKind::PRESET, "preset" },
  ActionRow<PtzPixelAction>{ ActionKind::PIXEL, "pixel" },
  ActionRow<PtzTrackDetectionsAction>{ ActionKind::TRACK_DETECTIONS, "track_detections" },
  ActionRow<PtzTourAction>{ ActionKind::TOUR, "tour" },  // TourGoals: its moves are goals of their own
  ActionRow<PtzSpeedAction>{ ActionKind::POSITION_ABS_SPEED, "position_abs_speed" },
};

/// How many actions the node serves.
inline constexpr std::size_t NODE_ACTION_COUNT = std::tuple_size_v<decltype(NODE_ACTIONS)>;

/**
 * \brief A server for each row of NODE_ACTIONS, indexed by ActionKind, each without actionlib's status timer: the
 * state tick publishes their status lists instead (publishStatuses()).
 *
 * actionlib gives each server a ros::Timer for its status list (5 Hz by default). roscpp's timer manager costs more
 * than linearly in the timers of a process: 64 cameras in one nodelet manager made 448 of them, which took a core. So
 * the servers start without one (actionlib_status_frequency 0 under each action's namespace while they start) and
 * the state tick publishes their lists at the rate actionlib would have used, to listeners only (NodeActionServer).
 *
 * Threads: start(), batch() and the goal callbacks on the node's main queue; publishStatuses() on the state thread.
 */
class ActionServers
{
public:
  /// Servers under move_ptz/ in \p node_handle's namespace, on its queue; actionlib's queues of \p queue_size and a
  /// \p status_list_timeout unless their parameters are set under the action's namespace.
  ActionServers(const ros::NodeHandle& node_handle, int queue_size, double status_list_timeout);

  ActionServers(const ActionServers&) = delete;
  ActionServers& operator=(const ActionServers&) = delete;

  /**
   * \brief Builds and starts the servers. A goal of the row's action goes to \p on_goal(handle, kind), a cancel to
   * \p on_cancel(handle, kind), with the handle an actionlib::ServerGoalHandle of the row's action type; the status
   * changes each call makes publish one list per server (batch()).
   */
  template <class OnGoal, class OnCancel>
  void start(const OnGoal& on_goal, const OnCancel& on_cancel)
  {
    std::apply([&](const auto&... row) { (add(row, on_goal, on_cancel), ...); }, NODE_ACTIONS);
    startWithoutStatusTimers();
  }

  /// On the state thread, every tick: publishes the listened servers' status lists at actionlib_status_frequency;
  /// returns how many it published.
  int publishStatuses();

  /// Runs \p changes (goal status changes, on the main thread) with each server's transitions making one status list,
  /// published when they are done.
  void batch(const std::function<void()>& changes);

private:
  template <class Action, class OnGoal, class OnCancel>
  void add(const ActionRow<Action>& row, const OnGoal& on_goal, const OnCancel& on_cancel)
  {
    using Server = NodeActionServer<Action>;
    const ActionKind kind = row.kind;
    servers_[static_cast<std::size_t>(kind)] = std::make_unique<Server>(
        node_handle_, actionNamespace(row.name),
        [this, kind, on_goal](typename Server::GoalHandle handle) { batch([&] { on_goal(handle, kind); }); },
        [this, kind, on_cancel](typename Server::GoalHandle handle) { batch([&] { on_cancel(handle, kind); }); });
  }

  /// "move_ptz/<name>", with actionlib's queue sizes and status_list_timeout set there unless they are.
  std::string actionNamespace(const char* name) const;
  /// Starts the servers with actionlib_status_frequency 0 under their namespaces, then restores it.
  void startWithoutStatusTimers();

  ros::NodeHandle node_handle_;
  const int queue_size_;
  const double status_list_timeout_;
  std::array<std::unique_ptr<NodeActionServerBase>, NODE_ACTION_COUNT> servers_;  ///< by ActionKind
  std::atomic<bool> started_{ false };  ///< the servers are started: their status may go out
  int status_period_ticks_ = 0;         ///< state ticks between status lists; 0: none (set before started_)
  int status_ticks_ = 0;                ///< state ticks so far (state thread)
};

}  // namespace ptz_action_server

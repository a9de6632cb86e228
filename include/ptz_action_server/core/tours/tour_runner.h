/**
 * \file
 * \brief The tour state machine, without ROS: a tour's stops in order with their dwell, yielding to an operator's
 * goal and resuming after idle, and the return to a preset after idle; driven by time and goal events only.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/tours/tour.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// How tours yield and what the device does when left alone.
struct TourSettings
{
  /// s with no goal after an operator's goal before a tour it interrupted resumes (at the stop it was at); 0: an
  /// operator's goal ends the tour (preempted).
  double resume_after = 0.0;
  /// The preset the device returns to after idle_seconds with no goal and no tour (as Axis cameras' auto-return);
  /// "" or idle_seconds 0: never.
  std::string idle_preset;
  double idle_seconds = 0.0;
};

/// Where a tour is.
enum class TourPhase : std::uint8_t
{
  NONE = 0,      ///< no tour
  MOVING = 1,    ///< moving to a stop
  DWELLING = 2,  ///< at a stop, for its dwell
  PAUSED = 3,    ///< yielded to an operator's goal; resumes resume_after s after the operator lets go
  STOPPING = 4,  ///< cancelled while moving: waits for the device to rest
};

/// What the node must do after an event, or when the deadline comes.
struct TourOrder
{
  enum class Kind
  {
    NOTHING,
    MOVE,         ///< move to \c preset at \c speed: the tour's next stop (its own goal, through the supervisor)
    STOP_MOVE,    ///< cancel the stop's move; stopPreempted() follows once the device rests
    IDLE_RETURN,  ///< move to \c preset: the device was left alone idle_seconds
    SUCCEED,      ///< end the tour goal: every round done (\c text)
    PREEMPT,      ///< end the tour goal preempted: cancelled, or an operator's goal (\c text)
    ABORT,        ///< end the tour goal aborted: a stop failed (\c text)
  };
  Kind kind = Kind::NOTHING;
  std::string preset;
  double speed = 0.0;  ///< fraction of top speed; 0: the default
  std::string text;
};

/// Where the tour is, for its feedback.
struct TourProgress
{
  TourPhase phase = TourPhase::NONE;
  std::string tour;
  std::size_t stop = 0;  ///< index in the tour's stops
  std::string preset;
  std::uint32_t round = 0;          ///< from 1
  std::uint32_t stops_visited = 0;  ///< stops reached so far
  /// s: the dwell left (DWELLING), until the tour resumes (PAUSED; -1 while the operator's goal runs), the stop's
  /// dwell (MOVING).
  double time_left = 0.0;
};

/**
 * \brief Runs one tour at a time and the idle return, as a pure state machine: events (a stop reached or failed, an
 * operator's goal accepted, no goal active any more, a cancel) and tick() at nextDeadline() return what the node must
 * do (TourOrder). It never commands anything itself, so it runs the same against a test's clock.
 *
 * One thread (the node's main thread).
 */
class TourRunner
{
public:
  /// \p now starts the idle time (the device is idle at start).
  TourRunner(const TourSettings& settings, TimePoint now);

  /// Starts \p tour (checked with checkTour()) for \p rounds rounds (0: until cancelled or preempted), replacing any;
  /// returns the move to its first stop.
  TourOrder start(const Tour& tour, std::uint32_t rounds, TimePoint now);
  /// The tour's move reached its stop: the dwell begins.
  TourOrder stopReached(TimePoint now);
  /// The tour's move was rejected or aborted (\p reason) at \p now: the tour aborts.
  TourOrder stopFailed(const std::string& reason, TimePoint now);
  /// The tour's move ended preempted (\p text): after STOP_MOVE, the tour ends preempted; otherwise an operator's
  /// goal replaced it, which operatorGoal() reports.
  TourOrder stopPreempted(const std::string& text);
  /// The tour goal was cancelled at \p now.
  TourOrder cancel(TimePoint now);
  /// A goal not of the tour nor the idle return (\p action: its action's name) was accepted: the tour pauses, or ends
  /// preempted without resume_after; the idle time stops.
  TourOrder operatorGoal(const std::string& action);
  /// No goal is active any more (the operator let go, or a move of ours ended): the idle time starts at \p now.
  void goalsIdle(TimePoint now);
  /// What is due at \p now: the next stop after a dwell, a paused tour's resume, the idle return.
  TourOrder tick(TimePoint now);

  /// When tick() has something to do next; TimePoint::max() if nothing waits for time.
  TimePoint nextDeadline() const;
  /// Where the tour is at \p now.
  TourProgress progress(TimePoint now) const;

  bool running() const
  {
    return phase_ != TourPhase::NONE;
  }

  /// Stops the last tour started reached, also once it has ended (its result).
  std::uint32_t stopsVisited() const
  {
    return visited_;
  }

private:
  /// The move to the current stop.
  TourOrder moveToStop();
  /// Ends the tour at \p now with an order of \p kind and \p text.
  TourOrder end(TourOrder::Kind kind, std::string text, TimePoint now);
  /// "stop 2 of 3 (yard)".
  std::string describeStop() const;

  const TourSettings settings_;
  TourPhase phase_ = TourPhase::NONE;
  Tour tour_;
  std::uint32_t rounds_ = 0;  ///< 0: until cancelled or preempted
  std::size_t stop_ = 0;
  std::uint32_t round_ = 0;
  std::uint32_t visited_ = 0;
  TimePoint dwell_end_ = TimePoint::max();
  bool operator_active_ = false;             ///< an operator's goal runs (accepted, not ended yet)
  TimePoint idle_since_ = TimePoint::max();  ///< no goal since then; max() while a goal runs
  bool idle_return_done_ = false;            ///< the idle return ran since the last operator's goal
};

/**
 * \brief The command of a move of the tours (a stop, the idle return) to \p pose at \p speed, a fraction of the
 * device's top speed (0: the default).
 *
 * Every move of the tours goes through here; the supervisor resolves the speed against the device as for
 * move_ptz/position_abs_speed (GoalCommand::speed).
 */
GoalCommand tourMoveCommand(const AxisValues& pose, double speed);

}  // namespace ptz_action_server

/**
 * \file
 * \brief One axis that ClosedLoopBackend steers on its reports, for devices that move at one speed whatever the
 * magnitude they are given (cheap ONVIF cameras): learning that speed, then timed moves that stop early.
 */
#pragma once

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Learns whether an axis moves at the speed it is given, and steers one that does not by timed moves.
 *
 * Learning: between two reports while one speed was in force the whole time, an axis that went at least twice as fast
 * as commanded (in the commanded direction), twice in a row, moves at one speed whatever the magnitude: that measured
 * speed is its speed from then on. A device that honours the magnitude never goes twice as fast as it is asked (it
 * brakes towards a lower speed, never past it), so it is never taken for one.
 *
 * Steering such an axis (step()): far from the target, it moves (at its one speed); within what it covers in a report
 * period and a half plus its coast, it gets a timed move: moving now, stopped by the caller's timer after
 * (distance - coast) / speed seconds. Once it rests, what it went past the timed stop is its coast (first guessed as
 * speed^2 / (2 deceleration)), learnt for the next move. One going the wrong way (past the target) is stopped first,
 * and its coast learnt from that. Within stop_within, it is there. It gives up (and the goal is the node's to judge)
 * when three timed moves in a row did not bring it a fifth nearer, or when it is nearer than half its smallest move
 * (the coast): another move could only take it farther.
 *
 * Pure and not thread-safe: ClosedLoopBackend sends the commands and runs the timer, under its lock.
 */
class TimedSteering
{
public:
  /// What the axis is to do now.
  struct Step
  {
    double speed = 0.0;        ///< the speed to command (0: stopped)
    double stop_after = -1.0;  ///< >= 0: a timed move: stop the axis this many seconds from now
    bool gave_up = false;      ///< it cannot come nearer: stopped where it is
  };

  /// \p stop_within: the target is reached this close; \p deceleration the device's (for the first coast guess).
  TimedSteering(double stop_within, double deceleration);

  /// A new goal for the axis: \p target; \p deceleration the device's (0: as before). What was learnt stays.
  void startGoal(double target, double deceleration = 0.0);
  /// A report: the axis at \p position at \p at. Learns from it what the speed in force did.
  void observe(TimePoint at, double position);
  /// The caller commanded \p speed after the report at \p at.
  void commanded(double speed, TimePoint at);
  /// True once the axis is known to move at one speed whatever it is given.
  bool fixedSpeed() const
  {
    return speed_ > 0.0;
  }
  /// That speed (0 while unknown).
  double speed() const
  {
    return speed_;
  }
  /// Its learnt coast past a stop (0 while unknown).
  double coast() const
  {
    return coast_ < 0.0 ? 0.0 : coast_;
  }
  /// The next step of an axis with fixedSpeed(), at the latest report; \p report_period between reports (s).
  Step step(double report_period);
  /// The caller's timer stopped the axis.
  void timedStopDone();
  /// A timed move is under way, or the axis still coasts after one: the goal goes on.
  bool busy() const
  {
    return move_ != Move::NONE;
  }
  /// How far the axis is from its target, after the latest report.
  double remaining() const
  {
    return target_ - position_;
  }

private:
  enum class Move
  {
    NONE,
    TIMED,     ///< moving, until the caller's timer stops it
    SETTLING,  ///< stopped after a timed move, coasting to rest
    BRAKING,   ///< stopped while going the wrong way, coasting to rest
  };

  const double stop_within_;
  double deceleration_;
  double target_ = 0.0;
  // The latest report and the one before.
  bool have_report_ = false;
  TimePoint at_{};
  double position_ = 0.0;
  bool moved_since_last_ = true;
  double last_step_ = 0.0;  ///< position change between the last two reports
  // What it was commanded, and after which report.
  double commanded_ = 0.0;
  TimePoint commanded_at_{};
  // Learning.
  int fast_intervals_ = 0;
  double speed_ = 0.0;   ///< > 0: its one speed
  double coast_ = -1.0;  ///< learnt coast (-1: not yet)
  // The timed move under way.
  Move move_ = Move::NONE;
  double move_from_ = 0.0;
  double move_seconds_ = 0.0;
  double move_distance_ = 0.0;  ///< how far it was when the move began
  int stalled_moves_ = 0;
};

}  // namespace ptz_action_server

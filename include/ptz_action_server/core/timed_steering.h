/**
 * \file
 * \brief One axis that ClosedLoopBackend steers on its reports, for devices that move at one speed whatever the
 * magnitude they are given (cheap ONVIF cameras): learning that speed, then timed moves that stop early.
 */
#pragma once

#include <array>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Learns whether an axis moves at the speed it is given, and steers one that does not by timed moves.
 *
 * Learning: the evidence is the axis' speed measured between reports while one speed was in force (sent after the
 * report that began the interval), against the fastest an axis that obeys could still be going: the speeds it was
 * given in that direction, each decaying at the device's deceleration once it was replaced (after a lag of
 * COMMAND_LAG for the command to reach the device), and the speed it had when the goal began. An axis that went at
 * least 1.5 times that fast, in the commanded direction, over report intervals in a row spanning EVIDENCE_SPAN (a
 * report closer than MIN_INTERVAL to the last is measured with the next), moves at one speed whatever the magnitude:
 * the fastest of them is its speed from then on. An axis that obeys but brakes at its own pace (a report held
 * up on a busy machine let it run past where it should have begun to) never goes faster than that bound, and a report
 * late or bunched with the next cannot make one short interval the evidence.
 *
 * A wrong verdict is undone: an axis taken for one at one speed that then moves at the speed it is given (within a
 * quarter), clearly not at its one speed, over intervals spanning EVIDENCE_SPAN after it had the time to reach it, is
 * judged again (rejudged()), from nothing. Far from its target it is given the speed its steering would give an
 * axis that obeys (step()'s \p proportional): all the same to one at one speed, and the test for one that is not.
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

  /// A new goal for the axis: \p target; \p deceleration the device's (0: as before); \p speed the axis' speed at
  /// \p at, when the goal begins (what it was doing before is unknown: it may brake from that). What was learnt stays.
  void startGoal(double target, double deceleration = 0.0, double speed = 0.0, TimePoint at = TimePoint{});
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
  /// True once after an axis taken for one at one speed showed that it moves at the speed it is given: its verdict is
  /// undone (fixedSpeed() false again).
  bool rejudged()
  {
    const bool rejudged = rejudged_;
    rejudged_ = false;
    return rejudged;
  }
  /// The next step of an axis with fixedSpeed(), at the latest report; \p report_period between reports (s);
  /// \p proportional the speed an axis that obeys would be given here (what it is given while far from the target).
  Step step(double report_period, double proportional = 0.0);
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

  /// A speed commanded (or the axis' speed at a goal's start), and when it was replaced.
  struct Given
  {
    double speed = 0.0;
    TimePoint until = TimePoint::max();  ///< max: still in force
  };
  /// The fastest an axis that obeys could be going at \p at in the direction of \p sign, given what it was given.
  double bound(TimePoint at, double sign) const;
  /// What \p given bounds the axis' speed to at \p at (-1: a free slot).
  double boundOf(const Given& given, TimePoint at) const;
  void give(double speed, TimePoint at);
  /// Learns from the interval from the learning reference to the report at \p at: evidence for one speed, or (once
  /// judged so) against it.
  void learn(TimePoint at, double position);

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
  std::array<Given, 16> given_{};  ///< the latest speeds given, for bound()
  // Learning: the report the next interval is measured from, and the evidence in a row so far.
  bool have_reference_ = false;
  TimePoint reference_at_{};
  double reference_position_ = 0.0;
  int evidence_intervals_ = 0;
  double evidence_seconds_ = 0.0;
  double evidence_speed_ = 0.0;  ///< the fastest of them
  double speed_ = 0.0;           ///< > 0: its one speed
  double coast_ = -1.0;          ///< learnt coast (-1: not yet)
  bool rejudged_ = false;
  // The timed move under way.
  Move move_ = Move::NONE;
  double move_from_ = 0.0;
  double move_seconds_ = 0.0;
  double move_distance_ = 0.0;  ///< how far it was when the move began
  int stalled_moves_ = 0;
};

}  // namespace ptz_action_server

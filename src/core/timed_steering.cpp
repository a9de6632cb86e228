#include "ptz_action_server/core/timed_steering.h"

#include <algorithm>
#include <cmath>

namespace ptz_action_server
{
namespace
{
/// An axis went this much faster than commanded (or more), in the commanded direction: not at the speed it was given.
constexpr double FAST_RATIO = 2.0;
/// Report intervals in a row it has to: one could be a report that came late.
constexpr int FAST_INTERVALS = 2;
/// A position change below this (rad, X) between two reports is rest.
constexpr double AT_REST = 1e-5;
/// A timed move that leaves the axis at more than this share of where it began made no progress.
constexpr double PROGRESS = 0.8;
/// Timed moves in a row without progress before it gives up (one may have been late: a busy machine's timer).
constexpr int STALLED_MOVES = 3;
/// Within this many report periods of travel (plus its coast), a move is timed rather than left to the next report.
constexpr double TIMED_WITHIN = 1.5;
}  // namespace

TimedSteering::TimedSteering(double stop_within, double deceleration)
  : stop_within_(stop_within), deceleration_(deceleration > 0.0 ? deceleration : 1.0)
{
}

void TimedSteering::startGoal(double target, double deceleration)
{
  target_ = target;
  deceleration_ = deceleration > 0.0 ? deceleration : deceleration_;
  move_ = Move::NONE;
  stalled_moves_ = 0;
}

void TimedSteering::observe(TimePoint at, double position)
{
  if (have_report_ && at > at_)
  {
    const double speed = (position - position_) / secondsBetween(at_, at);
    // Learnt only over an interval the speed commanded was in force for (sent after the report that began it).
    if (speed_ == 0.0 && commanded_ != 0.0 && commanded_at_ <= at_)
    {
      const bool fast = speed * commanded_ > 0.0 && std::abs(speed) >= FAST_RATIO * std::abs(commanded_);
      fast_intervals_ = fast ? fast_intervals_ + 1 : 0;
      if (fast_intervals_ >= FAST_INTERVALS)
      {
        speed_ = std::abs(speed);
      }
    }
    moved_since_last_ = std::abs(position - position_) > AT_REST;
    last_step_ = position - position_;
  }
  have_report_ = true;
  at_ = at;
  position_ = position;
}

void TimedSteering::commanded(double speed, TimePoint at)
{
  if (speed != commanded_)
  {
    commanded_ = speed;
    commanded_at_ = at;
  }
}

void TimedSteering::timedStopDone()
{
  if (move_ == Move::TIMED)
  {
    move_ = Move::SETTLING;
    commanded_ = 0.0;
  }
}

TimedSteering::Step TimedSteering::step(double report_period)
{
  Step step;
  const double distance = std::abs(remaining());
  if (move_ == Move::TIMED)
  {
    step.speed = commanded_;  // until the timer stops it
    return step;
  }
  if (move_ == Move::SETTLING || move_ == Move::BRAKING)
  {
    if (moved_since_last_)
    {
      return step;  // still coasting
    }
    // At rest: how far it went past what its speed covers in the move's time is its coast.
    const double coast = std::max(0.0, std::abs(position_ - move_from_) - speed_ * move_seconds_);
    coast_ = coast_ < 0.0 ? coast : 0.5 * (coast_ + coast);
    if (move_ == Move::SETTLING)
    {
      stalled_moves_ = distance > PROGRESS * move_distance_ ? stalled_moves_ + 1 : 0;
    }
    move_ = Move::NONE;
  }
  if (distance <= stop_within_)
  {
    return step;
  }
  if (moved_since_last_ && last_step_ * remaining() < 0.0)
  {
    // Going the wrong way (past the target before its speed was known): stopped first, its coast learnt on the way.
    move_ = Move::BRAKING;
    move_from_ = position_;
    move_seconds_ = 0.0;
    return step;
  }
  if (stalled_moves_ >= STALLED_MOVES || (coast_ >= 0.0 && distance < 0.5 * coast_))
  {
    step.gave_up = true;
    return step;
  }
  const double coast = coast_ >= 0.0 ? coast_ : speed_ * speed_ / (2.0 * deceleration_);
  const double lead = distance - coast;
  step.speed = std::copysign(speed_, remaining());  // it moves at its one speed whatever it is given
  if (lead > TIMED_WITHIN * speed_ * report_period)
  {
    return step;  // far: the next report decides again
  }
  move_ = Move::TIMED;
  move_from_ = position_;
  move_seconds_ = std::max(0.0, lead) / speed_;
  move_distance_ = distance;
  step.stop_after = move_seconds_;
  return step;
}

}  // namespace ptz_action_server

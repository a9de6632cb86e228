#include "ptz_action_server/core/timed_steering.h"

#include <algorithm>
#include <cmath>

namespace ptz_action_server
{
namespace
{
/// An axis went this much faster than one that obeys could have (or more), in the commanded direction: not at the speed
/// it was given. The bound is already the fastest it could go: any excess is evidence; this margin is for noise.
constexpr double FAST_RATIO = 1.5;
/// s a command may take to reach the device and show in its reports (a busy machine's, not an idle one's).
constexpr double COMMAND_LAG = 0.05;
/// s: a report closer than this to the one before (bunched: both held up, then read at once) is measured with the next.
constexpr double MIN_INTERVAL = 0.025;
/// s the evidence must span (two report intervals at least): a report's time errs by less than a poll, not by this.
constexpr double EVIDENCE_SPAN = 0.15;
/// An axis taken for one at one speed goes at the speed it is given within this share of it ...
constexpr double FOLLOWS = 0.25;
/// ... and this share of its one speed away from that one speed: it obeys after all.
constexpr double APART = 0.4;
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

void TimedSteering::startGoal(double target, double deceleration, double speed, TimePoint at)
{
  target_ = target;
  deceleration_ = deceleration > 0.0 ? deceleration : deceleration_;
  move_ = Move::NONE;
  stalled_moves_ = 0;
  // What the axis was given before this goal (a velocity goal, a stop) is not known here: only its speed now is.
  given_.fill(Given{});
  commanded_ = 0.0;
  commanded_at_ = at;
  give(speed, at);
  give(0.0, at);
  have_reference_ = false;
  evidence_intervals_ = 0;
}

void TimedSteering::give(double speed, TimePoint at)
{
  for (Given& given : given_)
  {
    given.until = std::min(given.until, at);
  }
  if (speed == 0.0)
  {
    return;
  }
  // Full only with many speeds given in a short time: the one that bounds least from now on makes room.
  const auto slot = std::min_element(given_.begin(), given_.end(), [&](const Given& one, const Given& other) {
    return boundOf(one, at) < boundOf(other, at);
  });
  *slot = Given{ speed, TimePoint::max() };
}

double TimedSteering::boundOf(const Given& given, TimePoint at) const
{
  if (given.speed == 0.0)
  {
    return -1.0;  // a free slot
  }
  const double braking = given.until == TimePoint::max() ? 0.0 : secondsBetween(given.until, at) - COMMAND_LAG;
  return std::max(0.0, std::abs(given.speed) - deceleration_ * std::max(0.0, braking));
}

double TimedSteering::bound(TimePoint at, double sign) const
{
  double fastest = 0.0;
  for (const Given& given : given_)
  {
    if (given.speed * sign > 0.0)
    {
      fastest = std::max(fastest, boundOf(given, at));
    }
  }
  return fastest;
}

void TimedSteering::observe(TimePoint at, double position)
{
  if (have_report_ && at > at_)
  {
    moved_since_last_ = std::abs(position - position_) > AT_REST;
    last_step_ = position - position_;
  }
  learn(at, position);
  have_report_ = true;
  at_ = at;
  position_ = position;
}

void TimedSteering::learn(TimePoint at, double position)
{
  if (have_reference_ && secondsBetween(reference_at_, at) < MIN_INTERVAL)
  {
    return;  // bunched with the reference (or the same report again): measured with the next
  }
  const double seconds = have_reference_ ? secondsBetween(reference_at_, at) : 0.0;
  const double moved = position - reference_position_;
  // Learnt only over an interval the speed commanded was in force for (sent after the report that began it).
  const bool in_force =
      have_reference_ && commanded_ != 0.0 && commanded_at_ <= reference_at_ && moved * commanded_ > 0.0;
  bool evidence = false;
  if (in_force && speed_ == 0.0)
  {
    // The fastest an axis that obeys could have gone, on average over the interval (the bound falls linearly).
    const double bounded = 0.5 * (bound(reference_at_, commanded_) + bound(at, commanded_));
    evidence = std::abs(moved) >= FAST_RATIO * bounded * seconds;
  }
  else if (in_force)
  {
    // Taken for one at one speed: it had the time to reach the speed it was given, and goes at that, not at its one.
    const double speed = std::abs(moved) / seconds;
    const double settle = COMMAND_LAG + std::max(speed_, std::abs(commanded_)) / deceleration_;
    evidence = secondsBetween(commanded_at_, reference_at_) >= settle &&
               std::abs(speed - std::abs(commanded_)) <= FOLLOWS * std::abs(commanded_) &&
               std::abs(speed - speed_) >= APART * speed_;
  }
  if (!evidence)
  {
    evidence_intervals_ = 0;
    evidence_seconds_ = evidence_speed_ = 0.0;
  }
  else
  {
    ++evidence_intervals_;
    evidence_seconds_ += seconds;
    evidence_speed_ = std::max(evidence_speed_, std::abs(moved) / seconds);
  }
  if (evidence_intervals_ >= 2 && evidence_seconds_ >= EVIDENCE_SPAN)
  {
    if (speed_ == 0.0)
    {
      speed_ = evidence_speed_;  // an interval it turned in (past the target) goes slower
    }
    else
    {
      // It obeys after all: judged again from nothing, and steered on its speeds from this report on.
      speed_ = 0.0;
      coast_ = -1.0;
      move_ = Move::NONE;
      stalled_moves_ = 0;
      rejudged_ = true;
    }
    evidence_intervals_ = 0;
    evidence_seconds_ = evidence_speed_ = 0.0;
  }
  have_reference_ = true;
  reference_at_ = at;
  reference_position_ = position;
}

void TimedSteering::commanded(double speed, TimePoint at)
{
  if (speed != commanded_)
  {
    commanded_ = speed;
    commanded_at_ = at;
    give(speed, at);
  }
}

void TimedSteering::timedStopDone()
{
  if (move_ == Move::TIMED)
  {
    move_ = Move::SETTLING;
    commanded_ = 0.0;
    commanded_at_ = at_;
    give(0.0, at_);
  }
}

TimedSteering::Step TimedSteering::step(double report_period, double proportional)
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
    // Far: the next report decides again. It is given what an axis that obeys would be: one at one speed goes at that
    // speed all the same, and one taken for one wrongly shows it.
    step.speed = proportional * remaining() > 0.0 ? proportional : step.speed;
    return step;
  }
  move_ = Move::TIMED;
  move_from_ = position_;
  move_seconds_ = std::max(0.0, lead) / speed_;
  move_distance_ = distance;
  step.stop_after = move_seconds_;
  return step;
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/tours/tour_runner.h"

#include <algorithm>
#include <utility>

namespace ptz_action_server
{
TourRunner::TourRunner(const TourSettings& settings, TimePoint now) : settings_(settings), idle_since_(now)
{
}

TourOrder TourRunner::start(const Tour& tour, std::uint32_t rounds, TimePoint)
{
  tour_ = tour;
  rounds_ = rounds;
  stop_ = 0;
  round_ = 1;
  visited_ = 0;
  operator_active_ = false;  // the tour's first move preempts the operator's goal
  idle_return_done_ = false;
  return moveToStop();
}

TourOrder TourRunner::stopReached(TimePoint now)
{
  if (phase_ == TourPhase::MOVING)
  {
    phase_ = TourPhase::DWELLING;
    dwell_end_ = addSeconds(now, tour_.stops[stop_].dwell);
    ++visited_;
  }
  return {};
}

TourOrder TourRunner::stopFailed(const std::string& reason, TimePoint now)
{
  if (phase_ != TourPhase::MOVING && phase_ != TourPhase::STOPPING)
  {
    return {};
  }
  return end(TourOrder::Kind::ABORT, describeStop() + ": " + reason, now);
}

TourOrder TourRunner::stopPreempted(const std::string& text)
{
  if (phase_ != TourPhase::STOPPING)
  {
    return {};  // an operator's goal: operatorGoal() follows
  }
  // The device rests: the supervisor's goalsIdle() follows and starts the idle time.
  return end(TourOrder::Kind::PREEMPT, text, TimePoint::max());
}

TourOrder TourRunner::cancel(TimePoint now)
{
  switch (phase_)
  {
    case TourPhase::MOVING:
      phase_ = TourPhase::STOPPING;
      return { TourOrder::Kind::STOP_MOVE, {}, 0.0, {} };
    case TourPhase::DWELLING:
    case TourPhase::PAUSED:
      return end(TourOrder::Kind::PREEMPT, "cancelled at " + describeStop(), now);
    default:
      return {};
  }
}

TourOrder TourRunner::operatorGoal(const std::string& action)
{
  operator_active_ = true;
  idle_since_ = TimePoint::max();
  idle_return_done_ = false;
  if (phase_ == TourPhase::NONE || phase_ == TourPhase::PAUSED)
  {
    return {};
  }
  const std::string text = "preempted at " + describeStop() + " by a new " + action + " goal";
  switch (phase_)
  {
    case TourPhase::MOVING:
    case TourPhase::DWELLING:
      if (settings_.resume_after > 0.0)
      {
        phase_ = TourPhase::PAUSED;  // resumes at the stop it was at, dwell and all
        dwell_end_ = TimePoint::max();
        return {};
      }
      return end(TourOrder::Kind::PREEMPT, text, TimePoint::max());
    case TourPhase::STOPPING:
      return end(TourOrder::Kind::PREEMPT, text, TimePoint::max());
    default:
      return {};
  }
}

void TourRunner::goalsIdle(TimePoint now)
{
  operator_active_ = false;
  idle_since_ = now;
}

TourOrder TourRunner::tick(TimePoint now)
{
  if (now < nextDeadline())
  {
    return {};
  }
  switch (phase_)
  {
    case TourPhase::DWELLING:
      if (++stop_ == tour_.stops.size())
      {
        stop_ = 0;
        if (rounds_ != 0 && round_ == rounds_)
        {
          return end(TourOrder::Kind::SUCCEED,
                     "visited " + std::to_string(visited_) + " stops in " + std::to_string(rounds_) + " round" +
                         (rounds_ == 1 ? "" : "s"),
                     now);
        }
        ++round_;
      }
      return moveToStop();
    case TourPhase::PAUSED:
      return moveToStop();
    case TourPhase::NONE:
      idle_return_done_ = true;
      return { TourOrder::Kind::IDLE_RETURN, settings_.idle_preset, 0.0, {} };
    default:
      return {};
  }
}

TimePoint TourRunner::nextDeadline() const
{
  const bool idle = !operator_active_ && idle_since_ != TimePoint::max();
  switch (phase_)
  {
    case TourPhase::DWELLING:
      return dwell_end_;
    case TourPhase::PAUSED:
      return idle ? addSeconds(idle_since_, settings_.resume_after) : TimePoint::max();
    case TourPhase::NONE:
      return idle && !idle_return_done_ && !settings_.idle_preset.empty() && settings_.idle_seconds > 0.0 ?
                 addSeconds(idle_since_, settings_.idle_seconds) :
                 TimePoint::max();
    default:
      return TimePoint::max();
  }
}

TourProgress TourRunner::progress(TimePoint now) const
{
  TourProgress progress;
  progress.phase = phase_;
  if (phase_ == TourPhase::NONE)
  {
    return progress;
  }
  progress.tour = tour_.name;
  progress.stop = stop_;
  progress.preset = tour_.stops[stop_].preset;
  progress.round = round_;
  progress.stops_visited = visited_;
  const TimePoint deadline = nextDeadline();
  if (phase_ == TourPhase::DWELLING || phase_ == TourPhase::PAUSED)
  {
    progress.time_left = deadline == TimePoint::max() ? -1.0 : std::max(0.0, secondsBetween(now, deadline));
  }
  else
  {
    progress.time_left = tour_.stops[stop_].dwell;
  }
  return progress;
}

TourOrder TourRunner::moveToStop()
{
  phase_ = TourPhase::MOVING;
  dwell_end_ = TimePoint::max();
  idle_since_ = TimePoint::max();  // the move is a goal
  const TourStop& stop = tour_.stops[stop_];
  return { TourOrder::Kind::MOVE, stop.preset, stop.speed, {} };
}

TourOrder TourRunner::end(TourOrder::Kind kind, std::string text, TimePoint now)
{
  phase_ = TourPhase::NONE;
  dwell_end_ = TimePoint::max();
  if (!operator_active_ && now != TimePoint::max())
  {
    idle_since_ = now;
  }
  return { kind, {}, 0.0, std::move(text) };
}

std::string TourRunner::describeStop() const
{
  return "stop " + std::to_string(stop_ + 1) + " of " + std::to_string(tour_.stops.size()) + " (" +
         tour_.stops[stop_].preset + ") of tour '" + tour_.name + "'";
}

GoalCommand tourMoveCommand(const AxisValues& pose, double speed)
{
  GoalCommand command;
  command.values = pose;
  command.speed.fraction = speed;
  return command;
}

}  // namespace ptz_action_server

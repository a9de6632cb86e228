#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ptz_action_server/core/tours/tour_runner.h"

using namespace ptz_action_server;

namespace
{
const TimePoint T0(std::chrono::seconds(1000));

TimePoint at(double seconds)
{
  return addSeconds(T0, seconds);
}

/// Three stops with different dwells and speeds.
Tour gateRound()
{
  return { "gate_round", { { "gate", 2.0, 0.5 }, { "yard", 1.0, 0.0 }, { "door", 3.0, 1.0 } } };
}

/// Drives \p runner as the node would: each move reaches its stop \p travel s after it starts, and the supervisor
/// goes idle then; records the presets moved to until \p until s or the tour ends.
std::vector<std::string> runUntil(TourRunner& runner, TourOrder order, double now, double travel, double until,
                                  TourOrder* last = nullptr)
{
  std::vector<std::string> visited;
  while (true)
  {
    if (order.kind == TourOrder::Kind::MOVE)
    {
      visited.push_back(order.preset);
      now += travel;
      runner.stopReached(at(now));
      runner.goalsIdle(at(now));
    }
    else if (order.kind != TourOrder::Kind::NOTHING)
    {
      break;
    }
    const TimePoint deadline = runner.nextDeadline();
    if (deadline == TimePoint::max() || secondsBetween(T0, deadline) > until)
    {
      break;
    }
    now = secondsBetween(T0, deadline);
    order = runner.tick(deadline);
  }
  if (last)
  {
    *last = order;
  }
  return visited;
}

TEST(TourRunner, VisitsStopsInOrderWithTheirDwellAndSpeed)
{
  TourRunner runner(TourSettings{}, at(0.0));
  const TourOrder first = runner.start(gateRound(), 2, at(0.0));
  ASSERT_EQ(first.kind, TourOrder::Kind::MOVE);
  EXPECT_EQ(first.preset, "gate");
  EXPECT_DOUBLE_EQ(first.speed, 0.5);
  EXPECT_EQ(runner.progress(at(0.0)).phase, TourPhase::MOVING);

  // At the first stop the dwell runs: nothing is due before it ends.
  runner.stopReached(at(1.0));
  runner.goalsIdle(at(1.0));
  EXPECT_EQ(runner.nextDeadline(), at(3.0));
  EXPECT_EQ(runner.tick(at(2.9)).kind, TourOrder::Kind::NOTHING);
  const TourProgress dwelling = runner.progress(at(2.5));
  EXPECT_EQ(dwelling.phase, TourPhase::DWELLING);
  EXPECT_EQ(dwelling.preset, "gate");
  EXPECT_NEAR(dwelling.time_left, 0.5, 1e-9);
  const TourOrder second = runner.tick(at(3.0));
  EXPECT_EQ(second.preset, "yard");
  EXPECT_DOUBLE_EQ(second.speed, 0.0);

  TourOrder last;
  const std::vector<std::string> visited = runUntil(runner, second, 3.0, 1.0, 100.0, &last);
  EXPECT_EQ(visited, (std::vector<std::string>{ "yard", "door", "gate", "yard", "door" }));
  EXPECT_EQ(last.kind, TourOrder::Kind::SUCCEED);
  EXPECT_EQ(last.text, "visited 6 stops in 2 rounds");
  EXPECT_FALSE(runner.running());
}

TEST(TourRunner, EndlessTourGoesRoundUntilCancelled)
{
  TourRunner runner(TourSettings{}, at(0.0));
  const std::vector<std::string> visited = runUntil(runner, runner.start(gateRound(), 0, at(0.0)), 0.0, 0.5, 60.0);
  ASSERT_GT(visited.size(), 9U);
  for (std::size_t index = 0; index < visited.size(); ++index)
  {
    EXPECT_EQ(visited[index], gateRound().stops[index % 3].preset) << index;
  }
  EXPECT_GT(runner.progress(at(60.0)).round, 3U);
  // Cancelled while dwelling: it ends at once.
  ASSERT_EQ(runner.progress(at(60.0)).phase, TourPhase::DWELLING);
  const TourOrder cancelled = runner.cancel(at(61.0));
  EXPECT_EQ(cancelled.kind, TourOrder::Kind::PREEMPT);
  EXPECT_NE(cancelled.text.find("cancelled"), std::string::npos) << cancelled.text;
}

TEST(TourRunner, CancelWhileMovingStopsTheMoveFirst)
{
  TourRunner runner(TourSettings{}, at(0.0));
  runner.start(gateRound(), 0, at(0.0));
  EXPECT_EQ(runner.cancel(at(0.5)).kind, TourOrder::Kind::STOP_MOVE);
  EXPECT_TRUE(runner.running());
  const TourOrder ended = runner.stopPreempted("cancelled: the device rests");
  EXPECT_EQ(ended.kind, TourOrder::Kind::PREEMPT);
  EXPECT_EQ(ended.text, "cancelled: the device rests");
  EXPECT_FALSE(runner.running());
}

TEST(TourRunner, AFailedStopAbortsTheTour)
{
  TourRunner runner(TourSettings{}, at(0.0));
  runner.start(gateRound(), 0, at(0.0));
  const TourOrder aborted = runner.stopFailed("no preset named 'gate'", at(0.1));
  EXPECT_EQ(aborted.kind, TourOrder::Kind::ABORT);
  EXPECT_EQ(aborted.text, "stop 1 of 3 (gate) of tour 'gate_round': no preset named 'gate'");
  EXPECT_FALSE(runner.running());
}

TEST(TourRunner, OperatorGoalPreemptsTheTourWithoutResume)
{
  TourRunner runner(TourSettings{}, at(0.0));
  runner.start(gateRound(), 0, at(0.0));
  EXPECT_EQ(runner.stopPreempted("preempted by a new velocity goal").kind, TourOrder::Kind::NOTHING);
  const TourOrder preempted = runner.operatorGoal("velocity");
  EXPECT_EQ(preempted.kind, TourOrder::Kind::PREEMPT);
  EXPECT_NE(preempted.text.find("by a new velocity goal"), std::string::npos) << preempted.text;
  runner.goalsIdle(at(5.0));
  EXPECT_EQ(runner.nextDeadline(), TimePoint::max());  // nothing resumes
}

TEST(TourRunner, YieldsToAnOperatorAndResumesAfterIdle)
{
  TourSettings settings;
  settings.resume_after = 10.0;
  TourRunner runner(settings, at(0.0));
  const TourOrder first = runner.start(gateRound(), 0, at(0.0));
  runUntil(runner, first, 0.0, 1.0, 4.0);  // at yard, dwelling
  ASSERT_EQ(runner.progress(at(4.5)).preset, "yard");

  // The operator takes over while the tour dwells: it pauses, and waits as long as the operator's goal runs.
  EXPECT_EQ(runner.operatorGoal("position_abs").kind, TourOrder::Kind::NOTHING);
  EXPECT_EQ(runner.progress(at(5.0)).phase, TourPhase::PAUSED);
  EXPECT_DOUBLE_EQ(runner.progress(at(5.0)).time_left, -1.0);
  EXPECT_EQ(runner.nextDeadline(), TimePoint::max());
  EXPECT_EQ(runner.tick(at(100.0)).kind, TourOrder::Kind::NOTHING);

  // The operator lets go at 120 s; a second goal at 125 s restarts the wait.
  runner.goalsIdle(at(120.0));
  EXPECT_EQ(runner.nextDeadline(), at(130.0));
  EXPECT_NEAR(runner.progress(at(121.0)).time_left, 9.0, 1e-9);
  runner.operatorGoal("velocity");
  runner.goalsIdle(at(125.0));
  EXPECT_EQ(runner.tick(at(134.9)).kind, TourOrder::Kind::NOTHING);
  const TourOrder resumed = runner.tick(at(135.0));
  ASSERT_EQ(resumed.kind, TourOrder::Kind::MOVE);
  EXPECT_EQ(resumed.preset, "yard");  // the stop it was at, dwell and all

  // Preempted while moving, it pauses again and resumes again.
  runner.stopPreempted("preempted by a new preset goal");
  runner.operatorGoal("preset");
  EXPECT_EQ(runner.progress(at(136.0)).phase, TourPhase::PAUSED);
  runner.goalsIdle(at(140.0));
  EXPECT_EQ(runner.tick(at(150.0)).preset, "yard");
  runner.stopReached(at(151.0));
  runner.goalsIdle(at(151.0));
  EXPECT_EQ(runner.tick(at(152.0)).preset, "door");
}

TEST(TourRunner, ReturnsToThePresetAfterIdleOnceUntilTheNextGoal)
{
  TourSettings settings;
  settings.idle_preset = "home";
  settings.idle_seconds = 30.0;
  TourRunner runner(settings, at(0.0));
  EXPECT_EQ(runner.nextDeadline(), at(30.0));

  runner.operatorGoal("position_abs");
  EXPECT_EQ(runner.nextDeadline(), TimePoint::max());  // never while the operator's goal runs
  runner.goalsIdle(at(40.0));
  EXPECT_EQ(runner.tick(at(69.0)).kind, TourOrder::Kind::NOTHING);
  const TourOrder back = runner.tick(at(70.0));
  EXPECT_EQ(back.kind, TourOrder::Kind::IDLE_RETURN);
  EXPECT_EQ(back.preset, "home");
  // Its own move ending does not start it again.
  runner.goalsIdle(at(75.0));
  EXPECT_EQ(runner.nextDeadline(), TimePoint::max());
  // The next operator's goal does.
  runner.operatorGoal("velocity");
  runner.goalsIdle(at(200.0));
  EXPECT_EQ(runner.nextDeadline(), at(230.0));
}

TEST(TourRunner, IdleReturnWaitsForTheTourAndAPausedTourWins)
{
  TourSettings settings;
  settings.idle_preset = "home";
  settings.idle_seconds = 5.0;
  settings.resume_after = 20.0;
  TourRunner runner(settings, at(0.0));
  runUntil(runner, runner.start(gateRound(), 1, at(0.0)), 0.0, 1.0, 2.5);
  EXPECT_EQ(runner.nextDeadline(), at(3.0));  // the dwell, not the idle return
  runner.operatorGoal("velocity");
  runner.goalsIdle(at(10.0));
  EXPECT_EQ(runner.nextDeadline(), at(30.0));  // the resume, not the idle return at 15 s
  TourOrder last;
  runUntil(runner, runner.tick(at(30.0)), 30.0, 1.0, 100.0, &last);
  ASSERT_EQ(last.kind, TourOrder::Kind::SUCCEED);
  // Once the tour is done, the idle time starts when it ended.
  const TimePoint ended = runner.nextDeadline();
  EXPECT_EQ(runner.tick(ended).kind, TourOrder::Kind::IDLE_RETURN);
}

}  // namespace

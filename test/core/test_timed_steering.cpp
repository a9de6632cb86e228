// TimedSteering (what ClosedLoopBackend steers a device at one speed with), on reports written by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "ptz_action_server/core/timed_steering.h"
#include "ptz_action_server/core/types.h"

using namespace ptz_action_server;

namespace
{
const TimePoint T0(std::chrono::seconds(50));
TimePoint at(double seconds)
{
  return addSeconds(T0, seconds);
}
}  // namespace

TEST(TimedSteering, AnAxisThatMovesAtTheSpeedItIsGivenIsNeverTakenForOneAtOneSpeed)
{
  TimedSteering axis(0.0025, 3.0);
  axis.startGoal(1.0);
  // Slowing down towards the target as it is told, a poll behind (it brakes towards each lower speed, never past it).
  double position = 0.0;
  double speed = 1.5;
  for (int report = 0; report < 60; ++report)
  {
    axis.observe(at(0.1 * report), position);
    const double commanded = std::max(0.03, std::min(1.5, 2.0 * (1.0 - position)));
    axis.commanded(commanded, at(0.1 * report));
    speed = std::max(commanded, speed - 0.3);  // 3 rad/s^2 for 0.1 s
    position = std::min(1.0, position + speed * 0.1);
  }
  EXPECT_FALSE(axis.fixedSpeed());
}

TEST(TimedSteering, AnAxisAtOneSpeedIsLearntAndGetsATimedMoveNearItsTarget)
{
  TimedSteering axis(0.005, 3.0);
  axis.startGoal(0.5);
  // Commanded lower and lower, it goes on at 0.75 rad/s: faster than one that obeys could, braking at 3 rad/s^2 from
  // 0.3 rad/s a command's lag (0.1 s) after it was told 0.15, over two reports (0.2 s).
  const double commanded[] = { 0.3, 0.15 };
  for (int report = 0; report < 2; ++report)
  {
    axis.observe(at(0.1 * report), 0.075 * report);
    EXPECT_FALSE(axis.fixedSpeed()) << report;
    axis.commanded(commanded[report], at(0.1 * report));
  }
  axis.observe(at(0.2), 0.15);
  ASSERT_TRUE(axis.fixedSpeed());
  EXPECT_NEAR(axis.speed(), 0.75, 1e-9);
  axis.commanded(0.1, at(0.2));
  axis.observe(at(0.3), 0.225);
  EXPECT_FALSE(axis.rejudged());
  // 0.275 rad from the target, more than a report and a half at its speed plus its coast: it moves on, untimed.
  TimedSteering::Step step = axis.step(0.1);
  EXPECT_NEAR(step.speed, 0.75, 1e-9);
  EXPECT_LT(step.stop_after, 0.0);
  axis.commanded(step.speed, at(0.3));
  axis.observe(at(0.4), 0.3);
  axis.observe(at(0.5), 0.375);
  // 0.125 rad: a timed move, stopped when its speed has covered the distance less the coast it is thought to have
  // (0.75^2 / (2 x 3) = 0.09375 rad before it has learnt its own).
  step = axis.step(0.1);
  EXPECT_NEAR(step.speed, 0.75, 1e-9);
  EXPECT_NEAR(step.stop_after, (0.125 - 0.09375) / 0.75, 1e-6);
  EXPECT_TRUE(axis.busy());
  EXPECT_NEAR(axis.step(0.1).speed, 0.75, 1e-9);  // until the timer stops it
  axis.timedStopDone();
  axis.observe(at(0.6), 0.44);
  EXPECT_EQ(axis.step(0.1).speed, 0.0);  // coasting
  axis.observe(at(0.7), 0.45);
  EXPECT_EQ(axis.step(0.1).speed, 0.0);
  axis.observe(at(0.8), 0.45);
  // At rest 0.05 short: it went 0.075 rad, 0.03125 of it its speed's over the move: it coasts 0.04375 rad. The next
  // timed move covers the rest less that.
  step = axis.step(0.1);
  EXPECT_NEAR(axis.coast(), 0.075 - 0.03125, 1e-9);
  EXPECT_NEAR(step.stop_after, (0.05 - axis.coast()) / 0.75, 1e-9);
}

TEST(TimedSteering, ItGivesUpWhereAnotherMoveCouldOnlyTakeItFarther)
{
  TimedSteering axis(0.005, 3.0);
  axis.startGoal(0.5);
  const double commanded[] = { 0.3, 0.15, 0.1 };
  for (int report = 0; report < 3; ++report)
  {
    axis.observe(at(0.1 * report), 0.075 * report);
    axis.commanded(commanded[report], at(0.1 * report));
  }
  axis.observe(at(0.3), 0.45);
  ASSERT_TRUE(axis.fixedSpeed());
  // A timed move of nothing (it is nearer than its guessed coast) that goes 0.06 rad: past the target by 0.01.
  TimedSteering::Step step = axis.step(0.1);
  EXPECT_EQ(step.stop_after, 0.0);
  axis.timedStopDone();
  axis.observe(at(0.4), 0.51);
  axis.step(0.1);
  axis.observe(at(0.5), 0.51);
  step = axis.step(0.1);
  // 0.01 rad away, its smallest move 0.06: another would take it farther.
  EXPECT_TRUE(step.gave_up);
  EXPECT_EQ(step.speed, 0.0);
}

TEST(TimedSteering, ReportsHeldUpAndReadAtOnceAreNotTakenForAnAxisAtOneSpeed)
{
  TimedSteering axis(0.005, 3.0);
  axis.startGoal(1.0);
  // At the 0.5 rad/s it is given; the reports measured at 0.10 and 0.15 s reach the steering at 0.190 and 0.192 s.
  axis.observe(at(0.0), 0.0);
  axis.commanded(0.5, at(0.0));
  axis.observe(at(0.05), 0.025);
  axis.observe(at(0.19), 0.05);
  axis.observe(at(0.192), 0.075);  // 12.5 rad/s over 2 ms: measured with the next
  axis.observe(at(0.2), 0.1);
  for (int report = 5; report < 20; ++report)
  {
    axis.observe(at(0.05 * report), 0.025 * report);
  }
  EXPECT_FALSE(axis.fixedSpeed());
}

TEST(TimedSteering, AnAxisAtOneSpeedStaysSoWhateverItIsGivenAndOneTakenForItWronglyIsJudgedAgain)
{
  TimedSteering axis(0.005, 3.0);
  axis.startGoal(3.0);
  axis.observe(at(0.0), 0.0);
  axis.commanded(0.3, at(0.0));
  axis.observe(at(0.1), 0.075);
  axis.commanded(0.15, at(0.1));
  axis.observe(at(0.2), 0.15);
  ASSERT_TRUE(axis.fixedSpeed());
  // Far from its target it is given what an axis that obeys would be; at one speed, it goes on at 0.75 rad/s.
  EXPECT_NEAR(axis.step(0.1, 1.5).speed, 1.5, 1e-9);
  axis.commanded(1.5, at(0.2));
  double position = 0.15;
  for (int report = 3; report < 20; ++report)
  {
    position += 0.075;
    axis.observe(at(0.1 * report), position);
  }
  EXPECT_TRUE(axis.fixedSpeed());
  EXPECT_FALSE(axis.rejudged());
  // Now it goes at what it is given, 1.5 rad/s, once it had the time to reach it: it obeys after all.
  axis.startGoal(6.0);
  axis.observe(at(2.0), position);
  axis.commanded(1.5, at(2.0));
  for (int report = 21; report < 40 && axis.fixedSpeed(); ++report)
  {
    position += 0.15;
    axis.observe(at(0.1 * report), position);
  }
  EXPECT_FALSE(axis.fixedSpeed());
  EXPECT_TRUE(axis.rejudged());
  EXPECT_FALSE(axis.rejudged());  // told once
}

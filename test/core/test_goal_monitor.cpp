#include <gtest/gtest.h>

#include "ptz_action_server/core/goal/goal_monitor.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

using namespace ptz_action_server;

namespace
{
constexpr double TICK = 0.1;  // s, the node's state period

/// A simulated device and a monitor, stepped at the node's 10 Hz.
class GoalMonitorTest : public ::testing::Test
{
protected:
  GoalMonitorTest() : device_(SimDeviceConfig::defaults(), clock_.now())
  {
  }

  PtzSample sample()
  {
    return device_.sample(clock_.now());
  }

  /// Steps until the verdict is final or \p max_seconds pass; returns the last verdict.
  GoalVerdict runUntilFinal(GoalMonitor& monitor, double max_seconds, int* ticks = nullptr)
  {
    GoalVerdict verdict;
    int count = 0;
    for (double t = 0.0; t <= max_seconds; t += TICK)
    {
      clock_.advance(TICK);
      verdict = monitor.update(sample(), clock_.now());
      ++count;
      if (verdict.phase != GoalPhase::ACTIVE)
      {
        break;
      }
    }
    if (ticks)
    {
      *ticks = count;
    }
    return verdict;
  }

  ManualClock clock_;
  SimDeviceModel device_;
  Capabilities capabilities_ = SimDeviceConfig::defaults().capabilities();
  GoalMonitorConfig config_;
};
}  // namespace

TEST_F(GoalMonitorTest, SucceedsOnlyWhenInsideToleranceAndSettled)
{
  const AxisValues target{ 1.0, 0.3, 4.0 };
  device_.goTo(target, clock_.now());
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  bool saw_inside_but_moving = false;
  GoalVerdict verdict;
  for (int i = 0; i < 500 && verdict.phase == GoalPhase::ACTIVE; ++i)
  {
    clock_.advance(0.01);  // fine steps, to catch the last braking inside the tolerance
    const PtzSample now = sample();
    verdict = monitor.update(now, clock_.now());
    if (std::abs(now.position[PAN] - 1.0) < config_.tolerance[PAN] && now.moving)
    {
      saw_inside_but_moving = true;
      EXPECT_EQ(verdict.phase, GoalPhase::ACTIVE);
    }
  }
  EXPECT_TRUE(saw_inside_but_moving);
  ASSERT_EQ(verdict.phase, GoalPhase::SUCCEEDED) << verdict.reason;
  EXPECT_FALSE(sample().moving);
  EXPECT_NEAR(verdict.remaining[PAN], 0.0, config_.tolerance[PAN]);
  EXPECT_NE(verdict.reason.find("reached pan "), std::string::npos) << verdict.reason;
}

TEST_F(GoalMonitorTest, RemainingIsGoalMinusCurrentSigned)
{
  const AxisValues target{ -1.0, 0.5, 1.0 };
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  const GoalVerdict verdict = monitor.update(sample(), clock_.now());
  EXPECT_EQ(verdict.phase, GoalPhase::ACTIVE);
  EXPECT_DOUBLE_EQ(verdict.remaining[PAN], -1.0);
  EXPECT_DOUBLE_EQ(verdict.remaining[TILT], 0.5);
  EXPECT_DOUBLE_EQ(verdict.remaining[ZOOM], 0.0);
}

TEST_F(GoalMonitorTest, StalledAxisAbortsWithTheAxisInTheReason)
{
  SimFaults faults;
  faults.stalled[TILT] = true;
  device_.setFaults(faults, clock_.now());
  const AxisValues target{ 0.5, 0.5, 1.0 };
  device_.goTo(target, clock_.now());
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  int ticks = 0;
  const GoalVerdict verdict = runUntilFinal(monitor, 5.0, &ticks);
  ASSERT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_NE(verdict.reason.find("stalled: tilt"), std::string::npos) << verdict.reason;
  EXPECT_NEAR(ticks * TICK, config_.stall_timeout, 2 * TICK);
}

TEST_F(GoalMonitorTest, TurningBackAfterAPreemptIsNotAStall)
{
  config_.stall_timeout = 0.3;
  device_.goTo({ 3.0, 0.0, 1.0 }, clock_.now());
  clock_.advance(1.5);  // cruising at full speed
  const AxisValues target{ 0.0, 0.0, 1.0 };
  device_.goTo(target, clock_.now());
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  const GoalVerdict verdict = runUntilFinal(monitor, 10.0);
  EXPECT_EQ(verdict.phase, GoalPhase::SUCCEEDED) << verdict.reason;
}

TEST_F(GoalMonitorTest, TimeoutAbortsAndIsNeverASuccess)
{
  config_.fixed_timeout = 0.5;
  const AxisValues target{ 3.0, 0.0, 1.0 };
  device_.goTo(target, clock_.now());
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  EXPECT_DOUBLE_EQ(monitor.timeout(), 0.5);
  const GoalVerdict verdict = runUntilFinal(monitor, 5.0);
  ASSERT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_NE(verdict.reason.find("timed out after"), std::string::npos) << verdict.reason;
}

TEST_F(GoalMonitorTest, EstimatedTimeoutCoversTheTrapezoid)
{
  const AxisValues target{ 2.0, 0.0, 1.0 };
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  const double minimum = 2.0 / 1.5 + 1.5 / 3.0;
  EXPECT_NEAR(monitor.timeout(), minimum * config_.timeout_scale + config_.timeout_margin, 1e-9);
}

TEST_F(GoalMonitorTest, LostLinkAndDeviceFaultAbort)
{
  const AxisValues target{ 1.0, 0.0, 1.0 };
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  PtzSample silent = sample();
  silent.link_up = false;
  GoalVerdict verdict = monitor.update(silent, clock_.now());
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_NE(verdict.reason.find("link lost"), std::string::npos);

  GoalMonitor second = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  PtzSample refused = sample();
  refused.fault_count += 1;
  verdict = second.update(refused, clock_.now());
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_TRUE(verdict.device_fault);
}

TEST_F(GoalMonitorTest, ALinkThatBrokeAndCameBackStillAbortsTheGoal)
{
  const AxisValues target{ 1.0, 0.0, 1.0 };
  GoalMonitor monitor = GoalMonitor::forPosition(target, sample(), capabilities_, config_, clock_.now());
  PtzSample reconnected = sample();
  ASSERT_TRUE(reconnected.link_up);
  reconnected.link_losses += 1;  // lost and reopened between two samples
  const GoalVerdict verdict = monitor.update(reconnected, clock_.now());
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_TRUE(verdict.link_lost);
  EXPECT_EQ(verdict.reason, "link lost");

  GoalMonitor stopping = GoalMonitor::forStop(sample(), config_, clock_.now());
  const GoalVerdict stopped = stopping.update(reconnected, clock_.now());
  EXPECT_EQ(stopped.phase, GoalPhase::ABORTED);
  EXPECT_TRUE(stopped.link_lost);
}

TEST_F(GoalMonitorTest, VelocityGoalEndsAtTheLimitAndAsksForAStop)
{
  const AxisValues velocity{ 0.0, 1.0, 0.0 };
  device_.moveAtVelocity(velocity, clock_.now());
  GoalMonitor monitor = GoalMonitor::forVelocity(velocity, sample(), capabilities_, config_, clock_.now());
  clock_.advance(TICK);
  GoalVerdict verdict = monitor.update(sample(), clock_.now());
  EXPECT_EQ(verdict.phase, GoalPhase::ACTIVE);
  EXPECT_NEAR(verdict.remaining[TILT], 1.0 - 0.3, 1e-9);  // accelerating at 3 rad/s^2
  verdict = runUntilFinal(monitor, 5.0);
  ASSERT_EQ(verdict.phase, GoalPhase::SUCCEEDED) << verdict.reason;
  EXPECT_TRUE(verdict.stop_device);
  EXPECT_EQ(verdict.reason, "tilt reached its upper limit 1.5708 rad");
}

TEST_F(GoalMonitorTest, AllZeroVelocityGoalSucceedsOnceStopped)
{
  device_.moveAtVelocity({ 1.0, 0.0, 0.0 }, clock_.now());
  clock_.advance(1.0);
  device_.stop(clock_.now());
  GoalMonitor monitor = GoalMonitor::forVelocity({ 0.0, 0.0, 0.0 }, sample(), capabilities_, config_, clock_.now());
  EXPECT_EQ(monitor.update(sample(), clock_.now()).phase, GoalPhase::ACTIVE);  // still braking
  const GoalVerdict verdict = runUntilFinal(monitor, 2.0);
  EXPECT_EQ(verdict.phase, GoalPhase::SUCCEEDED);
  EXPECT_NE(verdict.reason.find("stopped at"), std::string::npos);
}

TEST_F(GoalMonitorTest, VelocityGoalOnAStalledAxisAborts)
{
  SimFaults faults;
  faults.stalled[PAN] = true;
  device_.setFaults(faults, clock_.now());
  const AxisValues velocity{ 0.5, 0.0, 0.0 };
  device_.moveAtVelocity(velocity, clock_.now());
  GoalMonitor monitor = GoalMonitor::forVelocity(velocity, sample(), capabilities_, config_, clock_.now());
  const GoalVerdict verdict = runUntilFinal(monitor, 5.0);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_NE(verdict.reason.find("stalled: pan"), std::string::npos) << verdict.reason;
}

TEST_F(GoalMonitorTest, StopWatchEndsWhenTheDeviceRests)
{
  device_.moveAtVelocity({ 1.5, 0.0, 0.0 }, clock_.now());
  clock_.advance(2.0);
  device_.stop(clock_.now());
  GoalMonitor monitor = GoalMonitor::forStop(sample(), config_, clock_.now());
  int ticks = 0;
  const GoalVerdict verdict = runUntilFinal(monitor, 3.0, &ticks);
  EXPECT_EQ(verdict.phase, GoalPhase::SUCCEEDED);
  EXPECT_EQ(ticks, 5);  // braking from 1.5 rad/s at 3 rad/s^2 takes 0.5 s
}

/**
 * \file
 * \brief The backend contract suite: a silent device, a recovery, links that break (and reopen at once) (the fixture:
 * device_contract.h).
 */
#include "device_contract.h"

namespace ptz_action_server
{
namespace
{
TEST_P(DeviceContract, SilenceEndsTheGoalAsLinkLostWithinTheDeadline)
{
  const AxisValues far = startLongGoal();
  // The stall timeout equals the state timeout, as in issue 23's field runs: the last progress may come before the
  // last report, but a stall needs reports that span its timeout, so a silence is never read as a stall.
  GoalMonitorConfig config;
  config.stall_timeout = stateTimeout();
  GoalMonitor monitor = monitorFor(far, config);
  harness_->setSilent(true);
  const TimePoint silenced = SteadyClock::now();
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  // No sample may say "up" past the deadline, however late this thread looked.
  EXPECT_LE(secondsBetween(silenced, last_up_at_), stateTimeout() + DEADLINE_SLACK);
  EXPECT_NE(backend_->lastLinkLoss().find("no state from"), std::string::npos) << backend_->lastLinkLoss();
  EXPECT_EQ(backend_->sample().link_losses, 1u);
}

TEST_P(DeviceContract, RecoveryHoldsTheDeviceOnceAndAGoalSentRightAfterSucceeds)
{
  startLongGoal();
  harness_->setSilent(true);
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, WAIT));
  const std::uint64_t recoveries = backend_->session().counters().recoveries;
  harness_->clearCommands();
  harness_->setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  // At once, as a client would: the recovery must not override it.
  const AxisValues target = device_->goal(-0.5, 0.1);
  backend_->goTo(target);
  ASSERT_TRUE(waitForRest(target)) << "at " << backend_->sample().position[PAN] << " after "
                                   << backend_->session().counters().impossible_states.value()
                                   << " impossible states; last loss: " << backend_->lastLinkLoss() << "; sent "
                                   << describe(harness_->commands()).substr(0, 400);
  EXPECT_EQ(backend_->session().counters().recoveries, recoveries + 1);
  EXPECT_EQ(device_->holds(harness_->commands(), target), 1u) << describe(harness_->commands());
}

TEST_P(DeviceContract, ABrokenLinkEndsTheGoalAsLinkLostAndTheNextGoalWorks)
{
  const AxisValues far = startLongGoal();
  GoalMonitor monitor = monitorFor(far);
  harness_->breakLink();
  const TimePoint broken = SteadyClock::now();
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  EXPECT_LE(secondsBetween(broken, last_up_at_), stateTimeout() + DEADLINE_SLACK);
  EXPECT_NE(backend_->lastLinkLoss().find(device_->linkLossWords()), std::string::npos) << backend_->lastLinkLoss();

  harness_->restoreLink();
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << "no reconnection";
  const AxisValues target = device_->goal(-0.4, 0.1);
  backend_->goTo(target);
  EXPECT_TRUE(waitForRest(target));
}

TEST_P(DeviceContract, ALinkThatBreaksAndReopensAtOnceEndsTheGoalAndTheRecoveryNeverOverridesTheNextOne)
{
  if (!harness_->breaksAtOnce())
  {
    GTEST_SKIP() << "no connection to break: on UDP only a silence longer than the state timeout is a loss";
  }
  const AxisValues far = startLongGoal();
  GoalMonitor monitor = monitorFor(far);
  harness_->clearCommands();
  harness_->breakLink();
  harness_->restoreLink();  // back faster than the state timeout
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  EXPECT_NE(backend_->lastLinkLoss().find(device_->linkLossWords()), std::string::npos) << backend_->lastLinkLoss();
  // A client's next goal, the moment the link is back: the device is held once (the old goal does not go on), and
  // the hold never overrides the new goal.
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << "no reconnection";
  const AxisValues target = device_->goal(-0.3, -0.1);
  backend_->goTo(target);
  ASSERT_TRUE(waitForRest(target)) << "sent " << describe(harness_->commands());
  EXPECT_EQ(device_->holds(harness_->commands(), target), 1u) << describe(harness_->commands());
}

}  // namespace
}  // namespace ptz_action_server

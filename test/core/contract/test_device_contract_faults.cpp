/**
 * \file
 * \brief The backend contract suite: impossible states, replies that never end, a slow device, a flood of states (the
 * fixture: device_contract.h).
 */
#include "device_contract.h"

namespace ptz_action_server
{
namespace
{
TEST_P(DeviceContract, AnImpossiblePositionIsNeverBelievedAndAGoalOnItEndsAsLinkLostNamingIt)
{
  if (!backend_->capabilities().axes[PAN].feedback)
  {
    GTEST_SKIP() << "the device reports no pan: nothing to judge";
  }
  const AxisValues far = startLongGoal();
  GoalMonitorConfig config;
  config.stall_timeout = stateTimeout();  // a stall must not win either: the frozen position is no progress
  GoalMonitor monitor = monitorFor(far, config);
  const PtzSample before = backend_->sample();
  const double pan_before = before.position[PAN];
  // The device goes on moving towards the goal, but reports itself 2.5 rad back: further than it can go in the
  // time between two reports.
  SimFaults jumping;
  jumping.report_offset[PAN] = -2.5;
  harness_->setFaults(jumping);
  const TimePoint faulted = SteadyClock::now();
  double lowest_pan = pan_before;
  GoalVerdict verdict;
  waitUntil(
      [&] {
        const PtzSample sample = backend_->sample();
        if (sample.link_losses == before.link_losses)  // after the loss, the new place is believed
        {
          lowest_pan = std::min(lowest_pan, sample.position[PAN]);
        }
        if (sample.link_up)
        {
          last_up_at_ = sample.stamp;
        }
        verdict = monitor.update(sample, SteadyClock::now());
        return verdict.phase != GoalPhase::ACTIVE;
      },
      WAIT);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  const AxisCapability pan = backend_->session().capabilities().axes[PAN];
  EXPECT_GE(lowest_pan, pan_before - 0.05) << "the jumped position was taken as the device's (pan " << pan.range.min
                                           << ".." << pan.range.max << " at " << pan.max_speed << " rad/s)";
  EXPECT_LE(secondsBetween(faulted, last_up_at_), stateTimeout() + DEADLINE_SLACK);
  EXPECT_NE(backend_->lastLinkLoss().find("only impossible states"), std::string::npos) << backend_->lastLinkLoss();
  EXPECT_NE(backend_->lastLinkLoss().find("pan jumped"), std::string::npos) << backend_->lastLinkLoss();
  EXPECT_GT(backend_->session().counters().impossible_states.value(), 0u);

  // Reporting truthfully again, the device is believed where it is (after one more state timeout: from the place it
  // was believed at, the true one is a jump too), and the next goal works.
  harness_->setFaults(SimFaults());
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample sample = backend_->sample();
        return sample.link_up && std::abs(sample.position[PAN] - harness_->deviceState().position[PAN]) < 0.05;
      },
      WAIT))
      << "never believed again: " << backend_->lastLinkLoss();
  const AxisValues target = device_->goal(-0.4, 0.1);
  backend_->goTo(target);
  EXPECT_TRUE(waitForRest(target));
}

TEST_P(DeviceContract, AReplyThatNeverEndsIsDroppedAndCountedAndTheLinkRecovers)
{
  const DeviceSession& session = backend_->session();
  // Bytes thrown away: by the protocol's framing, or (HTTP) with an answer cut at its limit.
  const auto dropped = [&session] {
    const HttpCounters* http = session.httpCounters();
    return session.counters().dropped_bytes.value() + (http != nullptr ? http->dropped_bytes.value() : 0u);
  };
  const std::uint64_t before = dropped();
  const std::uint64_t losses = backend_->sample().link_losses;
  if (!harness_->setEndless(true))
  {
    GTEST_SKIP() << "this emulator cannot send a reply that never ends";
  }
  // Nothing the device sends is a reply any more: dropped and counted, and without a state the link is lost.
  ASSERT_TRUE(waitUntil([&] { return dropped() > before && !backend_->sample().link_up; }, WAIT))
      << "dropped " << dropped() - before << " bytes, link " << (backend_->sample().link_up ? "up" : "down");
  EXPECT_GT(backend_->sample().link_losses, losses);

  // Its replies end again: the framing finds them (or the link reopens), and a goal works.
  ASSERT_TRUE(harness_->setEndless(false));
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << backend_->lastLinkLoss();
  if (!backend_->capabilities().axes[PAN].feedback)
  {
    return;  // a camera without a position cannot show a goal reached: the link up again is what it shows
  }
  const AxisValues target = device_->goal(-0.4, 0.1);
  backend_->goTo(target);
  EXPECT_TRUE(waitForRest(target)) << "at " << backend_->sample().position[PAN] << "; last loss "
                                   << backend_->lastLinkLoss();
}

TEST_P(DeviceContract, ASlowDeviceWorksWithinItsDeadlineAndPastItEndsTheGoalAsLinkLost)
{
  const double deadline = device_->replyDeadline();
  if (deadline <= 0.0)
  {
    GTEST_SKIP() << "no reply deadline to test: the device pushes its state unasked (a slow one is a late report, "
                    "which the silence cases cover), or see the fixture's replyDeadline() (HTTP cameras)";
  }
  // Every answer at 60 % of the deadline: slow (a device in good health answers in milliseconds), but in time. A goal
  // succeeds. Not 90 %: an HTTPS camera's answers come one after another, so the link's news may be two answers
  // apart, and a busy machine took the 10 % left (5 failures in 18 runs beside other test processes).
  SimFaults slow;
  slow.reply_delay = 0.6 * deadline;
  harness_->setFaults(slow);
  const AxisValues near = device_->goal(0.3, 0.1);
  // The stall timeout and goal timeout margin a user of a slow device sets: a poll round of several slow answers
  // (Pelco-D, VISCA) leaves little to the scheduler, and a busy machine sometimes takes it, losing a round; a goal of
  // 0.6 s on an HTTPS camera answering at 0.6 s took 2.95 s, its whole timeout, beside other test processes.
  const std::string end = runGoalToItsEnd(*backend_, near, 2.0 * stateTimeout(), 2.0 * stateTimeout());
  EXPECT_EQ(end.rfind("SUCCEEDED", 0), 0u) << end << "; last loss " << backend_->lastLinkLoss();

  // Every answer just past the deadline: nothing answers in time, and a goal under way ends as link lost, never as a
  // stall or a success.
  harness_->setFaults(SimFaults());
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  const AxisValues far = startLongGoal();
  GoalMonitorConfig config;
  config.stall_timeout = stateTimeout();
  GoalMonitor monitor = monitorFor(far, config);
  slow.reply_delay = 1.2 * deadline;
  harness_->setFaults(slow);
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  harness_->setFaults(SimFaults());
}

TEST_P(DeviceContract, AFloodOfStatesIsTakenInAsItComesAndAGoalStillSucceeds)
{
  constexpr unsigned FLOOD = 100;  ///< every state sent 100 times
  if (!harness_->setFlood(FLOOD))
  {
    GTEST_SKIP() << "no flood here: the device answers requests (it sends no more than it is asked), or a serial line "
                    "carries no more than its baud rate";
  }
  const DeviceSession& session = backend_->session();
  const std::uint64_t reports = session.counters().state_reports.value();
  const PtzSample before = backend_->sample();
  const AxisValues target = device_->goal(0.8, 0.1);
  backend_->goTo(target);
  EXPECT_TRUE(waitForRest(target)) << "at " << backend_->sample().position[PAN] << "; last loss "
                                   << backend_->lastLinkLoss();
  // Every report was read and judged as it came (the session keeps one snapshot: nothing queues), none was taken
  // for impossible, and the link never fell.
  EXPECT_GT(session.counters().state_reports.value() - reports, 10u * FLOOD);
  EXPECT_EQ(backend_->sample().link_losses, before.link_losses) << backend_->lastLinkLoss();
  EXPECT_EQ(session.counters().impossible_states.value(), 0u);
  ASSERT_TRUE(harness_->setFlood(1));
}

}  // namespace
}  // namespace ptz_action_server

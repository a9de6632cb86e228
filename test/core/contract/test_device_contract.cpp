/**
 * \file
 * \brief The backend contract suite: every device backend, over every transport it supports, against its emulator.
 *
 * A new device joins by adding a fixture to allDeviceFixtures(). The cases never assert how fast something took on
 * the test's clock: they assert what the backend reported (a link that was still "up" after its deadline fails,
 * wherever the test thread was), and they wait on conditions with generous deadlines.
 */
#include <gtest/gtest.h>

#include <cmath>

#include "../wait_until.h"
#include "../goal_supervisor_fixture.h"
#include "device_fixtures.h"
#include "ptz_action_server/core/goal/goal_monitor.h"

namespace ptz_action_server
{
namespace
{
constexpr double WAIT = 15.0;           ///< s: generous, for a loaded machine
constexpr double DEADLINE_SLACK = 0.3;  ///< s a late report may stretch the state timeout (loaded I/O thread)

class DeviceContract : public ::testing::TestWithParam<FixtureMaker>
{
protected:
  void SetUp() override
  {
    device_ = GetParam().make();
    backend_ = device_->makeBackend();
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << "the link never came up";
    ASSERT_TRUE(waitUntil([&] { return device_->startupReceived(); }, WAIT)) << "the start-up never reached the device";
  }

  double stateTimeout() const
  {
    return backend_->session().config().state_timeout;
  }

  bool atRest(const AxisValues& target) const
  {
    const PtzSample sample = backend_->sample();
    const Capabilities capabilities = backend_->capabilities();
    for (Axis axis : ALL_AXES)
    {
      if (capabilities.axes[axis].present &&
          std::abs(sample.position[axis] - target[axis]) > 2e-3 * (axis == ZOOM ? 10 : 1))
      {
        return false;
      }
    }
    return sample.link_up && !sample.moving;
  }

  bool waitForRest(const AxisValues& target)
  {
    return waitUntil([&] { return atRest(target); }, WAIT);
  }

  /// Starts a long goal (2.6 rad: inside every device's pan range, far enough for a busy test thread to act well
  /// before the device gets there) and waits until the device moves fast towards it.
  AxisValues startLongGoal()
  {
    const AxisValues far = device_->goal(2.6, 0.0);
    backend_->goTo(far);
    EXPECT_TRUE(waitUntil([&] { return device_->deviceState().position[PAN] > 0.5; }, WAIT));
    return far;
  }

  /// Feeds samples to \p monitor until it ends the goal; remembers the last sample that still said "link up".
  GoalVerdict superviseUntilFinal(GoalMonitor& monitor)
  {
    GoalVerdict verdict;
    waitUntil(
        [&] {
          const PtzSample sample = backend_->sample();
          if (sample.link_up)
          {
            last_up_at_ = sample.stamp;
          }
          verdict = monitor.update(sample, SteadyClock::now());
          return verdict.phase != GoalPhase::ACTIVE;
        },
        WAIT);
    return verdict;
  }

  GoalMonitor monitorFor(const AxisValues& target, const GoalMonitorConfig& config = GoalMonitorConfig()) const
  {
    return GoalMonitor::forPosition(target, backend_->sample(), backend_->capabilities(), config, SteadyClock::now());
  }

  std::unique_ptr<DeviceFixture> device_;
  std::unique_ptr<DeviceBackend> backend_;
  TimePoint last_up_at_{};
};

TEST_P(DeviceContract, AGoalArrivesAsTheProtocolsCommandsAndIsReached)
{
  device_->clearCommands();
  const AxisValues target = device_->goal(0.5, -0.2);
  backend_->goTo(target);
  ASSERT_TRUE(waitForRest(target)) << "pan " << backend_->sample().position[PAN] << ", tilt "
                                   << backend_->sample().position[TILT] << "; sent " << describe(device_->commands());
  // A loss (a busy machine starving the I/O threads) adds the recovery's hold: say so if the commands differ.
  SCOPED_TRACE("link losses: " + std::to_string(backend_->sample().link_losses) +
               ", the last: " + backend_->lastLinkLoss() +
               "; impossible states: " + std::to_string(backend_->session().counters().impossible_states.value()));
  device_->expectGoalCommands(device_->commands(), target);
  // The signs held end to end: the device itself is where the contract says.
  EXPECT_NEAR(device_->deviceState().position[PAN], target[PAN], 2e-3);
  EXPECT_NEAR(device_->deviceState().position[TILT], target[TILT], 2e-3);
  EXPECT_EQ(backend_->sample().fault_count, 0u);
}

TEST_P(DeviceContract, ANewGoalRetargetsTheMovingDeviceWithoutAStop)
{
  backend_->goTo(device_->goal(2.0, 0.0));
  ASSERT_TRUE(waitUntil([&] { return device_->deviceState().position[PAN] > 0.5; }, WAIT));
  device_->clearCommands();
  const AxisValues second = device_->goal(2.5, 0.0);
  backend_->goTo(second);
  // Until well before it brakes for the new target, the device never slows down as a stop would make it.
  double slowest = 1e9;
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample state = device_->deviceState();
        slowest = std::min(slowest, state.velocity[PAN]);
        return state.position[PAN] > 1.5;
      },
      WAIT));
  EXPECT_GT(slowest, 0.3) << "the device slowed to " << slowest << " rad/s";
  ASSERT_TRUE(waitForRest(second));
  for (const DeviceCommand& command : device_->commands())
  {
    EXPECT_NE(command.kind, DeviceCommand::Kind::STOP) << describe(device_->commands());
  }
}

TEST_P(DeviceContract, CancelDeceleratesTheDeviceToRest)
{
  const AxisValues far = startLongGoal();
  device_->clearCommands();
  const double at_cancel = device_->deviceState().position[PAN];
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return device_->holds(device_->commands(), far) > 0; }, WAIT))
      << describe(device_->commands());
  ASSERT_TRUE(waitUntil([&] { return !device_->deviceState().moving; }, WAIT));
  const double stopped = device_->deviceState().position[PAN];
  EXPECT_GT(stopped, at_cancel);       // it braked on: it did not jump back,
  EXPECT_LT(stopped, far[PAN] - 0.2);  // and it did not go on to the target
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
}

TEST_P(DeviceContract, AVelocityGoalMovesAtTheRateUntilStopped)
{
  backend_->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(device_->deviceState().velocity[PAN] - 0.3) < 0.05; }, WAIT))
      << device_->deviceState().velocity[PAN];
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend_->sample().velocity[PAN] - 0.3) < 0.08; }, WAIT))
      << backend_->sample().velocity[PAN];
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !device_->deviceState().moving && !backend_->sample().moving; }, WAIT));
}

TEST_P(DeviceContract, ARefusedCommandAbortsTheGoalWithTheDevicesWords)
{
  AxisValues refused{};
  const std::string words = device_->prepareRefusal(refused);
  if (words.empty())
  {
    GTEST_SKIP() << "this protocol has no error replies";
  }
  GoalMonitor monitor = monitorFor(refused);
  backend_->goTo(refused);
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.device_fault) << verdict.reason;
  EXPECT_NE(backend_->lastFault().find(words), std::string::npos) << backend_->lastFault();
}

TEST_P(DeviceContract, SilenceEndsTheGoalAsLinkLostWithinTheDeadline)
{
  const AxisValues far = startLongGoal();
  // The stall timeout equals the state timeout, as in issue 23's field runs: the last progress may come before the
  // last report, but a stall needs reports that span its timeout, so a silence is never read as a stall.
  GoalMonitorConfig config;
  config.stall_timeout = stateTimeout();
  GoalMonitor monitor = monitorFor(far, config);
  device_->setSilent(true);
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
  device_->setSilent(true);
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, WAIT));
  const std::uint64_t recoveries = backend_->session().counters().recoveries;
  device_->clearCommands();
  device_->setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  // At once, as a client would: the recovery must not override it.
  const AxisValues target = device_->goal(-0.5, 0.1);
  backend_->goTo(target);
  ASSERT_TRUE(waitForRest(target)) << "at " << backend_->sample().position[PAN] << " after "
                                   << backend_->session().counters().impossible_states.value()
                                   << " impossible states; last loss: " << backend_->lastLinkLoss() << "; sent "
                                   << describe(device_->commands()).substr(0, 400);
  EXPECT_EQ(backend_->session().counters().recoveries, recoveries + 1);
  EXPECT_EQ(device_->holds(device_->commands(), target), 1u) << describe(device_->commands());
}

TEST_P(DeviceContract, ABrokenLinkEndsTheGoalAsLinkLostAndTheNextGoalWorks)
{
  const AxisValues far = startLongGoal();
  GoalMonitor monitor = monitorFor(far);
  device_->breakLink();
  const TimePoint broken = SteadyClock::now();
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  EXPECT_LE(secondsBetween(broken, last_up_at_), stateTimeout() + DEADLINE_SLACK);
  EXPECT_NE(backend_->lastLinkLoss().find(device_->linkLossWords()), std::string::npos) << backend_->lastLinkLoss();

  device_->restoreLink();
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << "no reconnection";
  const AxisValues target = device_->goal(-0.4, 0.1);
  backend_->goTo(target);
  EXPECT_TRUE(waitForRest(target));
}

TEST_P(DeviceContract, ALinkThatBreaksAndReopensAtOnceEndsTheGoalAndTheRecoveryNeverOverridesTheNextOne)
{
  if (!device_->breaksAtOnce())
  {
    GTEST_SKIP() << "no connection to break: on UDP only a silence longer than the state timeout is a loss";
  }
  const AxisValues far = startLongGoal();
  GoalMonitor monitor = monitorFor(far);
  device_->clearCommands();
  device_->breakLink();
  device_->restoreLink();  // back faster than the state timeout
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  EXPECT_NE(backend_->lastLinkLoss().find(device_->linkLossWords()), std::string::npos) << backend_->lastLinkLoss();
  // A client's next goal, the moment the link is back: the device is held once (the old goal does not go on), and
  // the hold never overrides the new goal.
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << "no reconnection";
  const AxisValues target = device_->goal(-0.3, -0.1);
  backend_->goTo(target);
  ASSERT_TRUE(waitForRest(target)) << "sent " << describe(device_->commands());
  EXPECT_EQ(device_->holds(device_->commands(), target), 1u) << describe(device_->commands());
}

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
  ASSERT_TRUE(device_->setFaults(jumping)) << "the emulator cannot report an offset";
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
  ASSERT_TRUE(device_->setFaults(SimFaults()));
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample sample = backend_->sample();
        return sample.link_up && std::abs(sample.position[PAN] - device_->deviceState().position[PAN]) < 0.05;
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
  if (!device_->setEndlessReplies(true))
  {
    GTEST_SKIP() << "this emulator cannot send a reply that never ends";
  }
  // Nothing the device sends is a reply any more: dropped and counted, and without a state the link is lost.
  ASSERT_TRUE(waitUntil([&] { return dropped() > before && !backend_->sample().link_up; }, WAIT))
      << "dropped " << dropped() - before << " bytes, link " << (backend_->sample().link_up ? "up" : "down");
  EXPECT_GT(backend_->sample().link_losses, losses);

  // Its replies end again: the framing finds them (or the link reopens), and a goal works.
  ASSERT_TRUE(device_->setEndlessReplies(false));
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

/// A position goal the node's supervisor runs on the backend, to its end.
std::string runGoalToItsEnd(PtzBackend& backend, const AxisValues& target, double stall_timeout)
{
  GoalMonitorConfig config;
  config.stall_timeout = stall_timeout;
  return goal_supervisor_test::runGoalToItsEnd(
      std::shared_ptr<PtzBackend>(&backend, [](PtzBackend*) {}),
      goal_supervisor_test::positionGoal(target[PAN], target[TILT], target[ZOOM]), config, WAIT);
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
  ASSERT_TRUE(device_->setFaults(slow));
  const AxisValues near = device_->goal(0.3, 0.1);
  // The stall timeout a user of a slow device sets: a poll round of several slow answers (Pelco-D, VISCA) leaves
  // little to the scheduler, and a busy machine sometimes takes it, losing a round.
  const std::string end = runGoalToItsEnd(*backend_, near, 2.0 * stateTimeout());
  EXPECT_EQ(end.rfind("SUCCEEDED", 0), 0u) << end << "; last loss " << backend_->lastLinkLoss();

  // Every answer just past the deadline: nothing answers in time, and a goal under way ends as link lost, never as a
  // stall or a success.
  ASSERT_TRUE(device_->setFaults(SimFaults()));
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  const AxisValues far = startLongGoal();
  GoalMonitorConfig config;
  config.stall_timeout = stateTimeout();
  GoalMonitor monitor = monitorFor(far, config);
  slow.reply_delay = 1.2 * deadline;
  ASSERT_TRUE(device_->setFaults(slow));
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.link_lost) << verdict.reason;
  ASSERT_TRUE(device_->setFaults(SimFaults()));
}

TEST_P(DeviceContract, AFloodOfStatesIsTakenInAsItComesAndAGoalStillSucceeds)
{
  constexpr unsigned FLOOD = 100;  ///< every state sent 100 times
  if (!device_->setFlood(FLOOD))
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
  ASSERT_TRUE(device_->setFlood(1));
}

TEST_P(DeviceContract, ADeviceThatIgnoresAnAxisNeverGetsASucceededForIt)
{
  const Capabilities capabilities = backend_->capabilities();
  // An axis the device lacks (or cannot report): a goal that asks it to move is refused, naming it; but a zoom it
  // lacks is ignored (the seed's rule: ZoomOfADeviceWithoutZoomIsIgnored).
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities.axes[axis];
    if (axis == ZOOM && !capability.present)
    {
      continue;
    }
    if (!capability.present || !capability.feedback || !capability.absolute)
    {
      AxisValues target = device_->goal(0.2, 0.1);
      target[axis] = axis == ZOOM ? 4.0 : 0.3;
      const std::string end = runGoalToItsEnd(*backend_, target, 1.0);
      EXPECT_EQ(end.rfind("REJECTED: ", 0), 0u) << axisName(axis) << ": " << end;
      EXPECT_NE(end.find(std::string(axisName(axis)) + " goals are not supported"), std::string::npos) << end;
    }
  }
  // An axis the device has but silently ignores: never reported reached.
  std::vector<Axis> axes = { PAN };
  if (capabilities.axes[ZOOM].present && capabilities.axes[ZOOM].feedback && capabilities.axes[ZOOM].absolute)
  {
    axes.push_back(ZOOM);
  }
  for (Axis axis : axes)
  {
    ASSERT_TRUE(device_->ignoreAxis(axis, true)) << "the emulator cannot ignore the " << axisName(axis);
    const PtzSample before = backend_->sample();
    AxisValues target = device_->goal(before.position[PAN] + 0.4, before.position[TILT]);
    if (axis == ZOOM)
    {
      target[ZOOM] = before.position[ZOOM] < 2.0 ? 3.0 : 1.0;
    }
    const std::string end = runGoalToItsEnd(*backend_, target, 1.0);
    EXPECT_EQ(end.rfind("ABORTED: stalled: " + std::string(axisName(axis)), 0), 0u) << axisName(axis) << ": " << end;
    ASSERT_TRUE(device_->ignoreAxis(axis, false));
    EXPECT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
  }
}

TEST_P(DeviceContract, ZoomOfADeviceWithoutZoomIsIgnored)
{
  const AxisCapability zoom = backend_->capabilities().axes[ZOOM];
  if (zoom.present)
  {
    GTEST_SKIP() << "this device has a zoom";
  }
  // The seed: "if the camera does not support zoom (e.g. the Flir D46 PTU), the zoom field is ignored". A goal with
  // zoom 2 is judged on pan and tilt, and its text says the zoom was ignored, in the device's words.
  AxisValues target = device_->goal(0.5, 0.1);
  target[ZOOM] = 2.0;
  const std::string end = runGoalToItsEnd(*backend_, target, 1.0);
  EXPECT_EQ(end.rfind("SUCCEEDED: ", 0), 0u) << end;
  const std::string words = zoom.limitation.empty() ? "the device has no zoom" : zoom.limitation;
  EXPECT_NE(end.find("zoom 2.0000 X ignored: " + words), std::string::npos) << end;
  const double tolerance = GoalMonitorConfig().tolerance[PAN] + 1e-3;  // what SUCCEEDED vouches for
  EXPECT_NEAR(device_->deviceState().position[PAN], target[PAN], tolerance);
  EXPECT_NEAR(device_->deviceState().position[TILT], target[TILT], tolerance);
}

INSTANTIATE_TEST_SUITE_P(Devices, DeviceContract, ::testing::ValuesIn(allDeviceFixtures()),
                         [](const ::testing::TestParamInfo<FixtureMaker>& info) { return info.param.name; });

}  // namespace
}  // namespace ptz_action_server

/**
 * \file
 * \brief The link supervisor alone, on a ManualClock: the state deadline, the losses and their reasons, impossible
 * states, a recovery owed once, and the start-up wait.
 */
#include <gtest/gtest.h>

#include <future>
#include <limits>
#include <thread>

#include "ptz_action_server/core/device/link_supervisor.h"

using namespace ptz_action_server;

namespace
{
class LinkSupervisorTest : public ::testing::Test
{
protected:
  LinkSupervisorTest()
  {
    supervisor_.name("state from the test device", "states from the test device");
  }

  /// Connected, ready and one state: up for the first time.
  void bringUp()
  {
    supervisor_.connected();
    supervisor_.ready();
    supervisor_.stateReported();
    ASSERT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::FIRST);
  }

  std::shared_ptr<ManualClock> clock_ = std::make_shared<ManualClock>();
  LinkSupervisor supervisor_{ 0.5, clock_ };
};

TEST_F(LinkSupervisorTest, UpOnlyWhenConnectedReadyAndReported)
{
  EXPECT_FALSE(supervisor_.up());
  supervisor_.connected();
  supervisor_.stateReported();
  EXPECT_FALSE(supervisor_.up()) << "a state before the owner's set-up is done";
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::NONE);
  supervisor_.ready();
  EXPECT_TRUE(supervisor_.up());
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::FIRST);
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::NONE) << "a rise is reported once";
  EXPECT_TRUE(supervisor_.everUp());
  EXPECT_EQ(supervisor_.losses(), 0u);
  EXPECT_EQ(supervisor_.lastLoss(), "");
}

TEST_F(LinkSupervisorTest, AStateOlderThanTheDeadlineIsALossWithItsReason)
{
  bringUp();
  clock_->advance(0.5);
  EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::NONE) << "exactly state_timeout old is still in time";
  EXPECT_TRUE(supervisor_.up());
  clock_->advance(0.01);
  EXPECT_FALSE(supervisor_.up());
  EXPECT_EQ(supervisor_.losses(), 0u) << "up() only looks; check() counts";
  EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::SILENCE);
  EXPECT_EQ(supervisor_.losses(), 1u);
  EXPECT_EQ(supervisor_.lastLoss(), "no state from the test device for 0.50 s");
  clock_->advance(5.0);
  EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::NONE) << "one silence, one loss";
  EXPECT_EQ(supervisor_.losses(), 1u);
}

TEST_F(LinkSupervisorTest, ALongerDeadlineKeepsTheLinkOfASlowDeviceAndTheLossNamesTheDeadlineInForce)
{
  // The session stretches the deadline for a device whose replies take long (DeviceSession::replyDeadlineChanged()).
  bringUp();
  supervisor_.setStateTimeout(0.8);
  clock_->advance(0.7);
  EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::NONE);
  EXPECT_TRUE(supervisor_.up());
  clock_->advance(0.2);
  EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::SILENCE);
  EXPECT_EQ(supervisor_.lastLoss(), "no state from the test device for 0.80 s");
  // Shorter again (the device answers fast now): a report older than that is a loss at once.
  supervisor_.stateReported();
  ASSERT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::RECOVERED);
  clock_->advance(0.6);
  supervisor_.setStateTimeout(0.5);
  EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::SILENCE);
  EXPECT_EQ(supervisor_.losses(), 2u);
}

TEST_F(LinkSupervisorTest, AnAnswerWithoutStateKeepsTheLinkAlive)
{
  bringUp();
  for (int i = 0; i < 10; ++i)
  {
    clock_->advance(0.4);
    supervisor_.aliveReported();
    EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::NONE);
  }
  EXPECT_TRUE(supervisor_.up());
  EXPECT_EQ(supervisor_.losses(), 0u);
}

TEST_F(LinkSupervisorTest, ALateReportEndsTheSilenceAsALossFirst)
{
  bringUp();
  clock_->advance(2.0);
  supervisor_.stateReported();  // nobody checked during the silence
  EXPECT_EQ(supervisor_.losses(), 1u);
  EXPECT_EQ(supervisor_.lastLoss(), "no state from the test device for 0.50 s");
  EXPECT_TRUE(supervisor_.up());
}

TEST_F(LinkSupervisorTest, AClosedConnectionIsALossWithTheLinksReason)
{
  bringUp();
  supervisor_.disconnected("connection to 10.0.0.5:4000 closed");
  EXPECT_FALSE(supervisor_.up());
  EXPECT_EQ(supervisor_.losses(), 1u);
  EXPECT_EQ(supervisor_.lastLoss(), "connection to 10.0.0.5:4000 closed");
  supervisor_.disconnected("again");
  EXPECT_EQ(supervisor_.losses(), 1u) << "a link that was not up cannot be lost";
  EXPECT_EQ(supervisor_.lastLoss(), "connection to 10.0.0.5:4000 closed");
}

TEST_F(LinkSupervisorTest, OnlyImpossibleStatesForTheDeadlineAreALossNamingWhy)
{
  bringUp();
  clock_->advance(0.3);
  supervisor_.impossibleReported("pan 9.00 rad outside [-3.00, 3.00]");
  supervisor_.aliveReported();  // answers go on, the states stay impossible
  EXPECT_TRUE(supervisor_.up()) << "impossible for less than state_timeout";
  clock_->advance(0.3);
  EXPECT_EQ(supervisor_.check(), LinkSupervisor::Loss::IMPOSSIBLE);
  EXPECT_FALSE(supervisor_.up()) << "answers came, but no possible state";
  EXPECT_EQ(supervisor_.lastLoss(), "only impossible states from the test device for 0.50 s (pan 9.00 rad outside "
                                    "[-3.00, 3.00])");
  EXPECT_EQ(supervisor_.impossibleReason(), "pan 9.00 rad outside [-3.00, 3.00]");
  supervisor_.stateReported();
  EXPECT_EQ(supervisor_.impossibleReason(), "") << "a possible state ends the run";
  EXPECT_TRUE(supervisor_.up());
}

TEST_F(LinkSupervisorTest, TheRecoveryIsOwedOnceAfterALossAndAStateAfterItBringsTheLinkBack)
{
  bringUp();
  clock_->advance(1.0);
  ASSERT_EQ(supervisor_.check(), LinkSupervisor::Loss::SILENCE);
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::NONE) << "no report since";
  supervisor_.stateReported();
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::RECOVERED);
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::NONE) << "the device is held once, not on every report";
  EXPECT_TRUE(supervisor_.up());
  EXPECT_EQ(supervisor_.losses(), 1u);
  EXPECT_EQ(supervisor_.lastLoss(), "no state from the test device for 0.50 s") << "the reason outlives the loss";

  // Over a new connection: up only after ready() and a report on it.
  supervisor_.disconnected("reset");
  supervisor_.connected();
  supervisor_.stateReported();
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::NONE);
  supervisor_.ready();
  EXPECT_EQ(supervisor_.refresh(), LinkSupervisor::Rise::RECOVERED);
  EXPECT_EQ(supervisor_.losses(), 2u);
  EXPECT_EQ(supervisor_.lastLoss(), "reset");
}

TEST_F(LinkSupervisorTest, WithoutADeadlineOnlyAnExplicitLossCounts)
{
  LinkSupervisor supervisor(std::numeric_limits<double>::infinity(), clock_);
  supervisor.connected();
  supervisor.ready();
  supervisor.stateReported();
  EXPECT_EQ(supervisor.refresh(), LinkSupervisor::Rise::FIRST);
  clock_->advance(1e6);
  EXPECT_EQ(supervisor.check(), LinkSupervisor::Loss::NONE);
  EXPECT_TRUE(supervisor.up());
  supervisor.disconnected("the simulated device dropped out");
  EXPECT_EQ(supervisor.losses(), 1u);
}

TEST_F(LinkSupervisorTest, TheStartupWaitEndsWhenTheLinkIsFirstUp)
{
  std::mutex mutex;
  std::promise<bool> waited;
  std::thread waiter([&] {
    std::unique_lock<std::mutex> lock(mutex);
    waited.set_value(supervisor_.waitForStartup(lock, 60.0));
  });
  {
    std::lock_guard<std::mutex> lock(mutex);
    supervisor_.connected();
    supervisor_.ready();
    supervisor_.stateReported();
    supervisor_.refresh();
  }
  std::future<bool> result = waited.get_future();
  ASSERT_EQ(result.wait_for(std::chrono::seconds(30)), std::future_status::ready) << "the wait missed the rise";
  EXPECT_TRUE(result.get());
  waiter.join();
}

TEST_F(LinkSupervisorTest, AStartupProblemEndsTheWaitAtOnceAndFailsIt)
{
  std::mutex mutex;
  std::promise<bool> waited;
  std::thread waiter([&] {
    std::unique_lock<std::mutex> lock(mutex);
    waited.set_value(supervisor_.waitForStartup(lock, 60.0));
  });
  {
    std::lock_guard<std::mutex> lock(mutex);
    supervisor_.failStartup("TLS refused: the camera's certificate is not trusted");
  }
  std::future<bool> result = waited.get_future();
  ASSERT_EQ(result.wait_for(std::chrono::seconds(30)), std::future_status::ready) << "the wait missed the problem";
  EXPECT_FALSE(result.get());
  EXPECT_EQ(supervisor_.startupProblem(), "TLS refused: the camera's certificate is not trusted");
  waiter.join();
}

TEST_F(LinkSupervisorTest, TheStartupWaitGivesUpAfterItsTimeoutWhileTheLinkStaysDown)
{
  std::mutex mutex;
  std::unique_lock<std::mutex> lock(mutex);
  supervisor_.connected();
  supervisor_.impossibleReported("tilt NaN");
  EXPECT_FALSE(supervisor_.waitForStartup(lock, 0.05));
  EXPECT_FALSE(supervisor_.everUp());
  EXPECT_EQ(supervisor_.impossibleReason(), "tilt NaN") << "start() names it in its error";
  EXPECT_EQ(supervisor_.startupProblem(), "");
}

}  // namespace

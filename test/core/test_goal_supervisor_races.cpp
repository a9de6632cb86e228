#include "goal_supervisor_fixture.h"

using namespace ptz_action_server;
using namespace goal_supervisor_test;

// The race between the threads: the state thread samples the device while one goal is active, and before that sample
// reaches the main thread a new goal is accepted there. The stale sample tells of trouble the new goal started after
// (a link down, a link loss, a fault) and must not end it; the new goal's own samples still judge it.
TEST_F(GoalSupervisorTest, AStaleSampleWithTheLinkDownDoesNotAbortTheNextGoal)
{
  const auto first = submit(positionGoal(1.0, 0.0, 1.0), "first");
  backend_->state.link_up = false;
  ++backend_->state.link_losses;
  const GoalSample stale = supervisor_.sample();  // the state thread samples while the link is down
  backend_->state.link_up = true;                 // and the link is back when the next goal arrives
  const auto second = acceptSecondGoalThenDeliver(stale);
  EXPECT_EQ(first->end, "PREEMPTED: preempted by a new position_abs goal");
  EXPECT_TRUE(second->end.empty()) << "the first goal's sample ended the second: " << second->end;
  expectJudgedByItsOwnSamples(second);
}

TEST_F(GoalSupervisorTest, AStaleSampleFromBeforeALinkLossDoesNotAbortTheNextGoal)
{
  submit(positionGoal(1.0, 0.0, 1.0), "first");
  const GoalSample stale = supervisor_.sample();
  ++backend_->state.link_losses;  // the link breaks and heals after the state thread sampled
  const auto second = acceptSecondGoalThenDeliver(stale);
  EXPECT_TRUE(second->end.empty()) << "the first goal's sample ended the second: " << second->end;
  expectJudgedByItsOwnSamples(second);
}

TEST_F(GoalSupervisorTest, AStaleSampleFromBeforeAFaultDoesNotAbortTheNextGoal)
{
  submit(positionGoal(1.0, 0.0, 1.0), "first");
  const GoalSample stale = supervisor_.sample();
  ++backend_->state.fault_count;  // the device refuses the first goal after the state thread sampled
  backend_->last_fault = "the first goal was refused";
  const auto second = acceptSecondGoalThenDeliver(stale);
  EXPECT_TRUE(second->end.empty()) << "the first goal's sample ended the second: " << second->end;
  expectJudgedByItsOwnSamples(second);
}

// The same race with a cancel: a sample taken before the stop command (the device not yet under way) must not end
// the cancelled goal as if the device had come to rest.
TEST_F(GoalSupervisorTest, ASampleTakenBeforeACancelDoesNotEndTheStop)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  const GoalSample before_cancel = supervisor_.sample();  // at rest: the device has not started yet
  backend_->at({ 0.1, 0.0, 1.0 }, true);
  supervisor_.cancel("position_abs", "goal");
  supervisor_.supervise(before_cancel);
  EXPECT_TRUE(goal->end.empty()) << goal->end;
  backend_->at({ 0.15, 0.0, 1.0 }, false);
  tick();
  EXPECT_EQ(goal->end, "PREEMPTED: cancelled: stopped at pan 0.1500 rad, tilt 0.0000 rad, zoom 1.00 X");
}

TEST_F(GoalSupervisorTest, TheActiveGoalsOwnSamplesStillEndIt)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  backend_->state.link_up = false;
  const GoalSample sample = supervisor_.sample();
  supervisor_.supervise(sample);
  EXPECT_EQ(goal->end, "ABORTED: link lost: the device stopped reporting its state");
}

// A sample waits in the main thread's queue on a busy machine. It is judged at the time it was taken: the device went
// quiet just after it, and the wait must not read as an axis that made no progress while the link was still up.
TEST_F(GoalSupervisorTest, ASampleThatWaitedInTheQueueIsJudgedAtTheTimeItWasTaken)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  backend_->at({ 0.4, 0.0, 1.0 }, true);
  tick();  // the last report of the device's progress
  clock_->advance(0.95);
  const GoalSample queued = supervisor_.sample();  // nothing new since: still within the stall timeout (1 s)
  clock_->advance(0.3);                            // the main thread runs it late
  supervisor_.supervise(queued);
  EXPECT_TRUE(goal->end.empty()) << goal->end;
  backend_->state.link_up = false;  // the silence, as the backend reports it once it is over its state timeout
  backend_->last_link_loss = "no state from a MAVLink gimbal for 1.00 s";
  tick();
  EXPECT_EQ(goal->end, "ABORTED: link lost: no state from a MAVLink gimbal for 1.00 s");
}

// The device falls silent just after a sample whose unchanged position reads as a stall: the goal ends as a lost
// link, since that is what happened (the stall is only the last reports before the silence).
TEST_F(GoalSupervisorTest, AStallSeenAsTheLinkGoesDownEndsTheGoalAsALostLink)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  backend_->at({ 0.4, 0.0, 1.0 }, true);
  tick();
  clock_->advance(1.05);
  const GoalSample unchanged = supervisor_.sample();  // link up, no progress for over the stall timeout
  backend_->state.link_up = false;
  backend_->last_link_loss = "no state from a MAVLink gimbal for 1.00 s";
  supervisor_.supervise(unchanged);
  EXPECT_EQ(goal->end, "ABORTED: link lost: no state from a MAVLink gimbal for 1.00 s");
  EXPECT_EQ(backend_->commands.back(), "stop");
}

// Issue 23: the device's last reports before a silence show no progress (it was braking, or its reports lag), and the
// stall timeout equals the state timeout. The stall rule counts from the last progress, the link from the last report,
// so the stall came first, while the link was still judged up, and a silent device ended its goal "stalled". The
// device's reports must span the stall timeout for a stall: this one ends as a lost link, at the link's deadline.
TEST_F(GoalSupervisorTest, ADeviceThatFallsSilentAfterReportsWithoutProgressEndsAsALostLinkNotAStall)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  backend_->at({ 0.4, 0.0, 1.0 }, true);
  tick();  // the last progress
  clock_->advance(0.05);
  supervisor_.supervise(supervisor_.sample());  // one more report, unchanged
  backend_->fallSilent();
  for (int ticks = 0; ticks < 10; ++ticks)  // 1.0 s more: past the stall timeout since the last progress
  {
    tick();
  }
  EXPECT_TRUE(goal->end.empty()) << goal->end;
  backend_->state.link_up = false;  // the backend's deadline: 1 s after the last report
  backend_->last_link_loss = "no state from a MAVLink gimbal for 1.00 s";
  tick();
  EXPECT_EQ(goal->end, "ABORTED: link lost: no state from a MAVLink gimbal for 1.00 s");
}

// The stall rule still holds for a device that keeps reporting the same position.
TEST_F(GoalSupervisorTest, ADeviceThatKeepsReportingAnAxisThatDoesNotMoveStalls)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  backend_->at({ 0.4, 0.0, 1.0 }, true);
  tick();
  for (int ticks = 0; ticks < 12 && goal->end.empty(); ++ticks)
  {
    tick();
  }
  EXPECT_EQ(goal->end, "ABORTED: stalled: pan made no progress for 1.00 s (remaining 0.6000 rad)");
}

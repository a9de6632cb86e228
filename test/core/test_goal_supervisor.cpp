#include "goal_supervisor_fixture.h"

using namespace ptz_action_server;
using namespace goal_supervisor_test;

TEST_F(GoalSupervisorTest, AGoalTheDeviceAlreadySatisfiesSucceedsAtOnce)
{
  backend_->at({ 0.5, 0.0, 1.0 }, false);
  const auto goal = submit(positionGoal(0.5, 0.0, 1.0));
  EXPECT_TRUE(goal->accepted);
  EXPECT_EQ(goal->end, "SUCCEEDED: reached pan 0.5000 rad, tilt 0.0000 rad, zoom 1.00 X");
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "goTo 0.50 0.00 1.00" });
  EXPECT_FALSE(supervisor_.goalActive());
  EXPECT_EQ(supervisor_.mode(), GoalMode::IDLE);
}

TEST_F(GoalSupervisorTest, APositionGoalGivesFeedbackUntilTheDeviceRestsInsideTheTolerance)
{
  const auto goal = submit(positionGoal(1.0, -0.2, 1.0));
  ASSERT_TRUE(goal->accepted);
  EXPECT_TRUE(goal->end.empty());
  EXPECT_TRUE(supervisor_.goalActive());
  EXPECT_EQ(supervisor_.mode(), GoalMode::POSITION);
  EXPECT_TRUE(goal->feedback.empty()) << "feedback comes with the state tick, not with the goal";

  backend_->at({ 0.4, -0.1, 1.0 }, true);
  tick();
  ASSERT_FALSE(goal->feedback.empty());
  EXPECT_NEAR(goal->feedback.back()[PAN], 0.6, 1e-9);  // goal minus current, signed
  EXPECT_NEAR(goal->feedback.back()[TILT], -0.1, 1e-9);
  backend_->at({ 1.0, -0.2, 1.0 }, true);
  tick();
  EXPECT_TRUE(goal->end.empty()) << "inside the tolerance but still moving";
  backend_->at({ 1.0, -0.2, 1.0 }, false);
  tick();
  EXPECT_EQ(goal->end, "SUCCEEDED: reached pan 1.0000 rad, tilt -0.2000 rad, zoom 1.00 X");
  EXPECT_EQ(goal->ends, 1);
  EXPECT_EQ(supervisor_.mode(), GoalMode::IDLE);
  tick();
  EXPECT_EQ(goal->ends, 1);
}

TEST_F(GoalSupervisorTest, GoalsAreRejectedWhileTheLinkIsDownAndNothingMoves)
{
  backend_->state.link_up = false;
  const auto goal = submit(positionGoal(0.5, 0.0, 1.0));
  EXPECT_EQ(goal->end, "REJECTED: the fake device link is down");
  EXPECT_FALSE(goal->accepted);
  // The link comes first: a goal its conversion refused is rejected for the link too.
  const auto refused = submit([](const PtzSample&, GoalCommand&) { return std::string("pan position is NaN"); });
  EXPECT_EQ(refused->end, "REJECTED: the fake device link is down");
  EXPECT_TRUE(backend_->commands.empty());
}

TEST_F(GoalSupervisorTest, TheLinkIsJudgedOnTheSampleTheGoalWasConvertedAgainst)
{
  auto log = std::make_shared<GoalLog>();
  PtzSample current = backend_->sample();
  current.link_up = false;
  ConvertedGoal converted;
  converted.command.values = { 0.5, 0.0, 1.0 };
  supervisor_.submit(std::make_unique<RecordingGoal>("position_abs", "goal", log), current, converted);
  EXPECT_EQ(log->end, "REJECTED: the fake device link is down");
  EXPECT_TRUE(backend_->commands.empty());
}

TEST_F(GoalSupervisorTest, RefusedGoalsAreRejectedAndLeaveTheActiveGoalAlone)
{
  const auto active = submit(positionGoal(1.0, 0.0, 1.0), "active");
  const auto refused = submit([](const PtzSample&, GoalCommand&) { return std::string("pan position is NaN"); });
  EXPECT_EQ(refused->end, "REJECTED: pan position is NaN");
  EXPECT_EQ(submit(positionGoal(0.0, 2.0, 1.0))->end.find("REJECTED: tilt 2.0000 rad is outside the limits"), 0u);
  EXPECT_EQ(submit(velocityGoal(50.0, 0.0, 0.0))->end.find("REJECTED: pan velocity 50.0000 rad/s exceeds"), 0u);
  EXPECT_TRUE(active->end.empty());
  EXPECT_TRUE(supervisor_.goalActive());
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "goTo 1.00 0.00 1.00" });
}

TEST_F(GoalSupervisorTest, AGoalConvertedAgainstTheCurrentStateMovesFromThere)
{
  backend_->at({ 0.3, 0.1, 2.0 }, false);
  const auto goal = submit([](const PtzSample& current, GoalCommand& command) {
    command.values = { current.position[PAN] + 0.2, current.position[TILT], current.position[ZOOM] };
    return std::string();
  });
  EXPECT_TRUE(goal->accepted);
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "goTo 0.50 0.10 2.00" });
}

TEST_F(ClampingGoalSupervisorTest, ClampedGoalsSayWhatWasClampedInEveryText)
{
  const auto goal = submit(positionGoal(4.0, 0.0, 1.0));
  ASSERT_TRUE(goal->accepted);
  EXPECT_EQ(goal->accept_text, "clamped pan 4.0000 -> 3.1416 rad");
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "goTo 3.14 0.00 1.00" });
  backend_->at({ M_PI, 0.0, 1.0 }, false);
  tick();
  EXPECT_EQ(goal->end, "SUCCEEDED: reached pan 3.1416 rad, tilt 0.0000 rad, zoom 1.00 X (clamped pan 4.0000 -> "
                       "3.1416 rad)");
  EXPECT_EQ(submit(positionGoal(NAN, 0.0, 1.0))->end, "REJECTED: pan position is NaN");
}

TEST_F(GoalSupervisorTest, ANewGoalPreemptsTheActiveOneWithoutAStopInBetween)
{
  const auto first = submit(positionGoal(1.0, 0.0, 1.0), "first");
  backend_->at({ 0.5, 0.0, 1.0 }, true);
  tick();
  const auto second = submit(positionGoal(-1.0, 0.0, 1.0), "second", "position_rel");
  EXPECT_EQ(first->end, "PREEMPTED: preempted by a new position_rel goal");
  EXPECT_TRUE(second->accepted);
  EXPECT_TRUE(second->end.empty());
  EXPECT_EQ(backend_->commands, (std::vector<std::string>{ "goTo 1.00 0.00 1.00", "goTo -1.00 0.00 1.00" }));
  // The cancel of the preempted goal no longer stops anything.
  supervisor_.cancel("position_abs", "first");
  EXPECT_EQ(backend_->commands.size(), 2u);
  EXPECT_TRUE(supervisor_.goalActive());
}

TEST_F(GoalSupervisorTest, ACancelStopsTheDeviceAndTheGoalEndsOnceItRests)
{
  const auto goal = submit(positionGoal(1.5, 0.0, 1.0));
  backend_->at({ 0.6, 0.0, 1.0 }, true);
  tick();
  const std::size_t feedback = goal->feedback.size();
  supervisor_.cancel("position_abs", "another goal");
  supervisor_.cancel("velocity", "goal");
  EXPECT_EQ(backend_->commands.size(), 1u) << "a cancel of another goal stopped the device";

  supervisor_.cancel("position_abs", "goal");
  EXPECT_EQ(backend_->commands.back(), "stop");
  backend_->at({ 0.8, 0.0, 1.0 }, true);
  tick();
  EXPECT_TRUE(goal->end.empty()) << "ended while the device still moves";
  EXPECT_EQ(goal->feedback.size(), feedback) << "feedback while stopping";
  supervisor_.cancel("position_abs", "goal");
  EXPECT_EQ(backend_->commands.size(), 2u) << "a second cancel stopped again";
  EXPECT_EQ(supervisor_.mode(), GoalMode::POSITION);

  backend_->at({ 0.85, 0.0, 1.0 }, false);
  tick();
  EXPECT_EQ(goal->end, "PREEMPTED: cancelled: stopped at pan 0.8500 rad, tilt 0.0000 rad, zoom 1.00 X");
  EXPECT_EQ(supervisor_.mode(), GoalMode::IDLE);
}

TEST_F(GoalSupervisorTest, ACancelledGoalEndsAfterTheStopTimeoutIfTheDeviceKeepsMoving)
{
  const auto goal = submit(velocityGoal(0.5, 0.0, 0.0), "goal", "velocity");
  backend_->at({ 0.2, 0.0, 1.0 }, true);
  tick();
  supervisor_.cancel("velocity", "goal");
  for (int ticks = 0; ticks < 45; ++ticks)
  {
    tick();  // 4.5 s of the 5 s stop_timeout
  }
  EXPECT_TRUE(goal->end.empty()) << goal->end;
  for (int ticks = 0; ticks < 10 && goal->end.empty(); ++ticks)
  {
    tick();
  }
  EXPECT_EQ(goal->end, "PREEMPTED: cancelled: still moving 5.00 s after the stop command");
}

TEST_F(GoalSupervisorTest, ALostLinkAbortsTheGoalWithTheBackendsReasonAndStopsTheDevice)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  backend_->state.link_up = false;
  backend_->last_link_loss = "connection to 127.0.0.1:5500 closed";
  tick();
  EXPECT_EQ(goal->end, "ABORTED: link lost: connection to 127.0.0.1:5500 closed");
  EXPECT_EQ(backend_->commands.back(), "stop");
  EXPECT_FALSE(supervisor_.goalActive());
}

TEST_F(GoalSupervisorTest, ALinkLossThatHealedStillAbortsWithTheDefaultReason)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  ++backend_->state.link_losses;  // lost and back between two samples; the backend names no reason
  tick();
  EXPECT_EQ(goal->end, "ABORTED: link lost: the device stopped reporting its state");
}

TEST_F(GoalSupervisorTest, ADeviceFaultAbortsTheGoalWithTheFaultText)
{
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  ++backend_->state.fault_count;
  backend_->last_fault = "the device refused the position";
  tick();
  EXPECT_EQ(goal->end, "ABORTED: device fault: the device refused the position");
  EXPECT_EQ(backend_->commands.back(), "stop");
}

TEST_F(GoalSupervisorTest, AStalledAxisAbortsTheGoal)
{
  const auto goal = submit(positionGoal(0.0, 0.4, 1.0));
  for (int ticks = 0; ticks < 30 && goal->end.empty(); ++ticks)
  {
    tick();  // the device never moves
  }
  EXPECT_EQ(goal->end, "ABORTED: stalled: tilt made no progress for 1.00 s (remaining 0.4000 rad)");
  EXPECT_EQ(backend_->commands.back(), "stop");
}

TEST_F(GoalSupervisorTest, VelocityGoalsMoveUntilAnAllZeroGoalOrALimit)
{
  const auto moving = submit(velocityGoal(-0.4, 0.0, 0.0), "moving", "velocity");
  EXPECT_EQ(supervisor_.mode(), GoalMode::VELOCITY);
  backend_->at({ -0.3, 0.0, 1.0 }, true);
  backend_->state.velocity = { -0.4, 0.0, 0.0 };
  tick();
  ASSERT_FALSE(moving->feedback.empty());
  EXPECT_NEAR(moving->feedback.back()[PAN], 0.0, 1e-9);  // goal minus current velocity

  const auto stopper = submit(velocityGoal(0.0, 0.0, 0.0), "stopper", "velocity");
  EXPECT_EQ(moving->end, "PREEMPTED: preempted by a new velocity goal");
  EXPECT_EQ(backend_->commands.back(), "stop");
  backend_->at({ -0.35, 0.0, 1.0 }, false);
  backend_->state.velocity = {};
  tick();
  EXPECT_EQ(stopper->end, "SUCCEEDED: stopped at pan -0.3500 rad, tilt 0.0000 rad, zoom 1.00 X");

  const auto up = submit(velocityGoal(0.0, 1.0, 0.0), "up", "velocity");
  EXPECT_EQ(backend_->commands.back(), "moveAtVelocity 0.00 1.00 0.00");
  backend_->at({ -0.35, M_PI / 2, 1.0 }, true);
  tick();
  EXPECT_EQ(up->end, "SUCCEEDED: tilt reached its upper limit 1.5708 rad");
  EXPECT_EQ(backend_->commands.back(), "stop");
}

TEST_F(GoalSupervisorTest, ShutdownAbortsTheActiveGoalAndStopsTheDevice)
{
  supervisor_.shutdown("the node is shutting down");
  EXPECT_TRUE(backend_->commands.empty()) << "stopped without a goal";
  const auto goal = submit(positionGoal(1.0, 0.0, 1.0));
  supervisor_.shutdown("the node is shutting down");
  EXPECT_EQ(goal->end, "ABORTED: the node is shutting down");
  EXPECT_EQ(backend_->commands.back(), "stop");
  EXPECT_FALSE(supervisor_.goalActive());
}

/// The supervisor of a device whose zoom neither goes to positions nor reports them (a camera without a zoom table).
class BlindZoomSupervisorTest : public GoalSupervisorTest
{
protected:
  static Capabilities blindZoom()
  {
    Capabilities limits = SimDeviceConfig::defaults().capabilities();
    limits.axes[ZOOM].absolute = false;
    limits.axes[ZOOM].feedback = false;
    limits.axes[ZOOM].limitation = "this camera reports no zoom position";
    limits.axes[ZOOM].remedy = "set axis/zoom_table";
    return limits;
  }
  BlindZoomSupervisorTest() : blind_(backend_, blindZoom(), GoalMonitorConfig(), false, clock_)
  {
  }
  std::shared_ptr<GoalLog> submitBlind(const GoalConverter& convert)
  {
    auto log = std::make_shared<GoalLog>();
    submitConverted(blind_, *backend_, std::make_unique<RecordingGoal>("position_abs", "blind", log), convert);
    return log;
  }
  GoalSupervisor blind_;
};

TEST_F(BlindZoomSupervisorTest, AZoomItCannotSeeIsRefusedAndNothingMoves)
{
  const auto goal = submitBlind(positionGoal(0.5, 0.0, 4.0));
  EXPECT_EQ(goal->end, "REJECTED: this camera reports no zoom position: zoom goals are not supported; set "
                       "axis/zoom_table");
  EXPECT_TRUE(backend_->commands.empty());
}

TEST_F(BlindZoomSupervisorTest, AGoalThatLeavesTheZoomAloneIsJudgedOnPanAndTiltOnly)
{
  const auto goal = submitBlind(positionGoal(0.5, -0.1, 0.0));
  ASSERT_TRUE(goal->accepted) << goal->end;
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "goTo 0.50 -0.10 nan" });
  backend_->at({ 0.5, -0.1, 7.0 }, false);  // whatever the zoom's sample says, it is not the goal's
  clock_->advance(0.1);
  blind_.supervise(blind_.sample());
  EXPECT_EQ(goal->end, "SUCCEEDED: reached pan 0.5000 rad, tilt -0.1000 rad");
}

TEST_F(BlindZoomSupervisorTest, ZoomOneIsTheWidestViewAndTheTextsSaySoOnAZoomItCannotSee)
{
  const auto goal = submitBlind(positionGoal(0.5, -0.1, 1.0));
  ASSERT_TRUE(goal->accepted) << goal->end;
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "goTo 0.50 -0.10 nan" });  // no widest_view: left alone
  backend_->at({ 0.5, -0.1, 7.0 }, false);
  clock_->advance(0.1);
  blind_.supervise(blind_.sample());
  EXPECT_EQ(goal->end, "SUCCEEDED: reached pan 0.5000 rad, tilt -0.1000 rad (zoom 1 (the widest view) left as it is: "
                       "this camera reports no zoom position)");
}

/// A pan-tilt unit: no zoom at all.
class NoZoomSupervisorTest : public GoalSupervisorTest
{
protected:
  static Capabilities panTiltUnit()
  {
    Capabilities limits = SimDeviceConfig::defaults().capabilities();
    limits.axes[ZOOM] = absentAxis("a FLIR PTU has no zoom");
    return limits;
  }
  NoZoomSupervisorTest() : unit_(backend_, panTiltUnit(), GoalMonitorConfig(), false, clock_)
  {
  }
  std::shared_ptr<GoalLog> submitToUnit(const GoalConverter& convert, const std::string& action = "position_abs")
  {
    auto log = std::make_shared<GoalLog>();
    submitConverted(unit_, *backend_, std::make_unique<RecordingGoal>(action, "unit", log), convert);
    return log;
  }
  GoalSupervisor unit_;
};

TEST_F(NoZoomSupervisorTest, AZoomGoalIsJudgedOnPanAndTiltAndItsTextsSayTheZoomWasIgnored)
{
  const auto goal = submitToUnit(positionGoal(0.5, -0.1, 2.0));
  ASSERT_TRUE(goal->accepted) << goal->end;
  EXPECT_EQ(goal->accept_text, "zoom 2.0000 X ignored: a FLIR PTU has no zoom");
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "goTo 0.50 -0.10 1.00" });
  backend_->at({ 0.5, -0.1, 1.0 }, false);
  clock_->advance(0.1);
  unit_.supervise(unit_.sample());
  EXPECT_EQ(goal->end, "SUCCEEDED: reached pan 0.5000 rad, tilt -0.1000 rad (zoom 2.0000 X ignored: a FLIR PTU has "
                       "no zoom)");
}

TEST_F(NoZoomSupervisorTest, WhatTheConversionLeftOutComesBeforeTheValidationsNotes)
{
  const auto goal = submitToUnit(
      [](const PtzSample&, GoalCommand& command) {
        command.values = { 4.0, 0.0, 0.0 };
        command.note = "zoom offset 1.5000 X ignored: a FLIR PTU has no zoom";
        return std::string();
      },
      "position_rel");
  ASSERT_FALSE(goal->accepted) << goal->end;  // pan 4 is out of range: the note never hides a refusal
  EXPECT_EQ(goal->end, "REJECTED: pan 4.0000 rad is outside the limits [-3.1416, 3.1416] rad");
  const auto offset = submitToUnit(
      [](const PtzSample&, GoalCommand& command) {
        command.values = { 0.2, 0.0, 0.0 };
        command.note = "zoom offset 1.5000 X ignored: a FLIR PTU has no zoom";
        return std::string();
      },
      "position_rel");
  ASSERT_TRUE(offset->accepted) << offset->end;
  EXPECT_EQ(offset->accept_text, "zoom offset 1.5000 X ignored: a FLIR PTU has no zoom");
}

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ptz_action_server/core/goal_supervisor.h"
#include "ptz_action_server/core/sim_device_model.h"

using namespace ptz_action_server;

namespace
{
/// A device whose state the test sets by hand; it records the commands it is given.
class FakeBackend : public PtzBackend
{
public:
  FakeBackend()
  {
    state.link_up = true;
    state.position = { 0.0, 0.0, 1.0 };
  }
  std::string name() const override
  {
    return "fake";
  }
  Capabilities capabilities() const override
  {
    return SimDeviceConfig::defaults().capabilities();
  }
  void start() override
  {
  }
  void goTo(const AxisValues& position) override
  {
    commands.push_back("goTo " + describe(position));
  }
  void moveAtVelocity(const AxisValues& velocity) override
  {
    commands.push_back("moveAtVelocity " + describe(velocity));
  }
  void stop() override
  {
    commands.push_back("stop");
  }
  PtzSample sample() const override
  {
    return state;
  }
  std::string lastFault() const override
  {
    return last_fault;
  }
  std::string lastLinkLoss() const override
  {
    return last_link_loss;
  }

  /// Puts the device at \p position, moving or at rest.
  void at(const AxisValues& position, bool moving)
  {
    state.position = position;
    state.moving = moving;
  }

  PtzSample state;  ///< what sample() returns
  std::string last_fault;
  std::string last_link_loss;
  std::vector<std::string> commands;

private:
  static std::string describe(const AxisValues& values)
  {
    char text[96];
    std::snprintf(text, sizeof(text), "%.2f %.2f %.2f", values[PAN], values[TILT], values[ZOOM]);
    return text;
  }
};

/// Everything that happened to one goal; outlives the goal handle the supervisor owns.
struct GoalLog
{
  bool accepted = false;
  std::string accept_text;
  std::vector<AxisValues> feedback;
  std::string end;  ///< "REJECTED: ...", "SUCCEEDED: ...", "ABORTED: ..." or "PREEMPTED: ...", once ended
  int ends = 0;
};

class RecordingGoal : public GoalHandle
{
public:
  RecordingGoal(const std::string& action, const std::string& id, std::shared_ptr<GoalLog> log)
    : action_(action), id_(id), log_(std::move(log))
  {
  }
  const std::string& action() const override
  {
    return action_;
  }
  const std::string& id() const override
  {
    return id_;
  }
  void accept(const std::string& text) override
  {
    log_->accepted = true;
    log_->accept_text = text;
  }
  void reject(const std::string& text) override
  {
    end("REJECTED: " + text);
  }
  void publishFeedback(const AxisValues& remaining) override
  {
    log_->feedback.push_back(remaining);
  }
  void succeed(const std::string& text) override
  {
    end("SUCCEEDED: " + text);
  }
  void abort(const std::string& text) override
  {
    end("ABORTED: " + text);
  }
  void preempt(const std::string& text) override
  {
    end("PREEMPTED: " + text);
  }

private:
  void end(const std::string& text)
  {
    log_->end = text;
    ++log_->ends;
  }

  std::string action_;
  std::string id_;
  std::shared_ptr<GoalLog> log_;
};

GoalConverter positionGoal(double pan, double tilt, double zoom)
{
  return [=](const PtzSample&, GoalCommand& command) {
    command.values = { pan, tilt, zoom };
    return std::string();
  };
}

GoalConverter velocityGoal(double pan, double tilt, double zoom)
{
  return [=](const PtzSample&, GoalCommand& command) {
    command.velocity = true;
    command.values = { pan, tilt, zoom };
    return std::string();
  };
}

class GoalSupervisorTest : public ::testing::Test
{
protected:
  explicit GoalSupervisorTest(bool clamp_goals = false)
    : backend_(std::make_shared<FakeBackend>())
    , clock_(std::make_shared<ManualClock>())
    , supervisor_(backend_, backend_->capabilities(), GoalMonitorConfig(), clamp_goals, clock_)
  {
  }

  /// Submits a goal of \p action with id \p id; returns its log.
  std::shared_ptr<GoalLog> submit(const GoalConverter& convert, const std::string& id = "goal",
                                  const std::string& action = "position_abs")
  {
    auto log = std::make_shared<GoalLog>();
    supervisor_.submit(std::make_unique<RecordingGoal>(action, id, log), convert);
    return log;
  }

  /// What the state thread does every tick: the device's state, judged.
  void tick()
  {
    clock_->advance(0.1);
    supervisor_.supervise(supervisor_.sample());
  }

  /// The main thread's side of the race: a second goal is accepted before \p stale, sampled earlier, is judged.
  std::shared_ptr<GoalLog> acceptSecondGoalThenDeliver(const GoalSample& stale)
  {
    backend_->at({ 0.3, 0.0, 1.0 }, true);
    const auto second = submit(positionGoal(-1.0, 0.0, 1.0), "second");
    EXPECT_TRUE(second->accepted);
    supervisor_.supervise(stale);
    return second;
  }

  /// The goal's own samples give feedback, then end it when the device rests at -1 rad.
  void expectJudgedByItsOwnSamples(const std::shared_ptr<GoalLog>& goal)
  {
    backend_->at({ 0.2, 0.0, 1.0 }, true);
    tick();
    EXPECT_TRUE(goal->end.empty()) << goal->end;
    EXPECT_FALSE(goal->feedback.empty());
    backend_->at({ -1.0, 0.0, 1.0 }, false);
    tick();
    EXPECT_EQ(goal->end, "SUCCEEDED: reached pan -1.0000 rad, tilt 0.0000 rad, zoom 1.00 X");
  }

  std::shared_ptr<FakeBackend> backend_;
  std::shared_ptr<ManualClock> clock_;
  GoalSupervisor supervisor_;
};

class ClampingGoalSupervisorTest : public GoalSupervisorTest
{
protected:
  ClampingGoalSupervisorTest() : GoalSupervisorTest(true)
  {
  }
};
}  // namespace

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
  bool converted = false;
  const auto goal = submit([&](const PtzSample&, GoalCommand&) {
    converted = true;
    return std::string();
  });
  EXPECT_EQ(goal->end, "REJECTED: the fake device link is down");
  EXPECT_FALSE(goal->accepted);
  EXPECT_FALSE(converted);
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

TEST_F(GoalSupervisorTest, TheConverterSeesTheCurrentState)
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

/**
 * \file
 * \brief The GoalSupervisor gtests' fixture: a backend the test scripts by hand, goal handles that record what happened
 * to them, and a supervisor on a manual clock between them.
 */
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/sim/sim_device_model.h"
#include "wait_until.h"

namespace goal_supervisor_test
{
using namespace ptz_action_server;

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
  void aimInView(const ViewTarget& target) override
  {
    char text[96];
    std::snprintf(text, sizeof(text), "aimInView %.2f %.2f x%.2f", target.x, target.y, target.magnification());
    commands.push_back(text);
  }
  /// The state, stamped as the device's newest report: now while it reports, the moment it fell silent after.
  PtzSample sample() const override
  {
    PtzSample sample = state;
    if (clock)
    {
      sample.stamp = reporting ? clock->now() : silent_since;
    }
    return sample;
  }
  /// The device stops reporting (its link stays up until the backend's deadline says otherwise: set state.link_up).
  void fallSilent()
  {
    reporting = false;
    silent_since = clock->now();
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

  PtzSample state;  ///< what sample() returns (stamped by clock, when set)
  std::shared_ptr<const Clock> clock;
  bool reporting = true;
  TimePoint silent_since{};
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
  std::vector<AxisValues> ended;  ///< where a view goal's device ended (GoalHandle::ended()), told before its end
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
  void ended(const AxisValues& position) override
  {
    EXPECT_TRUE(log_->end.empty()) << "told where it ended after its end";
    log_->ended.push_back(position);
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

/// A goal as the test writes it: fills \p command from the device's \p current state, returns "" or why it is refused.
using GoalConverter = std::function<std::string(const PtzSample& current, GoalCommand& command)>;

/// Submits \p goal to \p supervisor as the node does: converted by \p convert against \p backend's sample first.
inline void submitConverted(GoalSupervisor& supervisor, const PtzBackend& backend, std::unique_ptr<GoalHandle> goal,
                            const GoalConverter& convert)
{
  const PtzSample current = backend.sample();
  ConvertedGoal converted;
  converted.rejection = convert(current, converted.command);
  supervisor.submit(std::move(goal), current, converted);
}

inline GoalConverter positionGoal(double pan, double tilt, double zoom)
{
  return [=](const PtzSample&, GoalCommand& command) {
    command.values = { pan, tilt, zoom };
    return std::string();
  };
}

/**
 * \brief Runs \p goal as the node's supervisor does on a real \p backend (validation, the axes it judges, its
 * monitor), judging each fresh sample until the goal ends or \p wait s pass; returns its log (its end "SUCCEEDED: ...",
 * "" if it had not by then). The supervisor takes the backend's capabilities as its limits.
 */
inline std::shared_ptr<GoalLog> runLoggedGoal(std::shared_ptr<PtzBackend> backend, const GoalConverter& goal,
                                              const GoalMonitorConfig& config, double wait)
{
  GoalSupervisor supervisor(backend, backend->capabilities(), config, false);
  auto log = std::make_shared<GoalLog>();
  submitConverted(supervisor, *backend, std::make_unique<RecordingGoal>("position_abs", "goal", log), goal);
  waitUntil(
      [&] {
        supervisor.supervise(supervisor.sample());
        return !log->end.empty();
      },
      wait);
  supervisor.shutdown("the test is over");
  return log;
}

/// runLoggedGoal()'s end.
inline std::string runGoalToItsEnd(std::shared_ptr<PtzBackend> backend, const GoalConverter& goal,
                                   const GoalMonitorConfig& config, double wait)
{
  return runLoggedGoal(std::move(backend), goal, config, wait)->end;
}

/// A goal the device aims itself, at \p target of its picture.
inline GoalConverter viewGoal(const ViewTarget& target)
{
  return [=](const PtzSample&, GoalCommand& command) {
    command.view = target;
    return std::string();
  };
}

inline GoalConverter velocityGoal(double pan, double tilt, double zoom)
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
    backend_->clock = clock_;
  }

  /// Submits a goal of \p action with id \p id; returns its log.
  std::shared_ptr<GoalLog> submit(const GoalConverter& convert, const std::string& id = "goal",
                                  const std::string& action = "position_abs")
  {
    auto log = std::make_shared<GoalLog>();
    submitConverted(supervisor_, *backend_, std::make_unique<RecordingGoal>(action, id, log), convert);
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
}  // namespace goal_supervisor_test

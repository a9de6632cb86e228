/**
 * \file
 * \brief Goals the device aims itself, in its own picture (GoalCommand::view): judged on what the device reports, ended
 * where it says it ended, never reached on an axis that did not move or that it does not report.
 */
#include <array>
#include <cmath>
#include <limits>

#include "goal_supervisor_fixture.h"

using namespace ptz_action_server;
using namespace goal_supervisor_test;

namespace
{
constexpr double TICK = 0.1;  // s, the node's state period
constexpr std::array<bool, AXIS_COUNT> PAN_AND_TILT{ { true, true, false } };
constexpr std::array<bool, AXIS_COUNT> NOTHING{ { false, false, false } };

PtzSample sampleAt(const AxisValues& position, bool moving)
{
  PtzSample sample;
  sample.link_up = true;
  sample.position = position;
  sample.moving = moving;
  return sample;
}

class ViewMonitorTest : public ::testing::Test
{
protected:
  /// Judges \p sample one tick later.
  GoalVerdict at(GoalMonitor& monitor, const AxisValues& position, bool moving)
  {
    clock_.advance(TICK);
    return monitor.update(sampleAt(position, moving), clock_.now());
  }

  ManualClock clock_;
  Capabilities capabilities_ = SimDeviceConfig::defaults().capabilities();
  GoalMonitorConfig config_;
  const AxisValues start_{ { 0.2, 0.1, 2.0 } };
};

TEST_F(ViewMonitorTest, SucceedsOnceTheDeviceHasMovedAndRestsSayingWhereAndWhatStayed)
{
  GoalMonitor monitor =
      GoalMonitor::forView(sampleAt(start_, false), capabilities_, config_, clock_.now(), PAN_AND_TILT);
  GoalVerdict verdict = at(monitor, start_, false);  // not begun yet
  EXPECT_EQ(verdict.phase, GoalPhase::ACTIVE);
  for (Axis axis : ALL_AXES)
  {
    EXPECT_TRUE(std::isnan(verdict.remaining[axis])) << "only the device knows where it goes";
  }
  EXPECT_EQ(at(monitor, { 0.25, 0.1, 2.0 }, true).phase, GoalPhase::ACTIVE);
  EXPECT_EQ(at(monitor, { 0.30, 0.12, 2.0 }, true).phase, GoalPhase::ACTIVE);
  // At rest by its word, but its pose still changes: not settled yet.
  EXPECT_EQ(at(monitor, { 0.31, 0.12, 2.0 }, false).phase, GoalPhase::ACTIVE);
  verdict = at(monitor, { 0.31, 0.12, 2.0 }, false);
  EXPECT_EQ(verdict.phase, GoalPhase::SUCCEEDED);
  EXPECT_EQ(verdict.reason, "the device aimed itself: ended at pan 0.3100 rad, tilt 0.1200 rad, zoom 2.00 X; zoom did "
                            "not move");
}

TEST_F(ViewMonitorTest, ADeviceThatMustMoveAndDoesNotAbortsAfterTheStallTimeout)
{
  GoalMonitor monitor =
      GoalMonitor::forView(sampleAt(start_, false), capabilities_, config_, clock_.now(), PAN_AND_TILT);
  GoalVerdict verdict;
  int ticks = 0;
  do
  {
    verdict = at(monitor, start_, false);
    ++ticks;
  } while (verdict.phase == GoalPhase::ACTIVE && ticks < 100);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_GE(ticks * TICK, config_.stall_timeout);
  EXPECT_LE(ticks * TICK, config_.stall_timeout + 2 * TICK);
  EXPECT_EQ(verdict.reason, "the device did not move within 1.00 s of its own command, at pan 0.2000 rad, tilt 0.1000 "
                            "rad, zoom 2.00 X");
}

TEST_F(ViewMonitorTest, APointAtTheCentreNeedsNoMove)
{
  GoalMonitor monitor = GoalMonitor::forView(sampleAt(start_, false), capabilities_, config_, clock_.now(), NOTHING);
  GoalVerdict verdict;
  for (int tick = 0; tick < 20 && verdict.phase == GoalPhase::ACTIVE; ++tick)
  {
    verdict = at(monitor, start_, false);
  }
  EXPECT_EQ(verdict.phase, GoalPhase::SUCCEEDED);
  EXPECT_EQ(verdict.reason, "already centred: the device did not move, at pan 0.2000 rad, tilt 0.1000 rad, zoom 2.00 "
                            "X");
}

TEST_F(ViewMonitorTest, WhatTheDeviceDoesNotReportIsNeverCalledReached)
{
  capabilities_.axes[ZOOM].feedback = false;
  GoalMonitor monitor =
      GoalMonitor::forView(sampleAt(start_, false), capabilities_, config_, clock_.now(), PAN_AND_TILT);
  at(monitor, { 0.3, 0.1, 1.0 }, true);
  const GoalVerdict verdict = at(monitor, { 0.3, 0.1, 1.0 }, false);
  EXPECT_EQ(verdict.phase, GoalPhase::SUCCEEDED);
  EXPECT_EQ(verdict.reason, "the device aimed itself: ended at pan 0.3000 rad, tilt 0.1000 rad; tilt did not move; the "
                            "device does not report its zoom");

  for (Axis axis : ALL_AXES)
  {
    capabilities_.axes[axis].feedback = false;
  }
  GoalMonitor blind = GoalMonitor::forView(sampleAt(start_, false), capabilities_, config_, clock_.now(), PAN_AND_TILT);
  GoalVerdict end;
  for (int tick = 0; tick < 20 && end.phase == GoalPhase::ACTIVE; ++tick)
  {
    end = at(blind, start_, false);
  }
  EXPECT_EQ(end.phase, GoalPhase::SUCCEEDED);
  EXPECT_EQ(end.reason, "sent to the device's own command; it reports no position, so where it ended is not known");
}

TEST_F(ViewMonitorTest, TheResultNamesOnlyAxesThatMovedOrWereNotAsked)
{
  capabilities_.axes[ZOOM].feedback = false;
  const ViewEnding ending{ start_, PAN_AND_TILT };
  const AxisValues end = ending.at(sampleAt({ 0.4, 0.1, 3.0 }, false), capabilities_);
  EXPECT_DOUBLE_EQ(end[PAN], 0.4);
  EXPECT_TRUE(std::isnan(end[TILT])) << "asked to move, did not: not reached";
  EXPECT_TRUE(std::isnan(end[ZOOM])) << "not reported: not known";
  capabilities_.axes[ZOOM].feedback = true;
  const AxisValues centred = ViewEnding{ start_, NOTHING }.at(sampleAt(start_, false), capabilities_);
  EXPECT_DOUBLE_EQ(centred[TILT], 0.1);  // not asked to move: where it stays
  EXPECT_DOUBLE_EQ(centred[ZOOM], 2.0);
}

TEST_F(ViewMonitorTest, ADeviceStillMovingPastTheTimeoutOfItsWholeRangeAborts)
{
  GoalMonitor monitor =
      GoalMonitor::forView(sampleAt(start_, false), capabilities_, config_, clock_.now(), PAN_AND_TILT);
  // Long enough for any axis to reach the farther end of its range (pan from 0.2 rad to -pi), and finite.
  EXPECT_GT(monitor.timeout(), config_.timeout_margin + (M_PI + start_[PAN]) / capabilities_.axes[PAN].max_speed);
  EXPECT_LT(monitor.timeout(), 60.0);
  GoalVerdict verdict;
  double pan = start_[PAN];
  for (int tick = 0; tick < 1000 && verdict.phase == GoalPhase::ACTIVE; ++tick)
  {
    pan += 0.001;
    verdict = at(monitor, { pan, 0.1, 2.0 }, true);
  }
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_EQ(verdict.reason.rfind("timed out after ", 0), 0U) << verdict.reason;
}

TEST_F(ViewMonitorTest, ALostLinkOrAFaultEndsItAsAnyGoal)
{
  GoalMonitor monitor =
      GoalMonitor::forView(sampleAt(start_, false), capabilities_, config_, clock_.now(), PAN_AND_TILT);
  PtzSample faulted = sampleAt(start_, false);
  faulted.fault_count = 1;
  clock_.advance(TICK);
  GoalVerdict verdict = monitor.update(faulted, clock_.now());
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_TRUE(verdict.device_fault);
}

/// A device that centres points of its own picture.
class ViewSupervisorTest : public ::testing::Test
{
protected:
  ViewSupervisorTest()
    : backend_(std::make_shared<FakeBackend>())
    , clock_(std::make_shared<ManualClock>())
    , supervisor_(backend_, viewCamera(), GoalMonitorConfig(), false, clock_)
  {
    backend_->clock = clock_;
    backend_->at({ 0.2, 0.1, 2.0 }, false);
  }

  static Capabilities viewCamera()
  {
    Capabilities capabilities = SimDeviceConfig::defaults().capabilities();
    capabilities.view_centre = true;
    capabilities.view_box_zoom = true;
    capabilities.axes[ZOOM].feedback = false;  // as an Axis camera without a zoom table
    return capabilities;
  }

  std::shared_ptr<GoalLog> submitView(double x, double y, const std::string& id = "goal")
  {
    auto log = std::make_shared<GoalLog>();
    ViewTarget target;
    target.x = x;
    target.y = y;
    target.image_width = 640;
    target.image_height = 360;
    submitConverted(supervisor_, *backend_, std::make_unique<RecordingGoal>("pixel", id, log),
                    [target](const PtzSample&, GoalCommand& command) {
                      command.view = target;
                      command.note = "aimed by the device's own command";
                      return std::string();
                    });
    return log;
  }

  void tick()
  {
    clock_->advance(TICK);
    supervisor_.supervise(supervisor_.sample());
  }

  std::shared_ptr<FakeBackend> backend_;
  std::shared_ptr<ManualClock> clock_;
  GoalSupervisor supervisor_;
};

TEST_F(ViewSupervisorTest, TheDeviceIsAskedAndTheGoalEndsWhereItSaysItEnded)
{
  const auto goal = submitView(0.75, 0.5);
  ASSERT_TRUE(goal->accepted);
  EXPECT_EQ(goal->accept_text, "aimed by the device's own command");
  EXPECT_EQ(backend_->commands, std::vector<std::string>{ "aimInView 0.75 0.50 x1.00" });
  EXPECT_EQ(supervisor_.mode(), GoalMode::POSITION);
  backend_->at({ 0.3, 0.1, 2.0 }, true);
  tick();
  ASSERT_FALSE(goal->feedback.empty());
  EXPECT_TRUE(std::isnan(goal->feedback.back()[PAN]));
  backend_->at({ 0.45, 0.1, 2.0 }, false);
  tick();
  EXPECT_EQ(goal->end, "") << "its pose changed since the last report: not settled";
  tick();
  EXPECT_EQ(goal->end, "SUCCEEDED: the device aimed itself: ended at pan 0.4500 rad, tilt 0.1000 rad; tilt did not "
                       "move; the device does not report its zoom (aimed by the device's own command)");
  ASSERT_EQ(goal->ended.size(), 1U);
  EXPECT_DOUBLE_EQ(goal->ended[0][PAN], 0.45);
  EXPECT_DOUBLE_EQ(goal->ended[0][TILT], 0.1);
  EXPECT_TRUE(std::isnan(goal->ended[0][ZOOM])) << "a zoom the device does not report has no place to end";
}

TEST_F(ViewSupervisorTest, ACancelStopsTheDeviceAndStillSaysWhereItEnded)
{
  const auto goal = submitView(0.1, 0.9);
  backend_->at({ 0.1, 0.0, 2.0 }, true);
  tick();
  supervisor_.cancel("pixel", "goal");
  EXPECT_EQ(backend_->commands.back(), "stop");
  backend_->at({ 0.05, -0.02, 2.0 }, false);
  tick();
  EXPECT_EQ(goal->end.rfind("PREEMPTED: cancelled: stopped at pan 0.0500 rad", 0), 0U) << goal->end;
  ASSERT_EQ(goal->ended.size(), 1U);
  EXPECT_DOUBLE_EQ(goal->ended[0][PAN], 0.05);
}

TEST_F(ViewSupervisorTest, APreemptedViewGoalSaysWhereItWasAndTheNextGoalRetargets)
{
  const auto first = submitView(0.9, 0.5, "first");
  backend_->at({ 0.4, 0.1, 2.0 }, true);
  auto second = std::make_shared<GoalLog>();
  submitConverted(supervisor_, *backend_, std::make_unique<RecordingGoal>("position_abs", "second", second),
                  positionGoal(-0.5, 0.0, 0.0));
  EXPECT_EQ(first->end, "PREEMPTED: preempted by a new position_abs goal (aimed by the device's own command)");
  ASSERT_EQ(first->ended.size(), 1U);
  EXPECT_DOUBLE_EQ(first->ended[0][PAN], 0.4);
  EXPECT_TRUE(second->ended.empty());
  EXPECT_EQ(backend_->commands.back(), "goTo -0.50 0.00 nan");  // no zoom feedback: the zoom left alone
}

TEST_F(ViewSupervisorTest, ADeviceWithoutItsOwnCommandRejectsTheGoal)
{
  GoalSupervisor plain(backend_, SimDeviceConfig::defaults().capabilities(), GoalMonitorConfig(), false, clock_);
  auto log = std::make_shared<GoalLog>();
  submitConverted(plain, *backend_, std::make_unique<RecordingGoal>("pixel", "goal", log),
                  [](const PtzSample&, GoalCommand& command) {
                    command.view = ViewTarget();
                    return std::string();
                  });
  EXPECT_EQ(log->end, "REJECTED: the fake device cannot aim in its own picture");
  EXPECT_TRUE(backend_->commands.empty());
}

}  // namespace

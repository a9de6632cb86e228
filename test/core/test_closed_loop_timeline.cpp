// ClosedLoopBackend on report timelines written by hand: a device that moves at the speed it is given (a Pelco-D
// camera without set-position), its reports late or bunched as on a busy machine, replayed deterministically.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ptz_action_server/core/closed_loop_backend.h"

using namespace ptz_action_server;

namespace
{
const TimePoint T0(std::chrono::seconds(100));

/**
 * A pan that moves at the speed it is given (Pelco-D's speed bytes: 1.5 rad/s at 0x3F, in 63 steps), reaching each
 * new speed at 3 rad/s^2 once the command has crossed the line, and reports its position when the test says so. No
 * thread: the test advances its time and calls the listener, as the device's I/O thread would after each report.
 */
class ProportionalPan : public PtzBackend
{
public:
  std::string name() const override
  {
    return "proportional_pan";
  }
  Capabilities capabilities() const override
  {
    Capabilities capabilities;
    capabilities.axes[PAN] = fullAxis(AxisRange{ -3.1, 3.1 }, MAX_SPEED, ACCELERATION);
    capabilities.axes[PAN].absolute = false;
    capabilities.axes[TILT] = absentAxis();
    capabilities.axes[ZOOM] = absentAxis();
    return capabilities;
  }
  void start() override
  {
  }
  void goTo(const AxisValues& /*position*/) override
  {
    ++position_commands;
  }
  void moveAtVelocity(const AxisValues& velocity) override
  {
    const double bytes = std::min(63.0, std::max(1.0, std::round(std::abs(velocity[PAN]) / MAX_SPEED * 63.0)));
    give(velocity[PAN] == 0.0 ? 0.0 : std::copysign(bytes / 63.0 * MAX_SPEED, velocity[PAN]));
  }
  void stop() override
  {
    give(0.0);
  }
  PtzSample sample() const override
  {
    return sample_;
  }
  std::string lastFault() const override
  {
    return "";
  }
  bool setSampleListener(SampleListener listener) override
  {
    listener_ = std::move(listener);
    return true;
  }

  /// The device's state as it was at \p measured reaches the node at \p stamp (no earlier than \p measured), whose
  /// steering answers it at once; its commands reach the device \p command_delay later.
  void report(double measured, double stamp, double command_delay = 0.005)
  {
    advance(measured);
    sample_.velocity[PAN] = have_report_ ? (position_ - sample_.position[PAN]) / (stamp - last_stamp_) : 0.0;
    sample_.stamp = addSeconds(T0, stamp);
    sample_.link_up = true;
    sample_.position = { { position_, 0.0, 1.0 } };
    sample_.moving = speed_ != 0.0;
    have_report_ = true;
    last_stamp_ = stamp;
    command_at_ = stamp + command_delay;
    listener_();
  }
  double position() const
  {
    return position_;
  }
  int position_commands = 0;

  static constexpr double MAX_SPEED = 1.5;
  static constexpr double ACCELERATION = 3.0;

private:
  void give(double speed)
  {
    std::lock_guard<std::mutex> lock(mutex_);  // a timed stop comes from the timer's thread
    pending_.push_back({ command_at_, speed });
  }
  /// Moves the device on to \p until (s), in 1 ms steps, taking each command as it arrives.
  void advance(double until)
  {
    constexpr double STEP = 0.001;
    std::lock_guard<std::mutex> lock(mutex_);
    while (now_ + 0.5 * STEP < until)
    {
      while (!pending_.empty() && pending_.front().first <= now_)
      {
        goal_speed_ = pending_.front().second;
        pending_.erase(pending_.begin());
      }
      speed_ += std::clamp(goal_speed_ - speed_, -ACCELERATION * STEP, ACCELERATION * STEP);
      position_ += speed_ * STEP;
      now_ += STEP;
    }
  }

  SampleListener listener_;
  std::mutex mutex_;
  PtzSample sample_;
  bool have_report_ = false;
  double last_stamp_ = 0.0;
  double command_at_ = 0.0;
  std::vector<std::pair<double, double>> pending_;  ///< (when it reaches the device, the speed)
  double now_ = 0.0;
  double position_ = 0.0;
  double speed_ = 0.0;
  double goal_speed_ = 0.0;
};

/// One report: when the device measured its state, and when the node got it (s from the start).
struct Report
{
  double measured;
  double stamp;
};

/// Reports every \p period from 0 to \p end; those due within [\p late_from, \p late_until) are measured on time and
/// all reach the node at \p late_until (the node's thread did not run), bunched a millisecond apart.
std::vector<Report> timeline(double period, double end, double late_from = -1.0, double late_until = -1.0)
{
  std::vector<Report> reports;
  int bunched = 0;
  for (double at = 0.0; at < end; at += period)
  {
    const bool late = at >= late_from && at < late_until;
    reports.push_back({ at, late ? late_until + 0.001 * bunched++ : at + 0.004 });
  }
  return reports;
}

class ClosedLoopTimeline : public ::testing::Test
{
protected:
  void SetUp() override
  {
    pan_ = std::make_shared<ProportionalPan>();
    backend_ = withClosedLoop(pan_, { { 0.009, 0.009, 0.05 } });  // config/pelco_d.yaml's tolerances
    ASSERT_TRUE(backend_->setSampleListener([] {}));
    backend_->start();
    pan_->report(0.0, 0.004);
  }

  /// Replays \p reports with a goal to \p target given after the first; true if the steering judged the pan to move at
  /// one speed at some report (it says so at once).
  bool judgedOneSpeed(const std::vector<Report>& reports, double target, double command_delay = 0.005)
  {
    backend_->goTo({ { target, std::nan(""), std::nan("") } });
    bool judged = false;
    for (const Report& report : reports)
    {
      pan_->report(report.measured, report.stamp, command_delay);
      for (const std::string& text : backend_->takeWarnings())
      {
        judged = judged || text.find("moves at one speed") != std::string::npos;
      }
    }
    return judged;
  }

  std::shared_ptr<ProportionalPan> pan_;
  std::shared_ptr<PtzBackend> backend_;
};
}  // namespace

TEST_F(ClosedLoopTimeline, OnTimeReportsSteerTheProportionalPanToItsTarget)
{
  EXPECT_FALSE(judgedOneSpeed(timeline(0.05, 3.0), 1.0));
  EXPECT_NEAR(pan_->position(), 1.0, 0.009);
  EXPECT_EQ(pan_->position_commands, 0);
}

TEST_F(ClosedLoopTimeline, ReportsHeldUpAtFullSpeedDoNotMakeItLookAsIfItMovedAtOneSpeed)
{
  // The node's thread does not run for 150 to 300 ms while the pan turns at full speed (a busy machine): when the
  // reports come back it is past where it should have begun braking, and it brakes at its own 3 rad/s^2 while the
  // speeds it is given fall faster; for a few reports it goes twice as fast as it is told. That is braking, not a pan
  // that ignores the speed.
  for (double stall : { 0.15, 0.2, 0.3 })
  {
    for (double from = 0.3; from < 0.75; from += 0.05)
    {
      SetUp();
      EXPECT_FALSE(judgedOneSpeed(timeline(0.05, 3.0, from, from + stall), 1.0))
          << "reports held up from " << from << " s for " << stall << " s";
      EXPECT_NEAR(pan_->position(), 1.0, 0.009) << "reports held up from " << from << " s for " << stall << " s";
    }
  }
}

TEST_F(ClosedLoopTimeline, CommandsThatReachThePanLateDoNotMakeItLookAsIfItMovedAtOneSpeed)
{
  // Each speed reaches the pan a report and a half after the report it answers (queued behind the polls).
  EXPECT_FALSE(judgedOneSpeed(timeline(0.05, 4.0), 1.0, 0.075));
  EXPECT_NEAR(pan_->position(), 1.0, 0.009);
}

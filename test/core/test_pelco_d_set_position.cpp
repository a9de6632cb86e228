/**
 * \file
 * \brief Pelco-D cameras without set-position (0x4B, 0x4D, 0x4F), as many conference cameras are: declared by
 * pelco_d/set_position, or found out on a goal, then steered on speed commands by the node's ClosedLoopBackend.
 */
#include <gtest/gtest.h>

#include <limits>

#include "goal_supervisor_fixture.h"
#include "line_test_support.h"
#include "wait_until.h"

#include "ptz_action_server/core/closed_loop_backend.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/core/pelco_d/set_position_check.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = LINE_TEST_WAIT;
constexpr double NAN_VALUE = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------- the check alone

using Step = pelco::SetPositionCheck::Step;

class SetPositionCheckTest : public ::testing::Test
{
protected:
  /// A whole poll round at \p position, \p seconds after the set-position went out.
  Step round(const AxisValues& position, double seconds)
  {
    return check_.update(position, addSeconds(start_, seconds));
  }

  pelco::SetPositionCheck check_{ pelco::SetPositionCheck::Config() };  // 0.5 s and 3 rounds, 0.1 degree, 0.2 X
  const TimePoint start_ = TimePoint(std::chrono::seconds(100));
  const AxisValues rest_{ { 0.0, 0.0, 1.0 } };
};

TEST_F(SetPositionCheckTest, ACameraThatMovesOnSetPositionIsNeverProbedAndNeverCheckedAgain)
{
  ASSERT_TRUE(check_.begin(rest_, { { 0.5, NAN_VALUE, NAN_VALUE } }, start_));
  EXPECT_EQ(round(rest_, 0.1), Step::NONE);
  EXPECT_EQ(round({ { 0.01, 0.0, 1.0 } }, 0.2), Step::HONOURED);
  EXPECT_EQ(round(rest_, 2.0), Step::NONE);
  // It took one: the next goal is not watched at all.
  EXPECT_FALSE(check_.begin(rest_, { { -0.5, 0.3, 2.0 } }, addSeconds(start_, 3.0)));
}

TEST_F(SetPositionCheckTest, ACameraThatStaysPutIsProbedTowardTheTargetAndIgnoresSetPositionIfTheProbeMovesIt)
{
  ASSERT_TRUE(check_.begin(rest_, { { -0.5, 0.3, NAN_VALUE } }, start_));
  // Neither half a second alone nor three rounds alone is enough: a starved machine gives time without positions.
  EXPECT_EQ(round(rest_, 0.6), Step::NONE);
  EXPECT_EQ(round(rest_, 0.7), Step::NONE);
  EXPECT_EQ(round(rest_, 0.8), Step::PROBE);
  EXPECT_EQ(check_.directions()[PAN], -1);
  EXPECT_EQ(check_.directions()[TILT], 1);
  EXPECT_EQ(check_.directions()[ZOOM], 0);  // left alone
  EXPECT_TRUE(check_.probing());
  EXPECT_EQ(round({ { -0.001, 0.0, 1.0 } }, 0.9), Step::NONE);  // less than a tenth of a degree
  EXPECT_EQ(round({ { -0.005, 0.001, 1.0 } }, 1.0), Step::IGNORED);
  EXPECT_FALSE(check_.probing());
}

TEST_F(SetPositionCheckTest, ACameraThatMovesNeitherWayIsNotCalledOneThatIgnoresSetPosition)
{
  ASSERT_TRUE(check_.begin(rest_, { { 0.0, 0.0, 5.0 } }, start_));
  for (double seconds : { 0.2, 0.4, 0.6 })
  {
    round(rest_, seconds);
  }
  ASSERT_TRUE(check_.probing());
  EXPECT_EQ(check_.directions()[ZOOM], 1);
  EXPECT_EQ(round(rest_, 0.8), Step::NONE);
  EXPECT_EQ(round(rest_, 1.0), Step::NONE);
  EXPECT_EQ(round(rest_, 1.2), Step::STUCK);
  // Nothing learnt: the next goal is watched again.
  EXPECT_TRUE(check_.begin(rest_, { { 0.3, 0.0, NAN_VALUE } }, addSeconds(start_, 2.0)));
}

TEST_F(SetPositionCheckTest, AGoalTooCloseToShowMovementOrACancelWatchesNothing)
{
  EXPECT_FALSE(check_.begin(rest_, { { 0.003, -0.003, 1.3 } }, start_));  // under two tenths of a degree, 0.4 X
  EXPECT_EQ(round(rest_, 5.0), Step::NONE);
  ASSERT_TRUE(check_.begin(rest_, { { 0.3, 0.0, NAN_VALUE } }, start_));
  check_.cancel();
  for (double seconds : { 0.6, 0.7, 0.8, 0.9 })
  {
    EXPECT_EQ(round(rest_, seconds), Step::NONE);
  }
}

// ---------------------------------------------------------------- against the emulator, closed-loop

/// A Pelco-D camera without set-position (the emulator's no-set-position mode), its backend wrapped as the node wraps
/// every device, and the node's goal supervisor on top.
class PelcoWithoutSetPosition : public ::testing::Test
{
protected:
  void start(PelcoSetPosition setting, const std::string& mode = "no-set-position")
  {
    PelcoDEmulatorConfig camera;
    ASSERT_TRUE(camera.applyMode(mode));
    camera.port.link = uniqueLink("pelco_no_set_position");
    camera.port.baud = 38400;
    emulator_ = std::make_unique<PelcoDEmulator>(camera);
    DeviceConfig<PelcoProtocol> config;
    config.link = serialLink(camera.port.link, camera.port.baud);
    config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
    config.settings.set_position = setting;
    device_ = std::shared_ptr<DeviceBackend>(makeDeviceBackend<PelcoProtocol>(config));
    backend_ = withClosedLoop(device_, monitor_.tolerance);
    backend_->setSampleListener([] {});
    backend_->start();
  }

  /// Runs a position goal as the node would, to its end; returns "SUCCEEDED: ..." or the like.
  std::string run(double pan, double tilt)
  {
    // At the zoom it has (1 X, the widest): Pelco-D's zoom has no speed byte, so only pan and tilt are steered here.
    return goal_supervisor_test::runGoalToItsEnd(backend_, goal_supervisor_test::positionGoal(pan, tilt, 1.0), monitor_,
                                                 WAIT);
  }

  std::size_t setPositionFrames() const
  {
    std::size_t count = 0;
    for (const ReceivedFrame& item : emulator_->received().items())
    {
      const std::uint8_t command = item.frame.command2;
      count += command == pelco::SET_PAN || command == pelco::SET_TILT || command == pelco::SET_ZOOM;
    }
    return count;
  }

  void expectAt(double pan, double tilt) const
  {
    EXPECT_NEAR(emulator_->sample().position[PAN], pan, monitor_.tolerance[PAN]);
    EXPECT_NEAR(emulator_->sample().position[TILT], tilt, monitor_.tolerance[TILT]);
  }

  /// The node's defaults, but a stall timeout generous for a busy machine: the check needs half a second and three
  /// poll rounds before its probe moves the camera, and a starved I/O thread must not make that look like a stall.
  GoalMonitorConfig monitor_ = [] {
    GoalMonitorConfig config;
    config.stall_timeout = 3.0;
    return config;
  }();
  std::unique_ptr<PelcoDEmulator> emulator_;
  std::shared_ptr<DeviceBackend> device_;
  std::shared_ptr<PtzBackend> backend_;
};

TEST_F(PelcoWithoutSetPosition, DeclaredBySettingItsPositionGoalsAreSteeredOnSpeedsAndNoSetPositionIsSent)
{
  start(PelcoSetPosition::NO);
  const Capabilities device = device_->capabilities();
  ASSERT_FALSE(device.axes[PAN].absolute);
  EXPECT_NE(device.axes[PAN].limitation.find("pelco_d/set_position is false"), std::string::npos);
  EXPECT_TRUE(device.axes[PAN].velocity && device.axes[PAN].feedback);
  EXPECT_TRUE(backend_->capabilities().axes[PAN].absolute);  // made up for by the steering
  const std::string first = run(0.6, -0.2);
  EXPECT_EQ(first.rfind("SUCCEEDED: reached pan 0.", 0), 0u) << first;
  expectAt(0.6, -0.2);
  const std::string second = run(-0.3, 0.1);
  EXPECT_EQ(second.rfind("SUCCEEDED: reached pan -0.", 0), 0u) << second;
  expectAt(-0.3, 0.1);
  EXPECT_EQ(setPositionFrames(), 0u);
}

TEST_F(PelcoWithoutSetPosition, FoundOutOnTheFirstGoalWhichAbortsNamingItAndTheSettingThenTheNextIsSteered)
{
  start(PelcoSetPosition::AUTO);
  ASSERT_TRUE(device_->capabilities().axes[PAN].absolute);  // it should take set-position, as far as anyone knows
  const std::string first = run(0.5, 0.2);
  EXPECT_EQ(first.rfind("ABORTED: device fault: this Pelco-D camera ignores set-position (0x4B, 0x4D, 0x4F)", 0), 0u)
      << first;
  EXPECT_NE(first.find("set pelco_d/set_position: false"), std::string::npos) << first;
  EXPECT_FALSE(device_->capabilities().axes[PAN].absolute);
  EXPECT_FALSE(device_->capabilities().axes[ZOOM].absolute);
  const std::vector<std::string> warnings = device_->takeWarnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("ignores set-position"), std::string::npos) << warnings[0];
  const std::size_t sent = setPositionFrames();
  EXPECT_EQ(sent, 3u);  // pan, tilt and zoom of the first goal
  // The next goal is steered on the position queries, and reached.
  const std::string second = run(0.5, 0.2);
  EXPECT_EQ(second.rfind("SUCCEEDED: reached pan 0.", 0), 0u) << second;
  expectAt(0.5, 0.2);
  EXPECT_EQ(setPositionFrames(), sent);
}

TEST_F(PelcoWithoutSetPosition, ACameraThatTakesSetPositionIsNeverProbedAndStaysAbsolute)
{
  start(PelcoSetPosition::AUTO, "standard");
  const std::string first = run(0.5, -0.2);
  EXPECT_EQ(first.rfind("SUCCEEDED: reached pan 0.", 0), 0u) << first;
  EXPECT_TRUE(device_->capabilities().axes[PAN].absolute);
  for (const ReceivedFrame& item : emulator_->received().items())
  {
    const bool movement = (item.frame.command2 & 0x01) == 0 && !(item.frame == pelco::stop(item.frame.address));
    EXPECT_FALSE(movement) << "a speed command went out: " << int(item.frame.command2);
  }
}

TEST_F(PelcoWithoutSetPosition, ACameraThatMovesNeitherOnSetPositionNorAtASpeedStallsAndKeepsItsCapabilities)
{
  start(PelcoSetPosition::AUTO);
  SimFaults faults;
  faults.stalled[PAN] = faults.stalled[TILT] = true;
  emulator_->setFaults(faults);
  const std::string first = run(0.5, 0.2);
  EXPECT_EQ(first.rfind("ABORTED: stalled", 0), 0u) << first;
  EXPECT_TRUE(device_->capabilities().axes[PAN].absolute);
  EXPECT_TRUE(device_->takeWarnings().empty());
}

}  // namespace

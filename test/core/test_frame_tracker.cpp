#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "goal_supervisor_fixture.h"
#include "ptz_action_server/core/motion/frame_tracker.h"
#include "ptz_action_server/core/limits.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

using namespace ptz_action_server;
using namespace goal_supervisor_test;

namespace
{
PtzKinematics shippedKinematics()
{
  std::ifstream file(std::string(PTZ_SOURCE_DIR) + "/urdf/ptz.urdf");
  std::stringstream text;
  text << file.rdbuf();
  return PtzKinematics::fromUrdf(text.str());
}

/// A point 5 m away at camera height, where the camera looks at pan \p angle (the shipped URDF pans clockwise seen
/// from above, as the contract says).
Eigen::Vector3d onCircle(const PtzKinematics& kinematics, double angle)
{
  const Eigen::Vector3d camera = kinematics.cameraInBase(0.0, 0.0).translation();
  return Eigen::Vector3d(5.0 * std::cos(angle), -5.0 * std::sin(angle), camera.z());
}

class FrameTrackerTest : public ::testing::Test
{
protected:
  FrameTrackerTest()
    : kinematics(shippedKinematics())
    , limits(intersectLimits(SimDeviceConfig::defaults().capabilities(), urdfLimits(kinematics)).limits)
  {
  }
  PtzSample at(double pan, double tilt)
  {
    PtzSample sample;
    sample.link_up = true;
    sample.position = { pan, tilt, 1.0 };
    return sample;
  }

  PtzKinematics kinematics;
  Capabilities limits;
  ManualClock clock;
};

TEST_F(FrameTrackerTest, AimRateIsTheCirclingPointsAngularRate)
{
  FrameTracker tracker(kinematics, limits, FrameTrackerConfig(), 1.0);
  for (int step = 0; step <= 10; ++step)
  {
    const double stamp = 0.05 * step;
    ASSERT_EQ(tracker.observe(onCircle(kinematics, 0.5 * stamp), stamp, clock.now()), "");
  }
  EXPECT_NEAR(tracker.aimRate()[PAN], 0.5, 0.02);
  EXPECT_NEAR(tracker.aimRate()[TILT], 0.0, 0.01);
  // Carried forward to a later moment at that rate.
  const AxisValues aim = tracker.aimAt(0.6, 0.0);
  double pan = 0.0;
  double tilt = 0.0;
  ASSERT_TRUE(kinematics.aimAt(onCircle(kinematics, 0.3), pan, tilt));
  EXPECT_NEAR(aim[PAN], pan, 0.005);
  EXPECT_NEAR(aim[ZOOM], 1.0, 1e-12);
}

TEST_F(FrameTrackerTest, AStampSeenBeforeChangesNothing)
{
  FrameTracker tracker(kinematics, limits, FrameTrackerConfig(), 1.0);
  tracker.observe(onCircle(kinematics, 0.0), 1.0, clock.now());
  const TimePoint first = tracker.lastNewPositionAt();
  clock.advance(0.5);
  tracker.observe(onCircle(kinematics, 0.3), 1.0, clock.now());
  EXPECT_EQ(tracker.lastNewPositionAt(), first) << "the same stamp is no new position";
  EXPECT_EQ(tracker.aimRate()[PAN], 0.0);
  tracker.observe(onCircle(kinematics, 0.1), 1.2, clock.now());
  EXPECT_GT(tracker.lastNewPositionAt(), first);
  EXPECT_NEAR(tracker.aimRate()[PAN], 0.5, 0.02);
}

TEST_F(FrameTrackerTest, VelocityCommandFeedsTheRateForwardAndCorrectsTheError)
{
  FrameTrackerConfig config;
  config.gain = 4.0;
  FrameTracker tracker(kinematics, limits, config, 1.0);
  tracker.observe(onCircle(kinematics, 0.0), 0.0, clock.now());
  tracker.observe(onCircle(kinematics, 0.05), 0.1, clock.now());
  AxisValues aim{};
  const GoalCommand command = tracker.command(at(0.0, 0.0), 0.1, aim);
  ASSERT_TRUE(command.velocity);
  EXPECT_NEAR(command.values[PAN], 0.5 + 4.0 * (aim[PAN] - 0.0), 1e-9);
  EXPECT_NEAR(aim[PAN], 0.05, 0.01);
  // Far behind: the speed is capped at the axis's maximum.
  const GoalCommand far = tracker.command(at(-2.0, 0.0), 0.1, aim);
  EXPECT_NEAR(far.values[PAN], limits.axes[PAN].max_speed, 1e-9);
}

TEST_F(FrameTrackerTest, PositionCommandsWithoutFeedForward)
{
  FrameTrackerConfig config;
  config.feed_forward = false;
  FrameTracker tracker(kinematics, limits, config, 2.0);
  tracker.observe(onCircle(kinematics, 0.4), 0.0, clock.now());
  AxisValues aim{};
  const GoalCommand command = tracker.command(at(0.0, 0.0), 0.0, aim);
  EXPECT_FALSE(command.velocity);
  EXPECT_NEAR(command.values[PAN], 0.4, 0.01);
  EXPECT_NEAR(command.values[ZOOM], 2.0, 1e-12);
}

TEST_F(FrameTrackerTest, PanFollowsAcrossTheBackOfTheCircleWithoutATurnInTheRate)
{
  Capabilities wide = limits;
  wide.axes[PAN].range = { -2.0 * M_PI, 2.0 * M_PI };
  FrameTracker tracker(kinematics, wide, FrameTrackerConfig(), 1.0);
  tracker.observe(onCircle(kinematics, M_PI - 0.05), 0.0, clock.now());
  tracker.observe(onCircle(kinematics, M_PI + 0.05), 0.2, clock.now());
  EXPECT_NEAR(tracker.aimRate()[PAN], 0.5, 0.02);
  // On a range wider than a turn the aim stays next to the camera (3.19 rad, not -3.09).
  EXPECT_NEAR(tracker.aimAt(0.2, 3.1)[PAN], M_PI + 0.05, 0.01);
  // On the shipped +-pi range the aim is the reachable turn, clamped into the range.
  FrameTracker shipped(kinematics, limits, FrameTrackerConfig(), 1.0);
  shipped.observe(onCircle(kinematics, M_PI + 0.05), 0.0, clock.now());
  const double pan = shipped.aimAt(0.0, 3.1)[PAN];
  EXPECT_TRUE(limits.axes[PAN].range.contains(pan)) << pan;
  EXPECT_NEAR(pan, -M_PI + 0.05, 0.01);
}

TEST_F(FrameTrackerTest, APointAtTheCameraCannotBeAimedAt)
{
  FrameTracker tracker(kinematics, limits, FrameTrackerConfig(), 1.0);
  const Eigen::Vector3d camera = kinematics.cameraInBase(0.0, 0.0).translation();
  EXPECT_NE(tracker.observe(camera, 0.0, clock.now()), "");
  EXPECT_FALSE(tracker.hasPosition());
}

/// Tracking goals in the supervisor: steered until preempted, cancelled or aborted.
class TrackingSupervisorTest : public GoalSupervisorTest
{
protected:
  std::shared_ptr<GoalLog> submitTrack(double pan, const std::string& id = "track")
  {
    return submit(
        [pan](const PtzSample&, GoalCommand& command) {
          command.track = true;
          command.values = { pan, 0.0, 1.0 };
          return std::string();
        },
        id, "track_frame");
  }
  static GoalCommand velocity(double pan)
  {
    GoalCommand command;
    command.velocity = true;
    command.values = { pan, 0.0, 0.0 };
    return command;
  }
};

TEST_F(TrackingSupervisorTest, ATrackingGoalNeverSucceedsAndFeedsBackTheAimError)
{
  const auto goal = submitTrack(0.5);
  ASSERT_TRUE(goal->accepted);
  EXPECT_EQ(backend_->commands.back(), "goTo 0.50 0.00 1.00");
  backend_->at({ 0.5, 0.0, 1.0 }, false);
  tick();
  EXPECT_TRUE(goal->end.empty()) << "on target and at rest is no end for a tracking goal";
  EXPECT_TRUE(supervisor_.steer("track_frame", "track", velocity(0.4), { 0.6, 0.0, 1.0 }));
  EXPECT_EQ(backend_->commands.back(), "moveAtVelocity 0.40 0.00 0.00");
  EXPECT_EQ(supervisor_.mode(), GoalMode::VELOCITY);
  tick();
  EXPECT_NEAR(goal->feedback.back()[PAN], 0.1, 1e-9);
}

TEST_F(TrackingSupervisorTest, AnAimOutsideTheLimitsIsClampedNotRejected)
{
  const auto goal = submitTrack(5.0);
  ASSERT_TRUE(goal->accepted);
  EXPECT_EQ(goal->accept_text, "");
  EXPECT_EQ(backend_->commands.back(), "goTo 3.14 0.00 1.00");
}

TEST_F(TrackingSupervisorTest, SteeringAGoalThatEndedCommandsNothing)
{
  const auto track = submitTrack(0.5);
  const auto next = submit(positionGoal(0.0, 0.0, 1.0), "next");
  EXPECT_EQ(track->end, "PREEMPTED: preempted by a new position_abs goal");
  const std::size_t commands = backend_->commands.size();
  EXPECT_FALSE(supervisor_.steer("track_frame", "track", velocity(0.4), { 0.6, 0.0, 1.0 }));
  EXPECT_EQ(backend_->commands.size(), commands);
}

TEST_F(TrackingSupervisorTest, ACancelledTrackingGoalIsNotSteeredWhileItStops)
{
  const auto goal = submitTrack(0.5);
  backend_->at({ 0.2, 0.0, 1.0 }, true);
  supervisor_.cancel("track_frame", "track");
  EXPECT_EQ(backend_->commands.back(), "stop");
  EXPECT_FALSE(supervisor_.steer("track_frame", "track", velocity(0.4), { 0.6, 0.0, 1.0 }));
  EXPECT_EQ(backend_->commands.back(), "stop");
  backend_->at({ 0.2, 0.0, 1.0 }, false);
  tick();
  EXPECT_EQ(goal->end.rfind("PREEMPTED: cancelled", 0), 0u) << goal->end;
}

TEST_F(TrackingSupervisorTest, AbortStopsTheDeviceWithTheReason)
{
  const auto goal = submitTrack(0.5);
  supervisor_.abort("track_frame", "other", "not this one");
  EXPECT_TRUE(goal->end.empty());
  supervisor_.abort("track_frame", "track", "frame 'target' has not been updated in tf for 1.0 s");
  EXPECT_EQ(backend_->commands.back(), "stop");
  EXPECT_EQ(goal->end, "ABORTED: frame 'target' has not been updated in tf for 1.0 s");
  EXPECT_FALSE(supervisor_.goalActive());
}

TEST_F(TrackingSupervisorTest, ALostLinkAbortsATrackingGoal)
{
  const auto goal = submitTrack(0.5);
  backend_->state.link_up = false;
  backend_->last_link_loss = "connection closed";
  tick();
  EXPECT_EQ(goal->end, "ABORTED: link lost: connection closed");
}

}  // namespace

TEST_F(FrameTrackerTest, TheZoomIsAimedAsValidationCommandsIt)
{
  // A pan-tilt unit ignores the goal's zoom: its aim holds the zoom it reports.
  Capabilities unit = limits;
  unit.axes[ZOOM] = absentAxis("a FLIR PTU has no zoom");
  FrameTracker ignored(kinematics, unit, FrameTrackerConfig(), 2.0);
  ignored.observe(onCircle(kinematics, 0.2), 1.0, clock.now());
  EXPECT_DOUBLE_EQ(ignored.aimAt(1.0, 0.0)[ZOOM], 1.0);
  // A zoom the node cannot position: zoom 0 leaves it alone (NaN, and no speed on it), zoom 1 is its widest view
  // where it can go there.
  Capabilities blind = limits;
  blind.axes[ZOOM].absolute = false;
  blind.axes[ZOOM].feedback = false;
  FrameTracker left_alone(kinematics, blind, FrameTrackerConfig(), 0.0);
  left_alone.observe(onCircle(kinematics, 0.2), 1.0, clock.now());
  AxisValues aim;
  const GoalCommand command = left_alone.command(at(0.0, 0.0), 1.0, aim);
  EXPECT_TRUE(std::isnan(aim[ZOOM]));
  EXPECT_EQ(command.values[ZOOM], 0.0);
  EXPECT_GT(command.values[PAN], 0.0);
  blind.axes[ZOOM].widest_view = true;
  FrameTracker widest(kinematics, blind, FrameTrackerConfig(), 1.0);
  widest.observe(onCircle(kinematics, 0.2), 1.0, clock.now());
  EXPECT_DOUBLE_EQ(widest.aimAt(1.0, 0.0)[ZOOM], 1.0);
}

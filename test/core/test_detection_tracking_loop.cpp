// The detection tracker in a closed loop: the simulated device moves as commanded, its poses go into a pose history,
// a "detector" finds the target in images taken at those poses and answers a latency later, and the tracker steers.
#include <cmath>
#include <deque>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "detection_tracker_test_support.h"
#include "ptz_action_server/core/limits.h"
#include "ptz_action_server/core/motion/detection_tracker.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

using namespace ptz_action_server;
using namespace detection_tracker_test;

namespace
{
constexpr double LOOP_STEP = 0.01;  ///< s of the loop's clock per iteration
constexpr int STATE_EVERY = 2;      ///< iterations between the node's state samples (20 ms: a backend's reports)
constexpr int IMAGE_EVERY = 10;     ///< between images (10 Hz, as the sim's camera)
constexpr int COMMAND_EVERY = 5;    ///< between tracking steps (20 Hz: track/rate)

/// Where the target is at a time (s): a point in the base frame, and its angular radius.
using TargetPath = std::function<Eigen::Vector3d(double)>;

/// What a run saw after its settling time.
struct RunFigures
{
  double max_error = 0.0;       ///< rad between the optical axis and the target, at the commands
  double mean_pan_speed = 0.0;  ///< rad/s, the device's: how far it panned over how long
  double last_fill = 0.0;       ///< the last image's box, larger side over the image's
  double last_zoom = 0.0;
  TrackingStep last_step;
  int lost_steps = 0;
};

class DetectionTrackingLoopTest : public ::testing::Test
{
protected:
  DetectionTrackingLoopTest()
    : kinematics(pixel_aim_test::shippedKinematics())
    , limits(intersectLimits(SimDeviceConfig::defaults().capabilities(), urdfLimits(kinematics)).limits)
    , camera(simCamera())
    , model(SimDeviceConfig::defaults(), clock.now())
  {
  }

  DetectionTracker make(const DetectionTrackerConfig& config)
  {
    return DetectionTracker(kinematics, limits, camera, config, clock.now());
  }

  /// Runs the loop from time \p from to \p to (s), the detector answering \p latency s after each image; figures from
  /// \p settled on. \p tracker null: the camera moves as it was told, its poses recorded. \p current_pose: each
  /// detection is seen from the camera's pose when it arrives, not from the pose history.
  RunFigures run(DetectionTracker* tracker, double from, double to, const TargetPath& target, double latency,
                 double settled, double radius = 0.01, bool current_pose = false)
  {
    RunFigures figures;
    double settled_pan = NAN;
    double settled_at = 0.0;
    const int first = static_cast<int>(std::lround(from / LOOP_STEP));
    const int last = static_cast<int>(std::lround(to / LOOP_STEP));
    for (int iteration = first; iteration <= last; ++iteration)
    {
      const double t = iteration * LOOP_STEP;
      const PtzSample sample = model.sample(clock.now());
      if (iteration % STATE_EVERY == 0)
      {
        history.add(stampAt(t), sample.position);
      }
      if (iteration % IMAGE_EVERY == 0)
      {
        ImageDetections image = imageOf(stampAt(t), {});
        ImageDetection detection;
        detection.id = "target";
        detection.score = 1.0;
        if (detect(kinematics, sample.position, target(t), radius, detection))
        {
          image.detections.push_back(detection);
          figures.last_fill = std::max(detection.width / WIDTH, detection.height / HEIGHT);
        }
        pending_.push_back({ t + latency - 1e-9, image });
      }
      while (tracker != nullptr && !pending_.empty() && pending_.front().due <= t)
      {
        if (current_pose)
        {
          PoseHistoryConfig naive_config;
          naive_config.capacity = 2;
          PoseHistory naive(naive_config);
          naive.add(pending_.front().image.stamp, sample.position);
          tracker->observe(pending_.front().image, naive, clock.now());
        }
        else
        {
          tracker->observe(pending_.front().image, history, clock.now());
        }
        pending_.pop_front();
      }
      if (tracker != nullptr && iteration % COMMAND_EVERY == 0)
      {
        figures.last_step = tracker->step(sample, stampAt(t), clock.now());
        const TrackingStep& step = figures.last_step;
        if (step.state == TrackingState::TRACKING && step.command.velocity)
        {
          model.moveAtVelocity(step.command.values, clock.now());
        }
        else if (step.state == TrackingState::TRACKING)
        {
          model.goTo(step.command.values, clock.now());
        }
        figures.lost_steps += step.state == TrackingState::LOST ? 1 : 0;
        if (t >= settled)
        {
          figures.max_error = std::max(figures.max_error, offAxis(kinematics, sample.position, target(t)));
          if (std::isnan(settled_pan))
          {
            settled_pan = sample.position[PAN];
            settled_at = t;
          }
          else
          {
            figures.mean_pan_speed = (sample.position[PAN] - settled_pan) / (t - settled_at);
          }
        }
      }
      figures.last_zoom = sample.position[ZOOM];
      clock.advance(LOOP_STEP);
    }
    return figures;
  }

  struct Pending
  {
    double due;
    ImageDetections image;
  };

  PtzKinematics kinematics;
  Capabilities limits;
  PixelCamera camera;
  ManualClock clock;
  SimDeviceModel model;
  PoseHistory history;
  std::deque<Pending> pending_;
};

/// A target 50 m away moving at \p rate rad/s in azimuth from \p azimuth, at \p elevation.
TargetPath movingTarget(double azimuth, double rate, double elevation)
{
  return [=](double t) { return pointAt(azimuth + rate * t, elevation); };
}

TEST_F(DetectionTrackingLoopTest, AStillTargetIsCentredThoughTheImagesWereTakenWhileTheCameraPannedAway)
{
  const TargetPath target = movingTarget(0.15, 0.0, 0.05);
  // The camera pans left at 0.6 rad/s when the goal starts, and the first images are of that motion.
  model.moveAtVelocity({ -0.6, 0.0, 0.0 }, clock.now());
  run(nullptr, 0.0, 0.5, target, 0.15, 10.0);
  ASSERT_LT(model.sample(clock.now()).position[PAN], -0.15);
  DetectionTrackerConfig config;
  DetectionTracker tracker = make(config);
  const RunFigures figures = run(&tracker, 0.51, 4.0, target, 0.15, 2.5);
  EXPECT_EQ(figures.last_step.state, TrackingState::TRACKING);
  EXPECT_LT(figures.max_error, 0.002) << "within about a pixel from 2.5 s on";
  EXPECT_LT(std::abs(figures.mean_pan_speed), 0.01) << "at rest on the target";
  EXPECT_EQ(tracker.counts().dropped, 0u);
  EXPECT_EQ(tracker.counts().used, tracker.counts().images) << "every image held the target";
}

TEST_F(DetectionTrackingLoopTest, AMovingTargetIsFollowedAtItsRateAndKeptNearTheCentre)
{
  const TargetPath target = movingTarget(-0.3, 0.4, 0.1);
  run(nullptr, 0.0, 0.3, target, 0.15, 10.0);
  DetectionTrackerConfig config;
  DetectionTracker tracker = make(config);
  const RunFigures figures = run(&tracker, 0.31, 6.0, target, 0.15, 3.0);
  EXPECT_EQ(figures.lost_steps, 0);
  EXPECT_LT(figures.max_error, 0.003) << "within about 2 px of the centre from 3 s on";
  EXPECT_NEAR(figures.mean_pan_speed, 0.4, 0.01) << "at the target's own rate";
  EXPECT_NEAR(figures.last_step.command.values[PAN], 0.4, 0.05);
  EXPECT_GT(figures.last_step.feedback.detection_age, 0.15 - 1e-6) << "the detector's latency";
}

TEST_F(DetectionTrackingLoopTest, SeenFromWhereTheCameraIsInsteadOfWhereItWasTheSameLoopSwings)
{
  // The same target, each detection taken as if its image showed the camera's pose when it arrives: the 0.15 to
  // 0.25 s of the detector's latency inside the loop make the camera swing from side to side at full speed.
  const TargetPath target = movingTarget(-0.3, 0.4, 0.1);
  run(nullptr, 0.0, 0.3, target, 0.15, 10.0);
  DetectionTracker tracker = make(DetectionTrackerConfig());
  const RunFigures figures = run(&tracker, 0.31, 6.0, target, 0.15, 3.0, 0.01, true);
  EXPECT_GT(figures.max_error, 0.1) << "where the pose history keeps it within 0.003 rad";
}

TEST_F(DetectionTrackingLoopTest, ADeviceWithoutVelocitiesFollowsByPositions)
{
  for (const Axis axis : { PAN, TILT })
  {
    limits.axes[axis].velocity = false;
  }
  const TargetPath target = movingTarget(0.2, -0.2, -0.1);
  run(nullptr, 0.0, 0.3, target, 0.1, 10.0);
  DetectionTracker tracker = make(DetectionTrackerConfig());
  ASSERT_FALSE(tracker.velocityCommands());
  const RunFigures figures = run(&tracker, 0.31, 6.0, target, 0.1, 3.0);
  EXPECT_FALSE(figures.last_step.command.velocity);
  EXPECT_LT(figures.max_error, 0.02);
  EXPECT_NEAR(figures.mean_pan_speed, -0.2, 0.02);
}

TEST_F(DetectionTrackingLoopTest, TheZoomHoldsTheBoxAtTheFractionOfTheView)
{
  // A ball of 0.02 rad radius: 22 px across at zoom 1, 3.5 % of the image's width.
  const TargetPath target = movingTarget(0.1, 0.05, 0.05);
  run(nullptr, 0.0, 0.3, target, 0.15, 10.0, 0.02);
  DetectionTrackerConfig config;
  config.zoom_fraction = 0.3;
  DetectionTracker tracker = make(config);
  const RunFigures figures = run(&tracker, 0.31, 8.0, target, 0.15, 6.0, 0.02);
  EXPECT_GT(figures.last_zoom, 3.5) << "the box's height spans 0.3 of the image's at zoom 4.9";
  EXPECT_NEAR(figures.last_fill, 0.3, 0.3 * DetectionTracker::ZOOM_BAND + 0.01) << "zoom " << figures.last_zoom;
  // The narrower view keeps it centred all the same: within 20 px at the zoom reached.
  EXPECT_LT(figures.max_error, 20.0 / viewAt(figures.last_zoom).fx);
  EXPECT_EQ(tracker.counts().dropped, 0u);
}

TEST_F(DetectionTrackingLoopTest, ATargetThatLeavesTheViewIsLostAfterTheTimeout)
{
  // The target jumps far behind the camera at 2 s: no more detections.
  const TargetPath target = [](double t) { return t < 2.0 ? pointAt(0.1, 0.0) : pointAt(3.0, 0.0); };
  DetectionTrackerConfig config;
  config.lost_timeout = 0.8;
  DetectionTracker tracker = make(config);
  const RunFigures before = run(&tracker, 0.0, 2.5, target, 0.1, 10.0);
  EXPECT_EQ(before.last_step.state, TrackingState::TRACKING);
  const RunFigures after = run(&tracker, 2.51, 3.5, target, 0.1, 10.0);
  ASSERT_EQ(after.last_step.state, TrackingState::LOST);
  EXPECT_NE(after.last_step.lost_reason.find("without a match"), std::string::npos) << after.last_step.lost_reason;
}

}  // namespace

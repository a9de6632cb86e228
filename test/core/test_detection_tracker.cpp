#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "detection_tracker_test_support.h"
#include "ptz_action_server/core/motion/detection_tracker.h"

using namespace ptz_action_server;
using namespace detection_tracker_test;

namespace
{
constexpr double CENTRE_U = (WIDTH - 1) / 2.0;
constexpr double CENTRE_V = (HEIGHT - 1) / 2.0;

class DetectionTrackerTest : public ::testing::Test
{
protected:
  DetectionTrackerTest()
    : kinematics(pixel_aim_test::shippedKinematics()), limits(pixel_aim_test::zoomCamera(24.0)), camera(simCamera())
  {
  }

  DetectionTracker make(const DetectionTrackerConfig& config)
  {
    return DetectionTracker(kinematics, limits, camera, config, clock.now());
  }
  static PtzSample at(double pan, double tilt, double zoom = 1.0)
  {
    PtzSample sample;
    sample.link_up = true;
    sample.position = { pan, tilt, zoom };
    return sample;
  }
  /// The camera still at \p pose from 0 to 2 s (header clock), a sample every 20 ms.
  void stillAt(const AxisValues& pose)
  {
    for (int step = 0; step <= 100; ++step)
    {
      history.add(stampAt(0.02 * step), pose);
    }
  }
  /// What the camera at \p pose sees of a target at \p azimuth, \p elevation: a box of \p id.
  ImageDetection seen(const AxisValues& pose, double azimuth, double elevation, const std::string& id = "target")
  {
    ImageDetection detection;
    detection.id = id;
    detection.score = 1.0;
    EXPECT_TRUE(detect(kinematics, pose, pointAt(azimuth, elevation), 0.01, detection));
    return detection;
  }

  PtzKinematics kinematics;
  Capabilities limits;
  PixelCamera camera;
  PoseHistory history;
  ManualClock clock;
};

TEST_F(DetectionTrackerTest, TheAimIsWhereTheTargetWasWhenItsImageWasTaken)
{
  // The camera pans at 0.5 rad/s; the detector sees an image of t = 0.6 s (pan 0.3) and answers at t = 0.8 (pan 0.4).
  for (int step = 0; step <= 50; ++step)
  {
    history.add(stampAt(0.02 * step), { 0.5 * 0.02 * step, 0.0, 1.0 });
  }
  DetectionTracker tracker = make(DetectionTrackerConfig());
  const ImageDetection detection = seen({ 0.3, 0.0, 1.0 }, 0.45, 0.02);
  EXPECT_EQ(tracker.observe(imageOf(stampAt(0.6), { detection }), history, clock.now()).use, DetectionUse::USED);
  const TrackingStep step = tracker.step(at(0.4, 0.0), stampAt(0.8), clock.now());
  ASSERT_EQ(step.state, TrackingState::TRACKING);
  double pan = 0.0;
  double tilt = 0.0;
  ASSERT_TRUE(kinematics.aimAt(pointAt(0.45, 0.02), pan, tilt));
  EXPECT_NEAR(step.aim[PAN], pan, 1e-3) << "seen from where the camera was (0.3), not where it is (0.4)";
  EXPECT_NEAR(step.aim[TILT], tilt, 1e-3);
  EXPECT_NEAR(step.feedback.pan_error, pan - 0.4, 1e-3);
  EXPECT_NEAR(step.feedback.detection_age, 0.2, 1e-6);
  EXPECT_NEAR(step.feedback.u_error, detection.u - CENTRE_U, 1e-9);
  EXPECT_NEAR(step.feedback.v_error, detection.v - CENTRE_V, 1e-9);
  EXPECT_GT(step.feedback.u_error, 50.0) << "0.15 rad right of the image's centre";
  EXPECT_EQ(step.feedback.target_id, "target");
  EXPECT_EQ(tracker.counts().used, 1u);
}

TEST_F(DetectionTrackerTest, TwoImagesGiveTheTargetsRateWhichTheCommandFeedsForward)
{
  stillAt({ 0.0, 0.0, 1.0 });
  DetectionTrackerConfig config;
  config.steering.gain = 4.0;
  DetectionTracker tracker = make(config);
  ASSERT_TRUE(tracker.velocityCommands());
  // The target moves right at 0.2 rad/s: 0.10 rad at t = 0.5 s, 0.14 at 0.7.
  tracker.observe(imageOf(stampAt(0.5), { seen({ 0.0, 0.0, 1.0 }, 0.10, 0.0) }), history, clock.now());
  tracker.observe(imageOf(stampAt(0.7), { seen({ 0.0, 0.0, 1.0 }, 0.14, 0.0) }), history, clock.now());
  const TrackingStep step = tracker.step(at(0.0, 0.0), stampAt(0.8), clock.now());
  ASSERT_EQ(step.state, TrackingState::TRACKING);
  ASSERT_TRUE(step.command.velocity);
  EXPECT_NEAR(step.aim[PAN], 0.16, 2e-3) << "carried forward to the command's moment";
  EXPECT_NEAR(step.command.values[PAN], 0.2 + 4.0 * step.aim[PAN], 0.01);
  EXPECT_NEAR(step.command.values[TILT], 4.0 * step.aim[TILT], 1e-4) << "the tilt moves little";
  EXPECT_EQ(step.command.values[ZOOM], 0.0) << "no zoom fraction: the zoom stays";
  EXPECT_EQ(step.aim[ZOOM], 1.0);
}

TEST_F(DetectionTrackerTest, DetectionsOfAnotherIdNeverMatchAndTheTargetIsLost)
{
  stillAt({ 0.0, 0.0, 1.0 });
  DetectionTrackerConfig config;
  config.target_id = "ball";
  config.lost_timeout = 1.0;
  DetectionTracker tracker = make(config);
  for (int image = 0; image < 10; ++image)
  {
    const ImageDetections detections = imageOf(stampAt(0.1 * image), { boxAt("person", 1.0, 300.0, 200.0) });
    EXPECT_EQ(tracker.observe(detections, history, clock.now()).use, DetectionUse::NO_MATCH);
    EXPECT_EQ(tracker.step(at(0.0, 0.0), stampAt(0.1 * image), clock.now()).state, TrackingState::WAITING);
    clock.advance(0.1);
  }
  clock.advance(0.05);
  const TrackingStep step = tracker.step(at(0.0, 0.0), stampAt(1.05), clock.now());
  ASSERT_EQ(step.state, TrackingState::LOST);
  EXPECT_NE(step.lost_reason.find("no detection of 'ball' matched for 1.05 s (lost_timeout 1.00 s)"), std::string::npos)
      << step.lost_reason;
  EXPECT_NE(step.lost_reason.find("10 images since: 10 without a match"), std::string::npos) << step.lost_reason;
  EXPECT_EQ(tracker.counts().no_match, 10u);
  EXPECT_EQ(tracker.counts().used, 0u);
}

TEST_F(DetectionTrackerTest, ATargetNotSeenForTheLostTimeoutIsLost)
{
  stillAt({ 0.0, 0.0, 1.0 });
  DetectionTrackerConfig config;
  config.lost_timeout = 0.5;
  DetectionTracker tracker = make(config);
  tracker.observe(imageOf(stampAt(0.1), { boxAt("a", 1.0, 330.0, 180.0) }), history, clock.now());
  clock.advance(0.45);
  EXPECT_EQ(tracker.step(at(0.0, 0.0), stampAt(0.55), clock.now()).state, TrackingState::TRACKING);
  clock.advance(0.1);
  const TrackingStep silent = tracker.step(at(0.0, 0.0), stampAt(0.65), clock.now());
  ASSERT_EQ(silent.state, TrackingState::LOST);
  EXPECT_NE(silent.lost_reason.find("lost: no detection matched for 0.55 s (lost_timeout 0.50 s); no detections "
                                    "arrived"),
            std::string::npos)
      << silent.lost_reason;
  EXPECT_EQ(silent.feedback.target_id, "a") << "the feedback still names the target lost";
  // Empty images since the last match are named.
  tracker.observe(imageOf(stampAt(0.7), {}), history, clock.now());
  tracker.observe(imageOf(stampAt(0.8), {}), history, clock.now());
  const TrackingStep empty = tracker.step(at(0.0, 0.0), stampAt(0.85), clock.now());
  EXPECT_NE(empty.lost_reason.find("2 images since: 2 without a match"), std::string::npos) << empty.lost_reason;
}

TEST_F(DetectionTrackerTest, DetectionsWithoutAPoseAreDroppedAndCounted)
{
  DetectionTracker tracker = make(DetectionTrackerConfig());
  const DetectionObservation none =
      tracker.observe(imageOf(stampAt(0.5), { boxAt("a", 1.0, 300.0, 200.0) }), history, clock.now());
  EXPECT_EQ(none.use, DetectionUse::DROPPED);
  EXPECT_NE(none.problem.find("the camera's pose when the image was taken is unknown"), std::string::npos)
      << none.problem;
  stillAt({ 0.0, 0.0, 1.0 });  // 0 to 2 s
  const DetectionObservation old =
      tracker.observe(imageOf(stampAt(-5.0), { boxAt("a", 1.0, 300.0, 200.0) }), history, clock.now());
  EXPECT_EQ(old.use, DetectionUse::DROPPED);
  EXPECT_NE(old.problem.find(history.at(stampAt(-5.0)).error), std::string::npos) << old.problem;
  EXPECT_EQ(tracker.observe(imageOf(stampAt(3.0), { boxAt("a", 1.0, 300.0, 200.0) }), history, clock.now()).use,
            DetectionUse::DROPPED)
      << "newer than the history by more than its tolerance";
  const DetectionObservation off_image =
      tracker.observe(imageOf(stampAt(1.0), { boxAt("a", 1.0, -40.0, 200.0) }), history, clock.now());
  EXPECT_EQ(off_image.use, DetectionUse::DROPPED);
  EXPECT_NE(off_image.problem.find("detection 'a' at (-40, 200) px: pixel (-40, 200) is not on the 640 x 360 px image"),
            std::string::npos)
      << off_image.problem;
  EXPECT_EQ(tracker.counts().dropped, 4u);
  EXPECT_EQ(tracker.step(at(0.0, 0.0), stampAt(1.0), clock.now()).state, TrackingState::WAITING);
  // A good box beside a bad one is used.
  EXPECT_EQ(tracker
                .observe(imageOf(stampAt(1.0), { boxAt("a", 1.0, -40.0, 200.0), boxAt("b", 0.1, 300.0, 200.0) }),
                         history, clock.now())
                .use,
            DetectionUse::USED);
  EXPECT_EQ(tracker.step(at(0.0, 0.0), stampAt(1.0), clock.now()).feedback.target_id, "b");
}

TEST_F(DetectionTrackerTest, AnImageNotNewerThanTheNewestUsedIsStale)
{
  stillAt({ 0.0, 0.0, 1.0 });
  DetectionTracker tracker = make(DetectionTrackerConfig());
  EXPECT_EQ(tracker.observe(imageOf(stampAt(1.0), { boxAt("a", 1.0, 330.0, 180.0) }), history, clock.now()).use,
            DetectionUse::USED);
  EXPECT_EQ(tracker.observe(imageOf(stampAt(0.9), { boxAt("a", 1.0, 100.0, 180.0) }), history, clock.now()).use,
            DetectionUse::STALE);
  EXPECT_EQ(tracker.observe(imageOf(stampAt(1.0), { boxAt("a", 1.0, 100.0, 180.0) }), history, clock.now()).use,
            DetectionUse::STALE);
  EXPECT_EQ(tracker.counts().stale, 2u);
  EXPECT_NEAR(tracker.step(at(0.0, 0.0), stampAt(1.0), clock.now()).feedback.u_error, 330.0 - CENTRE_U, 1e-9);
}

TEST_F(DetectionTrackerTest, TheBestScoreFirstThenTheOneNearestTheTarget)
{
  stillAt({ 0.0, 0.0, 1.0 });
  DetectionTracker tracker = make(DetectionTrackerConfig());
  tracker.observe(imageOf(stampAt(0.1), { boxAt("left", 0.9, 200.0, 180.0), boxAt("right", 0.5, 450.0, 180.0) }),
                  history, clock.now());
  EXPECT_EQ(tracker.step(at(0.0, 0.0), stampAt(0.1), clock.now()).feedback.target_id, "left");
  // The detector's ids and scores change; the target is the box where it was.
  tracker.observe(imageOf(stampAt(0.2), { boxAt("other", 0.99, 450.0, 180.0), boxAt("dim", 0.1, 205.0, 182.0) }),
                  history, clock.now());
  const TrackingStep step = tracker.step(at(0.0, 0.0), stampAt(0.2), clock.now());
  EXPECT_EQ(step.feedback.target_id, "dim");
  EXPECT_NEAR(step.feedback.u_error, 205.0 - CENTRE_U, 1e-9);
  EXPECT_LT(step.feedback.pan_error, -0.1) << "left of the centre";
}

TEST_F(DetectionTrackerTest, TheDeadZoneLeavesASmallErrorAloneAndCorrectsALargeOneToHalfOfIt)
{
  stillAt({ 0.0, 0.0, 1.0 });
  // A still target 0.1 rad right of pan 0: 0.174 of the half image off the centre.
  const ImageDetections image = imageOf(stampAt(0.5), { seen({ 0.0, 0.0, 1.0 }, 0.1, 0.0) });
  ASSERT_NEAR((image.detections[0].u - CENTRE_U) / (WIDTH / 2.0), 0.174, 0.002);
  DetectionTrackerConfig config;
  config.dead_zone = 0.2;
  DetectionTracker inside = make(config);
  inside.observe(image, history, clock.now());
  TrackingStep step = inside.step(at(0.0, 0.0), stampAt(0.6), clock.now());
  EXPECT_EQ(step.command.values[PAN], 0.0) << "within the dead zone, a still target needs no motion";
  EXPECT_GT(step.feedback.pan_error, 0.09) << "the error is still reported";

  config.dead_zone = 0.15;
  DetectionTracker tracker = make(config);
  tracker.observe(image, history, clock.now());
  EXPECT_GT(tracker.step(at(0.0, 0.0), stampAt(0.6), clock.now()).command.values[PAN], 0.1) << "outside: corrected";
  // Off by 0.121 of the half image (pan 0.03): inside the zone, but corrected until within half of it.
  EXPECT_GT(tracker.step(at(0.03, 0.0), stampAt(0.6), clock.now()).command.values[PAN], 0.1);
  // 0.052 (pan 0.07): within half of it, the correction stops, and stays stopped within the zone.
  EXPECT_EQ(tracker.step(at(0.07, 0.0), stampAt(0.6), clock.now()).command.values[PAN], 0.0);
  EXPECT_EQ(tracker.step(at(0.03, 0.0), stampAt(0.6), clock.now()).command.values[PAN], 0.0);
  EXPECT_GT(tracker.step(at(0.0, 0.0), stampAt(0.6), clock.now()).command.values[PAN], 0.1);

  config.dead_zone = 0.0;
  config.steering.gain = 3.0;
  DetectionTracker always = make(config);
  always.observe(image, history, clock.now());
  step = always.step(at(0.07, 0.0), stampAt(0.6), clock.now());
  EXPECT_NEAR(step.command.values[PAN], 3.0 * step.feedback.pan_error, 1e-9);
  EXPECT_GT(step.command.values[PAN], 0.05);
}

TEST_F(DetectionTrackerTest, TheSpeedLimitCapsVelocitiesAndPositionSteps)
{
  stillAt({ 0.0, 0.0, 1.0 });
  const ImageDetections image = imageOf(stampAt(0.5), { boxAt("a", 1.0, 600.0, 20.0) });
  DetectionTrackerConfig config;
  config.steering.gain = 50.0;
  DetectionTracker device_speed = make(config);
  device_speed.observe(image, history, clock.now());
  EXPECT_DOUBLE_EQ(device_speed.step(at(0.0, 0.0), stampAt(0.5), clock.now()).command.values[PAN],
                   limits.axes[PAN].max_speed);
  config.max_speed = 0.3;
  DetectionTracker limited = make(config);
  limited.observe(image, history, clock.now());
  const TrackingStep step = limited.step(at(0.0, 0.0), stampAt(0.5), clock.now());
  EXPECT_DOUBLE_EQ(step.command.values[PAN], 0.3);
  EXPECT_DOUBLE_EQ(step.command.values[TILT], 0.3);
  // A device that only goes to positions: each step aims at most a step's travel at that speed ahead.
  limits.axes[PAN].velocity = false;
  config.steering.rate = 20.0;
  DetectionTracker positions = make(config);
  ASSERT_FALSE(positions.velocityCommands());
  positions.observe(image, history, clock.now());
  const TrackingStep position_step = positions.step(at(0.1, 0.0), stampAt(0.5), clock.now());
  EXPECT_FALSE(position_step.command.velocity);
  EXPECT_NEAR(position_step.command.values[PAN], 0.1 + 0.3 / 20.0, 1e-12);
  EXPECT_GT(position_step.aim[PAN], 0.4) << "the aim is the target's, the step only goes part of the way";
}

TEST_F(DetectionTrackerTest, PositionCommandsWhereTheDeviceTakesNoVelocityOrTheNodeSaysSo)
{
  stillAt({ 0.0, 0.0, 1.0 });
  const ImageDetections image = imageOf(stampAt(0.5), { seen({ 0.0, 0.0, 1.0 }, 0.2, 0.1) });
  double pan = 0.0;
  double tilt = 0.0;
  ASSERT_TRUE(kinematics.aimAt(pointAt(0.2, 0.1), pan, tilt));
  DetectionTrackerConfig config;
  config.steering.feed_forward = false;
  DetectionTracker told = make(config);
  EXPECT_FALSE(told.velocityCommands());
  limits.axes[TILT].velocity = false;
  DetectionTracker no_velocity = make(DetectionTrackerConfig());
  EXPECT_FALSE(no_velocity.velocityCommands());
  for (DetectionTracker* tracker : { &told, &no_velocity })
  {
    tracker->observe(image, history, clock.now());
    const TrackingStep step = tracker->step(at(0.0, 0.0, 2.0), stampAt(0.5), clock.now());
    EXPECT_FALSE(step.command.velocity);
    EXPECT_NEAR(step.command.values[PAN], pan, 1e-3);
    EXPECT_NEAR(step.command.values[TILT], tilt, 1e-3);
    EXPECT_EQ(step.command.values[ZOOM], 2.0) << "the zoom left where it is";
  }
}

TEST_F(DetectionTrackerTest, ABadConfigIsNamed)
{
  DetectionTrackerConfig config;
  EXPECT_EQ(findBadTrackingConfig(config), "");
  config.zoom_fraction = 1.5;
  EXPECT_EQ(findBadTrackingConfig(config), "zoom_fraction 1.5 must be in (0, 1], or 0 to leave the zoom");
  EXPECT_THROW(make(config), ConfigError);
  config.zoom_fraction = 1.0;
  config.dead_zone = 1.0;
  EXPECT_EQ(findBadTrackingConfig(config), "dead_zone 1 must be in [0, 1): a part of the half image");
  config.dead_zone = 0.0;
  config.max_speed = -0.1;
  EXPECT_EQ(findBadTrackingConfig(config), "max_speed -0.1 rad/s must be positive, or 0 for the device's own");
  config.max_speed = 0.0;
  config.lost_timeout = 0.0;
  EXPECT_EQ(findBadTrackingConfig(config), "lost_timeout 0 s must be positive");
  config.lost_timeout = std::nan("");
  EXPECT_NE(findBadTrackingConfig(config), "");
}

}  // namespace

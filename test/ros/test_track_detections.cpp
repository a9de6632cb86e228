/**
 * \file
 * \brief rostest client of move_ptz/track_detections on the sim node (track_detections.test): a target the test moves
 * across the view, drawn by the simulated camera and found by the shipped ptz_blob_detector, is kept near the image
 * centre; once it is no longer drawn the goal ends "lost" and the camera goes to the lost preset. A detection of
 * another id is lost too (the camera holds); any other goal preempts tracking and tracking preempts it; bad goals are
 * refused with their reason.
 */
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include <tf2_ros/transform_broadcaster.h>

#include "camera_observer.h"
#include "node_test.h"
#include "ptz_action_server/PtzTrackDetectionsAction.h"

namespace track_detections_test
{
using ptz_action_server::centroidOf;
using ptz_action_server::PtzTrackDetectionsAction;
using ptz_action_server::PtzTrackDetectionsFeedback;
using ptz_action_server::PtzTrackDetectionsFeedbackConstPtr;
using ptz_action_server::PtzTrackDetectionsGoal;
using ptz_action_server::waitUntil;
using TrackClient = actionlib::SimpleActionClient<PtzTrackDetectionsAction>;

// track_detections.test lists this frame first (magenta, ptz_blob_detector's default colour).
const char* const TARGET = "track_detections_target";
constexpr std::uint8_t TARGET_COLOUR[3] = { 255, 0, 255 };
constexpr double START_PAN = -0.45;  // rad: where the target starts, the camera looking at it
constexpr double END_PAN = 0.45;     // rad: where it stops
constexpr double SPEED = 0.2;        // rad/s across the view (the sim's 60 degree view: 1.05 rad)
constexpr double ELEVATION = 0.1;    // rad, seen from the base's origin
constexpr double DISTANCE = 10.0;    // m
constexpr double CATCH_UP = 1.5;     // s after the target starts before its error counts
/// px from the image centre most images are within: 10 (0.018 rad at 1 X), or the test's ~pixel_error (position
/// commands trail a moving target by the device's own settling).
double pixelError()
{
  return ros::NodeHandle("~").param("pixel_error", 10.0);
}
constexpr double MOST = 0.8;          // the part of the images of the run that must be within pixelError()
constexpr double LOST_TIMEOUT = 1.0;  // s
constexpr double AT_HOME = 0.01;      // rad: config/sim.yaml's home is pan 0, tilt 0

/// Broadcasts TARGET at 50 Hz: still at START_PAN until start(), then at SPEED to END_PAN, where it stays until
/// hide() sends it 1 km below the camera, out of the picture.
class CrossingTarget
{
public:
  CrossingTarget() : thread_([this] { run(); })
  {
  }
  ~CrossingTarget()
  {
    running_ = false;
    thread_.join();
  }
  void start()
  {
    started_at_ = ros::Time::now().toSec();
  }
  void hide()
  {
    hidden_ = true;
  }
  /// The azimuth at \p now (s, ROS time).
  double panAt(double now) const
  {
    const double started_at = started_at_;
    return started_at == 0.0 ? START_PAN : std::min(END_PAN, START_PAN + SPEED * (now - started_at));
  }
  /// When it reached END_PAN (ROS time s), 0 while it has not.
  double arrivedAt() const
  {
    const double started_at = started_at_;
    const double arrival = started_at + (END_PAN - START_PAN) / SPEED;
    return started_at != 0.0 && ros::Time::now().toSec() >= arrival ? arrival : 0.0;
  }

private:
  void run()
  {
    tf2_ros::TransformBroadcaster broadcaster;
    geometry_msgs::TransformStamped transform;
    transform.header.frame_id = "ptz_base_link";
    transform.child_frame_id = TARGET;
    transform.transform.rotation.w = 1.0;
    ros::WallRate rate(50.0);
    while (running_ && ros::ok())
    {
      transform.header.stamp = ros::Time::now();
      const double pan = panAt(transform.header.stamp.toSec());
      transform.transform.translation.x = DISTANCE * std::cos(ELEVATION) * std::cos(pan);
      transform.transform.translation.y = -DISTANCE * std::cos(ELEVATION) * std::sin(pan);
      transform.transform.translation.z = hidden_ ? -1000.0 : DISTANCE * std::sin(ELEVATION);
      broadcaster.sendTransform(transform);
      rate.sleep();
    }
  }

  std::atomic<bool> running_{ true };
  std::atomic<bool> hidden_{ false };
  std::atomic<double> started_at_{ 0.0 };
  std::thread thread_;
};

/// Where the target is in each image: its centroid's distance from the image centre, or none.
class TargetInImages
{
public:
  struct Seen
  {
    double stamp = 0.0;  ///< s, the image's
    bool found = false;
    double error = 0.0;  ///< px
  };

  TargetInImages()
  {
    ros::NodeHandle node_handle;
    subscriber_ = node_handle.subscribe("image_raw", 5, &TargetInImages::onImage, this);
  }
  /// The images stamped within [\p from, \p to].
  std::vector<Seen> between(double from, double to) const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Seen> seen;
    std::copy_if(seen_.begin(), seen_.end(), std::back_inserter(seen),
                 [&](const Seen& image) { return image.stamp >= from && image.stamp <= to; });
    return seen;
  }

private:
  void onImage(const sensor_msgs::Image::ConstPtr& image)
  {
    Seen seen;
    seen.stamp = image->header.stamp.toSec();
    double u = 0.0;
    double v = 0.0;
    seen.found = centroidOf(*image, TARGET_COLOUR, u, v);
    seen.error = std::hypot(u - (image->width - 1) / 2.0, v - (image->height - 1) / 2.0);
    std::lock_guard<std::mutex> lock(mutex_);
    seen_.push_back(seen);
  }

  ros::Subscriber subscriber_;
  mutable std::mutex mutex_;
  std::vector<Seen> seen_;
};

PtzTrackDetectionsGoal trackGoal()
{
  PtzTrackDetectionsGoal goal;
  goal.detections_topic = "detections";
  goal.lost_timeout = LOST_TIMEOUT;
  return goal;
}

class TrackDetectionsTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    if (observer_ == nullptr)  // not yet set up by another suite in this run
    {
      NodeTest::SetUpTestSuite();
    }
    track_ = new TrackClient("move_ptz/track_detections", true);
    images_ = new TargetInImages();
    feedback_ = new FeedbackLog<PtzTrackDetectionsFeedback>();
  }
  void SetUp() override
  {
    NodeTest::SetUp();
    ASSERT_TRUE(track_->waitForServer(ros::Duration(30.0))) << "no move_ptz/track_detections";
  }
  /// Sends \p goal, recording its feedback.
  void send(const PtzTrackDetectionsGoal& goal)
  {
    {
      std::lock_guard<std::mutex> lock(feedback_->mutex);
      feedback_->items.clear();
    }
    track_->sendGoal(goal, TrackClient::SimpleDoneCallback(), TrackClient::SimpleActiveCallback(),
                     [](const PtzTrackDetectionsFeedbackConstPtr& feedback) { feedback_->add(*feedback); });
  }
  /// Waits for the first feedback: the target is being tracked.
  bool tracking()
  {
    return waitUntil([] { return !feedback_->all().empty(); }, GOAL_WAIT);
  }
  std::string outcome() const
  {
    const auto result = track_->getResult();
    return result ? result->outcome : std::string("(no result)");
  }

  static inline TrackClient* track_ = nullptr;
  static inline FeedbackLog<PtzTrackDetectionsFeedback>* feedback_ = nullptr;  ///< the latest goal's
  static inline TargetInImages* images_ = nullptr;
};

TEST_F(TrackDetectionsTest, ATargetCrossingTheViewIsKeptNearTheCentreThenLostAndTheCameraGoesToThePreset)
{
  ASSERT_EQ(moveTo(START_PAN, ELEVATION, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  CrossingTarget target;
  PtzTrackDetectionsGoal goal = trackGoal();
  goal.lost_preset = "home";
  send(goal);
  ASSERT_TRUE(tracking()) << track_->getState().toString() << ": " << outcome();
  target.start();
  const double started_at = ros::Time::now().toSec();
  ASSERT_TRUE(waitUntil([&] { return target.arrivedAt() != 0.0; }, GOAL_WAIT + (END_PAN - START_PAN) / SPEED));
  ASSERT_EQ(track_->getState(), State::ACTIVE) << outcome();
  EXPECT_GT(observer_->latest().pan, END_PAN - 0.1) << "the camera followed the target across";

  const std::vector<TargetInImages::Seen> seen = images_->between(started_at + CATCH_UP, target.arrivedAt());
  ASSERT_GE(seen.size(), 10u) << "images while the target crossed (10 Hz for "
                              << target.arrivedAt() - started_at - CATCH_UP << " s)";
  const double pixel_error = pixelError();
  const auto within = std::count_if(seen.begin(), seen.end(), [&](const TargetInImages::Seen& image) {
    return image.found && image.error < pixel_error;
  });
  std::vector<double> errors;
  for (const TargetInImages::Seen& image : seen)
  {
    errors.push_back(image.found ? image.error : INFINITY);
  }
  std::sort(errors.begin(), errors.end());
  std::printf("pixel error over %zu images: p50 %.1f px, p80 %.1f px, max %.1f px\n", errors.size(),
              errors[errors.size() / 2], errors[errors.size() * 4 / 5], errors.back());
  EXPECT_GE(static_cast<double>(within), MOST * seen.size())
      << within << " of " << seen.size() << " images show the target within " << pixel_error << " px of the centre";
  const std::vector<PtzTrackDetectionsFeedback> feedback = feedback_->all();
  ASSERT_FALSE(feedback.empty());
  EXPECT_EQ(feedback.back().target_id, "blob");
  EXPECT_GT(feedback.back().detection_age, 0.0) << "an image is older than its detections";
  EXPECT_LT(std::abs(feedback.back().pan_error), 0.2);

  target.hide();
  ASSERT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT + LOST_TIMEOUT)));
  EXPECT_EQ(track_->getState(), State::ABORTED) << outcome();
  EXPECT_EQ(outcome().rfind("lost: ", 0), 0u) << outcome();
  EXPECT_NE(outcome().find("at preset 'home'"), std::string::npos) << outcome();
  EXPECT_FALSE(track_->getResult()->success);
  ASSERT_TRUE(observer_->waitTicks(1));
  EXPECT_NEAR(observer_->latest().pan, 0.0, AT_HOME);
  EXPECT_NEAR(observer_->latest().tilt, 0.0, AT_HOME);
}

TEST_F(TrackDetectionsTest, DetectionsOfAnotherIdAreLostAndTheCameraHolds)
{
  ASSERT_EQ(moveTo(START_PAN, ELEVATION, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  CrossingTarget target;  // in the picture, but its id is "blob"
  PtzTrackDetectionsGoal goal = trackGoal();
  goal.target_id = "person";
  send(goal);
  ASSERT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT + LOST_TIMEOUT)));
  EXPECT_EQ(track_->getState(), State::ABORTED) << outcome();
  EXPECT_EQ(outcome().rfind("lost: ", 0), 0u) << outcome();
  EXPECT_NE(outcome().find("'person'"), std::string::npos) << outcome();
  EXPECT_TRUE(feedback_->all().empty()) << "nothing was tracked";
  ASSERT_TRUE(observer_->waitTicks(1));
  EXPECT_NEAR(observer_->latest().pan, START_PAN, TOLERANCE) << "the camera held where it was";
}

TEST_F(TrackDetectionsTest, TrackingPreemptsAnyGoalAndAnyGoalPreemptsTracking)
{
  PtzTrackDetectionsGoal goal = trackGoal();
  goal.lost_timeout = 60.0;  // no target: it waits for one until preempted
  velocity_->sendGoal(makePtzGoal(0.1, 0.0, 0.0));
  ASSERT_TRUE(waitUntil([] { return velocity_->getState() == State::ACTIVE; }, GOAL_WAIT));
  send(goal);
  ASSERT_TRUE(velocity_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(velocity_->getState(), State::PREEMPTED) << velocity_->getState().getText();
  ASSERT_TRUE(waitUntil([] { return track_->getState() == State::ACTIVE; }, GOAL_WAIT))
      << track_->getState().toString() << ": " << outcome();

  absolute_->sendGoal(makePtzGoal(0.2, 0.1, 1.0));
  ASSERT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(track_->getState(), State::PREEMPTED) << outcome();
  EXPECT_NE(outcome().find("preempted"), std::string::npos) << outcome();
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::SUCCEEDED) << absolute_->getState().getText();

  send(goal);
  ASSERT_TRUE(waitUntil([] { return track_->getState() == State::ACTIVE; }, GOAL_WAIT));
  track_->cancelGoal();
  ASSERT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(track_->getState(), State::PREEMPTED) << outcome();
  EXPECT_NE(outcome().find("cancelled"), std::string::npos) << outcome();
}

TEST_F(TrackDetectionsTest, BadGoalsAreRejectedWithTheirReason)
{
  const auto rejection = [&](const PtzTrackDetectionsGoal& goal) {
    send(goal);
    EXPECT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT)));
    EXPECT_EQ(track_->getState(), State::REJECTED) << outcome();
    return track_->getState().getText();
  };
  PtzTrackDetectionsGoal goal = trackGoal();
  goal.detections_topic = "";
  EXPECT_NE(rejection(goal).find("detections_topic"), std::string::npos);
  goal = trackGoal();
  goal.detections_topic = "not a topic";
  EXPECT_NE(rejection(goal).find("not a topic name"), std::string::npos);
  goal = trackGoal();
  goal.zoom_fraction = 2.0;
  EXPECT_NE(rejection(goal).find("zoom_fraction"), std::string::npos);
  goal = trackGoal();
  goal.lost_preset = "nowhere";
  EXPECT_NE(rejection(goal).find("no preset named 'nowhere'"), std::string::npos);
}

}  // namespace track_detections_test

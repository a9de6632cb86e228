/**
 * \file
 * \brief move_ptz/track_frame against the sim node: a frame the test moves around the camera is followed, the goal
 * goes on until cancelled or preempted, and a frame that stops updating aborts it.
 */
#include <thread>

#include <tf2_ros/transform_broadcaster.h>

#include "node_test.h"

namespace
{
using TrackClient = actionlib::SimpleActionClient<PtzFrameAction>;

constexpr double CIRCLE_RATE = 0.5;  ///< rad/s
constexpr double RADIUS = 3.0;       ///< m

/// Publishes "test_moving" at 50 Hz, circling the pan axis at camera height from pan -1 rad at 0.5 rad/s.
class CirclingFrame
{
public:
  CirclingFrame() : thread_([this] { run(); })
  {
  }
  ~CirclingFrame()
  {
    stop();
  }
  void stop()
  {
    running_ = false;
    if (thread_.joinable())
    {
      thread_.join();
    }
  }

private:
  void run()
  {
    tf2_ros::TransformBroadcaster broadcaster;
    geometry_msgs::TransformStamped transform;
    transform.header.frame_id = "ptz_base_link";
    transform.child_frame_id = "test_moving";
    transform.transform.rotation.w = 1.0;
    transform.transform.translation.z = 0.17;  // about the optical axis's height at tilt 0
    const ros::Time start = ros::Time::now();
    ros::Rate rate(50.0);
    while (running_ && ros::ok())
    {
      const ros::Time now = ros::Time::now();
      const double pan = -1.0 + CIRCLE_RATE * (now - start).toSec();  // clockwise seen from above
      transform.header.stamp = now;
      transform.transform.translation.x = RADIUS * std::cos(pan);
      transform.transform.translation.y = -RADIUS * std::sin(pan);
      broadcaster.sendTransform(transform);
      rate.sleep();
    }
  }

  std::atomic<bool> running_{ true };
  std::thread thread_;
};

/// The angle between the optical axis and the direction to test_moving, both at their latest common time in tf.
bool trackingError(tf2_ros::Buffer& buffer, double& error)
{
  try
  {
    const auto target = buffer.lookupTransform("ptz_camera_link", "test_moving", ros::Time(0));
    const Eigen::Vector3d in_camera = tf2::transformToEigen(target).translation();
    error = std::atan2(std::hypot(in_camera.y(), in_camera.z()), in_camera.x());
    return true;
  }
  catch (const tf2::TransformException&)
  {
    return false;
  }
}

PtzFrameGoal trackGoal()
{
  PtzFrameGoal goal;
  goal.frame_id = "test_moving";
  goal.zoom = 1.0;
  return goal;
}

class TrackFrameTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    NodeTest::SetUpTestSuite();
    track_ = new TrackClient("move_ptz/track_frame", true);
  }
  void SetUp() override
  {
    NodeTest::SetUp();
    ASSERT_TRUE(track_->waitForServer(ros::Duration(30.0)));
  }
  /// Sends the track goal until the node's tf listener knows the frame (it rejects the goal before that).
  void startTracking()
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
    do
    {
      track_->sendGoal(trackGoal());
      track_->waitForResult(ros::Duration(0.5));
    } while (track_->getState() == State::REJECTED && ros::WallTime::now() < deadline &&
             ros::WallDuration(0.05).sleep());
    ASSERT_TRUE(track_->getState() == State::ACTIVE || track_->getState() == State::PENDING)
        << track_->getState().toString() << ": " << track_->getState().getText();
  }
  static inline TrackClient* track_ = nullptr;
};

TEST_F(TrackFrameTest, AFrameMovingAroundTheCameraIsFollowedUntilCancelled)
{
  moveTo(-1.0, 0.0, 1.0);
  CirclingFrame frame;
  startTracking();
  // Two seconds to catch up, then the error at each state tick for three seconds.
  ASSERT_TRUE(observer_->waitTicks(20));
  std::vector<double> errors;
  for (int tick = 0; tick < 30; ++tick)
  {
    ASSERT_TRUE(observer_->waitTicks(1));
    double error = 0.0;
    if (trackingError(*tf_buffer_, error))
    {
      errors.push_back(error);
    }
  }
  ASSERT_GE(errors.size(), 20u);
  std::sort(errors.begin(), errors.end());
  EXPECT_LT(errors[errors.size() / 2], 0.03) << "median angular error";
  EXPECT_LT(errors.back(), 0.15) << "largest angular error";
  EXPECT_GT(observer_->latest().pan, 0.0) << "the frame went round from -1 rad; so did the camera";
  EXPECT_EQ(track_->getState(), State::ACTIVE) << "a tracking goal goes on until cancelled";

  track_->cancelGoal();
  ASSERT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(track_->getState(), State::PREEMPTED) << track_->getState().getText();
}

TEST_F(TrackFrameTest, AnotherGoalPreemptsTracking)
{
  CirclingFrame frame;
  startTracking();
  ASSERT_TRUE(observer_->waitTicks(3));
  absolute_->sendGoal(makePtzGoal(0.2, 0.1, 1.0));
  ASSERT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(track_->getState(), State::PREEMPTED) << track_->getState().getText();
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::SUCCEEDED) << absolute_->getState().getText();
}

TEST_F(TrackFrameTest, AFrameThatStopsUpdatingAbortsTheGoalWithTheReason)
{
  CirclingFrame frame;
  startTracking();
  ASSERT_TRUE(observer_->waitTicks(3));
  frame.stop();
  // track_timeout is 1 s by default.
  ASSERT_TRUE(track_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(track_->getState(), State::ABORTED);
  EXPECT_NE(track_->getState().getText().find("'test_moving' has not been updated in tf"), std::string::npos)
      << track_->getState().getText();
}

}  // namespace

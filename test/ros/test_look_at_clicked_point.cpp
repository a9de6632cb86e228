/**
 * \file
 * \brief "Look here" against the sim node: points on /clicked_point aim the optical axis at them while the
 * look_at_clicked_point switch is on, through the same goal supervision as the actions; nothing moves while it is off.
 */
#include <geometry_msgs/PointStamped.h>
#include <std_msgs/Bool.h>
#include <std_srvs/SetBool.h>

#include "node_test.h"

namespace
{
constexpr double AIM_TOLERANCE = 0.012;  ///< rad between the optical axis and the point: two axes' tolerance

geometry_msgs::PointStamped makePoint(const std::string& frame, double x, double y, double z)
{
  geometry_msgs::PointStamped point;
  point.header.frame_id = frame;
  point.header.stamp = ros::Time::now();
  point.point.x = x;
  point.point.y = y;
  point.point.z = z;
  return point;
}

/// The angle between the optical axis and the direction to \p point, from tf; false if tf cannot say yet.
bool aimError(tf2_ros::Buffer& buffer, const geometry_msgs::PointStamped& point, double& error)
{
  try
  {
    const auto transform = buffer.lookupTransform("ptz_camera_link", point.header.frame_id, ros::Time(0));
    const Eigen::Vector3d in_camera =
        tf2::transformToEigen(transform) * Eigen::Vector3d(point.point.x, point.point.y, point.point.z);
    error = std::atan2(std::hypot(in_camera.y(), in_camera.z()), in_camera.x());
    return true;
  }
  catch (const tf2::TransformException&)
  {
    return false;
  }
}
}  // namespace

class LookAtClickedPointTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    NodeTest::SetUpTestSuite();
    ros::NodeHandle node_handle;
    point_publisher_ = new ros::Publisher(node_handle.advertise<geometry_msgs::PointStamped>("/clicked_point", 10));
    enabled_subscriber_ = new ros::Subscriber(
        node_handle.subscribe("look_at_clicked_point/enabled", 10, &LookAtClickedPointTest::onEnabled));
  }

  static void onEnabled(const std_msgs::Bool::ConstPtr& message)
  {
    enabled_ = message->data ? 1 : 0;
  }

  /// Waits until the latched look_at_clicked_point/enabled says \p value.
  static bool enabledIs(bool value)
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
    while (ros::WallTime::now() < deadline)
    {
      if (enabled_ == (value ? 1 : 0))
      {
        return true;
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }

  static bool setSwitch(bool value)
  {
    std_srvs::SetBool service;
    service.request.data = value;
    return ros::service::waitForService("look_at_clicked_point", ros::Duration(10.0)) &&
           ros::service::call("look_at_clicked_point", service) && service.response.success;
  }

  /// Switches on and waits until the node has subscribed to the clicked points.
  static void switchOn()
  {
    ASSERT_TRUE(setSwitch(true));
    ASSERT_TRUE(enabledIs(true));
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
    while (point_publisher_->getNumSubscribers() == 0 && ros::WallTime::now() < deadline)
    {
      ros::WallDuration(0.01).sleep();
    }
    ASSERT_GT(point_publisher_->getNumSubscribers(), 0u) << "the node did not subscribe to /clicked_point";
  }

  /// Publishes \p point once per state tick for \p ticks ticks and expects the camera idle and still all along.
  void expectNothingMoves(const geometry_msgs::PointStamped& point, std::size_t ticks)
  {
    ASSERT_TRUE(observer_->waitTicks(1));
    const PtzState before = observer_->latest();
    observer_->clear();
    for (std::size_t tick = 0; tick < ticks; ++tick)
    {
      point_publisher_->publish(point);
      ASSERT_TRUE(observer_->waitTicks(1));
    }
    for (const PtzState& state : observer_->states())
    {
      EXPECT_EQ(state.mode, PtzState::MODE_IDLE);
      EXPECT_NEAR(state.pan, before.pan, 1e-4);
      EXPECT_NEAR(state.tilt, before.tilt, 1e-4);
    }
  }

  /// Publishes \p point, then waits until the camera rests aiming at it, having moved (mode POSITION) on the way.
  void expectAimedAt(const geometry_msgs::PointStamped& point)
  {
    observer_->clear();
    point_publisher_->publish(point);
    double error = M_PI;
    const bool aimed = observer_->waitFor(
        [&](const PtzState& state) {
          return state.mode == PtzState::MODE_IDLE && aimError(*tf_buffer_, point, error) && error < AIM_TOLERANCE;
        },
        GOAL_WAIT);
    EXPECT_TRUE(aimed) << "aim error " << error << " rad";
    bool moved = false;
    for (const PtzState& state : observer_->states())
    {
      moved = moved || state.mode == PtzState::MODE_POSITION;
    }
    EXPECT_TRUE(moved) << "ptz_state never showed the clicked point's goal";
  }

  static inline ros::Publisher* point_publisher_ = nullptr;
  static inline ros::Subscriber* enabled_subscriber_ = nullptr;
  static inline std::atomic<int> enabled_{ -1 };
};

TEST_F(LookAtClickedPointTest, OffAtStartAndAPointMovesNothing)
{
  EXPECT_TRUE(enabledIs(false)) << "the latched topic should say off (~look_at_clicked_point defaults to false)";
  ASSERT_EQ(moveTo(0.0, 0.0, zoomOr1(1.0)), State::SUCCEEDED);
  expectNothingMoves(makePoint("ptz_base_link", 2.0, 2.0, 0.0), 5);
}

TEST_F(LookAtClickedPointTest, APointInTheBaseFrameAimsTheOpticalAxisAtIt)
{
  switchOn();
  ASSERT_EQ(moveTo(0.0, 0.0, zoomOr1(2.0)), State::SUCCEEDED);
  expectAimedAt(makePoint("ptz_base_link", 3.0, -1.0, 0.8));
  EXPECT_NEAR(observer_->latest().zoom, zoomOr1(2.0), 0.06) << "the zoom stays where it was";
}

TEST_F(LookAtClickedPointTest, APointInAnotherFrameAimsFromThatFrame)
{
  switchOn();
  ASSERT_EQ(moveTo(0.0, 0.0, zoomOr1(1.0)), State::SUCCEEDED);
  // test_rotated is turned 0.3 rad about the base's z: the point is at a pan the base frame's numbers would not give.
  expectAimedAt(makePoint("test_rotated", 2.0, 1.5, -0.4));
}

TEST_F(LookAtClickedPointTest, AnUnknownFrameOrAPointAtTheCameraMovesNothing)
{
  switchOn();
  ASSERT_EQ(moveTo(0.3, 0.0, zoomOr1(1.0)), State::SUCCEEDED);
  // The unknown frame waits frame_wait (1 s) for tf, then is refused: 15 ticks cover it.
  expectNothingMoves(makePoint("no_such_frame", 1.0, 0.0, 0.0), 15);
  expectNothingMoves(makePoint("ptz_camera_link", 0.0, 0.0, 0.0), 3);
}

TEST_F(LookAtClickedPointTest, APointPreemptsAnActionGoalAndAnActionGoalPreemptsIt)
{
  switchOn();
  ASSERT_EQ(moveTo(0.0, 0.0, zoomOr1(1.0)), State::SUCCEEDED);
  velocity_->sendGoal(makePtzGoal(0.2, 0.0, 0.0));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.mode == PtzState::MODE_VELOCITY; }, 10.0));
  // Far round to the other side: it takes long enough for the action goal below to come while it runs.
  point_publisher_->publish(makePoint("ptz_base_link", -3.0, 1.0, 0.0));
  ASSERT_TRUE(velocity_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(velocity_->getState(), State::PREEMPTED);
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.mode == PtzState::MODE_POSITION; }, 10.0));
  ASSERT_EQ(moveTo(-0.5, 0.1, zoomOr1(1.0)), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(3));
  EXPECT_EQ(observer_->latest().mode, PtzState::MODE_IDLE);
  EXPECT_NEAR(observer_->latest().pan, -0.5, TOLERANCE) << "the clicked point's goal came back after the preempt";
}

TEST_F(LookAtClickedPointTest, TheServiceTurnsItOffAgain)
{
  switchOn();
  ASSERT_TRUE(setSwitch(false));
  ASSERT_TRUE(enabledIs(false));
  ASSERT_EQ(moveTo(0.0, 0.0, zoomOr1(1.0)), State::SUCCEEDED);
  expectNothingMoves(makePoint("ptz_base_link", 2.0, 2.0, 0.0), 5);
}

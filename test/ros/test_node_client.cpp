/**
 * \file
 * \brief rostest client: drives the running node through its actions and checks what a user would see.
 *
 * Runs in the node's namespace against whichever backend the .test file started. Tests wait on conditions with
 * deadlines, never on bare sleeps, except where a test must show that nothing happens for a while.
 */
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_eigen/tf2_eigen.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/ros/ptz_goal.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzRelToAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/SetSimFaults.h"

using ptz_action_server::makePtzGoal;
using ptz_action_server::PtzAction;
using ptz_action_server::PtzFeedbackConstPtr;
using ptz_action_server::PtzFrameAction;
using ptz_action_server::PtzFrameGoal;
using ptz_action_server::PtzGoal;
using ptz_action_server::PtzRelToAction;
using ptz_action_server::PtzRelToGoal;
using ptz_action_server::PtzState;
using State = actionlib::SimpleClientGoalState;
using PtzClient = actionlib::SimpleActionClient<PtzAction>;

namespace
{
constexpr double TOLERANCE = 0.006;  // rad: the node's 0.005 plus float32 rounding
constexpr double GOAL_WAIT = 20.0;   // s

/// Everything the node publishes that the tests look at.
class NodeObserver
{
public:
  NodeObserver()
  {
    state_subscriber_ = node_handle_.subscribe("ptz_state", 100, &NodeObserver::onState, this);
    joint_subscriber_ = node_handle_.subscribe("joint_states", 100, &NodeObserver::onJointState, this);
  }

  PtzState latest() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.empty() ? PtzState() : states_.back();
  }
  std::vector<PtzState> states() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_;
  }
  sensor_msgs::JointState latestJoints() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return joints_;
  }
  void clear()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    states_.clear();
  }
  /// Waits until \p predicate holds for a fresh state, or \p timeout passes.
  bool waitFor(const std::function<bool(const PtzState&)>& predicate, double timeout)
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
    std::size_t seen = count();
    while (ros::WallTime::now() < deadline)
    {
      if (count() > seen)
      {
        seen = count();
        if (predicate(latest()))
        {
          return true;
        }
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }
  /// Waits for \p ticks new states (the node publishes 10 a second).
  bool waitTicks(std::size_t ticks)
  {
    const std::size_t target = count() + ticks;
    return waitFor([&](const PtzState&) { return count() >= target; }, ticks * 0.1 + 2.0);
  }

private:
  std::size_t count() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return received_;
  }
  void onState(const PtzState::ConstPtr& state)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    states_.push_back(*state);
    ++received_;
  }
  void onJointState(const sensor_msgs::JointState::ConstPtr& joints)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    joints_ = *joints;
  }

  ros::NodeHandle node_handle_;
  ros::Subscriber state_subscriber_;
  ros::Subscriber joint_subscriber_;
  mutable std::mutex mutex_;
  std::vector<PtzState> states_;
  std::size_t received_ = 0;
  sensor_msgs::JointState joints_;
};

/// Records feedback of one goal.
template <class Feedback>
struct FeedbackLog
{
  std::mutex mutex;
  std::vector<Feedback> items;

  void add(const Feedback& feedback)
  {
    std::lock_guard<std::mutex> lock(mutex);
    items.push_back(feedback);
  }
  std::vector<Feedback> all()
  {
    std::lock_guard<std::mutex> lock(mutex);
    return items;
  }
};

class NodeTest : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    observer_ = new NodeObserver();
    absolute_ = new PtzClient("move_ptz/position_abs", true);
    second_absolute_ = new PtzClient("move_ptz/position_abs", true);
    relative_ = new PtzClient("move_ptz/position_rel", true);
    velocity_ = new PtzClient("move_ptz/velocity", true);
    relative_to_ = new actionlib::SimpleActionClient<PtzRelToAction>("move_ptz/position_abs_tf", true);
    frame_ = new actionlib::SimpleActionClient<PtzFrameAction>("move_ptz/frame", true);
    tf_buffer_ = new tf2_ros::Buffer();
    tf_listener_ = new tf2_ros::TransformListener(*tf_buffer_);
    broadcastTestFrames();
  }

  /// Static frames for the frame and position_abs_tf goals.
  static void broadcastTestFrames()
  {
    static tf2_ros::StaticTransformBroadcaster broadcaster;
    std::vector<geometry_msgs::TransformStamped> frames(2);
    frames[0].header.frame_id = "ptz_base_link";
    frames[0].child_frame_id = "test_target";
    frames[0].transform.translation.x = 2.0;
    frames[0].transform.translation.y = -2.0;
    frames[0].transform.translation.z = 0.5;
    frames[0].transform.rotation.w = 1.0;
    // A frame turned 0.3 rad counter-clockwise (REP-103 yaw) about the base's z axis.
    frames[1].header.frame_id = "ptz_base_link";
    frames[1].child_frame_id = "test_rotated";
    frames[1].transform.rotation.z = std::sin(0.15);
    frames[1].transform.rotation.w = std::cos(0.15);
    for (auto& frame : frames)
    {
      frame.header.stamp = ros::Time::now();
    }
    broadcaster.sendTransform(frames);
  }

  void SetUp() override
  {
    for (PtzClient* client : { absolute_, second_absolute_, relative_, velocity_ })
    {
      ASSERT_TRUE(client->waitForServer(ros::Duration(30.0))) << "no action server";
    }
    ASSERT_TRUE(relative_to_->waitForServer(ros::Duration(30.0)));
    ASSERT_TRUE(frame_->waitForServer(ros::Duration(30.0)));
    ASSERT_TRUE(observer_->waitTicks(1)) << "no ptz_state";
    setFaults(ptz_action_server::SetSimFaults::Request());  // no faults left over from another test
  }

  /// Sends a goal and waits for its end; returns the final state.
  State moveTo(double pan, double tilt, double zoom)
  {
    absolute_->sendGoal(makePtzGoal(pan, tilt, zoom));
    EXPECT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
    return absolute_->getState();
  }

  /// The sim backend's fault hooks, when the node runs the sim backend.
  static bool setFaults(const ptz_action_server::SetSimFaults::Request& request)
  {
    ptz_action_server::SetSimFaults service;
    service.request = request;
    return ros::service::exists("ptz_action_server/sim/set_faults", false) &&
           ros::service::call("ptz_action_server/sim/set_faults", service) && service.response.success;
  }

  static bool simBackend()
  {
    return ros::service::exists("ptz_action_server/sim/set_faults", false);
  }

  /// x axis of ptz_camera_link in ptz_base_link, from tf.
  static bool opticalAxis(Eigen::Vector3d& axis)
  {
    try
    {
      const auto transform = tf_buffer_->lookupTransform("ptz_base_link", "ptz_camera_link", ros::Time(0));
      axis = tf2::transformToEigen(transform).linear() * Eigen::Vector3d::UnitX();
      return true;
    }
    catch (const tf2::TransformException& error)
    {
      ADD_FAILURE() << error.what();
      return false;
    }
  }

  static NodeObserver* observer_;
  static PtzClient* absolute_;
  static PtzClient* second_absolute_;
  static PtzClient* relative_;
  static PtzClient* velocity_;
  static actionlib::SimpleActionClient<PtzRelToAction>* relative_to_;
  static actionlib::SimpleActionClient<PtzFrameAction>* frame_;
  static tf2_ros::Buffer* tf_buffer_;
  static tf2_ros::TransformListener* tf_listener_;
};

NodeObserver* NodeTest::observer_ = nullptr;
PtzClient* NodeTest::absolute_ = nullptr;
PtzClient* NodeTest::second_absolute_ = nullptr;
PtzClient* NodeTest::relative_ = nullptr;
PtzClient* NodeTest::velocity_ = nullptr;
actionlib::SimpleActionClient<PtzRelToAction>* NodeTest::relative_to_ = nullptr;
actionlib::SimpleActionClient<PtzFrameAction>* NodeTest::frame_ = nullptr;
tf2_ros::Buffer* NodeTest::tf_buffer_ = nullptr;
tf2_ros::TransformListener* NodeTest::tf_listener_ = nullptr;
}  // namespace

TEST_F(NodeTest, PositionGoalSucceedsWithFeedback)
{
  ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  FeedbackLog<ptz_action_server::PtzFeedback> feedback;
  observer_->clear();
  absolute_->sendGoal(makePtzGoal(0.6, -0.3, 5.0), PtzClient::SimpleDoneCallback(), PtzClient::SimpleActiveCallback(),
                      [&](const PtzFeedbackConstPtr& item) { feedback.add(*item); });
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(absolute_->getResult());
  EXPECT_TRUE(absolute_->getResult()->success);

  // Feedback at every state tick: the move takes about 0.8 s, so several, signed goal minus current.
  const auto items = feedback.all();
  ASSERT_GE(items.size(), 4u);
  EXPECT_GT(items.front().pan_remaining, 0.3);
  EXPECT_LT(items.front().tilt_remaining, -0.1);
  EXPECT_NEAR(items.back().pan_remaining, 0.0, 0.2);

  ASSERT_TRUE(observer_->waitTicks(1));
  const PtzState state = observer_->latest();
  EXPECT_NEAR(state.pan, 0.6, TOLERANCE);
  EXPECT_NEAR(state.tilt, -0.3, TOLERANCE);
  if (simBackend())
  {
    EXPECT_NEAR(state.zoom, 5.0, 0.05);
  }
  EXPECT_EQ(state.mode, PtzState::MODE_IDLE);
  bool saw_position_mode = false;
  for (const PtzState& seen : observer_->states())
  {
    saw_position_mode = saw_position_mode || seen.mode == PtzState::MODE_POSITION;
  }
  EXPECT_TRUE(saw_position_mode);

  const sensor_msgs::JointState joints = observer_->latestJoints();
  ASSERT_EQ(joints.name.size(), 2u);
  EXPECT_EQ(joints.name[0], "ptz_pan_joint");
  EXPECT_EQ(joints.name[1], "ptz_tilt_joint");
  EXPECT_NEAR(joints.position[0], state.pan, 1e-6);
  EXPECT_NEAR(joints.position[1], state.tilt, 1e-6);
}

TEST_F(NodeTest, SecondGoalPreemptsWithoutAStopInBetween)
{
  ASSERT_EQ(moveTo(-1.0, 0.0, 1.0), State::SUCCEEDED);
  observer_->clear();
  absolute_->sendGoal(makePtzGoal(1.0, 0.0, 1.0));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.pan > -0.3; }, 5.0));  // well under way
  second_absolute_->sendGoal(makePtzGoal(1.6, 0.2, 1.0));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::PREEMPTED);
  EXPECT_NE(absolute_->getState().getText().find("preempted"), std::string::npos) << absolute_->getState().getText();
  EXPECT_FALSE(absolute_->getResult()->success);
  ASSERT_TRUE(second_absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(second_absolute_->getState(), State::SUCCEEDED) << second_absolute_->getState().getText();

  // Pan kept increasing on every tick from the start until it neared the second target: no stop in between.
  const std::vector<PtzState> states = observer_->states();
  std::size_t rising = 0;
  for (std::size_t index = 1; index < states.size() && states[index].pan < 1.5; ++index)
  {
    if (states[index - 1].pan > -0.99)
    {
      EXPECT_GT(states[index].pan, states[index - 1].pan) << "pan stopped at tick " << index;
      ++rising;
    }
  }
  EXPECT_GE(rising, 5u);
}

TEST_F(NodeTest, CancelDeceleratesTheDeviceToRest)
{
  ASSERT_EQ(moveTo(-1.5, 0.0, 1.0), State::SUCCEEDED);
  absolute_->sendGoal(makePtzGoal(1.5, 0.0, 1.0));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.pan > -0.2; }, 5.0));
  const double at_cancel = observer_->latest().pan;
  absolute_->cancelGoal();
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::PREEMPTED);
  EXPECT_NE(absolute_->getState().getText().find("cancelled"), std::string::npos) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(1));
  const double stopped = observer_->latest().pan;
  // It braked past the point of the cancel, within the braking distance at full speed (1.5^2 / (2 x 3) rad) plus
  // the travel while the state seen here was old (a tick, and a device state period for remote devices), and far
  // from the goal.
  EXPECT_GT(stopped, at_cancel);
  EXPECT_LT(stopped - at_cancel, 0.375 + 0.25 + TOLERANCE);
  EXPECT_LT(stopped, 1.0);
  ASSERT_TRUE(observer_->waitTicks(3));
  EXPECT_NEAR(observer_->latest().pan, stopped, 1e-6) << "the device kept moving after the cancel ended";
  EXPECT_EQ(observer_->latest().mode, PtzState::MODE_IDLE);
}

TEST_F(NodeTest, InvalidGoalsAreRejectedAndNothingMoves)
{
  ASSERT_EQ(moveTo(0.2, 0.1, 2.0), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(1));
  const PtzState before = observer_->latest();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case
  {
    PtzClient* client;
    PtzGoal goal;
    const char* reason;
  };
  const std::vector<Case> cases = {
    { absolute_, makePtzGoal(nan, 0.0, 1.0), "pan position is NaN" },
    { absolute_, makePtzGoal(0.0, 0.0, inf), "zoom position is +Inf" },
    { absolute_, makePtzGoal(0.0, 2.0, 1.0), "tilt 2.0000 rad is outside the limits" },
    { absolute_, makePtzGoal(-4.0, 0.0, 1.0), "pan -4.0000 rad is outside the limits" },
    { relative_, makePtzGoal(0.0, nan, 0.0), "tilt offset is NaN" },
    { relative_, makePtzGoal(3.5, 0.0, 0.0), "is outside the limits" },
    { velocity_, makePtzGoal(0.0, -inf, 0.0), "tilt velocity is -Inf" },
    { velocity_, makePtzGoal(50.0, 0.0, 0.0), "exceeds the maximum speed" },
  };
  for (const Case& item : cases)
  {
    item.client->sendGoal(item.goal);
    ASSERT_TRUE(item.client->waitForResult(ros::Duration(5.0)));
    EXPECT_EQ(item.client->getState(), State::REJECTED) << item.reason;
    EXPECT_NE(item.client->getState().getText().find(item.reason), std::string::npos)
        << "'" << item.client->getState().getText() << "' should say '" << item.reason << "'";
    EXPECT_FALSE(item.client->getResult()->success);
  }
  ASSERT_TRUE(observer_->waitTicks(3));
  const PtzState after = observer_->latest();
  EXPECT_EQ(after.pan, before.pan);
  EXPECT_EQ(after.tilt, before.tilt);
  EXPECT_EQ(after.zoom, before.zoom);
  EXPECT_EQ(after.mode, PtzState::MODE_IDLE);
}

TEST_F(NodeTest, StalledAxisAbortsWithoutSuccess)
{
  if (!simBackend())
  {
    GTEST_SKIP() << "fault hooks belong to the sim backend";
  }
  ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  ptz_action_server::SetSimFaults::Request faults;
  faults.stall_tilt = true;
  ASSERT_TRUE(setFaults(faults));
  absolute_->sendGoal(makePtzGoal(0.3, 0.4, 1.0));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::ABORTED);
  EXPECT_NE(absolute_->getState().getText().find("stalled: tilt"), std::string::npos)
      << absolute_->getState().getText();
  ASSERT_TRUE(absolute_->getResult());
  EXPECT_FALSE(absolute_->getResult()->success);
  ASSERT_TRUE(setFaults(ptz_action_server::SetSimFaults::Request()));
  EXPECT_EQ(moveTo(0.0, 0.4, 1.0), State::SUCCEEDED);
}

TEST_F(NodeTest, LostLinkAbortsAndTheNodeRecovers)
{
  if (!simBackend())
  {
    GTEST_SKIP() << "fault hooks belong to the sim backend";
  }
  ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  absolute_->sendGoal(makePtzGoal(2.0, 0.0, 1.0));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.pan > 0.2; }, 5.0));
  ptz_action_server::SetSimFaults::Request dropout;
  dropout.dropout = true;
  ASSERT_TRUE(setFaults(dropout));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::ABORTED);
  EXPECT_NE(absolute_->getState().getText().find("link lost"), std::string::npos) << absolute_->getState().getText();
  // PtzState keeps coming while the link is down, and new goals are refused with the reason.
  EXPECT_TRUE(observer_->waitTicks(5));
  EXPECT_EQ(moveTo(0.5, 0.0, 1.0), State::REJECTED);
  EXPECT_NE(absolute_->getState().getText().find("link is down"), std::string::npos);
  ASSERT_TRUE(setFaults(ptz_action_server::SetSimFaults::Request()));
  EXPECT_EQ(moveTo(-0.5, 0.0, 1.0), State::SUCCEEDED);
  EXPECT_NEAR(observer_->latest().pan, -0.5, TOLERANCE);
}

TEST_F(NodeTest, RelativeGoalMovesByTheOffset)
{
  ASSERT_EQ(moveTo(0.1, -0.2, 3.0), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(1));
  const PtzState start = observer_->latest();
  relative_->sendGoal(makePtzGoal(0.25, 0.15, 1.0));
  ASSERT_TRUE(relative_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(relative_->getState(), State::SUCCEEDED) << relative_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(1));
  EXPECT_NEAR(observer_->latest().pan, start.pan + 0.25, TOLERANCE);
  EXPECT_NEAR(observer_->latest().tilt, start.tilt + 0.15, TOLERANCE);
  if (simBackend())
  {
    EXPECT_NEAR(observer_->latest().zoom, start.zoom + 1.0, 0.05);
  }
}

TEST_F(NodeTest, VelocityGoalMovesUntilStoppedOrAtTheLimit)
{
  ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  FeedbackLog<ptz_action_server::PtzFeedback> feedback;
  velocity_->sendGoal(makePtzGoal(-0.4, 0.0, 0.0), PtzClient::SimpleDoneCallback(), PtzClient::SimpleActiveCallback(),
                      [&](const PtzFeedbackConstPtr& item) { feedback.add(*item); });
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.pan < -0.3; }, 5.0));
  EXPECT_EQ(observer_->latest().mode, PtzState::MODE_VELOCITY);
  EXPECT_FALSE(velocity_->getState().isDone());
  ASSERT_FALSE(feedback.all().empty());
  EXPECT_NEAR(feedback.all().back().pan_remaining, 0.0, 0.05);  // at speed: goal minus current velocity

  // An all-zero velocity goal preempts it and stops the device.
  PtzClient stopper("move_ptz/velocity", true);
  ASSERT_TRUE(stopper.waitForServer(ros::Duration(5.0)));
  stopper.sendGoal(makePtzGoal(0.0, 0.0, 0.0));
  ASSERT_TRUE(velocity_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(velocity_->getState(), State::PREEMPTED);
  ASSERT_TRUE(stopper.waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(stopper.getState(), State::SUCCEEDED) << stopper.getState().getText();
  ASSERT_TRUE(observer_->waitTicks(1));
  const double stopped = observer_->latest().pan;
  ASSERT_TRUE(observer_->waitTicks(3));
  EXPECT_EQ(observer_->latest().pan, stopped);

  // Tilt up at 1 rad/s runs into the upper limit, and the goal ends there.
  velocity_->sendGoal(makePtzGoal(0.0, 1.0, 0.0));
  ASSERT_TRUE(velocity_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(velocity_->getState(), State::SUCCEEDED) << velocity_->getState().getText();
  EXPECT_NE(velocity_->getState().getText().find("tilt reached its upper limit"), std::string::npos)
      << velocity_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(1));
  EXPECT_NEAR(observer_->latest().tilt, M_PI / 2, 0.01);
}

TEST_F(NodeTest, TfOfTheCameraFollowsTheContractSigns)
{
  ASSERT_EQ(moveTo(0.5, 0.0, 1.0), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(2));  // tf from a tick after the goal ended
  Eigen::Vector3d axis;
  ASSERT_TRUE(opticalAxis(axis));
  EXPECT_NEAR(axis.x(), std::cos(0.5), TOLERANCE);
  EXPECT_NEAR(axis.y(), -std::sin(0.5), TOLERANCE);  // positive pan looks right
  EXPECT_NEAR(axis.z(), 0.0, TOLERANCE);

  ASSERT_EQ(moveTo(0.0, 0.3, 1.0), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(2));
  ASSERT_TRUE(opticalAxis(axis));
  EXPECT_NEAR(axis.x(), std::cos(0.3), TOLERANCE);
  EXPECT_NEAR(axis.y(), 0.0, TOLERANCE);
  EXPECT_NEAR(axis.z(), std::sin(0.3), TOLERANCE);  // positive tilt looks up
}

TEST_F(NodeTest, FrameGoalsPointAtTfFrames)
{
  // The frames were broadcast when the suite started; the node looks a frame up once per goal, so wait until its
  // tf listener has them (it rejects the goal until then).
  PtzFrameGoal frame_goal;
  frame_goal.frame_id = "test_target";
  frame_goal.zoom = 2.0;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  do
  {
    frame_->sendGoal(frame_goal);
    ASSERT_TRUE(frame_->waitForResult(ros::Duration(GOAL_WAIT)));
  } while (frame_->getState() == State::REJECTED && ros::WallTime::now() < deadline && ros::WallDuration(0.05).sleep());
  ASSERT_EQ(frame_->getState(), State::SUCCEEDED) << frame_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
  const auto target = tf_buffer_->lookupTransform("ptz_camera_link", "test_target", ros::Time(0));
  const Eigen::Vector3d in_camera = tf2::transformToEigen(target).translation();
  EXPECT_GT(in_camera.x(), 2.5);
  EXPECT_NEAR(in_camera.y(), 0.0, 0.03) << "the target is off the optical axis";
  EXPECT_NEAR(in_camera.z(), 0.0, 0.03) << "the target is off the optical axis";
  EXPECT_GT(observer_->latest().pan, 0.0);  // to the right is positive

  // Pan 0, tilt 0 in the axes of a frame turned 0.3 rad to the left is pan -0.3 for the camera.
  PtzRelToGoal relative_goal;
  relative_goal.frame_id = "test_rotated";
  relative_goal.pan = 0.0;
  relative_goal.tilt = 0.2;
  relative_goal.zoom = 1.0;
  relative_to_->sendGoal(relative_goal);
  ASSERT_TRUE(relative_to_->waitForResult(ros::Duration(GOAL_WAIT)));
  ASSERT_EQ(relative_to_->getState(), State::SUCCEEDED) << relative_to_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(1));
  EXPECT_NEAR(observer_->latest().pan, -0.3, TOLERANCE);
  EXPECT_NEAR(observer_->latest().tilt, 0.2, TOLERANCE);

  // Unknown frames are rejected with the reason, and nothing moves.
  frame_goal.frame_id = "no_such_frame";
  frame_->sendGoal(frame_goal);
  ASSERT_TRUE(frame_->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(frame_->getState(), State::REJECTED);
  EXPECT_NE(frame_->getState().getText().find("frame 'no_such_frame' is unknown to tf"), std::string::npos)
      << frame_->getState().getText();
  relative_goal.frame_id = "";
  relative_to_->sendGoal(relative_goal);
  ASSERT_TRUE(relative_to_->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(relative_to_->getState(), State::REJECTED);
  EXPECT_EQ(relative_to_->getState().getText(), "frame_id is empty");
}

TEST_F(NodeTest, StormOfGoalsFromSeveralClientsLosesNone)
{
  constexpr int CLIENTS = 4;
  constexpr int GOALS_PER_CLIENT = 40;
  std::vector<std::unique_ptr<actionlib::ActionClient<PtzAction>>> clients;
  std::vector<actionlib::ClientGoalHandle<PtzAction>> handles;
  for (int index = 0; index < CLIENTS; ++index)
  {
    clients.push_back(std::make_unique<actionlib::ActionClient<PtzAction>>("move_ptz/position_abs"));
    ASSERT_TRUE(clients.back()->waitForActionServerToStart(ros::Duration(10.0)));
  }
  ros::WallRate rate(50.0);
  for (int round = 0; round < GOALS_PER_CLIENT; ++round)
  {
    for (int index = 0; index < CLIENTS; ++index)
    {
      handles.push_back(clients[index]->sendGoal(makePtzGoal(0.01 * round - 0.2, 0.005 * index, 1.0)));
    }
    rate.sleep();
  }
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(GOAL_WAIT);
  auto done = [&]() {
    return std::all_of(handles.begin(), handles.end(), [](actionlib::ClientGoalHandle<PtzAction>& handle) {
      return handle.getCommState() == actionlib::CommState::DONE;
    });
  };
  while (!done() && ros::WallTime::now() < deadline)
  {
    ros::WallDuration(0.05).sleep();
  }
  int succeeded = 0;
  int preempted = 0;
  for (auto& handle : handles)
  {
    ASSERT_EQ(handle.getCommState(), actionlib::CommState::DONE) << "a goal never ended";
    const actionlib::TerminalState state = handle.getTerminalState();
    succeeded += state == actionlib::TerminalState::SUCCEEDED;
    preempted += state == actionlib::TerminalState::PREEMPTED;
  }
  EXPECT_EQ(succeeded + preempted, CLIENTS * GOALS_PER_CLIENT);
  EXPECT_GE(succeeded, 1);  // at least the last goal to arrive
}

/// Runs only in clamp.test, where the node has clamp_goals:=true.
class ClampTest : public NodeTest
{
};

TEST_F(ClampTest, OutOfRangeGoalsAreClampedAndSaySo)
{
  absolute_->sendGoal(makePtzGoal(4.0, -2.0, 1.0));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::SUCCEEDED) << absolute_->getState().getText();
  EXPECT_NE(absolute_->getState().getText().find("clamped pan 4.0000 -> 3.1416 rad, tilt -2.0000 -> -1.5708 rad"),
            std::string::npos)
      << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(1));
  EXPECT_NEAR(observer_->latest().pan, M_PI, TOLERANCE);
  EXPECT_NEAR(observer_->latest().tilt, -M_PI / 2, TOLERANCE);

  // Clamping never makes NaN acceptable.
  absolute_->sendGoal(makePtzGoal(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(absolute_->getState(), State::REJECTED);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "test_node_client");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}

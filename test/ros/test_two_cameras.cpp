/**
 * \file
 * \brief Two cameras on one master (launch/two_cameras.launch): their actions, topics, tf frames and diagnostics do
 * not collide, a goal to one never moves the other, and a node listens to tf only around frame goals.
 */
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_listener.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/ros/node_process.h"
#include "ptz_action_server/ros/ptz_goal.h"

using ptz_action_server::waitUntilWall;

namespace
{
using ptz_action_server::makePtzGoal;
using ptz_action_server::PtzAction;
using ptz_action_server::PtzFrameAction;
using ptz_action_server::PtzState;
using State = actionlib::SimpleClientGoalState;

constexpr double WAIT = 30.0;  // s: generous, CI is a busy 2-core machine

/// The nodes the master lists as publishers (index 0) or subscribers (index 1) of \p topic.
std::set<std::string> nodesOn(const std::string& topic, int index)
{
  XmlRpc::XmlRpcValue request(ros::this_node::getName());
  XmlRpc::XmlRpcValue response;
  XmlRpc::XmlRpcValue payload;
  std::set<std::string> nodes;
  if (!ros::master::execute("getSystemState", request, response, payload, false))
  {
    return nodes;
  }
  XmlRpc::XmlRpcValue& entries = payload[index];
  for (int entry = 0; entry < entries.size(); ++entry)
  {
    if (static_cast<std::string>(entries[entry][0]) == topic)
    {
      for (int node = 0; node < entries[entry][1].size(); ++node)
      {
        nodes.insert(static_cast<std::string>(entries[entry][1][node]));
      }
    }
  }
  return nodes;
}

/// What one camera publishes.
struct CameraObserver
{
  explicit CameraObserver(const std::string& ns) : node_handle(ns)
  {
    state_subscriber = node_handle.subscribe<PtzState>("ptz_state", 100, [this](const PtzState::ConstPtr& state) {
      std::lock_guard<std::mutex> lock(mutex);
      states.push_back(*state);
    });
    joint_subscriber = node_handle.subscribe<sensor_msgs::JointState>(
        "joint_states", 10, [this](const sensor_msgs::JointState::ConstPtr& message) {
          std::lock_guard<std::mutex> lock(mutex);
          joint_names = message->name;
        });
  }
  std::vector<PtzState> all()
  {
    std::lock_guard<std::mutex> lock(mutex);
    return states;
  }
  bool latest(PtzState& state)
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (states.empty())
    {
      return false;
    }
    state = states.back();
    return true;
  }

  ros::NodeHandle node_handle;
  ros::Subscriber state_subscriber;
  ros::Subscriber joint_subscriber;
  std::mutex mutex;
  std::vector<PtzState> states;
  std::vector<std::string> joint_names;
};

/// The observers and clients, made once for the whole run as NodeTest's are. With a fresh set per test, one run under
/// load died of SIGSEGV in this process just after a test's clients were destroyed and the next test's were made.
struct Cameras
{
  CameraObserver left{ "left" };
  CameraObserver right{ "right" };
  actionlib::SimpleActionClient<PtzAction> left_absolute{ "left/move_ptz/position_abs", true };
  actionlib::SimpleActionClient<PtzAction> right_absolute{ "right/move_ptz/position_abs", true };
  actionlib::SimpleActionClient<PtzFrameAction> left_frame{ "left/move_ptz/frame", true };
};

class TwoCamerasTest : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    cameras_ = new Cameras();  // never deleted: see Cameras
  }

  void SetUp() override
  {
    ASSERT_TRUE(left_absolute_.waitForServer(ros::Duration(WAIT)));
    ASSERT_TRUE(right_absolute_.waitForServer(ros::Duration(WAIT)));
    ASSERT_TRUE(left_frame_.waitForServer(ros::Duration(WAIT)));
    PtzState state;
    ASSERT_TRUE(waitUntilWall([&] { return left_.latest(state) && right_.latest(state); }, WAIT)) << "no ptz_state";
  }

  static inline Cameras* cameras_ = nullptr;
  CameraObserver& left_ = cameras_->left;
  CameraObserver& right_ = cameras_->right;
  actionlib::SimpleActionClient<PtzAction>& left_absolute_ = cameras_->left_absolute;
  actionlib::SimpleActionClient<PtzAction>& right_absolute_ = cameras_->right_absolute;
  actionlib::SimpleActionClient<PtzFrameAction>& left_frame_ = cameras_->left_frame;
};

TEST_F(TwoCamerasTest, NamesDoNotCollide)
{
  // As nodelets, both cameras publish from their manager's process (~publisher_node: /cameras).
  const std::string manager = ros::NodeHandle("~").param<std::string>("publisher_node", "");
  for (const char* ns : { "left", "right" })
  {
    const std::string node = manager.empty() ? std::string("/") + ns + "/ptz_action_server" : manager;
    for (const char* topic : { "ptz_state", "joint_states", "move_ptz/position_abs/status" })
    {
      const std::string name = std::string("/") + ns + "/" + topic;
      EXPECT_EQ(nodesOn(name, 0), std::set<std::string>{ node }) << name << " has other publishers";
    }
  }
  ASSERT_TRUE(waitUntilWall([&] { return left_.all().size() > 1 && right_.all().size() > 1; }, WAIT));
  {
    std::lock_guard<std::mutex> lock(left_.mutex);
    EXPECT_EQ(left_.joint_names, (std::vector<std::string>{ "left_ptz_pan_joint", "left_ptz_tilt_joint" }));
  }
  {
    std::lock_guard<std::mutex> lock(right_.mutex);
    EXPECT_EQ(right_.joint_names, (std::vector<std::string>{ "right_ptz_pan_joint", "right_ptz_tilt_joint" }));
  }

  // Each camera's frames are its own, under one tree.
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  for (const char* frame : { "left_ptz_camera_link", "right_ptz_camera_link", "left_ptz_camera_optical_frame",
                             "right_ptz_camera_optical_frame" })
  {
    EXPECT_TRUE(buffer.canTransform("base_link", frame, ros::Time(0), ros::Duration(WAIT))) << frame;
  }

  // Diagnostics name the node's namespace.
  std::mutex mutex;
  std::set<std::string> statuses;
  ros::NodeHandle node_handle;
  ros::Subscriber diagnostics = node_handle.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& status : array->status)
        {
          statuses.insert(status.name.substr(0, status.name.find(':')));
        }
      });
  EXPECT_TRUE(waitUntilWall(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return statuses.count("left/ptz_action_server") > 0 && statuses.count("right/ptz_action_server") > 0;
      },
      WAIT));
}

TEST_F(TwoCamerasTest, AGoalToOneNeverMovesTheOther)
{
  PtzState right_before;
  ASSERT_TRUE(right_.latest(right_before));
  const std::size_t right_seen = right_.all().size();
  left_absolute_.sendGoal(makePtzGoal(0.8, -0.3, 2.0));
  ASSERT_TRUE(left_absolute_.waitForResult(ros::Duration(WAIT)));
  EXPECT_EQ(left_absolute_.getState(), State::SUCCEEDED) << left_absolute_.getState().getText();
  ASSERT_TRUE(waitUntilWall([&] { return right_.all().size() > right_seen + 5; }, WAIT));  // the right one went on
  // The result can come before the next 10 Hz state, so the left camera's settled pose is awaited, not sampled.
  PtzState left_after;
  EXPECT_TRUE(waitUntilWall(
      [&] {
        return left_.latest(left_after) && left_after.mode == PtzState::MODE_IDLE &&
               std::abs(left_after.pan - 0.8) < 0.006;
      },
      WAIT))
      << "the left camera shows pan " << left_after.pan << ", mode " << int(left_after.mode);
  const std::vector<PtzState> right_states = right_.all();
  for (std::size_t index = right_seen; index < right_states.size(); ++index)
  {
    EXPECT_EQ(right_states[index].pan, right_before.pan);
    EXPECT_EQ(right_states[index].tilt, right_before.tilt);
    EXPECT_EQ(right_states[index].mode, PtzState::MODE_IDLE);
  }
}

/// A node listens to tf only from a frame goal until frame_listen_time after it (1.5 s in two_cameras.test), and
/// the first frame goal after a quiet spell still succeeds at once: it waits for tf rather than being rejected.
TEST_F(TwoCamerasTest, TfIsHeardOnlyAroundFrameGoals)
{
  const std::string left_node = "/left/ptz_action_server";
  const std::string right_node = "/right/ptz_action_server";
  ASSERT_TRUE(waitUntilWall([&] { return nodesOn("/tf", 1).count(left_node) == 0; }, WAIT)) << "listening while idle";
  EXPECT_EQ(nodesOn("/tf", 1).count(right_node), 0u);
  EXPECT_EQ(nodesOn("/tf_static", 1).count(right_node), 0u);

  // The left camera points at the right one's base: 0.6 m to its right (and level), so pan = +pi/2.
  ptz_action_server::PtzFrameGoal goal;
  goal.frame_id = "right_ptz_base_link";
  goal.zoom = 1.0;
  left_frame_.sendGoal(goal);
  ASSERT_TRUE(left_frame_.waitForResult(ros::Duration(WAIT)));
  ASSERT_EQ(left_frame_.getState(), State::SUCCEEDED) << left_frame_.getState().getText();
  PtzState state;
  // The result can come before the next 10 Hz state, so the settled pose is awaited.
  EXPECT_TRUE(waitUntilWall(
      [&] { return left_.latest(state) && state.mode == PtzState::MODE_IDLE && std::abs(state.pan - M_PI / 2) < 0.05; },
      WAIT))
      << "the left camera shows pan " << state.pan << ", mode " << int(state.mode);
  EXPECT_LT(state.tilt, 0.0);  // the base is below the camera's tilt axis

  EXPECT_EQ(nodesOn("/tf", 1).count(left_node), 1u) << "the listener went too soon";
  EXPECT_EQ(nodesOn("/tf", 1).count(right_node), 0u);
  EXPECT_TRUE(waitUntilWall([&] { return nodesOn("/tf", 1).count(left_node) == 0; }, WAIT)) << "still listening after "
                                                                                               "frame_listen_time";
}
}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_two_cameras");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}

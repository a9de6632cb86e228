/**
 * \file
 * \brief The rostest client's fixture: NodeTest's action clients, tf and an observer of what the node publishes.
 *
 * The client drives the running node through its actions and checks what a user would see. It runs in the node's
 * namespace against whichever backend the .test file started; the .test files pick tests by name
 * (--gtest_filter=NodeTest.*), and every test file links into the one test_node_client. Tests wait on conditions with
 * deadlines, never on bare sleeps, except where a test must show that nothing happens for a while.
 */
#pragma once

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
#include "ptz_action_server/PtzCapabilities.h"
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

inline constexpr double TOLERANCE = 0.006;  // rad: the node's 0.005 plus float32 rounding
inline constexpr double GOAL_WAIT = 20.0;   // s

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
    // Latched once the node has started its device.
    const auto capabilities =
        ros::topic::waitForMessage<ptz_action_server::PtzCapabilities>("capabilities", ros::Duration(60.0));
    if (capabilities)
    {
      capabilities_ = new ptz_action_server::PtzCapabilities(*capabilities);
    }
  }

  /// True when the device's zoom takes position goals (the node's latched capabilities say so).
  static bool zoomable()
  {
    return capabilities_ != nullptr && capabilities_->zoom.absolute;
  }
  /// \p zoom on a device whose zoom takes position goals; otherwise 1, the zoom a device without one reports.
  static double zoomOr1(double zoom)
  {
    return zoomable() ? zoom : 1.0;
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
    ASSERT_NE(capabilities_, nullptr) << "no latched capabilities";
    setFaults(ptz_action_server::SetSimFaults::Request());  // no faults left over from another test
  }

  /// Sends a goal and waits for its end; returns the final state.
  State moveTo(double pan, double tilt, double zoom)
  {
    absolute_->sendGoal(makePtzGoal(pan, tilt, zoom));
    EXPECT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
    return absolute_->getState();
  }

  /// moveTo(), repeated while the node refuses it because the device's link is still down (a remote device reports
  /// again only at its next state message); the final state of the first goal it takes.
  State moveToOnceTheLinkIsBack(double pan, double tilt, double zoom)
  {
    State state = State::REJECTED;
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(GOAL_WAIT);
    while (state == State::REJECTED && ros::WallTime::now() < deadline)
    {
      state = moveTo(pan, tilt, zoom);
      if (state == State::REJECTED)
      {
        EXPECT_NE(absolute_->getState().getText().find("link is down"), std::string::npos);
        observer_->waitTicks(1);
      }
    }
    return state;
  }

  /// The device's fault hooks (a SetSimFaults service): the sim backend's, or an emulator's named by ~fault_service.
  static bool setFaults(const ptz_action_server::SetSimFaults::Request& request)
  {
    ptz_action_server::SetSimFaults service;
    service.request = request;
    return faultHooks() && ros::service::call(faultService(), service) && service.response.success;
  }

  static std::string faultService()
  {
    return ros::NodeHandle("~").param<std::string>("fault_service", "ptz_action_server/sim/set_faults");
  }

  static bool faultHooks()
  {
    return ros::service::exists(faultService(), false);
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

  static inline NodeObserver* observer_ = nullptr;
  static inline ptz_action_server::PtzCapabilities* capabilities_ = nullptr;
  static inline PtzClient* absolute_ = nullptr;
  static inline PtzClient* second_absolute_ = nullptr;
  static inline PtzClient* relative_ = nullptr;
  static inline PtzClient* velocity_ = nullptr;
  static inline actionlib::SimpleActionClient<PtzRelToAction>* relative_to_ = nullptr;
  static inline actionlib::SimpleActionClient<PtzFrameAction>* frame_ = nullptr;
  static inline tf2_ros::Buffer* tf_buffer_ = nullptr;
  static inline tf2_ros::TransformListener* tf_listener_ = nullptr;
};

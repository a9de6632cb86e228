/**
 * \file
 * \brief launch/many_cameras.launch: N cameras in one nodelet manager, loaded by one ptz_camera_loader. Each camera
 * answers its own goals, and a subscriber that comes late to /tf_static gets every camera's fixed joints (one latched
 * message per process, not the last camera's), those of the fleet and the ~other_frames of other managers' cameras.
 */
#include <gtest/gtest.h>

#include <mutex>
#include <set>
#include <sstream>
#include <string>

#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/ros/node_process.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace
{
using ptz_action_server::makePtzGoal;
using ptz_action_server::PtzAction;
using ptz_action_server::waitUntilWall;
using State = actionlib::SimpleClientGoalState;

constexpr double WAIT = 60.0;  // s: generous, CI is a busy 2-core machine

std::string cameraName(int index)
{
  char name[16];
  std::snprintf(name, sizeof(name), "cam_%02d", index);
  return name;
}

int cameraCount()
{
  int count = 0;
  ros::NodeHandle("~").getParam("cameras", count);
  return count;
}

TEST(ManyCameras, EveryCameraOfTheLoaderAnswersItsOwnGoal)
{
  const int cameras = cameraCount();
  ASSERT_GE(cameras, 2);
  for (int index = 0; index < cameras; ++index)
  {
    actionlib::SimpleActionClient<PtzAction> client("/" + cameraName(index) + "/move_ptz/position_abs", true);
    ASSERT_TRUE(client.waitForServer(ros::Duration(WAIT))) << cameraName(index);
    const double pan = 0.1 * (index + 1);
    client.sendGoal(makePtzGoal(pan, 0.0, 1.0));
    ASSERT_TRUE(client.waitForResult(ros::Duration(WAIT))) << cameraName(index);
    EXPECT_EQ(client.getState(), State::SUCCEEDED) << cameraName(index) << ": " << client.getState().getText();
  }
}

TEST(ManyCameras, ALateTfStaticSubscriberGetsTheFixedJointsOfEveryCamera)
{
  const int cameras = cameraCount();
  // Wait until every camera is up (its action server answers), then subscribe: only the latched message reaches us.
  for (int index = 0; index < cameras; ++index)
  {
    actionlib::SimpleActionClient<PtzAction> client("/" + cameraName(index) + "/move_ptz/position_abs", true);
    ASSERT_TRUE(client.waitForServer(ros::Duration(WAIT))) << cameraName(index);
  }
  ros::NodeHandle node_handle;
  std::mutex mutex;
  std::set<std::string> children;
  ros::Subscriber subscriber =
      node_handle.subscribe<tf2_msgs::TFMessage>("/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& transform : message->transforms)
        {
          children.insert(transform.child_frame_id);
        }
      });
  std::set<std::string> expected;
  for (int index = 0; index < cameras; ++index)
  {
    expected.insert(cameraName(index) + "_ptz_camera_optical_frame");
    expected.insert(cameraName(index) + "_ptz_camera_link");
  }
  std::string other_frames;
  ros::NodeHandle("~").getParam("other_frames", other_frames);
  std::istringstream others(other_frames);
  for (std::string frame; others >> frame;)
  {
    expected.insert(frame);
  }
  const auto missing = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    std::string text;
    for (const std::string& frame : expected)
    {
      text += children.count(frame) == 0 ? frame + " " : "";
    }
    return text;
  };
  EXPECT_TRUE(waitUntilWall([&] { return missing().empty(); }, WAIT)) << "missing from /tf_static: " << missing();
}

}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_many_cameras");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  spinner.stop();
  ros::shutdown();
  return result;
}

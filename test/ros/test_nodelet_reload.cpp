/**
 * \file
 * \brief Cameras as nodelets in one manager (test/ros/nodelet_cameras.test): a camera unloaded while another keeps
 * serving, and one unloaded and loaded again 20 times with goals in flight, leaking no thread and no fd of the
 * manager, while the other camera's ptz_state goes on unbroken.
 *
 * The camera this test loads and unloads, /spare/ptz_action_server, has its parameters and URDF set by the .test file
 * and is loaded through the manager's own load_nodelet service, without a bond: nothing else holds it.
 */
#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <nodelet/NodeletList.h>
#include <nodelet/NodeletLoad.h>
#include <nodelet/NodeletUnload.h>
#include <ros/ros.h>
#include <ros/topic.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/ros/node_process.h"
#include "ptz_action_server/ros/ptz_goal.h"

using ptz_action_server::pidOfNode;
using ptz_action_server::waitUntilWall;

namespace
{
using ptz_action_server::makePtzGoal;
using ptz_action_server::PtzAction;
using ptz_action_server::PtzState;
using PtzClient = actionlib::SimpleActionClient<PtzAction>;
using State = actionlib::SimpleClientGoalState;

constexpr double WAIT = 30.0;  // s: generous, CI is a busy 2-core machine
constexpr int RELOADS = 20;
const char* const MANAGER = "/cameras";
const char* const SPARE = "/spare/ptz_action_server";

/// Entries of /proc/PID/\p what (task: threads, fd: open files and sockets), or -1.
int countEntries(int pid, const char* what)
{
  const std::string path = "/proc/" + std::to_string(pid) + "/" + what;
  DIR* directory = opendir(path.c_str());
  if (!directory)
  {
    return -1;
  }
  int count = 0;
  while (const dirent* entry = readdir(directory))
  {
    count += entry->d_name[0] != '.';
  }
  closedir(directory);
  return count;
}

/// The names the manager holds.
std::vector<std::string> loadedNodelets()
{
  nodelet::NodeletList list;
  ros::service::call(std::string(MANAGER) + "/list", list);
  return list.response.nodelets;
}

bool load(const std::string& name)
{
  nodelet::NodeletLoad load;
  load.request.name = name;
  load.request.type = "ptz_action_server/PtzNodelet";
  return ros::service::call(std::string(MANAGER) + "/load_nodelet", load) && load.response.success;
}

bool loadSpare()
{
  return load(SPARE);
}

bool unload(const std::string& name)
{
  nodelet::NodeletUnload unload;
  unload.request.name = name;
  return ros::service::call(std::string(MANAGER) + "/unload_nodelet", unload) && unload.response.success;
}

bool unloadSpare()
{
  return unload(SPARE);
}

/// The ptz_state of a camera: how many, the latest, and the longest silence between two.
struct StateWatch
{
  explicit StateWatch(const std::string& ns)
  {
    subscriber = ros::NodeHandle(ns).subscribe<PtzState>("ptz_state", 100, [this](const PtzState::ConstPtr& state) {
      std::lock_guard<std::mutex> lock(mutex);
      const ros::WallTime now = ros::WallTime::now();
      if (count > 0)
      {
        longest_gap = std::max(longest_gap, (now - last).toSec());
      }
      last = now;
      latest = *state;
      ++count;
    });
  }
  int received()
  {
    std::lock_guard<std::mutex> lock(mutex);
    return count;
  }
  double longestGap()
  {
    std::lock_guard<std::mutex> lock(mutex);
    return longest_gap;
  }
  void restartGap()
  {
    std::lock_guard<std::mutex> lock(mutex);
    longest_gap = 0.0;
    count = 0;
  }

  ros::Subscriber subscriber;
  std::mutex mutex;
  int count = 0;
  ros::WallTime last;
  double longest_gap = 0.0;
  PtzState latest;
};

class NodeletReloadTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_TRUE(ros::service::waitForService(std::string(MANAGER) + "/load_nodelet", ros::Duration(WAIT)));
    ASSERT_TRUE(left_client_.waitForServer(ros::Duration(WAIT)));
    ASSERT_TRUE(waitUntilWall([&] { return left_.received() > 0; }, WAIT)) << "no ptz_state from the left camera";
    const std::vector<std::string> loaded = loadedNodelets();
    if (std::find(loaded.begin(), loaded.end(), SPARE) == loaded.end())
    {
      ASSERT_TRUE(loadSpare());
    }
    ASSERT_TRUE(spare_client_.waitForServer(ros::Duration(WAIT)));
  }

  /// Sends \p pan to the spare camera and waits until the goal runs.
  void startSpareGoal(double pan)
  {
    spare_client_.sendGoal(makePtzGoal(pan, 0.0, 1.0));
    ASSERT_TRUE(waitUntilWall([&] { return spare_client_.getState() == State::ACTIVE; }, WAIT))
        << spare_client_.getState().toString();
  }

  StateWatch left_{ "left" };
  StateWatch spare_{ "spare" };
  PtzClient left_client_{ "left/move_ptz/position_abs", true };
  PtzClient spare_client_{ "spare/move_ptz/position_abs", true };
};

TEST_F(NodeletReloadTest, UnloadingOneCameraLeavesTheOtherServing)
{
  ASSERT_TRUE(waitUntilWall([&] { return spare_.received() > 0; }, WAIT)) << "no ptz_state from the spare camera";
  startSpareGoal(1.5);
  ASSERT_TRUE(unloadSpare());
  EXPECT_TRUE(waitUntilWall([&] { return !spare_client_.isServerConnected(); }, WAIT)) << "the spare still serves";
  const std::vector<std::string> loaded = loadedNodelets();
  EXPECT_EQ(std::count(loaded.begin(), loaded.end(), SPARE), 0);

  // The left camera still takes goals and reports.
  const int seen = left_.received();
  left_client_.sendGoal(makePtzGoal(-0.4, 0.2, 1.0));
  ASSERT_TRUE(left_client_.waitForResult(ros::Duration(WAIT)));
  EXPECT_EQ(left_client_.getState(), State::SUCCEEDED) << left_client_.getState().getText();
  EXPECT_TRUE(waitUntilWall([&] { return left_.received() > seen + 5; }, WAIT));

  ASSERT_TRUE(loadSpare());  // back for the next test
}

/// A camera whose configuration is wrong (/broken: an unknown backend) says so and stays inert: the manager and
/// its other cameras go on.
TEST_F(NodeletReloadTest, AMisconfiguredCameraStaysInertAndTheManagerGoesOn)
{
  const int manager = pidOfNode(MANAGER);
  ASSERT_TRUE(load("/broken/ptz_action_server"));
  const std::vector<std::string> loaded = loadedNodelets();
  EXPECT_EQ(std::count(loaded.begin(), loaded.end(), "/broken/ptz_action_server"), 1);
  EXPECT_FALSE(ros::topic::waitForMessage<PtzState>("/broken/ptz_state", ros::Duration(0.5))) << "it publishes";
  left_client_.sendGoal(makePtzGoal(0.3, 0.1, 1.0));
  ASSERT_TRUE(left_client_.waitForResult(ros::Duration(WAIT)));
  EXPECT_EQ(left_client_.getState(), State::SUCCEEDED) << left_client_.getState().getText();
  EXPECT_TRUE(unload("/broken/ptz_action_server"));
  EXPECT_EQ(pidOfNode(MANAGER), manager);
}

TEST_F(NodeletReloadTest, ReloadingACameraWithGoalsInFlightLeaksNoThreadOrFdAndTheOtherGoesOn)
{
  const int manager = pidOfNode(MANAGER);
  ASSERT_GT(manager, 0) << "cannot find the manager's pid";
  // The baseline: the spare loaded, serving, its goal connections made and one goal done.
  spare_client_.sendGoal(makePtzGoal(0.2, 0.0, 1.0));
  ASSERT_TRUE(spare_client_.waitForResult(ros::Duration(WAIT)));
  ASSERT_TRUE(waitUntilWall([&] { return spare_.received() > 0; }, WAIT));
  const int threads_before = countEntries(manager, "task");
  const int fds_before = countEntries(manager, "fd");
  ASSERT_GT(threads_before, 0);
  left_.restartGap();

  for (int round = 0; round < RELOADS; ++round)
  {
    // Both cameras move: the spare's goal is cut by the unload, the left one's runs through it.
    left_client_.sendGoal(makePtzGoal(round % 2 ? 0.6 : -0.6, 0.0, 1.0));
    startSpareGoal(round % 2 ? -1.5 : 1.5);
    ASSERT_TRUE(unloadSpare()) << "round " << round;
    ASSERT_TRUE(loadSpare()) << "round " << round;
    ASSERT_TRUE(spare_client_.waitForServer(ros::Duration(WAIT))) << "round " << round;
  }
  EXPECT_EQ(pidOfNode(MANAGER), manager) << "the manager was restarted";

  // The spare serves after its last load, and the left camera never stopped.
  spare_client_.sendGoal(makePtzGoal(0.2, 0.0, 1.0));
  ASSERT_TRUE(spare_client_.waitForResult(ros::Duration(WAIT)));
  EXPECT_EQ(spare_client_.getState(), State::SUCCEEDED) << spare_client_.getState().getText();
  ASSERT_TRUE(left_client_.waitForResult(ros::Duration(WAIT)));
  EXPECT_EQ(left_client_.getState(), State::SUCCEEDED) << left_client_.getState().getText();
  EXPECT_GT(left_.received(), 0);
  // 10 Hz is 0.1 s; a silence of 20 periods would mean the reloads held the other camera up.
  EXPECT_LT(left_.longestGap(), 2.0) << "the left camera's ptz_state stopped for a while during the reloads";

  // An unloaded camera's threads are joined and its sockets closed as it goes; the last ones may take a moment.
  int threads_after = 0;
  int fds_after = 0;
  waitUntilWall(
      [&] {
        threads_after = countEntries(manager, "task");
        fds_after = countEntries(manager, "fd");
        return threads_after <= threads_before && fds_after <= fds_before;
      },
      WAIT);
  RecordProperty("manager_threads_before", threads_before);
  RecordProperty("manager_threads_after", threads_after);
  RecordProperty("manager_fds_before", fds_before);
  RecordProperty("manager_fds_after", fds_after);
  EXPECT_EQ(threads_after, threads_before) << "threads of the manager before and after " << RELOADS << " reloads";
  EXPECT_LE(fds_after, fds_before) << "open fds of the manager before and after " << RELOADS << " reloads";
}

}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_nodelet_reload");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  spinner.stop();
  ros::shutdown();
  return result;
}

/**
 * \file
 * \brief TeleopGoals against the sim node: a stick deflected before the teleop's action client is connected drives
 * the camera once it is; and a stick tapped at 50 Hz, each goal's stop coming a moment after the goal, before the
 * node's first status of it, loses no goal of the teleop's action client (none goes LOST).
 */
#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/console.h>
#include <ros/ros.h>

#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/ros/ptz_teleop.h"

namespace
{
using ptz_action_server::PtzState;
using ptz_action_server::TeleopCommand;
using ptz_action_server::TeleopGoals;

/// Counts actionlib's client-side complaints: a goal given up as LOST, a result for a goal already ended. Stays
/// registered for the whole process (rosconsole's log4cxx backend crashes in deregister_appender()).
class ActionlibComplaints : public ros::console::LogAppender
{
public:
  static ActionlibComplaints& instance()
  {
    static ActionlibComplaints* complaints = [] {
      auto* appender = new ActionlibComplaints;
      ros::console::register_appender(appender);
      return appender;
    }();
    return *complaints;
  }
  void log(ros::console::Level, const char* message, const char*, const char*, int) override
  {
    const std::string text(message);
    lost += text.find("Transitioning goal to LOST") != std::string::npos;
    result_after_done += text.find("already in the DONE state") != std::string::npos;
  }
  std::atomic<int> lost{ 0 };
  std::atomic<int> result_after_done{ 0 };
};

TEST(TeleopGoalsTest, AStickDeflectedBeforeTheActionClientIsConnectedDrivesOnceItIs)
{
  ros::CallbackQueue queue;
  ros::NodeHandle node_handle;
  node_handle.setCallbackQueue(&queue);
  std::mutex mutex;
  std::optional<double> pan;
  const ros::Subscriber states = node_handle.subscribe<PtzState>("ptz_state", 10, [&](const PtzState::ConstPtr& state) {
    std::lock_guard<std::mutex> lock(mutex);
    pan = state->pan;
  });
  ros::AsyncSpinner spinner(1, &queue);
  spinner.start();
  const auto latestPan = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    return pan;
  };
  const auto waitFor = [](const std::function<bool()>& condition, double seconds, const std::function<void()>& tick) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
    ros::WallRate rate(20.0);  // the teleop's stale-joystick timer
    while (!condition() && ros::WallTime::now() < deadline)
    {
      tick();
      rate.sleep();
    }
    return condition();
  };
  ASSERT_TRUE(waitFor([&] { return latestPan().has_value(); }, 60.0, [] {})) << "no ptz_state from the node";
  const double start = *latestPan();

  // The node is up, the joystick deflected: the teleop's fresh action client connects only a moment later. A goal
  // published before then went nowhere, and a held stick sends nothing new, so the camera never moved.
  TeleopGoals teleop(node_handle);
  TeleopCommand move;
  move.type = TeleopCommand::Type::VELOCITY;
  move.velocity = { 0.3, 0.0, 0.0 };
  teleop.execute({ move });
  EXPECT_TRUE(waitFor([&] { return std::abs(*latestPan() - start) > 0.05; }, 30.0, [&] { teleop.sendHeld(); }))
      << "the stick deflected before the connection never drove the camera (pan stayed at " << start << " rad)";
  EXPECT_EQ(teleop.lastCommand(), "velocity pan +0.30 tilt +0.00 zoom +0.00");
  teleop.execute({ TeleopCommand{} });
  EXPECT_TRUE(teleop.waitUntilDone(30.0)) << "the stop never ended the goal";
}

TEST(TeleopGoalsTest, AStopRightAfterItsGoalLosesNoGoal)
{
  ActionlibComplaints& complaints = ActionlibComplaints::instance();
  // The teleop as the ptz_teleop node runs it: on a queue and thread of its own.
  ros::CallbackQueue queue;
  ros::NodeHandle node_handle;
  node_handle.setCallbackQueue(&queue);
  TeleopGoals teleop(node_handle);
  ros::AsyncSpinner spinner(1, &queue);
  spinner.start();
  ASSERT_TRUE(teleop.waitForServers(60.0));

  // 3 s of taps at a joystick driver's 50 Hz: the node publishes its status lists (on transitions and at 5 Hz to
  // listeners) while each new goal and its stop are on the wire.
  constexpr int TAPS = 150;
  ros::WallRate joystick(50.0);
  for (int tap = 0; tap < TAPS; ++tap)
  {
    TeleopCommand move;
    move.type = TeleopCommand::Type::VELOCITY;
    move.velocity = { tap % 2 == 0 ? 0.3 : -0.3, 0.0, 0.0 };
    teleop.execute({ move, TeleopCommand{} });  // the default command is a stop
    joystick.sleep();
  }
  EXPECT_TRUE(teleop.waitUntilDone(30.0)) << "the last tap's goal never ended";
  EXPECT_EQ(teleop.lastCommand(), "stop");
  EXPECT_EQ(complaints.lost, 0) << "goals the teleop's client gave up as LOST";
  EXPECT_EQ(complaints.result_after_done, 0) << "results that came for goals already ended";
}

}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_teleop_goals");
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}

/**
 * \file
 * \brief TeleopGoals against the sim node, a stick tapped at 50 Hz: each goal's stop comes a moment after the goal,
 * before the node's first status of it, and no goal of the teleop's action client may go LOST for that.
 */
#include <atomic>
#include <string>

#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/console.h>
#include <ros/ros.h>

#include "ptz_action_server/ros/ptz_teleop.h"

namespace
{
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

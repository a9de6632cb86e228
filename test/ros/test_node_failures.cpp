/**
 * \file
 * \brief rostest client, goals that must not succeed: rejections, a stalled axis, a lost link; and clamping
 * (ClampTest runs only in clamp.test, where the node has clamp_goals:=true).
 */
#include "node_test.h"

#include <signal.h>

#include <fstream>

TEST_F(NodeTest, InvalidGoalsAreRejectedAndNothingMoves)
{
  ASSERT_EQ(moveTo(0.2, 0.1, zoomOr1(2.0)), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));  // the result can come before the state that shows the goal reached
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
  if (!faultHooks())
  {
    GTEST_SKIP() << "no fault hooks (the sim backend's, or an emulator's given as ~fault_service)";
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
  if (!faultHooks())
  {
    GTEST_SKIP() << "no fault hooks (the sim backend's, or an emulator's given as ~fault_service)";
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
  EXPECT_EQ(moveToOnceTheLinkIsBack(-0.5, 0.0, 1.0), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(2));  // the result can come before the state that shows the goal reached
  EXPECT_NEAR(observer_->latest().pan, -0.5, TOLERANCE);
}

/**
 * The device's link breaks while a goal runs, by the emulator's own fault signal, as a user would break it: the goal
 * ends ABORTED with "link lost: <the link>", PtzState keeps coming, and the first goal the node takes afterwards
 * succeeds. The .test file names the emulator's pid file and the fault: "drop" (SIGUSR2: every connection dropped,
 * reopened at once), "unplug" (SIGUSR2: unplugged until the goal has ended, then SIGUSR2 again: replugged) or
 * "silence" (SIGUSR1 likewise). The contract suite breaks and reopens links faster than the state timeout.
 */
TEST_F(NodeTest, ALinkBrokenMidGoalEndsItAsLinkLostAndTheNextGoalSucceeds)
{
  ros::NodeHandle private_handle("~");
  std::string pid_file;
  std::string fault;
  private_handle.param<std::string>("emulator_pid_file", pid_file, "");
  private_handle.param<std::string>("emulator_fault", fault, "");
  if (pid_file.empty())
  {
    GTEST_SKIP() << "no emulator to break (the sim's own dropout is LostLinkAbortsAndTheNodeRecovers)";
  }
  std::ifstream file(pid_file);
  int pid = 0;
  ASSERT_TRUE(file >> pid) << "no pid in " << pid_file;
  ASSERT_EQ(moveTo(-1.2, 0.0, 1.0), State::SUCCEEDED);
  absolute_->sendGoal(makePtzGoal(1.2, 0.0, 1.0));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.pan > -0.8; }, GOAL_WAIT));
  const int signal = fault == "silence" ? SIGUSR1 : SIGUSR2;
  ASSERT_EQ(::kill(pid, signal), 0);
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::ABORTED) << absolute_->getState().getText();
  EXPECT_EQ(absolute_->getState().getText().rfind("link lost: ", 0), 0u) << absolute_->getState().getText();
  EXPECT_FALSE(absolute_->getResult()->success);
  EXPECT_TRUE(observer_->waitTicks(3));  // PtzState goes on
  if (fault != "drop")
  {
    ASSERT_EQ(::kill(pid, signal), 0);  // the device is back (the signal toggles the fault)
  }
  // The first goal the node takes once the link is back succeeds (goals are refused while it is down).
  EXPECT_EQ(moveToOnceTheLinkIsBack(0.3, 0.1, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
  EXPECT_NEAR(observer_->latest().pan, 0.3, TOLERANCE);
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
  ASSERT_TRUE(observer_->waitTicks(2));
  EXPECT_NEAR(observer_->latest().pan, M_PI, TOLERANCE);
  EXPECT_NEAR(observer_->latest().tilt, -M_PI / 2, TOLERANCE);

  // Clamping never makes NaN acceptable.
  absolute_->sendGoal(makePtzGoal(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(absolute_->getState(), State::REJECTED);
}

TEST_F(NodeTest, CapabilitiesAreLatchedAndZoomGoalsFollowWhatTheDeviceHas)
{
  const ptz_action_server::PtzCapabilities& can = *capabilities_;
  EXPECT_FALSE(can.backend.empty());
  // Every backend's pan and tilt take position goals, report themselves, and have the limits goals are checked with.
  for (const auto* axis : { &can.pan, &can.tilt })
  {
    EXPECT_TRUE(axis->present && axis->absolute && axis->feedback);
    EXPECT_LT(axis->min, axis->max);
    EXPECT_GT(axis->max_speed, 0.0);
  }
  ASSERT_EQ(moveTo(0.1, 0.0, zoomOr1(2.0)), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
  const PtzState before = observer_->latest();
  if (can.zoom.absolute)
  {
    EXPECT_TRUE(can.zoom.present && can.zoom.feedback);
    EXPECT_LE(can.zoom.min, 1.0 + 1e-6);
    EXPECT_GT(can.zoom.max, can.zoom.min);
    EXPECT_FALSE(std::isnan(before.zoom));
    return;  // the zoom goals of the other tests cover it
  }
  if (!can.zoom.present)
  {
    // The seed: "if the camera does not support zoom (e.g. the Flir D46 PTU), the zoom field is ignored". Every action
    // takes the goal on pan and tilt and says the zoom was ignored, in the device's words.
    const std::string words = can.zoom.limitation.empty() ? "the device has no zoom" : can.zoom.limitation;
    struct Ignored
    {
      PtzClient* client;
      PtzGoal goal;
      const char* text;
    };
    const std::vector<Ignored> ignored = {
      { absolute_, makePtzGoal(0.3, 0.1, 2.0), "zoom 2.0000 X ignored: " },
      { relative_, makePtzGoal(-0.1, 0.0, 1.5), "zoom offset 1.5000 X ignored: " },
      { velocity_, makePtzGoal(0.0, 0.0, 0.5), "zoom velocity 0.5000 X/s ignored: " },
    };
    for (const Ignored& item : ignored)
    {
      item.client->sendGoal(item.goal);
      ASSERT_TRUE(item.client->waitForResult(ros::Duration(GOAL_WAIT)));
      const std::string text = item.client->getState().getText();
      EXPECT_EQ(item.client->getState(), State::SUCCEEDED) << text;
      EXPECT_NE(text.find(item.text + words), std::string::npos) << "'" << text << "' should say '" << item.text << "'";
    }
    ASSERT_TRUE(observer_->waitTicks(2));
    EXPECT_NEAR(observer_->latest().pan, 0.2, 2 * TOLERANCE);  // 0.3, then 0.1 to the left of where it got
    EXPECT_NEAR(observer_->latest().tilt, 0.1, 2 * TOLERANCE);
    EXPECT_EQ(observer_->latest().zoom, 1.0f);  // a zoom it lacks is reported as 1
    return;
  }
  // A zoom it cannot position: a goal that asks for one is refused with the device's words, and nothing moves.
  struct Case
  {
    PtzClient* client;
    PtzGoal goal;
    const char* reason;
  };
  const std::vector<Case> cases = {
    { absolute_, makePtzGoal(0.3, 0.0, 4.0), "zoom goals are not supported" },
    { relative_, makePtzGoal(0.1, 0.0, 1.0), "zoom relative goals are not supported" },
    { velocity_, makePtzGoal(0.0, 0.0, 0.5), "zoom velocity goals are not supported" },
  };
  for (const Case& item : cases)
  {
    if (item.client == velocity_ && can.zoom.velocity)
    {
      continue;
    }
    item.client->sendGoal(item.goal);
    ASSERT_TRUE(item.client->waitForResult(ros::Duration(5.0)));
    EXPECT_EQ(item.client->getState(), State::REJECTED) << item.client->getState().getText();
    EXPECT_NE(item.client->getState().getText().find(item.reason), std::string::npos)
        << "'" << item.client->getState().getText() << "' should say '" << item.reason << "'";
    if (!can.zoom.limitation.empty())
    {
      EXPECT_NE(item.client->getState().getText().find(can.zoom.limitation.substr(0, 20)), std::string::npos)
          << item.client->getState().getText();
    }
  }
  ASSERT_TRUE(observer_->waitTicks(3));
  EXPECT_EQ(observer_->latest().pan, before.pan);
  // A zoom it lacks is reported as 1, one it cannot see as NaN.
  if (can.zoom.present)
  {
    EXPECT_TRUE(std::isnan(observer_->latest().zoom));
  }
  else
  {
    EXPECT_EQ(observer_->latest().zoom, 1.0f);
  }
}

/// Only in onvif_no_position_node.test: a camera whose status carries no position.
TEST_F(NodeTest, ACameraThatReportsNoPositionTakesVelocityGoalsAndCancelOnly)
{
  const ptz_action_server::PtzCapabilities& can = *capabilities_;
  for (const auto* axis : { &can.pan, &can.tilt })
  {
    EXPECT_TRUE(axis->present && axis->velocity);
    EXPECT_FALSE(axis->feedback);
    EXPECT_FALSE(axis->absolute);
    EXPECT_FALSE(axis->limitation.empty());
  }
  // Its pose is unknown: NaN in ptz_state, no pan or tilt joint in joint_states (nor tf).
  ASSERT_TRUE(observer_->waitTicks(2));
  EXPECT_TRUE(std::isnan(observer_->latest().pan));
  EXPECT_TRUE(std::isnan(observer_->latest().tilt));
  EXPECT_TRUE(observer_->latestJoints().name.empty());

  // Position, relative and frame goals need a position: refused with the camera's words.
  EXPECT_EQ(moveTo(0.3, 0.0, 0.0), State::REJECTED);
  EXPECT_NE(absolute_->getState().getText().find("pan goals are not supported"), std::string::npos)
      << absolute_->getState().getText();
  EXPECT_NE(absolute_->getState().getText().find(can.pan.limitation.substr(0, 20)), std::string::npos)
      << absolute_->getState().getText();
  relative_->sendGoal(makePtzGoal(0.1, 0.0, 0.0));
  ASSERT_TRUE(relative_->waitForResult(ros::Duration(5.0)));
  EXPECT_EQ(relative_->getState(), State::REJECTED) << relative_->getState().getText();

  // A velocity goal runs (no limit or stall can be seen, so it goes on) until cancelled.
  velocity_->sendGoal(makePtzGoal(0.3, 0.0, 0.0));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.mode == PtzState::MODE_VELOCITY; }, 10.0));
  ASSERT_TRUE(observer_->waitTicks(15));
  EXPECT_EQ(velocity_->getState(), State::ACTIVE) << velocity_->getState().getText();
  velocity_->cancelGoal();
  ASSERT_TRUE(velocity_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(velocity_->getState(), State::PREEMPTED) << velocity_->getState().getText();
  EXPECT_NE(velocity_->getState().getText().find("cancelled"), std::string::npos) << velocity_->getState().getText();
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.mode == PtzState::MODE_IDLE; }, 10.0));
}

/**
 * \file
 * \brief rostest client, goals that run their course: success with feedback, preemption, cancel, relative and
 * velocity goals, a storm of goals; and main() of test_node_client.
 */
#include <algorithm>
#include <memory>

#include "node_test.h"

TEST_F(NodeTest, PositionGoalSucceedsWithFeedback)
{
  ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  FeedbackLog<ptz_action_server::PtzFeedback> feedback;
  observer_->clear();
  absolute_->sendGoal(makePtzGoal(0.6, -0.3, zoomOr1(5.0)), PtzClient::SimpleDoneCallback(),
                      PtzClient::SimpleActiveCallback(), [&](const PtzFeedbackConstPtr& item) { feedback.add(*item); });
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

  ASSERT_TRUE(observer_->waitTicks(2));
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

  // Pan kept increasing from the start until it neared the second target: no stop in between. A device that
  // reports at the tick's own rate (DigiView: every 100 ms) may have no new report for one tick on a busy
  // machine, so a single unchanged tick is allowed; two in a row, or any step back, is a stop.
  const std::vector<PtzState> states = observer_->states();
  std::size_t rising = 0;
  std::size_t unchanged_in_a_row = 0;
  for (std::size_t index = 1; index < states.size() && states[index].pan < 1.5; ++index)
  {
    if (states[index - 1].pan > -0.99)
    {
      EXPECT_GE(states[index].pan, states[index - 1].pan) << "pan went back at tick " << index;
      unchanged_in_a_row = states[index].pan > states[index - 1].pan ? 0 : unchanged_in_a_row + 1;
      EXPECT_LT(unchanged_in_a_row, 2u) << "pan stopped at tick " << index;
      rising += unchanged_in_a_row == 0 ? 1 : 0;
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
  ASSERT_TRUE(observer_->waitTicks(2));
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

TEST_F(NodeTest, RelativeGoalMovesByTheOffset)
{
  ASSERT_EQ(moveTo(0.1, -0.2, zoomOr1(3.0)), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(2));
  const PtzState start = observer_->latest();
  relative_->sendGoal(makePtzGoal(0.25, 0.15, zoomable() ? 1.0 : 0.0));
  ASSERT_TRUE(relative_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(relative_->getState(), State::SUCCEEDED) << relative_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
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
  ASSERT_TRUE(observer_->waitTicks(2));
  const double stopped = observer_->latest().pan;
  ASSERT_TRUE(observer_->waitTicks(3));
  EXPECT_EQ(observer_->latest().pan, stopped);

  // Tilt up at 1 rad/s runs into the upper limit, and the goal ends there.
  velocity_->sendGoal(makePtzGoal(0.0, 1.0, 0.0));
  ASSERT_TRUE(velocity_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(velocity_->getState(), State::SUCCEEDED) << velocity_->getState().getText();
  EXPECT_NE(velocity_->getState().getText().find("tilt reached its upper limit"), std::string::npos)
      << velocity_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
  // The URDF's limit, unless the device's own is narrower (a gimbal manager's, given as ~tilt_upper_limit).
  double upper_limit = M_PI / 2;
  ros::NodeHandle("~").param("tilt_upper_limit", upper_limit, upper_limit);
  EXPECT_NEAR(observer_->latest().tilt, upper_limit, 0.01);
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

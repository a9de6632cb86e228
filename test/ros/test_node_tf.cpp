/**
 * \file
 * \brief rostest client, tf: the camera's transforms follow the contract's signs; frame and position_abs_tf goals.
 */
#include "node_test.h"

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
  frame_goal.zoom = zoomOr1(2.0);
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
  ASSERT_TRUE(observer_->waitTicks(2));
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

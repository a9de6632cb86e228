/**
 * \file
 * \brief rostest client, presets on whichever backend the .test file started: a preset saved at one pose is reached
 * from another through move_ptz/preset. (presets.test covers the rest against the sim, restarts included.)
 */
#include "node_test.h"

#include "ptz_action_server/DeletePreset.h"
#include "ptz_action_server/PtzPresetAction.h"
#include "ptz_action_server/SavePreset.h"

TEST_F(NodeTest, APresetSavedHereIsReachedFromElsewhere)
{
  ros::NodeHandle node_handle;
  const std::string save_name = node_handle.resolveName("move_ptz/save_preset");
  ASSERT_TRUE(ros::service::waitForService(save_name, ros::Duration(GOAL_WAIT)));
  actionlib::SimpleActionClient<ptz_action_server::PtzPresetAction> preset("move_ptz/preset", true);
  ASSERT_TRUE(preset.waitForServer(ros::Duration(GOAL_WAIT)));

  ASSERT_EQ(moveTo(0.4, -0.2, 1.0), State::SUCCEEDED);
  ASSERT_TRUE(observer_->waitTicks(2));  // the result can come before the state that shows the goal reached
  const PtzState saved_at = observer_->latest();
  ptz_action_server::SavePreset save;
  save.request.name = "node_test";
  ASSERT_TRUE(ros::service::call(save_name, save));
  ASSERT_TRUE(save.response.success) << save.response.message;

  ASSERT_EQ(moveTo(-0.3, 0.1, 1.0), State::SUCCEEDED);
  ptz_action_server::PtzPresetGoal goal;
  goal.name = "node_test";
  preset.sendGoal(goal);
  ASSERT_TRUE(preset.waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(preset.getState(), State::SUCCEEDED) << preset.getState().getText();
  EXPECT_TRUE(preset.getResult()->success);
  EXPECT_TRUE(observer_->waitFor(
      [&](const PtzState& state) {
        return std::abs(state.pan - saved_at.pan) < 2 * TOLERANCE &&
               std::abs(state.tilt - saved_at.tilt) < 2 * TOLERANCE;
      },
      5.0))
      << "saved at pan " << saved_at.pan << " tilt " << saved_at.tilt << ", now pan " << observer_->latest().pan
      << " tilt " << observer_->latest().tilt;

  ptz_action_server::DeletePreset remove;
  remove.request.name = "node_test";
  ASSERT_TRUE(ros::service::call(node_handle.resolveName("move_ptz/delete_preset"), remove));
  EXPECT_TRUE(remove.response.success) << remove.response.message;
}

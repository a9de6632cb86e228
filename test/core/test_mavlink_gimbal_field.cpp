/**
 * \file
 * \brief The MAVLink gimbal backend against autopilots as the field has them, each an emulator mode: one that speaks
 * only gimbal protocol v1 (the start says so and what to set), PX4's own gimbal output (YAW_LOCK on every attitude
 * while its yaw is the vehicle's, no delta_yaw) and PX4 losing YAW_IN_EARTH_FRAME from setpoints.
 */
#include <gtest/gtest.h>

#include <string>

#include "mavlink_gimbal_test_fixture.h"

namespace ptz_action_server
{
namespace
{
using namespace mavlink_gimbal_test;

class MavlinkGimbalFieldTest : public MavlinkGimbalTest
{
};

TEST_F(MavlinkGimbalFieldTest, AnAutopilotSpeakingOnlyGimbalProtocolV1FailsTheStartSayingSoAndWhatToSet)
{
  emulator_config_.gimbal_v1 = true;  // PX4 with its mount on MAVLink v1: MOUNT_ORIENTATION, no manager
  startEmulator();
  const std::string failure = startFailure();
  EXPECT_NE(failure.find("no gimbal manager answered REQUEST_MESSAGE GIMBAL_MANAGER_INFORMATION: the autopilot 1/1 "
                         "(PX4) speaks gimbal protocol v1 (it sends MOUNT_ORIENTATION) (the old protocol: this node "
                         "speaks only v2); a gimbal manager (MAVLink Gimbal Protocol v2) is needed: on PX4 (1.13 or "
                         "later) set MNT_MODE_IN to 4"),
            std::string::npos)
      << failure;
  EXPECT_EQ(failure.find("within"), std::string::npos) << "said before the start-up timeout: " << failure;
}

TEST_F(MavlinkGimbalFieldTest, AnArduPilotWithMountStatusIsToldItsParameter)
{
  emulator_config_.gimbal_v1 = true;
  emulator_config_.v1_mount_status = true;
  startEmulator();
  const std::string failure = startFailure();
  EXPECT_NE(failure.find("the autopilot 1/1 (ArduPilot) speaks gimbal protocol v1 (it sends MOUNT_STATUS)"),
            std::string::npos)
      << failure;
  EXPECT_NE(failure.find("on ArduPilot (4.3 or later; 4.4 for GIMBAL_MANAGER_INFORMATION) set MNT1_TYPE"),
            std::string::npos)
      << failure;
  EXPECT_EQ(failure.find("MNT_MODE_IN"), std::string::npos) << failure;
}

TEST_F(MavlinkGimbalFieldTest, PX4sOwnGimbalOutputIsReadInTheVehicleFrameWhateverItsYawLockSays)
{
  emulator_config_.px4_gimbal_output = true;
  emulator_config_.vehicle_yaw = 0.5;
  config_.settings.yaw_lock = true;  // goals relative to North
  startBoth();
  backend_->goTo(AxisValues{ { 0.8, 0.1, 1.0 } });
  // North 0.8 with the vehicle heading 0.5 (its ATTITUDE; PX4's delta_yaw is 0): 0.3 right of the vehicle's nose.
  ASSERT_TRUE(waitUntil([&] { return reached(0.8, 0.1); }, WAIT)) << backend_->sample().position[PAN];
  EXPECT_NEAR(emulator_->gimbal().position[PAN], 0.3, 1e-3);
  EXPECT_EQ(diagnostic("attitude yaw frame"), "auto: read as the vehicle's");
}

TEST_F(MavlinkGimbalFieldTest, PX4sOwnGimbalOutputInTheVehicleFrameNeedsNoHeading)
{
  emulator_config_.px4_gimbal_output = true;
  emulator_config_.vehicle_yaw = 0.5;
  startBoth();
  backend_->goTo(AxisValues{ { -0.4, 0.0, 1.0 } });
  ASSERT_TRUE(waitUntil([&] { return reached(-0.4, 0.0); }, WAIT)) << backend_->sample().position[PAN];
  EXPECT_NEAR(emulator_->gimbal().position[PAN], -0.4, 1e-3);
  EXPECT_EQ(backend_->protocol<MavlinkGimbalProtocol>().counters().unusable_attitudes.value(), 0u);
}

TEST_F(MavlinkGimbalFieldTest, TheFlagsSettingReadsYawLockAsNorthAsTheDefinitionSays)
{
  // A gimbal whose YAW_LOCK is right (not PX4's own output): attitude_yaw_frame flags takes it at its word.
  emulator_config_.px4_gimbal_output = true;
  emulator_config_.vehicle_yaw = 0.5;
  config_.settings.attitude_yaw_frame = MavlinkYawFrame::FLAGS;
  startBoth();
  // The gimbal at 0 (vehicle frame), read as North 0: the vehicle frame's -0.5.
  ASSERT_TRUE(waitUntil([&] { return reached(-0.5, 0.0); }, WAIT)) << backend_->sample().position[PAN];
  EXPECT_EQ(diagnostic("attitude yaw frame"), "flags: read as North");
}

TEST_F(MavlinkGimbalFieldTest, YawLockGoalsStillAimAtNorthWhenTheEarthFrameFlagIsDropped)
{
  // PX4 issue 26569: YAW_IN_EARTH_FRAME never reaches the gimbal. The backend says North with YAW_LOCK.
  emulator_config_.earth_frame_flag_dropped = true;
  emulator_config_.vehicle_yaw = 0.5;
  config_.settings.yaw_lock = true;
  startBoth();
  backend_->goTo(AxisValues{ { 0.8, 0.0, 1.0 } });
  ASSERT_TRUE(waitUntil([&] { return reached(0.8, 0.0); }, WAIT)) << backend_->sample().position[PAN];
  EXPECT_NEAR(emulator_->gimbal().position[PAN], 0.3, 1e-3);
}

}  // namespace
}  // namespace ptz_action_server

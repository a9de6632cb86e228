/**
 * \file
 * \brief The MAVLink gimbal backend where a vehicle has several gimbals (issue 21's field cases): which one it
 * takes, drives, reports and releases, and how it says which it could not choose.
 */
#include <gtest/gtest.h>

#include <string>

#include "mavlink_gimbal_test_fixture.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using namespace mavlink_gimbal_test;

TEST_F(MavlinkGimbalTest, TwoGimbalsBehindOneManagerAndNoneChosenFailTheStartNamingBoth)
{
  setGimbals({ 1, 2 });
  startEmulator();
  const std::string error = startFailure();
  EXPECT_NE(error.find("several gimbals found and none chosen"), std::string::npos) << error;
  EXPECT_NE(error.find("gimbal_device_id 1 of the gimbal manager 1/1"), std::string::npos) << error;
  EXPECT_NE(error.find("gimbal_device_id 2 of the gimbal manager 1/1"), std::string::npos) << error;
  EXPECT_NE(error.find("choose one with gimbal_device_id"), std::string::npos) << error;
  EXPECT_TRUE(commandsReceived(command_id::DO_GIMBAL_MANAGER_CONFIGURE).empty()) << "took a gimbal it had not chosen";
}

TEST_F(MavlinkGimbalTest, TwoGimbalDevicesAndNoneChosenFailTheStartNamingBoth)
{
  setGimbals({ MAV_COMP_ID_GIMBAL, MAV_COMP_ID_GIMBAL2 });
  startEmulator();
  const std::string error = startFailure();
  EXPECT_NE(error.find("gimbal_device_id 154 (the gimbal device 1/154) of the gimbal manager 1/1"), std::string::npos)
      << error;
  EXPECT_NE(error.find("gimbal_device_id 171 (the gimbal device 1/171) of the gimbal manager 1/1"), std::string::npos)
      << error;
  EXPECT_TRUE(commandsReceived(command_id::DO_GIMBAL_MANAGER_CONFIGURE).empty());
}

TEST_F(MavlinkGimbalTest, TwoGimbalsThatAreTheirOwnManagersAreToldApartByTheirComponent)
{
  // Two camera-gimbals, each its own manager with its gimbal inside (gimbal_device_id 1 in both).
  emulator_config_.component_id = MAV_COMP_ID_GIMBAL;
  emulator_config_.gimbals.resize(2);
  emulator_config_.gimbals[1].manager_component = 155;
  emulator_config_.gimbals[1].device.axes[PAN].initial_position = 1.0;
  startEmulator();
  const std::string error = startFailure();
  EXPECT_NE(error.find("gimbal_device_id 1 of the gimbal manager 1/154"), std::string::npos) << error;
  EXPECT_NE(error.find("gimbal_device_id 1 of the gimbal manager 1/155"), std::string::npos) << error;
  EXPECT_NE(error.find("target_component"), std::string::npos) << error;

  config_.settings.target_component = 155;
  startBackend();
  EXPECT_EQ(emulator_->primaryController(1).second, 191);
  EXPECT_EQ(emulator_->primaryController(0).second, 0);
  EXPECT_TRUE(waitUntil([&] { return std::abs(backend_->sample().position[PAN] - 1.0) < 1e-3; }, WAIT)) << "the state "
                                                                                                           "of 1/155's "
                                                                                                           "gimbal";
}

TEST_F(MavlinkGimbalTest, OfTwoGimbalsBehindOneManagerOnlyTheChosenOneIsTakenDrivenReportedAndReleased)
{
  setGimbals({ 1, 2 }, 1.0, -0.5);
  config_.settings.gimbal_device_id = 2;
  startEmulator();
  emulator_->giveControlTo(3, 190, true, 0);  // the other gimbal is someone else's
  startBackend();
  EXPECT_EQ(protocol().gimbal().device_id, 2);
  expectOnlyOursIsTaken(1, 2, 0, MAV_COMP_ID_AUTOPILOT1);
}

TEST_F(MavlinkGimbalTest, OfTwoGimbalDevicesOnlyTheChosenOneIsTakenDrivenReportedAndReleased)
{
  // The autopilot manages the MAVLink gimbal devices 1/154 and 1/171; 154 sends its attitude with gimbal_device_id 0
  // from its own component, which the node once took for its gimbal's.
  setGimbals({ MAV_COMP_ID_GIMBAL, MAV_COMP_ID_GIMBAL2 }, 1.0, -0.5);
  config_.settings.gimbal_device_id = MAV_COMP_ID_GIMBAL2;
  startEmulator();
  emulator_->giveControlTo(3, 190, true, 0);
  startBackend();
  // The attitude is asked of the device that sends it.
  EXPECT_FALSE(commandsTo(command_id::SET_MESSAGE_INTERVAL, MAV_COMP_ID_GIMBAL2).empty());
  EXPECT_TRUE(commandsTo(command_id::SET_MESSAGE_INTERVAL, MAV_COMP_ID_GIMBAL).empty());
  expectOnlyOursIsTaken(1, MAV_COMP_ID_GIMBAL2, 0, MAV_COMP_ID_AUTOPILOT1);
}

TEST_F(MavlinkGimbalTest, TheOnlyGimbalDeviceBehindAnAutopilotIsChosenByItself)
{
  setGimbals({ MAV_COMP_ID_GIMBAL });
  startBoth();
  EXPECT_EQ(protocol().gimbal(), (MavlinkGimbalAddress{ 1, 1, MAV_COMP_ID_GIMBAL }));
  EXPECT_EQ(emulator_->primaryController().second, 191);
  backend_->goTo(AxisValues{ { -0.3, 0.1, 1.0 } });
  EXPECT_TRUE(waitUntil([&] { return reached(-0.3, 0.1); }, WAIT));
  EXPECT_EQ(setpoints().back().gimbal_device_id, MAV_COMP_ID_GIMBAL);
  EXPECT_EQ(protocol().counters().other_attitudes.value(), 0u);
}

TEST_F(MavlinkGimbalTest, AGimbalNamedThatIsNotThereFailsTheStartNamingThoseThatAre)
{
  config_.settings.gimbal_device_id = 3;
  startEmulator();
  const std::string error = startFailure();
  EXPECT_NE(error.find("no gimbal found matches"), std::string::npos) << error;
  EXPECT_NE(error.find("gimbal_device_id 3"), std::string::npos) << error;
  EXPECT_NE(error.find("found: gimbal_device_id 1 of the gimbal manager 1/1"), std::string::npos) << error;
}

TEST_F(MavlinkGimbalTest, TakingControlFromAnotherControllerIsWarnedOnceNamingIt)
{
  startEmulator();
  emulator_->giveControlTo(1, 190, false);  // a ground station took it earlier, and yields it
  startBackend();
  EXPECT_EQ(emulator_->primaryController().second, 191);
  const std::vector<std::string> said = warnings();
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("from 1/190"), std::string::npos) << said[0];
  EXPECT_NE(said[0].find("gimbal_device_id 1 of the gimbal manager 1/1"), std::string::npos) << said[0];
  EXPECT_EQ(diagnostic("previous controller"), "1/190");
}

TEST_F(MavlinkGimbalTest, ANameInFullNeedsNoDiscoveryWait)
{
  config_.settings.target_system = 1;
  config_.settings.target_component = 1;
  config_.settings.gimbal_device_id = 1;
  config_.settings.discovery_time = 30.0;  // would outlast the start-up timeout
  startBoth();
  EXPECT_EQ(protocol().gimbal().device_id, 1);
}

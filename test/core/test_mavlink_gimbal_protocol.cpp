/**
 * \file
 * \brief The MAVLink gimbal backend against the emulator: start-up, goals, control taken and given back, frames
 * and diagnostics.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mavlink_gimbal_test_fixture.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using namespace mavlink_gimbal_test;

TEST_F(MavlinkGimbalTest, StartUpFindsTheManagerTakesControlAndAsksForTheAttitude)
{
  startBoth();
  EXPECT_EQ(emulator_->primaryController().first, 1);
  EXPECT_EQ(emulator_->primaryController().second, 191);
  const auto configure = commandsReceived(command_id::DO_GIMBAL_MANAGER_CONFIGURE);
  ASSERT_FALSE(configure.empty());
  EXPECT_EQ(configure[0].params[0], 1.0f);
  EXPECT_EQ(configure[0].params[1], 191.0f);
  EXPECT_EQ(configure[0].params[2], -1.0f) << "secondary control left unchanged";
  EXPECT_EQ(configure[0].params[6], 1.0f) << "the gimbal the manager's information named";
  EXPECT_EQ(configure[0].target_system, 1);
  EXPECT_EQ(configure[0].target_component, 1);
  const auto interval = commandsReceived(command_id::SET_MESSAGE_INTERVAL);
  ASSERT_FALSE(interval.empty());
  EXPECT_EQ(interval[0].params[0], 285.0f);
  EXPECT_EQ(interval[0].params[1], 50000.0f);
  // Limits: the manager's pitch range (-pi/2 .. pi/4) narrows the settings' default.
  EXPECT_NEAR(backend_->capabilities().axes[TILT].range.max, M_PI / 4.0, 1e-6);
  // What a gimbal manager offers: angles and rates for pitch and yaw, and the attitude back; no zoom.
  const Capabilities capabilities = backend_->capabilities();
  for (Axis axis : { PAN, TILT })
  {
    const AxisCapability& capability = capabilities.axes[axis];
    EXPECT_TRUE(capability.present && capability.absolute && capability.velocity && capability.feedback) << axis;
  }
  EXPECT_FALSE(capabilities.axes[ZOOM].present);
  EXPECT_FALSE(capabilities.axes[ZOOM].limitation.empty());
}

TEST_F(MavlinkGimbalTest, AGimbalThatIsItsOwnManagerIsFoundToo)
{
  // A camera-gimbal at component 154 that is its own manager: its gimbal is inside it, gimbal_device_id 1.
  emulator_config_.component_id = MAV_COMP_ID_GIMBAL;
  startBoth();
  EXPECT_EQ(emulator_->primaryController().second, 191);
  backend_->goTo(AxisValues{ { 0.2, -0.3, 1.0 } });
  EXPECT_TRUE(waitUntil([&] { return reached(0.2, -0.3); }, WAIT));
  const auto sent = setpoints();
  ASSERT_FALSE(sent.empty());
  EXPECT_EQ(sent.back().target_component, MAV_COMP_ID_GIMBAL);
  EXPECT_EQ(sent.back().gimbal_device_id, 1);
}

TEST_F(MavlinkGimbalTest, AManagerThatRefusesControlFailsTheStartWithItsResult)
{
  startEmulator();
  emulator_->setRefuse(true);
  backend_ = makeDeviceBackend<MavlinkGimbalProtocol>(config_);
  try
  {
    backend_->start();
    FAIL() << "started without primary control";
  }
  catch (const BackendError& error)
  {
    EXPECT_NE(std::string(error.what()).find("refused DO_GIMBAL_MANAGER_CONFIGURE: DENIED"), std::string::npos)
        << error.what();
  }
}

TEST_F(MavlinkGimbalTest, AnotherControllerHoldingControlIsNamedInTheStartError)
{
  startEmulator();
  emulator_->giveControlTo(3, 190);
  backend_ = makeDeviceBackend<MavlinkGimbalProtocol>(config_);
  try
  {
    backend_->start();
    FAIL() << "started while 3/190 holds control";
  }
  catch (const BackendError& error)
  {
    EXPECT_NE(std::string(error.what()).find("held by 3/190"), std::string::npos) << error.what();
  }
}

TEST_F(MavlinkGimbalTest, APositionGoalIsAPitchYawSetpointWithNanRates)
{
  startBoth();
  backend_->goTo(AxisValues{ { -0.6, 0.4, 1.0 } });
  ASSERT_TRUE(waitUntil([&] { return reached(-0.6, 0.4); }, WAIT));
  const auto sent = setpoints();
  ASSERT_FALSE(sent.empty());
  EXPECT_FLOAT_EQ(sent.front().yaw, -0.6f);
  EXPECT_FLOAT_EQ(sent.front().pitch, 0.4f);
  EXPECT_TRUE(std::isnan(sent.front().yaw_rate));
  EXPECT_TRUE(std::isnan(sent.front().pitch_rate));
  EXPECT_EQ(sent.front().flags, 0u);
  EXPECT_NEAR(emulator_->gimbal().position[PAN], -0.6, 1e-3);
  EXPECT_NEAR(emulator_->gimbal().position[TILT], 0.4, 1e-3);
}

TEST_F(MavlinkGimbalTest, AVelocityGoalIsRepeatedFasterThanTheRateTimeoutAndCancelStopsItWhereItIs)
{
  emulator_config_.rate_timeout = 0.3;
  startBoth();
  emulator_->received().clear();
  backend_->moveAtVelocity(AxisValues{ { 0.4, 0.0, 0.0 } });
  // Longer than several rate timeouts: the gimbal keeps turning only if the rates are repeated.
  ASSERT_TRUE(waitUntil([&] { return emulator_->gimbal().position[PAN] > 0.5; }, WAIT));
  EXPECT_EQ(emulator_->counters().rate_timeouts, 0u);
  const auto sent = setpoints();
  ASSERT_GE(sent.size(), 5u);
  for (const auto& setpoint : sent)
  {
    EXPECT_TRUE(std::isnan(setpoint.yaw) && std::isnan(setpoint.pitch));
    EXPECT_FLOAT_EQ(setpoint.yaw_rate, 0.4f);
  }
  emulator_->received().clear();
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !emulator_->gimbal().moving; }, WAIT));
  const auto stops = setpoints();
  ASSERT_FALSE(stops.empty());
  EXPECT_EQ(stops.front().yaw_rate, 0.0f);
  EXPECT_EQ(stops.front().pitch_rate, 0.0f);
  EXPECT_TRUE(std::isnan(stops.front().yaw));
  const double rest = emulator_->gimbal().position[PAN];
  EXPECT_GT(rest, 0.5) << "stopped where it was, not sent back";
}

TEST_F(MavlinkGimbalTest, RatesRepeatedTooSlowlyTimeOutAtTheManager)
{
  // The emulator's rate timeout, seen by repeating slower than it: the repeats above are what keep a gimbal going.
  emulator_config_.rate_timeout = 0.2;
  config_.settings.rate_period = 0.6;
  startBoth();
  backend_->moveAtVelocity(AxisValues{ { 0.5, 0.0, 0.0 } });
  EXPECT_TRUE(waitUntil([&] { return emulator_->counters().rate_timeouts > 0; }, WAIT));
}

TEST_F(MavlinkGimbalTest, ControlTakenMidGoalAbortsItAndControlIsTakenBackWhenFree)
{
  startBoth();
  const std::uint64_t faults = backend_->sample().fault_count;
  backend_->goTo(AxisValues{ { 2.5, 0.0, 1.0 } });
  emulator_->giveControlTo(3, 190);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().fault_count > faults; }, WAIT));
  EXPECT_NE(backend_->lastFault().find("gave primary control of the gimbal to 3/190"), std::string::npos)
      << backend_->lastFault();
  EXPECT_EQ(protocol().counters().control_lost, 1u);
  emulator_->releaseControl();
  ASSERT_TRUE(waitUntil([&] { return emulator_->primaryController().second == 191; }, WAIT));
  backend_->goTo(AxisValues{ { -0.2, 0.1, 1.0 } });
  EXPECT_TRUE(waitUntil([&] { return reached(-0.2, 0.1); }, WAIT));
}

TEST_F(MavlinkGimbalTest, AnAttitudeInTheEarthFrameIsTurnedIntoTheVehicles)
{
  emulator_config_.report_earth_frame = true;
  emulator_config_.vehicle_yaw = 0.5;
  startBoth();
  backend_->goTo(AxisValues{ { 0.3, 0.0, 1.0 } });
  ASSERT_TRUE(waitUntil([&] { return reached(0.3, 0.0); }, WAIT)) << backend_->sample().position[PAN];
  EXPECT_NEAR(emulator_->gimbal().position[PAN], 0.3, 1e-3);
}

TEST_F(MavlinkGimbalTest, YawLockAimsRelativeToNorth)
{
  emulator_config_.vehicle_yaw = 0.5;
  config_.settings.yaw_lock = true;
  startBoth();
  backend_->goTo(AxisValues{ { 0.8, 0.0, 1.0 } });
  ASSERT_TRUE(waitUntil([&] { return reached(0.8, 0.0); }, WAIT)) << backend_->sample().position[PAN];
  // North 0.8 with the vehicle heading 0.5: 0.3 to the right of the vehicle's nose.
  EXPECT_NEAR(emulator_->gimbal().position[PAN], 0.3, 1e-3);
  EXPECT_EQ(setpoints().back().flags, gimbal_flags::YAW_LOCK);
}

TEST_F(MavlinkGimbalTest, HeartbeatsGoOutAndShutdownReleasesControl)
{
  startBoth();
  ASSERT_TRUE(emulator_->received().waitFor(
      [](const ReceivedMavlinkFrame& item) {
        return item.frame.message_id == message_id::HEARTBEAT && item.frame.header.component_id == 191 &&
               decode<Heartbeat>(item.frame).type == MAV_TYPE_ONBOARD_CONTROLLER;
      },
      WAIT));
  backend_.reset();
  EXPECT_TRUE(waitUntil([&] { return emulator_->primaryController().first == 0; }, WAIT));
}

TEST_F(MavlinkGimbalTest, DiagnosticsNameTheManagerAndCountTheFrames)
{
  startBoth();
  std::vector<DiagnosticValue> values;
  backend_->diagnostics(values);
  auto value = [&values](const std::string& name) {
    for (const auto& entry : values)
    {
      if (entry.first == name)
      {
        return entry.second;
      }
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(value("gimbal manager"), "1/1");
  EXPECT_EQ(value("gimbal"), "gimbal_device_id 1 of the gimbal manager 1/1");
  EXPECT_EQ(value("previous controller"), "none");
  EXPECT_EQ(value("primary control"), "ours");
  EXPECT_NE(value("frames"), "0");
  EXPECT_EQ(value("dropped: bad_checksum"), "0");
}

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"
#include "wait_until.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;

namespace
{
constexpr double WAIT = 10.0;  ///< s: generous, the machine may be busy

/// A gimbal manager emulator on UDP and a backend configured for it (started by the test).
class MavlinkGimbalTest : public ::testing::Test
{
protected:
  void startEmulator()
  {
    emulator_ = std::make_unique<MavlinkGimbalEmulator>(emulator_config_);
    config_.link.port = emulator_->udpPort();
    config_.link.local_host = "127.0.0.1";
    config_.session.state_timeout = 1.0;
    config_.session.startup_timeout = 5.0;
  }
  void startBoth()
  {
    startEmulator();
    backend_ = makeMavlinkGimbalBackend(config_);
    backend_->start();
  }
  const MavlinkGimbalProtocol& protocol() const
  {
    return backend_->protocol<MavlinkGimbalProtocol>();
  }
  /// The SET_PITCHYAW setpoints the manager received from us.
  std::vector<GimbalManagerSetPitchYaw> setpoints() const
  {
    std::vector<GimbalManagerSetPitchYaw> found;
    for (const ReceivedMavlinkFrame& item : emulator_->received().items())
    {
      if (item.frame.message_id == message_id::GIMBAL_MANAGER_SET_PITCHYAW)
      {
        found.push_back(decode<GimbalManagerSetPitchYaw>(item.frame));
      }
    }
    return found;
  }
  std::vector<CommandLong> commandsReceived(std::uint16_t id) const
  {
    std::vector<CommandLong> found;
    for (const ReceivedMavlinkFrame& item : emulator_->received().items())
    {
      if (item.frame.message_id == message_id::COMMAND_LONG && decode<CommandLong>(item.frame).command == id)
      {
        found.push_back(decode<CommandLong>(item.frame));
      }
    }
    return found;
  }
  bool reached(double pan, double tilt, double tolerance = 0.01) const
  {
    const PtzSample sample = backend_->sample();
    return sample.link_up && !sample.moving && std::abs(sample.position[PAN] - pan) < tolerance &&
           std::abs(sample.position[TILT] - tilt) < tolerance;
  }

  MavlinkGimbalEmulatorConfig emulator_config_;
  std::unique_ptr<MavlinkGimbalEmulator> emulator_;
  MavlinkGimbalConfig config_;
  std::unique_ptr<DeviceBackend> backend_;
};
}  // namespace

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
  EXPECT_FALSE(backend_->capabilities().axes[ZOOM].present);
}

TEST_F(MavlinkGimbalTest, AGimbalThatIsItsOwnManagerIsFoundToo)
{
  emulator_config_.component_id = MAV_COMP_ID_GIMBAL;
  emulator_config_.gimbal_device_id = MAV_COMP_ID_GIMBAL;
  startBoth();
  EXPECT_EQ(emulator_->primaryController().second, 191);
  backend_->goTo(AxisValues{ { 0.2, -0.3, 1.0 } });
  EXPECT_TRUE(waitUntil([&] { return reached(0.2, -0.3); }, WAIT));
  const auto sent = setpoints();
  ASSERT_FALSE(sent.empty());
  EXPECT_EQ(sent.back().target_component, MAV_COMP_ID_GIMBAL);
  EXPECT_EQ(sent.back().gimbal_device_id, MAV_COMP_ID_GIMBAL);
}

TEST_F(MavlinkGimbalTest, AManagerThatRefusesControlFailsTheStartWithItsResult)
{
  startEmulator();
  emulator_->setRefuse(true);
  backend_ = makeMavlinkGimbalBackend(config_);
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
  backend_ = makeMavlinkGimbalBackend(config_);
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
  config_.gimbal.rate_period = 0.6;
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
  config_.gimbal.yaw_lock = true;
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
  EXPECT_EQ(value("primary control"), "ours");
  EXPECT_NE(value("frames"), "0");
  EXPECT_EQ(value("dropped: bad_checksum"), "0");
}

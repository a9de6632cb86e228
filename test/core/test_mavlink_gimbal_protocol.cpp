#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "diagnostic_value.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"
#include "wait_until.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;

namespace
{
constexpr double WAIT = 10.0;  ///< s: generous, the machine may be busy
/// Who holds primary control: system, component.
using Controller = std::pair<std::uint8_t, std::uint8_t>;

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
    startBackend();
  }
  void startBackend()
  {
    backend_ = makeDeviceBackend<MavlinkGimbalProtocol>(config_);
    backend_->start();
  }
  /// The text start() fails with ("" if it does not).
  std::string startFailure()
  {
    try
    {
      startBackend();
    }
    catch (const BackendError& error)
    {
      return error.what();
    }
    return "";
  }
  /// Every warning the backend gave so far (what the node would log).
  std::vector<std::string> warnings()
  {
    for (const std::string& text : backend_->takeWarnings())
    {
      warnings_.push_back(text);
    }
    return warnings_;
  }
  /// Gimbals of the emulator: the first at \p first_pan / \p first_tilt (to tell their attitudes apart), the
  /// others at 0 / 0.
  void setGimbals(const std::vector<std::uint8_t>& device_ids, double first_pan = 0.0, double first_tilt = 0.0)
  {
    emulator_config_.gimbals.clear();
    for (std::uint8_t id : device_ids)
    {
      MavlinkEmulatedGimbal gimbal;
      gimbal.device_id = id;
      emulator_config_.gimbals.push_back(gimbal);
    }
    emulator_config_.gimbals.front().device.axes[PAN].initial_position = first_pan;
    emulator_config_.gimbals.front().device.axes[TILT].initial_position = first_tilt;
  }
  std::string diagnostic(const std::string& name) const
  {
    return diagnosticValue(*backend_, name);
  }
  /// The COMMAND_LONGs of \p id the emulator received, with the component each was sent to.
  std::vector<CommandLong> commandsTo(std::uint16_t id, std::uint8_t component) const
  {
    std::vector<CommandLong> found;
    for (const CommandLong& command : commandsReceived(id))
    {
      if (command.target_component == component)
      {
        found.push_back(command);
      }
    }
    return found;
  }
  /// Checks, for two gimbals of which the backend drives the one at \p ours (index in the emulator's gimbals) named
  /// \p ours_id and leaves alone \p other (at 1.0 / -0.5, under 3/190's control): configured, driven, reported and
  /// released, that one only.
  void expectOnlyOursIsTaken(std::size_t ours, std::uint8_t ours_id, std::size_t other, std::uint8_t manager)
  {
    EXPECT_EQ(emulator_->primaryController(ours), Controller(1, 191));
    EXPECT_EQ(emulator_->primaryController(other), Controller(3, 190));
    const auto configure = commandsReceived(command_id::DO_GIMBAL_MANAGER_CONFIGURE);
    ASSERT_FALSE(configure.empty());
    for (const CommandLong& command : configure)
    {
      EXPECT_EQ(command.params[6], static_cast<float>(ours_id)) << "DO_GIMBAL_MANAGER_CONFIGURE for another gimbal";
      EXPECT_EQ(command.target_component, manager);
    }
    EXPECT_TRUE(warnings().empty()) << "no one held our gimbal: " << warnings().front();

    // The other gimbal's attitudes arrive and are dropped: the state is ours (0 / 0), never the other's.
    ASSERT_TRUE(waitUntil([&] { return protocol().counters().other_attitudes.value() >= 2; }, WAIT));
    EXPECT_NEAR(backend_->sample().position[PAN], 0.0, 1e-3);
    EXPECT_NEAR(backend_->sample().position[TILT], 0.0, 1e-3);

    backend_->goTo(AxisValues{ { 0.4, 0.2, 1.0 } });
    ASSERT_TRUE(waitUntil([&] { return reached(0.4, 0.2); }, WAIT));
    EXPECT_NEAR(emulator_->gimbal(ours).position[PAN], 0.4, 1e-3);
    EXPECT_NEAR(emulator_->gimbal(other).position[PAN], 1.0, 1e-3) << "the other gimbal was driven";
    EXPECT_NEAR(emulator_->gimbal(other).position[TILT], -0.5, 1e-3);
    EXPECT_EQ(emulator_->counters().executed_per_gimbal[other], 0u);
    for (const GimbalManagerSetPitchYaw& setpoint : setpoints())
    {
      EXPECT_EQ(setpoint.gimbal_device_id, ours_id);
      EXPECT_EQ(setpoint.target_component, manager);
    }
    EXPECT_GT(protocol().counters().other_attitudes.value(), 0u);

    // Shutdown releases ours, and only ours.
    emulator_->received().clear();
    backend_.reset();
    EXPECT_TRUE(waitUntil([&] { return emulator_->primaryController(ours).first == 0; }, WAIT));
    const auto release = commandsReceived(command_id::DO_GIMBAL_MANAGER_CONFIGURE);
    ASSERT_EQ(release.size(), 1u);
    EXPECT_EQ(release[0].params[0], -3.0f);
    EXPECT_EQ(release[0].params[6], static_cast<float>(ours_id));
    EXPECT_EQ(emulator_->primaryController(other), Controller(3, 190));
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
  DeviceConfig<MavlinkGimbalProtocol> config_;
  std::unique_ptr<DeviceBackend> backend_;
  std::vector<std::string> warnings_;
};

/// A bare MAVLink controller on UDP (as 1/200), to see what the emulator sends and does without the backend.
class RawController
{
public:
  explicit RawController(std::uint16_t port) : to_(UdpEndpoint::resolve("127.0.0.1", port))
  {
    socket_.bind("127.0.0.1", 0);
    thread_ = std::thread([this] { run(); });
  }
  ~RawController()
  {
    running_ = false;
    socket_.interrupt();
    thread_.join();
  }
  template <class Message>
  void send(const Message& message)
  {
    const EncodedFrame frame = encode(FrameHeader{ sequence_++, SYSTEM, COMPONENT }, message);
    socket_.sendTo(to_, frame.data(), frame.size);
  }
  void command(std::uint8_t component, std::uint16_t id, const std::array<float, 7>& params)
  {
    CommandLong message;
    message.params = params;
    message.command = id;
    message.target_system = 1;
    message.target_component = component;
    send(message);
  }
  /// Takes primary control of gimbal \p gimbal_device_id of the manager at \p manager.
  void takeControl(std::uint8_t manager, std::uint8_t gimbal_device_id)
  {
    command(manager, command_id::DO_GIMBAL_MANAGER_CONFIGURE,
            { static_cast<float>(SYSTEM), static_cast<float>(COMPONENT), -1, -1, 0, 0,
              static_cast<float>(gimbal_device_id) });
  }
  /// Frames of \p id from \p component (0: any) received so far.
  std::vector<Frame> frames(std::uint32_t id, std::uint8_t component = 0) const
  {
    std::vector<Frame> found;
    for (const Frame& frame : received_.items())
    {
      if (frame.message_id == id && (component == 0 || frame.header.component_id == component))
      {
        found.push_back(frame);
      }
    }
    return found;
  }
  bool waitFor(std::uint32_t id, std::uint8_t component, const std::function<bool(const Frame&)>& also = nullptr)
  {
    return received_.waitFor(
        [&](const Frame& frame) {
          return frame.message_id == id && frame.header.component_id == component && (!also || also(frame));
        },
        WAIT);
  }

  static constexpr std::uint8_t SYSTEM = 1;
  static constexpr std::uint8_t COMPONENT = 200;

private:
  void run()
  {
    std::array<std::uint8_t, 2048> buffer{};
    while (running_)
    {
      std::size_t size = 0;
      UdpEndpoint from;
      if (socket_.receive(buffer.data(), buffer.size(), size, from, 10) == ReceiveStatus::DATAGRAM)
      {
        parser_.feed(buffer.data(), size, [this](const Frame& frame) { received_.add(frame); });
      }
    }
  }

  UdpEndpoint to_;
  UdpSocket socket_;
  std::uint8_t sequence_ = 0;
  FrameParser parser_;  ///< receiving thread only
  ReceivedLog<Frame> received_;
  std::atomic<bool> running_{ true };
  std::thread thread_;
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

// ---------------------------------------------------------------- several gimbals (issue 21's field cases)

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

// ---------------------------------------------------------------- the emulator, as Gimbal Protocol v2 has it

TEST(MavlinkGimbalEmulator, GimbalDeviceIdIsOneToSixInsideTheManagerAndZeroFromAGimbalDeviceOfItsOwn)
{
  MavlinkGimbalEmulatorConfig config;
  config.gimbals.resize(2);
  config.gimbals[0].device_id = 2;                   // inside the autopilot
  config.gimbals[1].device_id = MAV_COMP_ID_GIMBAL;  // a gimbal device of its own
  MavlinkGimbalEmulator emulator(config);
  RawController controller(emulator.udpPort());
  controller.command(MAV_COMP_ID_AUTOPILOT1, command_id::REQUEST_MESSAGE,
                     { static_cast<float>(message_id::GIMBAL_MANAGER_INFORMATION), 0, 0, 0, 0, 0, 0 });
  ASSERT_TRUE(controller.waitFor(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS, MAV_COMP_ID_GIMBAL));
  ASSERT_TRUE(controller.waitFor(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS, MAV_COMP_ID_AUTOPILOT1));
  ASSERT_TRUE(controller.waitFor(message_id::GIMBAL_MANAGER_INFORMATION, MAV_COMP_ID_AUTOPILOT1, [](const Frame& f) {
    return decode<GimbalManagerInformation>(f).gimbal_device_id == MAV_COMP_ID_GIMBAL;
  }));
  ASSERT_TRUE(controller.waitFor(message_id::HEARTBEAT, MAV_COMP_ID_GIMBAL));

  for (const Frame& frame : controller.frames(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS, MAV_COMP_ID_GIMBAL))
  {
    EXPECT_EQ(decode<GimbalDeviceAttitudeStatus>(frame).gimbal_device_id, 0) << "a separate device sends 0";
  }
  for (const Frame& frame : controller.frames(message_id::GIMBAL_DEVICE_ATTITUDE_STATUS, MAV_COMP_ID_AUTOPILOT1))
  {
    EXPECT_EQ(decode<GimbalDeviceAttitudeStatus>(frame).gimbal_device_id, 2) << "the manager names its gimbal";
  }
  std::set<std::uint8_t> informed, reported;
  for (const Frame& frame : controller.frames(message_id::GIMBAL_MANAGER_INFORMATION))
  {
    EXPECT_EQ(frame.header.component_id, MAV_COMP_ID_AUTOPILOT1) << "only the manager informs";
    const auto information = decode<GimbalManagerInformation>(frame);
    informed.insert(information.gimbal_device_id);
    EXPECT_EQ(information.cap_flags & (gimbal_caps::HAS_PITCH_AXIS | gimbal_caps::HAS_YAW_AXIS),
              gimbal_caps::HAS_PITCH_AXIS | gimbal_caps::HAS_YAW_AXIS);
    EXPECT_EQ(information.cap_flags & gimbal_caps::HAS_ROLL_AXIS, 0u);
  }
  ASSERT_TRUE(controller.waitFor(message_id::GIMBAL_MANAGER_STATUS, MAV_COMP_ID_AUTOPILOT1));
  for (const Frame& frame : controller.frames(message_id::GIMBAL_MANAGER_STATUS))
  {
    EXPECT_EQ(frame.header.component_id, MAV_COMP_ID_AUTOPILOT1);
    reported.insert(decode<GimbalManagerStatus>(frame).gimbal_device_id);
  }
  EXPECT_EQ(informed, (std::set<std::uint8_t>{ 2, MAV_COMP_ID_GIMBAL }));
  EXPECT_EQ(reported.count(0), 0u) << "a manager's status names its gimbal";

  // The gimbal device is no manager.
  controller.command(MAV_COMP_ID_GIMBAL, command_id::REQUEST_MESSAGE,
                     { static_cast<float>(message_id::GIMBAL_MANAGER_INFORMATION), 0, 0, 0, 0, 0, 0 });
  EXPECT_TRUE(controller.waitFor(message_id::COMMAND_ACK, MAV_COMP_ID_GIMBAL, [](const Frame& frame) {
    return decode<CommandAck>(frame).result == Result::UNSUPPORTED;
  }));
}

TEST(MavlinkGimbalEmulator, AGimbalTheProtocolCannotAddressIsRefused)
{
  MavlinkGimbalEmulatorConfig itself;
  itself.component_id = MAV_COMP_ID_GIMBAL;
  itself.gimbals.front().device_id = MAV_COMP_ID_GIMBAL;  // 154 inside 154: the field case's emulator
  EXPECT_THROW(MavlinkGimbalEmulator{ itself }, std::invalid_argument);
  MavlinkGimbalEmulatorConfig zero;
  zero.gimbals.front().device_id = 0;
  EXPECT_THROW(MavlinkGimbalEmulator{ zero }, std::invalid_argument);
  MavlinkGimbalEmulatorConfig twice;
  twice.gimbals.resize(2);
  EXPECT_THROW(MavlinkGimbalEmulator{ twice }, std::invalid_argument);
}

TEST(MavlinkGimbalEmulator, SetAttitudeDrivesTheGimbalItNamesFromItsPrimaryControllerOnly)
{
  MavlinkGimbalEmulatorConfig config;
  config.gimbals.resize(2);
  config.gimbals[1].device_id = 2;
  config.vehicle_yaw = 0.5;
  MavlinkGimbalEmulator emulator(config);
  RawController controller(emulator.udpPort());

  GimbalManagerSetAttitude attitude;
  attitude.target_system = 1;
  attitude.target_component = MAV_COMP_ID_AUTOPILOT1;
  attitude.gimbal_device_id = 2;
  attitude.q = quaternionFromPanTilt(0.6, -0.4);
  controller.send(attitude);  // not in control yet: ignored
  EXPECT_TRUE(waitUntil([&] { return emulator.counters().setpoints_ignored == 1; }, WAIT));
  EXPECT_NEAR(emulator.gimbal(1).position[PAN], 0.0, 1e-6);

  controller.takeControl(MAV_COMP_ID_AUTOPILOT1, 2);
  ASSERT_TRUE(waitUntil([&] { return emulator.primaryController(1).second == RawController::COMPONENT; }, WAIT));
  EXPECT_EQ(emulator.primaryController(0).second, 0) << "param7 2 configures gimbal 2 only";
  controller.send(attitude);
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample state = emulator.gimbal(1);
        return !state.moving && std::abs(state.position[PAN] - 0.6) < 1e-3 &&
               std::abs(state.position[TILT] + 0.4) < 1e-3;
      },
      WAIT));
  EXPECT_NEAR(emulator.gimbal(0).position[PAN], 0.0, 1e-6) << "gimbal 1 was not addressed";

  // YAW_LOCK: the yaw is North's; with the vehicle heading 0.5, North 0.8 is 0.3 right of the nose.
  attitude.flags = gimbal_flags::YAW_LOCK;
  attitude.q = quaternionFromPanTilt(0.8, 0.0);
  controller.send(attitude);
  EXPECT_TRUE(waitUntil([&] { return std::abs(emulator.gimbal(1).position[PAN] - 0.3) < 1e-3; }, WAIT));

  // Rates only: the quaternion all NaN, y pitch rate, z yaw rate; they stop unless repeated.
  attitude.flags = 0;
  attitude.q = Quaternion{ { UNSET, UNSET, UNSET, UNSET } };
  attitude.angular_velocity_y = 0.0f;
  attitude.angular_velocity_z = -0.5f;
  controller.send(attitude);
  EXPECT_TRUE(waitUntil([&] { return emulator.gimbal(1).position[PAN] < 0.1; }, WAIT));
  EXPECT_TRUE(waitUntil([&] { return emulator.counters().rate_timeouts == 1; }, WAIT));

  // NEUTRAL: back to pan 0, tilt 0.
  attitude.flags = gimbal_flags::NEUTRAL;
  attitude.angular_velocity_z = UNSET;
  controller.send(attitude);
  EXPECT_TRUE(waitUntil(
      [&] {
        const PtzSample state = emulator.gimbal(1);
        return !state.moving && std::abs(state.position[PAN]) < 1e-3 && std::abs(state.position[TILT]) < 1e-3;
      },
      WAIT));
  EXPECT_EQ(emulator.counters().executed_per_gimbal[0], 0u);
}

TEST(MavlinkGimbalEmulator, AReleaseFromAControllerWithoutControlChangesNothing)
{
  MavlinkGimbalEmulatorConfig config;
  MavlinkGimbalEmulator emulator(config);
  emulator.giveControlTo(3, 190, false);
  RawController controller(emulator.udpPort());
  controller.command(MAV_COMP_ID_AUTOPILOT1, command_id::DO_GIMBAL_MANAGER_CONFIGURE, { -3, -3, -1, -1, 0, 0, 1 });
  ASSERT_TRUE(controller.waitFor(message_id::COMMAND_ACK, MAV_COMP_ID_AUTOPILOT1));
  EXPECT_EQ(emulator.primaryController(), Controller(3, 190));
}

/**
 * \file
 * \brief The MAVLink gimbal backend's gtests' fixture: a gimbal manager emulator on UDP and a backend configured for
 * it, and what the emulator received from it.
 */
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "diagnostic_value.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"
#include "wait_until.h"

namespace mavlink_gimbal_test
{
using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;

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
}  // namespace mavlink_gimbal_test

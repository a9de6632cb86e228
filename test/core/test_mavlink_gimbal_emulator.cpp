/**
 * \file
 * \brief The MAVLink gimbal emulator, as Gimbal Protocol v2 has it, seen by a bare controller.
 */
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "mavlink_gimbal_test_fixture.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"

using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;
using namespace mavlink_gimbal_test;

namespace
{
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

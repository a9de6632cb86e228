/**
 * \file
 * \brief What only the pantilt backend does, against the PanTilt emulator on 127.0.0.1 with ephemeral ports
 * (the backend contract suite covers what every device does).
 */
#include <gtest/gtest.h>

#include "wait_until.h"

#include <chrono>
#include <functional>
#include <thread>

#include "ptz_action_server/core/units.h"

#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"

using namespace ptz_action_server;
using namespace cr::pantilt;
using Bytes = std::vector<std::uint8_t>;

namespace
{
/// The frames the device received that are not state requests (params frames).
std::vector<Bytes> commandsReceived(const PanTiltEmulator& device)
{
  std::vector<Bytes> commands;
  for (const ReceivedDatagram& datagram : device.received().items())
  {
    if (!datagram.bytes.empty() && datagram.bytes[0] != PARAMS_HEADER)
    {
      commands.push_back(datagram.bytes);
    }
  }
  return commands;
}

Bytes setParamFrame(PanTiltParam id, float value, WireFormat format)
{
  Bytes frame(SET_PARAM_SIZE);
  int size = 0;
  PanTilt::encodeSetParamCommand(frame.data(), size, id, value, format);
  return frame;
}

Bytes commandFrame(PanTiltCommand id, WireFormat format, float arg1 = 0.0f, float arg2 = 0.0f)
{
  Bytes frame(MAX_COMMAND_SIZE);
  int size = 0;
  PanTilt::encodeCommand(frame.data(), size, id, format, arg1, arg2);
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

class PanTiltUdpTest : public ::testing::TestWithParam<WireFormat>
{
protected:
  void SetUp() override
  {
    PanTiltEmulatorConfig device_config;
    device_config.format = GetParam();
    device_config.state_period = 0.05;
    device_ = std::make_unique<PanTiltEmulator>(device_config);
    DeviceConfig<PanTiltProtocol> config;
    config.settings.format = GetParam();
    config.link.port = device_->udpPort();
    config.link.local_host = "127.0.0.1";
    config.link.local_port = localPort();
    config.session.state_timeout = 1.0;  // generous: a busy test machine may starve the I/O threads
    local_port_ = config.link.local_port;
    backend_ = makeDeviceBackend<PanTiltProtocol>(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 10.0)) << "the link never came up";
    // The link is up at the device's first frame, which can leave before the last start-up datagram (the state
    // request that follows the speeds) is read: tests that look at what the device received start after it.
    ASSERT_TRUE(waitUntil([&] { return stateRequestsReceived() > 0; }, 10.0)) << "no state request arrived";
  }

  std::size_t stateRequestsReceived() const
  {
    std::size_t requests = 0;
    for (const ReceivedDatagram& datagram : device_->received().items())
    {
      requests += !datagram.bytes.empty() && datagram.bytes[0] == PARAMS_HEADER ? 1 : 0;
    }
    return requests;
  }

  bool waitForRest(double pan, double tilt, double timeout = 10.0)
  {
    return waitUntil(
        [&] {
          const PtzSample sample = backend_->sample();
          return !sample.moving && std::abs(sample.position[PAN] - pan) < 2e-3 &&
                 std::abs(sample.position[TILT] - tilt) < 2e-3;
        },
        timeout);
  }

  /// A free UDP port for the backend, so the test can send it datagrams.
  static std::uint16_t localPort()
  {
    UdpSocket probe;
    probe.bind("127.0.0.1", 0);
    return probe.localEndpoint().port();
  }

  PanTiltCounters counters() const
  {
    return backend_->protocol<PanTiltProtocol>().counters();
  }
  /// Every datagram dropped: from strangers (the link's count) and from the device (the protocol's).
  std::uint64_t dropped() const
  {
    return backend_->session().linkCounters().foreign_datagrams + counters().dropped();
  }

  std::unique_ptr<PanTiltEmulator> device_;
  std::unique_ptr<DeviceBackend> backend_;
  std::uint16_t local_port_ = 0;
};
}  // namespace

TEST_P(PanTiltUdpTest, VelocityGoalsMoveAndStop)
{
  const WireFormat format = GetParam();
  device_->received().clear();
  backend_->moveAtVelocity({ -0.75, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] < -0.7; }, 10.0))
      << backend_->sample().velocity[PAN];
  const std::vector<Bytes> commands = commandsReceived(*device_);
  if (hasCommandArguments(format))
  {
    EXPECT_EQ(commands.front(), commandFrame(PanTiltCommand::MOVE_PAN_TILT, format, -50.0f, 0.0f));
  }
  else
  {
    // The seed's format: the speed as a motor-speed param, and a move towards the limit.
    EXPECT_EQ(commands.front(), setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 50.0f, format));
    EXPECT_EQ(commands[1], setParamFrame(PanTiltParam::PAN_ANGLE, -180.0f, format));
    EXPECT_EQ(commands[2], setParamFrame(PanTiltParam::TILT_MOTOR_SPEED, 100.0f, format));  // tilt holds
    EXPECT_EQ(commands[4], commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, format));
  }
  backend_->stop();
  EXPECT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, 10.0));
  // The next position goal runs at the configured speed again.
  backend_->goTo({ 2.0, 0.0, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] > 1.4; }, 10.0));
}

TEST_P(PanTiltUdpTest, AGoalsSpeedIsItsMotorSpeeds)
{
  const WireFormat format = GetParam();
  const Capabilities capabilities = backend_->capabilities();
  EXPECT_EQ(capabilities.speed.control[PAN], SpeedControl::DEVICE);
  EXPECT_EQ(capabilities.speed.control[TILT], SpeedControl::DEVICE);
  EXPECT_NEAR(capabilities.speed.min_speed[PAN], 0.015, 1e-9);  // 1 % of pan/max_speed 1.5 rad/s
  device_->received().clear();
  // 0.75 of 1.5 rad/s: 50 %; 0.1 of 1.0 rad/s: 10 %.
  backend_->goToAtSpeed({ 1.0, 0.3, 1.0 }, { 0.75, 0.1, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return commandsReceived(*device_).size() >= 3; }, 10.0));
  // Golden SET_PARAMs (published-wire-facts.md 2.1: `01 01 MINOR id:i32 value:f32`; PAN_MOTOR_SPEED is 7 in the
  // seed's ids and 5 in v1.x's, TILT_MOTOR_SPEED 8 and 6).
  const Bytes golden_pan[] = { { 0x01, 0x01, 0x00, 0x07, 0x00, 0x00, 0x00, 0x00, 0x00, 0x48, 0x42 },
                               { 0x01, 0x01, 0x00, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0x48, 0x42 },
                               { 0x01, 0x01, 0x01, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0x48, 0x42 } };
  const Bytes golden_tilt[] = { { 0x01, 0x01, 0x00, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 },
                                { 0x01, 0x01, 0x00, 0x06, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 },
                                { 0x01, 0x01, 0x01, 0x06, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x41 } };
  const std::size_t row = format == WireFormat::SEED ? 0 : (format == WireFormat::V1_0 ? 1 : 2);
  const std::vector<Bytes> commands = commandsReceived(*device_);
  EXPECT_EQ(commands[0], golden_pan[row]);
  EXPECT_EQ(commands[1], golden_tilt[row]);
  if (hasCommandArguments(format))
  {
    EXPECT_EQ(commands[2], commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, format,
                                        static_cast<float>(toDegrees(1.0)), static_cast<float>(toDegrees(0.3))));
  }
  // The device took them and cruises at them.
  EXPECT_FLOAT_EQ(device_->panTilt().getParam(PanTiltParam::PAN_MOTOR_SPEED), 50.0f);
  EXPECT_FLOAT_EQ(device_->panTilt().getParam(PanTiltParam::TILT_MOTOR_SPEED), 10.0f);
  double fastest = 0.0;
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample device = device_->panTilt().sample();
        fastest = std::max(fastest, device.velocity[PAN]);
        return std::abs(device.position[PAN] - 1.0) < 1e-3 && !device.moving;
      },
      20.0));
  EXPECT_NEAR(fastest, 0.75, 0.01);
  EXPECT_TRUE(waitForRest(1.0, 0.3));

  // Above the configured speed it is the configured speed; below 1 % it is 1 %; without a speed, the configured.
  device_->received().clear();
  backend_->goToAtSpeed({ 0.9, 0.3, 1.0 }, { 9.0, 1e-4, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return commandsReceived(*device_).size() >= 2; }, 10.0));
  EXPECT_EQ(commandsReceived(*device_)[0], setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 100.0f, format));
  EXPECT_EQ(commandsReceived(*device_)[1], setParamFrame(PanTiltParam::TILT_MOTOR_SPEED, 1.0f, format));
  device_->received().clear();
  backend_->goTo({ 0.8, 0.3, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return commandsReceived(*device_).size() >= 2; }, 10.0));
  EXPECT_EQ(commandsReceived(*device_)[1], setParamFrame(PanTiltParam::TILT_MOTOR_SPEED, 100.0f, format));
  EXPECT_TRUE(waitForRest(0.8, 0.3));
}

TEST_P(PanTiltUdpTest, MalformedDatagramsAreCountedOnceAndDropped)
{
  const WireFormat format = GetParam();
  const UdpEndpoint backend_endpoint = UdpEndpoint::resolve("127.0.0.1", local_port_);
  const std::string backend_address = backend_endpoint.toString();
  UdpSocket stranger;
  stranger.bind("127.0.0.1", 0);

  PanTiltParams params;
  Bytes valid(MAX_PARAMS_FRAME_SIZE);
  int size = 0;
  params.encode(valid.data(), static_cast<int>(valid.size()), size, nullptr, format);
  valid.resize(static_cast<std::size_t>(size));
  const Bytes bad_size(valid.begin(), valid.end() - 1);
  Bytes bad_header = valid;
  bad_header[0] = 0x00;
  Bytes bad_version = valid;
  bad_version[2] = 0x07;  // no format's minor version (a minor byte of another format would be another format)
  Bytes bad_mask = valid;
  bad_mask[4] |= 0x01;
  const Bytes empty;
  const Bytes oversized(4000, 0x02);
  const std::vector<const Bytes*> from_device = { &bad_size, &bad_header, &bad_version, &bad_mask, &empty, &oversized };

  const PanTiltCounters before = counters();
  const std::uint64_t dropped_before = dropped();
  const std::uint64_t foreign_before = backend_->session().linkCounters().foreign_datagrams;
  constexpr int TOTAL = 10000;
  constexpr int BATCH = 25;  // paced so that the kernel's socket buffer (~200 kB of small datagrams) never overflows
  for (int sent = 0; sent < TOTAL; sent += 2 * BATCH)
  {
    for (int index = 0; index < BATCH; ++index)
    {
      stranger.sendTo(backend_endpoint, valid.data(), valid.size());  // a valid frame, but from a stranger
      const Bytes& garbage = *from_device[static_cast<std::size_t>(sent / 2 + index) % from_device.size()];
      device_->sendRaw(backend_address, garbage.data(), garbage.size());
    }
    ASSERT_TRUE(waitUntil([&] { return dropped() - dropped_before >= std::uint64_t(sent + 2 * BATCH); }, 10.0))
        << "the backend stopped counting at " << dropped() - dropped_before << " size " << counters().bad_size
        << " header " << counters().bad_header << " version " << counters().bad_version << " mask "
        << counters().bad_mask;
  }
  const PanTiltCounters after = counters();
  EXPECT_EQ(backend_->session().linkCounters().foreign_datagrams - foreign_before, TOTAL / 2u);
  // 5000 from the device's port, spread over six kinds; empty and oversized count as bad size.
  const std::uint64_t bad_sizes = after.bad_size - before.bad_size;
  const std::uint64_t bad_headers = after.bad_header - before.bad_header;
  const std::uint64_t bad_versions = after.bad_version - before.bad_version;
  const std::uint64_t bad_masks = after.bad_mask - before.bad_mask;
  EXPECT_EQ(bad_sizes + bad_headers + bad_versions + bad_masks, TOTAL / 2u);
  EXPECT_NEAR(static_cast<double>(bad_sizes), TOTAL / 2.0 * 3 / 6, 2.0);
  EXPECT_NEAR(static_cast<double>(bad_headers), TOTAL / 2.0 / 6, 2.0);
  EXPECT_NEAR(static_cast<double>(bad_versions), TOTAL / 2.0 / 6, 2.0);
  EXPECT_NEAR(static_cast<double>(bad_masks), TOTAL / 2.0 / 6, 2.0);

  // Invalid frames are no sign of life: with the device silent, garbage from its port keeps nothing up.
  device_->setSilent(true);
  const TimePoint silenced = SteadyClock::now();
  EXPECT_TRUE(waitUntil(
      [&] {
        device_->sendRaw(backend_address, bad_header.data(), bad_header.size());
        stranger.sendTo(backend_endpoint, valid.data(), valid.size());
        return !backend_->sample().link_up && secondsBetween(silenced, SteadyClock::now()) > 0.8;
      },
      10.0, std::chrono::milliseconds(10)));
  device_->setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 10.0));
  backend_->goTo({ 0.2, 0.0, 1.0 });
  EXPECT_TRUE(waitForRest(0.2, 0.0));
}

INSTANTIATE_TEST_SUITE_P(EveryWireFormat, PanTiltUdpTest,
                         ::testing::Values(WireFormat::SEED, WireFormat::V1_0, WireFormat::V1_1),
                         [](const ::testing::TestParamInfo<WireFormat>& info) {
                           return info.param == WireFormat::SEED ? std::string("Seed") :
                                  info.param == WireFormat::V1_0 ? std::string("V1_0") :
                                                                   std::string("V1_1");
                         });

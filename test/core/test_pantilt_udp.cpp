/**
 * \file
 * \brief The pantilt_udp backend against the PanTilt device emulator, on 127.0.0.1 with ephemeral ports.
 */
#include <gtest/gtest.h>

#include "wait_until.h"

#include <chrono>
#include <functional>
#include <thread>

#include "ptz_action_server/core/goal_monitor.h"
#include "ptz_action_server/core/pantilt/pantilt_udp_backend.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"

using namespace ptz_action_server;
using namespace cr::pantilt;
using Bytes = std::vector<std::uint8_t>;

namespace
{
/// The frames the device received that are not state requests (params frames).
std::vector<Bytes> commandsReceived(const PanTiltEmulator& device)
{
  std::vector<Bytes> commands;
  for (const ReceivedDatagram& datagram : device.received())
  {
    if (!datagram.bytes.empty() && datagram.bytes[0] != PARAMS_HEADER)
    {
      commands.push_back(datagram.bytes);
    }
  }
  return commands;
}

Bytes setParamFrame(PanTiltParam id, float value, WireVersion version)
{
  Bytes frame(SET_PARAM_SIZE);
  int size = 0;
  PanTilt::encodeSetParamCommand(frame.data(), size, id, value, version);
  return frame;
}

Bytes commandFrame(PanTiltCommand id, WireVersion version, float arg1 = 0.0f, float arg2 = 0.0f)
{
  Bytes frame(COMMAND_SIZE_V1_1);
  int size = 0;
  PanTilt::encodeCommand(frame.data(), size, id, version, arg1, arg2);
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

double degrees(double radians)
{
  return radians * 180.0 / M_PI;
}

class PanTiltUdpTest : public ::testing::TestWithParam<WireVersion>
{
protected:
  void SetUp() override
  {
    PanTiltEmulatorConfig device_config;
    device_config.version = GetParam();
    device_config.state_period = 0.05;
    device_ = std::make_unique<PanTiltEmulator>(device_config);
    PanTiltUdpConfig config;
    config.version = GetParam();
    config.device_port = device_->endpoint().port();
    config.local_host = "127.0.0.1";
    backend_ = std::make_unique<PanTiltUdpBackend>(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0)) << "the link never came up";
  }

  bool waitForRest(double pan, double tilt, double timeout = 5.0)
  {
    return waitUntil(
        [&] {
          const PtzSample sample = backend_->sample();
          return !sample.moving && std::abs(sample.position[PAN] - pan) < 2e-3 &&
                 std::abs(sample.position[TILT] - tilt) < 2e-3;
        },
        timeout);
  }

  std::unique_ptr<PanTiltEmulator> device_;
  std::unique_ptr<PanTiltUdpBackend> backend_;
};
}  // namespace

TEST_P(PanTiltUdpTest, GoalReachesTheDeviceAsTheRightFrames)
{
  const WireVersion version = GetParam();
  device_->clearReceived();
  backend_->goTo({ 0.5, -0.2, 1.0 });
  const std::size_t expected_count = version == WireVersion::V1_0 ? 5 : 3;
  ASSERT_TRUE(waitUntil([&] { return commandsReceived(*device_).size() >= expected_count; }, 2.0));
  const std::vector<Bytes> commands = commandsReceived(*device_);
  ASSERT_EQ(commands.size(), expected_count);
  EXPECT_EQ(commands[0], setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 100.0f, version));
  EXPECT_EQ(commands[1], setParamFrame(PanTiltParam::TILT_MOTOR_SPEED, 100.0f, version));
  if (version == WireVersion::V1_0)
  {
    EXPECT_EQ(commands[2], setParamFrame(PanTiltParam::PAN_ANGLE, static_cast<float>(degrees(0.5)), version));
    EXPECT_EQ(commands[3], setParamFrame(PanTiltParam::TILT_ANGLE, static_cast<float>(degrees(-0.2)), version));
    EXPECT_EQ(commands[4], commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, version));
  }
  else
  {
    EXPECT_EQ(commands[2], commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, version, static_cast<float>(degrees(0.5)),
                                        static_cast<float>(degrees(-0.2))));
  }
  EXPECT_TRUE(waitForRest(0.5, -0.2)) << "pan " << backend_->sample().position[PAN];
  EXPECT_EQ(device_->counters().commands_refused, 0u);
  EXPECT_DOUBLE_EQ(backend_->sample().position[ZOOM], 1.0);
  EXPECT_FALSE(backend_->capabilities().axes[ZOOM].present);
}

TEST_P(PanTiltUdpTest, CancelSendsStopAndTheDeviceDecelerates)
{
  backend_->goTo({ 3.0, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.5; }, 3.0));
  device_->clearReceived();
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !commandsReceived(*device_).empty(); }, 1.0));
  EXPECT_EQ(commandsReceived(*device_).front(), commandFrame(PanTiltCommand::STOP, GetParam()));
  const double at_stop = backend_->sample().position[PAN];
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, 2.0));
  const double stopped = backend_->sample().position[PAN];
  EXPECT_GT(stopped, at_stop);        // braked on, not jumped
  EXPECT_LT(stopped, at_stop + 0.5);  // within the braking distance (0.375 rad) and a frame of travel
  EXPECT_LT(stopped, 2.5);
}

TEST_P(PanTiltUdpTest, VelocityGoalsMoveAndStop)
{
  const WireVersion version = GetParam();
  device_->clearReceived();
  backend_->moveAtVelocity({ -0.75, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] < -0.7; }, 3.0))
      << backend_->sample().velocity[PAN];
  const std::vector<Bytes> commands = commandsReceived(*device_);
  if (version == WireVersion::V1_1)
  {
    EXPECT_EQ(commands.front(), commandFrame(PanTiltCommand::MOVE_PAN_TILT, version, -50.0f, 0.0f));
  }
  else
  {
    // 1.0: the speed as a motor-speed param, and a move towards the limit.
    EXPECT_EQ(commands.front(), setParamFrame(PanTiltParam::PAN_MOTOR_SPEED, 50.0f, version));
    EXPECT_EQ(commands[1], setParamFrame(PanTiltParam::PAN_ANGLE, -180.0f, version));
    EXPECT_EQ(commands[2], setParamFrame(PanTiltParam::TILT_MOTOR_SPEED, 100.0f, version));  // tilt holds
    EXPECT_EQ(commands[4], commandFrame(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, version));
  }
  backend_->stop();
  EXPECT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, 2.0));
  // The next position goal runs at the configured speed again.
  backend_->goTo({ 2.0, 0.0, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] > 1.4; }, 3.0));
}

TEST_P(PanTiltUdpTest, SilentDeviceAbortsTheGoalWithinTheTimeoutAndRecovers)
{
  GoalMonitorConfig monitor_config;
  const AxisValues target{ 2.5, 0.0, 1.0 };
  backend_->goTo(target);
  GoalMonitor monitor = GoalMonitor::forPosition(target, backend_->sample(), backend_->capabilities(), monitor_config,
                                                 SteadyClock::now());
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.3; }, 3.0));
  device_->setSilent(true);
  const TimePoint silenced = SteadyClock::now();
  GoalVerdict verdict;
  ASSERT_TRUE(waitUntil(
      [&] {
        verdict = monitor.update(backend_->sample(), SteadyClock::now());
        return verdict.phase != GoalPhase::ACTIVE;
      },
      2.0));
  const double took = secondsBetween(silenced, SteadyClock::now());
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_NE(verdict.reason.find("link lost"), std::string::npos) << verdict.reason;
  EXPECT_LE(took, 0.5 + 0.1) << "state_timeout is 0.5 s";
  EXPECT_GE(took, 0.5 - 0.06);  // the last frame came at most a state period before the silence
  // The I/O thread notices the loss on its next wake-up, within a state request period.
  EXPECT_TRUE(waitUntil([&] { return backend_->counters().link_losses == 1u; }, 0.5));

  // Back again: the backend stops whatever the device was doing, and new goals work.
  device_->clearReceived();
  device_->setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  ASSERT_TRUE(waitUntil([&] { return !commandsReceived(*device_).empty(); }, 1.0));
  EXPECT_EQ(commandsReceived(*device_).front(), commandFrame(PanTiltCommand::STOP, GetParam()));
  backend_->goTo({ -0.3, 0.1, 1.0 });
  EXPECT_TRUE(waitForRest(-0.3, 0.1, 8.0));
}

TEST_P(PanTiltUdpTest, MalformedDatagramsAreCountedOnceAndDropped)
{
  const WireVersion version = GetParam();
  const UdpEndpoint backend_endpoint = backend_->localEndpoint();
  UdpSocket stranger;
  stranger.bind("127.0.0.1", 0);

  PanTiltParams params;
  Bytes valid(MAX_PARAMS_FRAME_SIZE);
  int size = 0;
  params.encode(valid.data(), static_cast<int>(valid.size()), size, nullptr, version);
  valid.resize(static_cast<std::size_t>(size));
  const Bytes bad_size(valid.begin(), valid.end() - 1);
  Bytes bad_header = valid;
  bad_header[0] = 0x00;
  Bytes bad_version = valid;
  bad_version[2] ^= 0x01;
  Bytes bad_mask = valid;
  bad_mask[4] |= 0x01;
  const Bytes empty;
  const Bytes oversized(4000, 0x02);
  const std::vector<const Bytes*> from_device = { &bad_size, &bad_header, &bad_version, &bad_mask, &empty, &oversized };

  const PanTiltUdpCounters before = backend_->counters();
  constexpr int TOTAL = 10000;
  constexpr int BATCH = 25;  // paced so that the kernel's socket buffer (~200 kB of small datagrams) never overflows
  for (int sent = 0; sent < TOTAL; sent += 2 * BATCH)
  {
    for (int index = 0; index < BATCH; ++index)
    {
      stranger.sendTo(backend_endpoint, valid.data(), valid.size());  // a valid frame, but from a stranger
      const Bytes& garbage = *from_device[static_cast<std::size_t>(sent / 2 + index) % from_device.size()];
      device_->sendRaw(backend_endpoint, garbage.data(), garbage.size());
    }
    ASSERT_TRUE(waitUntil(
        [&] { return backend_->counters().dropped() - before.dropped() >= std::uint64_t(sent + 2 * BATCH); }, 5.0))
        << "the backend stopped counting at " << backend_->counters().dropped() - before.dropped() << " foreign "
        << backend_->counters().foreign_sender << " size " << backend_->counters().bad_size << " header "
        << backend_->counters().bad_header << " version " << backend_->counters().bad_version << " mask "
        << backend_->counters().bad_mask;
  }
  const PanTiltUdpCounters after = backend_->counters();
  EXPECT_EQ(after.foreign_sender - before.foreign_sender, TOTAL / 2u);
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
  while (secondsBetween(silenced, SteadyClock::now()) < 0.8)
  {
    device_->sendRaw(backend_endpoint, bad_header.data(), bad_header.size());
    stranger.sendTo(backend_endpoint, valid.data(), valid.size());
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_FALSE(backend_->sample().link_up);
  device_->setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  backend_->goTo({ 0.2, 0.0, 1.0 });
  EXPECT_TRUE(waitForRest(0.2, 0.0));
}

INSTANTIATE_TEST_SUITE_P(BothWireVersions, PanTiltUdpTest, ::testing::Values(WireVersion::V1_0, WireVersion::V1_1),
                         [](const ::testing::TestParamInfo<WireVersion>& info) {
                           return info.param == WireVersion::V1_0 ? std::string("V1_0") : std::string("V1_1");
                         });

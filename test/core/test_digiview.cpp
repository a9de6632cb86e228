/**
 * \file
 * \brief The digiview backend against the DigiView emulator on 127.0.0.1, and the emulator's own answers.
 */
#include <gtest/gtest.h>

#include "wait_until.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include "ptz_action_server/core/digiview/digiview_backend.h"
#include "ptz_action_server/emulators/digiview_emulator.h"
#include "ptz_action_server/core/goal_monitor.h"

using namespace ptz_action_server;
using namespace ptz_action_server::digiview;

namespace
{
DigiViewConfig backendConfig(const DigiViewEmulator& device, DigiViewTransport transport = DigiViewTransport::TCP)
{
  DigiViewConfig config;
  config.port = device.port();
  config.transport = transport;
  config.acceleration = 4.0;  // as the emulator turns
  config.startup_timeout = 5.0;
  return config;
}

bool received(const DigiViewEmulator& device, MessageType type, digiview::ParamType param)
{
  for (const ReceivedMessage& item : device.received())
  {
    if (item.error == UnpackError::NONE && item.message.message_type == type && item.message.param_type == param)
    {
      return true;
    }
  }
  return false;
}

class DigiViewTest : public ::testing::TestWithParam<DigiViewTransport>
{
protected:
  void SetUp() override
  {
    DigiViewEmulatorConfig config;
    config.transport = GetParam();
    device_ = std::make_unique<DigiViewEmulator>(config);
    backend_ = std::make_unique<DigiViewBackend>(backendConfig(*device_, GetParam()));
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  }

  bool atRest(double pan, double tilt, double zoom) const
  {
    const PtzSample sample = backend_->sample();
    return !sample.moving && std::abs(sample.position[PAN] - pan) < 2e-3 &&
           std::abs(sample.position[TILT] - tilt) < 2e-3 && std::abs(sample.position[ZOOM] - zoom) < 0.01;
  }

  std::unique_ptr<DigiViewEmulator> device_;
  std::unique_ptr<DigiViewBackend> backend_;
};
}  // namespace

TEST_P(DigiViewTest, StartupSubscribesToTheViewAndLearnsTheStream)
{
  EXPECT_TRUE(received(*device_, MessageType::GET_PARAMETERS, digiview::ParamType::VIDEO_OUTPUT));
  EXPECT_TRUE(received(*device_, MessageType::GET_INTERVAL, digiview::ParamType::CAM_TARGETING));
  EXPECT_TRUE(received(*device_, MessageType::GET_INTERVAL, digiview::ParamType::CAM_OPTICS_AND_CONTROL));
  const PtzSample sample = backend_->sample();
  EXPECT_NEAR(sample.position[ZOOM], 1.0, 1e-3);  // the emulator starts at fov 1.2 = fov_wide: zoom 1x
  // States keep coming every 100 ms.
  const std::uint64_t states = backend_->counters().states;
  ASSERT_TRUE(waitUntil([&] { return backend_->counters().states >= states + 6; }, 1.0));
  EXPECT_DOUBLE_EQ(backend_->capabilities().axes[ZOOM].range.max, 12.0);  // fov_wide / 0.1
}

TEST_P(DigiViewTest, GoalBecomesDirectionalTargetingAndFieldOfView)
{
  device_->clearReceived();
  backend_->goTo({ 0.5, -0.2, 2.0 });
  ASSERT_TRUE(device_->waitForReceived(
      [](const ReceivedMessage& item) {
        return item.message.message_type == MessageType::SET_PARAMETERS &&
               item.message.param_type == digiview::ParamType::CAM_OPTICS_AND_CONTROL;
      },
      1.0));
  for (const ReceivedMessage& item : device_->received())
  {
    if (item.message.message_type != MessageType::SET_PARAMETERS)
    {
      continue;
    }
    if (item.message.param_type == digiview::ParamType::CAM_TARGETING)
    {
      CamTargeting targeting;
      ASSERT_EQ(unpackTargeting(item.message, targeting), UnpackError::NONE);
      EXPECT_EQ(targeting.camera.stream_name, "main");
      EXPECT_EQ(targeting.targeting_mode, 0);  // directional
      EXPECT_FALSE(targeting.euler_delta);
      EXPECT_DOUBLE_EQ(targeting.yaw, 0.5);     // clockwise, as the contract's pan
      EXPECT_DOUBLE_EQ(targeting.pitch, -0.2);  // up positive, as the contract's tilt
    }
    else
    {
      CamOpticsAndControl optics;
      ASSERT_EQ(unpackOptics(item.message, optics), UnpackError::NONE);
      EXPECT_DOUBLE_EQ(optics.fov, 0.6);  // fov_wide 1.2 / 2x
    }
  }
  EXPECT_TRUE(waitUntil([&] { return atRest(0.5, -0.2, 2.0); }, 5.0));
  EXPECT_GE(backend_->counters().acknowledged, 2u);
}

TEST_P(DigiViewTest, CancelHoldsTheViewWhereItComesToRest)
{
  backend_->goTo({ 2.5, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.8; }, 4.0));
  const double at_cancel = device_->view("main", 0).position[PAN];
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !device_->view("main", 0).moving; }, 3.0));
  const double stopped = device_->view("main", 0).position[PAN];
  EXPECT_GT(stopped, at_cancel);         // it braked on,
  EXPECT_LT(stopped, at_cancel + 0.35);  // within its braking distance and a state period, far from 2.5
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_NEAR(device_->view("main", 0).position[PAN], stopped, 1e-9) << "no return after the stop";
}

TEST_P(DigiViewTest, VelocityGoalMovesTheTargetAtTheRate)
{
  backend_->moveAtVelocity({ 0.4, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.2; }, 3.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_NEAR(backend_->sample().velocity[PAN], 0.4, 0.1);
  backend_->stop();
  EXPECT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, 3.0));
}

TEST_P(DigiViewTest, ARefusedGoalAbortsWithDigiViewsReason)
{
  device_->setRefuse(true);
  const AxisValues target{ 0.3, 0.0, 1.0 };
  GoalMonitor monitor = GoalMonitor::forPosition(target, backend_->sample(), backend_->capabilities(),
                                                 GoalMonitorConfig(), SteadyClock::now());
  backend_->goTo(target);
  GoalVerdict verdict;
  ASSERT_TRUE(waitUntil(
      [&] {
        verdict = monitor.update(backend_->sample(), SteadyClock::now());
        return verdict.phase != GoalPhase::ACTIVE;
      },
      2.0));
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_TRUE(verdict.device_fault);
  // Both SETs of the goal were refused; the fault names the last.
  EXPECT_EQ(backend_->lastFault().rfind("DigiView refused SET CAM_", 0), 0u) << backend_->lastFault();
  EXPECT_NE(backend_->lastFault().find(": FORBIDDEN (the sender does not have permission to perform the requested "
                                       "action)"),
            std::string::npos)
      << backend_->lastFault();
}

TEST_P(DigiViewTest, SilenceDropsTheLinkWithinTheTimeoutAndRecoveryHoldsTheView)
{
  backend_->goTo({ 2.0, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.3; }, 3.0));
  device_->setSilent(true);
  const TimePoint silenced = SteadyClock::now();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, 2.0));
  EXPECT_LE(secondsBetween(silenced, SteadyClock::now()), 0.5 + 0.01);
  EXPECT_GE(secondsBetween(silenced, SteadyClock::now()), 0.5 - 0.11);  // the last state was at most 100 ms old
  device_->clearReceived();
  device_->setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  EXPECT_TRUE(device_->waitForReceived(
      [](const ReceivedMessage& item) {
        return item.message.message_type == MessageType::SET_PARAMETERS &&
               item.message.param_type == digiview::ParamType::CAM_TARGETING;
      },
      1.0))
      << "the view was not held after the recovery";
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, 3.0));
  EXPECT_LT(backend_->sample().position[PAN], 1.9);  // the old goal did not go on
  backend_->goTo({ -0.5, 0.1, 3.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(-0.5, 0.1, 3.0); }, 5.0));
}

INSTANTIATE_TEST_SUITE_P(Transports, DigiViewTest, ::testing::Values(DigiViewTransport::TCP, DigiViewTransport::UDP),
                         [](const ::testing::TestParamInfo<DigiViewTransport>& info) {
                           return info.param == DigiViewTransport::TCP ? std::string("Tcp") : std::string("Udp");
                         });

TEST(DigiViewConnection, ADroppedConnectionIsReopenedAndQuitIsSentAtShutdown)
{
  DigiViewEmulator device(DigiViewEmulatorConfig{});
  {
    DigiViewBackend backend(backendConfig(device));
    backend.start();
    ASSERT_TRUE(waitUntil([&] { return device.connections() == 1; }, 2.0));
    device.dropConnections();
    // Reconnected within the backoff (0.1 s), before the link times out: the link may never show down.
    ASSERT_TRUE(waitUntil([&] { return backend.counters().connections == 2u && device.connections() == 1; }, 3.0));
    ASSERT_TRUE(waitUntil([&] { return backend.sample().link_up; }, 3.0));
    backend.goTo({ 0.2, 0.2, 1.5 });
    EXPECT_TRUE(waitUntil(
        [&] { return !backend.sample().moving && std::abs(backend.sample().position[PAN] - 0.2) < 2e-3; }, 5.0));
    device.clearReceived();
  }
  EXPECT_TRUE(received(device, MessageType::QUIT, digiview::ParamType::SYSTEM_STATUS));
  EXPECT_TRUE(waitUntil([&] { return device.connections() == 0; }, 1.0)) << "QUIT closes the connection";
}

TEST(DigiViewConnection, ACameraTheStreamDoesNotHaveFailsAtStart)
{
  DigiViewEmulatorConfig device_config;
  device_config.layout_mode = 0;  // one user view
  DigiViewEmulator device(device_config);
  DigiViewConfig config = backendConfig(device);
  config.cam_id = 1;
  DigiViewBackend backend(config);
  try
  {
    backend.start();
    FAIL() << "start() accepted a camera that does not exist";
  }
  catch (const BackendError& error)
  {
    EXPECT_NE(std::string(error.what()).find("stream 'main' has 1 user view(s), so cam_id 1 does not exist"),
              std::string::npos)
        << error.what();
  }
}

TEST(DigiViewEmulator, AnswersLikeDigiView)
{
  DigiViewEmulator device(DigiViewEmulatorConfig{});
  boost::asio::io_context context;
  boost::asio::ip::tcp::socket socket(context);
  socket.connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), device.port()));
  auto exchange = [&](Bytes bytes) {
    boost::asio::write(socket, boost::asio::buffer(bytes));
    Bytes answer{};
    boost::asio::read(socket, boost::asio::buffer(answer));
    Message message;
    EXPECT_EQ(Message::unpack(answer.data(), answer.size(), message), UnpackError::NONE);
    return message;
  };
  const CameraId camera{ "main", 0 };
  CamTargeting targeting;
  targeting.camera = camera;
  targeting.yaw = 0.1;
  EXPECT_EQ(exchange(packTargeting(MessageType::SET_PARAMETERS, targeting).pack()).message_type,
            MessageType::ACKNOWLEDGEMENT);
  Bytes broken = packTargeting(MessageType::SET_PARAMETERS, targeting).pack();
  broken[30] ^= 0x10;
  EXPECT_EQ(exchange(broken).message_type, MessageType::CHECKSUM_ERROR);
  Bytes unknown = packBare(MessageType::ACKNOWLEDGEMENT, digiview::ParamType::CAM_TARGETING).pack();
  unknown[9] = 42;
  unknown[75] = crc8(unknown.data(), 75);
  EXPECT_EQ(exchange(unknown).message_type, MessageType::UNKNOWN);
  Bytes out_of_range = packTargeting(MessageType::SET_PARAMETERS, targeting).pack();
  out_of_range[11 + 8] = 9;  // cam_id 9
  out_of_range[75] = crc8(out_of_range.data(), 75);
  EXPECT_EQ(exchange(out_of_range).message_type, MessageType::DATA_ERROR);
  EXPECT_EQ(exchange(packGet(digiview::ParamType::AI, camera).pack()).message_type, MessageType::UNKNOWN);
  const Message state = exchange(packGet(digiview::ParamType::CAM_TARGETING, camera).pack());
  EXPECT_EQ(state.message_type, MessageType::CURRENT_PARAMETERS);

  // GET_INTERVAL: under 100 ms is ignored; 100 ms comes periodically; 0 cancels.
  device.clearReceived();
  boost::asio::write(
      socket,
      boost::asio::buffer(packInterval(IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 50 }).pack()));
  boost::asio::write(
      socket,
      boost::asio::buffer(packInterval(IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 100 }).pack()));
  const TimePoint started = SteadyClock::now();
  for (int count = 0; count < 3; ++count)
  {
    Bytes answer{};
    boost::asio::read(socket, boost::asio::buffer(answer));
  }
  const double three = secondsBetween(started, SteadyClock::now());
  EXPECT_GT(three, 0.25);  // three at 100 ms, not at 50 ms
  EXPECT_LT(three, 0.45);
  boost::asio::write(
      socket,
      boost::asio::buffer(packInterval(IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 0 }).pack()));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  socket.non_blocking(true);
  Bytes drain{};
  boost::system::error_code error;
  while (socket.read_some(boost::asio::buffer(drain), error) > 0)
  {
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(350));
  EXPECT_EQ(socket.available(), 0u) << "the subscription went on after an interval of 0";

  // QUIT closes the connection.
  socket.non_blocking(false);
  boost::asio::write(socket,
                     boost::asio::buffer(packBare(MessageType::QUIT, digiview::ParamType::SYSTEM_STATUS).pack()));
  Bytes after{};
  boost::asio::read(socket, boost::asio::buffer(after), error);
  EXPECT_EQ(error, boost::asio::error::eof);
}

/**
 * \file
 * \brief What only the Pelco-D protocol does, against its emulator over real pseudo-terminals, and start-up failures
 * of the serial backends (the backend contract suite covers what every device does; test_flir_protocol.cpp the FLIR
 * PTU).
 */
#include <gtest/gtest.h>

#include <limits>

#include "line_test_support.h"
#include "wait_until.h"

#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = LINE_TEST_WAIT;
constexpr double STATE_TIMEOUT = LINE_TEST_STATE_TIMEOUT;

// ---------------------------------------------------------------- Pelco-D

class PelcoTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    PelcoDEmulatorConfig emulator_config;
    emulator_config.port.link = uniqueLink("pelco");
    emulator_config.address = 7;
    emulator_ = std::make_unique<PelcoDEmulator>(emulator_config);
    DeviceConfig<PelcoProtocol> config;
    config.link = serialLink(emulator_config.port.link, 9600);
    config.session.state_timeout = STATE_TIMEOUT;
    config.settings.address = 7;
    backend_ = makeDeviceBackend<PelcoProtocol>(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  }

  std::vector<pelco::Frame> commandsReceived() const
  {
    std::vector<pelco::Frame> frames;
    for (const ReceivedFrame& item : emulator_->received().items())
    {
      const std::uint8_t command = item.frame.command2;
      if (command != pelco::QUERY_PAN && command != pelco::QUERY_TILT && command != pelco::QUERY_ZOOM)
      {
        frames.push_back(item.frame);
      }
    }
    return frames;
  }

  std::unique_ptr<PelcoDEmulator> emulator_;
  std::unique_ptr<DeviceBackend> backend_;
};

TEST_F(PelcoTest, VelocityGoalsBecomeMovementFramesWithScaledSpeeds)
{
  emulator_->received().clear();
  backend_->moveAtVelocity({ -0.75, 0.5, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] < -0.6; }, WAIT));
  ASSERT_FALSE(commandsReceived().empty());
  EXPECT_EQ(commandsReceived().front(), pelco::move(7, -32, 32, 0));  // half and half speed: 0x20
  backend_->stop();
  ASSERT_TRUE(
      emulator_->received().waitFor([](const ReceivedFrame& item) { return item.frame == pelco::stop(7); }, WAIT));
  EXPECT_TRUE(waitUntil([&] { return !emulator_->sample().moving; }, WAIT));
}

TEST_F(PelcoTest, AnAxisLeftAloneGetsNoSetPosition)
{
  emulator_->received().clear();
  const double zoom_before = emulator_->sample().position[ZOOM];
  backend_->goTo({ 0.2, -0.1, std::numeric_limits<double>::quiet_NaN() });  // a goal that leaves the zoom alone
  ASSERT_TRUE(waitUntil([&] { return atRest(*backend_, 0.2, -0.1); }, WAIT));
  for (const pelco::Frame& frame : commandsReceived())
  {
    EXPECT_NE(frame.command2, pelco::SET_ZOOM) << "a zoom position went out: " << frame.value();
  }
  EXPECT_DOUBLE_EQ(emulator_->sample().position[ZOOM], zoom_before);
}

TEST_F(PelcoTest, GarbledRepliesAreDroppedAndCounted)
{
  emulator_->port().setGarbleRatio(0.05);
  ASSERT_TRUE(waitUntil(
      [&] {
        const PelcoCounters& counters = backend_->protocol<PelcoProtocol>().counters();
        return counters.bad_checksum + counters.skipped_bytes + counters.wrong_address > 3;
      },
      WAIT));
  emulator_->port().setGarbleRatio(0.0);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  backend_->goTo({ 0.2, 0.2, 3.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, 0.2, 0.2); }, WAIT));
}

TEST(PelcoTurbo, OnlyAConfiguredTurboByteGoesFasterThan0x3F)
{
  PelcoDEmulatorConfig emulator_config;
  emulator_config.port.link = uniqueLink("pelco_turbo");
  emulator_config.pan_turbo_speed = 3.0;
  PelcoDEmulator emulator(emulator_config);
  auto velocityFrame = [&emulator] {
    for (const ReceivedFrame& item : emulator.received().items())
    {
      const bool standard = (item.frame.command2 & 0x01) == 0;  // extended commands (queries too) are odd
      if (standard && (item.frame.command2 & (pelco::LEFT | pelco::RIGHT)) != 0)
      {
        return item.frame;
      }
    }
    return pelco::Frame();
  };
  DeviceConfig<PelcoProtocol> config;
  config.link = serialLink(emulator_config.port.link, 9600);
  config.session.state_timeout = STATE_TIMEOUT;
  {
    // No turbo configured: the fastest goal is the speed at 0x3F, and nothing faster goes out.
    auto backend = makeDeviceBackend<PelcoProtocol>(config);
    backend->start();
    EXPECT_DOUBLE_EQ(backend->capabilities().axes[PAN].max_speed, 1.5);
    backend->moveAtVelocity({ 2.5, 0.0, 0.0 });
    ASSERT_TRUE(waitUntil([&] { return velocityFrame().data1 != 0; }, WAIT));
    EXPECT_EQ(velocityFrame().data1, pelco::MAX_SPEED);
    backend->stop();
  }
  emulator.received().clear();
  config.settings.turbo_byte = 0xFF;
  config.settings.turbo_speed = 3.0;
  auto backend = makeDeviceBackend<PelcoProtocol>(config);
  backend->start();
  EXPECT_DOUBLE_EQ(backend->capabilities().axes[PAN].max_speed, 3.0);
  backend->moveAtVelocity({ -2.5, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return velocityFrame().data1 != 0; }, WAIT));
  EXPECT_EQ(velocityFrame().data1, 0xFF);
  EXPECT_EQ(velocityFrame().command2, pelco::LEFT);
  EXPECT_TRUE(waitUntil([&] { return emulator.sample().velocity[PAN] < -2.9; }, WAIT));  // turbo, to the left
  backend->stop();
  EXPECT_TRUE(waitUntil([&] { return !emulator.sample().moving; }, WAIT));
  // Turbo is one speed: a speed nearer the 0x3F speed (1.5) than turbo's (3.0) goes at 0x3F, never twice as fast as
  // asked (a device steered on its speeds, closed-loop, would overshoot).
  emulator.received().clear();
  backend->moveAtVelocity({ 2.1, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return velocityFrame().data1 != 0; }, WAIT));
  EXPECT_EQ(velocityFrame().data1, pelco::MAX_SPEED);
  EXPECT_EQ(velocityFrame().command2, pelco::RIGHT);
  backend->stop();
  EXPECT_TRUE(waitUntil([&] { return !emulator.sample().moving; }, WAIT));
}

TEST(PelcoGeneralReplies, CommandsAreAcknowledged)
{
  PelcoDEmulatorConfig emulator_config;
  emulator_config.port.link = uniqueLink("pelco_general");
  emulator_config.general_reply = true;
  PelcoDEmulator emulator(emulator_config);
  DeviceConfig<PelcoProtocol> config;
  config.link = serialLink(emulator_config.port.link, 9600);
  config.session.state_timeout = STATE_TIMEOUT;
  config.settings.general_reply = true;
  auto backend = makeDeviceBackend<PelcoProtocol>(config);
  backend->start();
  backend->goTo({ -0.3, 0.1, 2.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend, -0.3, 0.1); }, WAIT));
  EXPECT_EQ(backend->protocol<PelcoProtocol>().counters().unexpected_frames, 0u);
  EXPECT_TRUE(backend->sample().link_up);
}

// ---------------------------------------------------------------- start-up failures

TEST(SerialBackend, StartFailsWithAClearReasonWhenNoDeviceAnswers)
{
  DeviceConfig<FlirProtocol> config;
  config.link = serialLink("/tmp/ptz_no_such_port", 9600);
  config.session.startup_timeout = 0.3;
  auto backend = makeDeviceBackend<FlirProtocol>(config);
  try
  {
    backend->start();
    FAIL() << "start() succeeded without a device";
  }
  catch (const BackendError& error)
  {
    const std::string text = error.what();
    EXPECT_NE(text.find("no answer from a FLIR PTU on /tmp/ptz_no_such_port at 9600 baud within 0.3 s"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("No such file"), std::string::npos) << text;
  }
}

TEST(SerialBackend, StartOverTcpFailsWithTheConnectionsReason)
{
  DeviceConfig<PelcoProtocol> config;
  config.link.kind = LinkKind::TCP;
  config.link.port = 9;  // discard: nothing listens there on 127.0.0.1
  config.session.startup_timeout = 0.5;
  auto backend = makeDeviceBackend<PelcoProtocol>(config);
  try
  {
    backend->start();
    FAIL() << "start() succeeded without a device";
  }
  catch (const BackendError& error)
  {
    const std::string text = error.what();
    EXPECT_NE(text.find("no answer from a Pelco-D device (address 1) on tcp 127.0.0.1:9"), std::string::npos) << text;
    EXPECT_NE(text.find("connection to 127.0.0.1:9 failed: Connection refused"), std::string::npos) << text;
  }
}

}  // namespace

/**
 * \file
 * \brief What only the FLIR and Pelco-D protocols do, against their emulators over real pseudo-terminals (the
 * backend contract suite covers what every device does).
 */
#include <gtest/gtest.h>

#include "wait_until.h"

#include <dirent.h>
#include <unistd.h>

#include <cmath>
#include <fstream>

#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

using namespace ptz_action_server;

namespace
{
const double FLIR_RESOLUTION = arcSecondsToRadians(185.1428);
constexpr double WAIT = 20.0;
/// s without a reply before the link is down: generous, a busy test machine may starve the I/O threads.
constexpr double STATE_TIMEOUT = 1.0;

std::string uniqueLink(const char* name)
{
  static int counter = 0;
  return ::testing::TempDir() + "ptz_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
}

std::size_t openDescriptors()
{
  std::size_t count = 0;
  DIR* directory = ::opendir("/proc/self/fd");
  while (directory && ::readdir(directory))
  {
    ++count;
  }
  if (directory)
  {
    ::closedir(directory);
  }
  return count;
}

long residentKilobytes()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmRSS:", 0) == 0)
    {
      return std::stol(line.substr(6));
    }
  }
  return -1;
}

LinkConfig serialLink(const std::string& path, unsigned baud)
{
  LinkConfig link;
  link.path = path;
  link.baud = baud;
  return link;
}

bool atRest(const PtzBackend& backend, double pan, double tilt)
{
  const PtzSample sample = backend.sample();
  return !sample.moving && std::abs(sample.position[PAN] - pan) < 2e-3 && std::abs(sample.position[TILT] - tilt) < 2e-3;
}

// ---------------------------------------------------------------- FLIR

class FlirTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    startWith(9600);
  }

  void startWith(unsigned baud)
  {
    backend_.reset();
    emulator_.reset();
    FlirPtuEmulatorConfig emulator_config;
    emulator_config.port.link = uniqueLink("flir");
    emulator_config.port.baud = baud;
    emulator_ = std::make_unique<FlirPtuEmulator>(emulator_config);
    FlirConfig config;
    config.link = serialLink(emulator_config.port.link, baud);
    config.session.state_timeout = STATE_TIMEOUT;
    backend_ = makeFlirBackend(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  }

  bool received(const std::string& command) const
  {
    for (const ReceivedCommand& item : emulator_->received().items())
    {
      if (item.text == command)
      {
        return true;
      }
    }
    return false;
  }

  std::unique_ptr<FlirPtuEmulator> emulator_;
  std::unique_ptr<DeviceBackend> backend_;
};

TEST_F(FlirTest, StartupReadsResolutionLimitsAndSpeedsFromTheUnit)
{
  // The emulator started verbose, echoing, with a banner: the backend switched it to terse without echo.
  EXPECT_TRUE(received("FT"));
  EXPECT_TRUE(received("ED"));
  EXPECT_TRUE(received("CI"));
  const Capabilities capabilities = backend_->capabilities();
  // The unit's pan is counter-clockwise positive: PX (3090) is the contract's minimum.
  EXPECT_NEAR(capabilities.axes[PAN].range.min, -3090 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[PAN].range.max, 3090 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[TILT].range.min, -907 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[TILT].range.max, 604 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[PAN].max_speed, 1.5, 1e-3);
  EXPECT_FALSE(capabilities.axes[ZOOM].present);
  EXPECT_GT(backend_->protocol<FlirProtocol>().counters().unexpected_text, 0u);  // the banner
  EXPECT_EQ(backend_->name(), "serial/flir");
}

TEST_F(FlirTest, VelocityGoalsUseVelocityModeWithTheUnitsSign)
{
  emulator_->received().clear();
  backend_->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] > 0.25; }, WAIT));
  EXPECT_TRUE(received("CV"));
  EXPECT_TRUE(received("PS-334"));                     // clockwise 0.3 rad/s is a negative pan speed for the unit
  EXPECT_GT(emulator_->sample().velocity[PAN], 0.25);  // and the unit turns clockwise, as the contract asked
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
}

TEST_F(FlirTest, GarbledRepliesAreSurvived)
{
  emulator_->port().setGarbleRatio(0.02);
  backend_->goTo({ 0.3, 0.1, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return emulator_->port().bytesGarbled() > 20; }, WAIT));
  emulator_->port().setGarbleRatio(0.0);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  backend_->goTo({ -0.3, -0.1, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, -0.3, -0.1); }, WAIT));
}

TEST_F(FlirTest, FiftyUnplugReplugCyclesKeepDescriptorsAndMemorySteady)
{
  startWith(115200);
  // One cycle first, so lazily allocated buffers exist before counting.
  emulator_->unplug();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, WAIT));
  emulator_->replug();
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  const std::size_t descriptors = openDescriptors();
  const long memory = residentKilobytes();
  for (int cycle = 0; cycle < 50; ++cycle)
  {
    emulator_->unplug();
    ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, WAIT)) << "cycle " << cycle;
    emulator_->replug();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << "cycle " << cycle;
  }
  EXPECT_EQ(openDescriptors(), descriptors);
  EXPECT_LT(residentKilobytes() - memory, 2048) << "resident memory grew by " << residentKilobytes() - memory << " kB";
  EXPECT_EQ(backend_->sample().link_losses, 51u);
}

TEST(FlirTcp, AnEseriesUnitIsSetUpAfterItsBannerOnEveryConnection)
{
  FlirPtuEmulatorConfig emulator_config;
  emulator_config.port.kind = DevicePortConfig::Kind::TCP;
  FlirPtuEmulator emulator(emulator_config);
  FlirConfig config;
  config.link.kind = LinkKind::TCP;
  config.link.port = emulator.port().tcpPort();
  config.session.state_timeout = STATE_TIMEOUT;
  auto backend = makeFlirBackend(config);
  backend->start();
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  // The banner's `Initializing...*` is no reply: it must not have been taken for FT's.
  const std::vector<ReceivedCommand> commands = emulator.received().items();
  ASSERT_FALSE(commands.empty());
  EXPECT_EQ(commands.front().text, "FT");
  EXPECT_EQ(backend->protocol<FlirProtocol>().counters().errors, 0u);
  EXPECT_NEAR(backend->capabilities().axes[PAN].range.max, 3090 * FLIR_RESOLUTION, 1e-9);
}

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
    PelcoConfig config;
    config.link = serialLink(emulator_config.port.link, 9600);
    config.session.state_timeout = STATE_TIMEOUT;
    config.pelco.address = 7;
    backend_ = makePelcoBackend(config);
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
  PelcoConfig config;
  config.link = serialLink(emulator_config.port.link, 9600);
  config.session.state_timeout = STATE_TIMEOUT;
  {
    // No turbo configured: the fastest goal is the speed at 0x3F, and nothing faster goes out.
    auto backend = makePelcoBackend(config);
    backend->start();
    EXPECT_DOUBLE_EQ(backend->capabilities().axes[PAN].max_speed, 1.5);
    backend->moveAtVelocity({ 2.5, 0.0, 0.0 });
    ASSERT_TRUE(waitUntil([&] { return velocityFrame().data1 != 0; }, WAIT));
    EXPECT_EQ(velocityFrame().data1, pelco::MAX_SPEED);
    backend->stop();
  }
  emulator.received().clear();
  config.pelco.turbo_byte = 0xFF;
  config.pelco.turbo_speed = 3.0;
  auto backend = makePelcoBackend(config);
  backend->start();
  EXPECT_DOUBLE_EQ(backend->capabilities().axes[PAN].max_speed, 3.0);
  backend->moveAtVelocity({ -2.5, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return velocityFrame().data1 != 0; }, WAIT));
  EXPECT_EQ(velocityFrame().data1, 0xFF);
  EXPECT_EQ(velocityFrame().command2, pelco::LEFT);
  EXPECT_TRUE(waitUntil([&] { return emulator.sample().velocity[PAN] < -2.9; }, WAIT));  // turbo, to the left
  backend->stop();
  EXPECT_TRUE(waitUntil([&] { return !emulator.sample().moving; }, WAIT));
}

TEST(PelcoGeneralReplies, CommandsAreAcknowledged)
{
  PelcoDEmulatorConfig emulator_config;
  emulator_config.port.link = uniqueLink("pelco_general");
  emulator_config.general_reply = true;
  PelcoDEmulator emulator(emulator_config);
  PelcoConfig config;
  config.link = serialLink(emulator_config.port.link, 9600);
  config.session.state_timeout = STATE_TIMEOUT;
  config.pelco.general_reply = true;
  auto backend = makePelcoBackend(config);
  backend->start();
  backend->goTo({ -0.3, 0.1, 2.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend, -0.3, 0.1); }, WAIT));
  EXPECT_EQ(backend->protocol<PelcoProtocol>().counters().unexpected_frames, 0u);
  EXPECT_TRUE(backend->sample().link_up);
}

// ---------------------------------------------------------------- start-up failures

TEST(SerialBackend, StartFailsWithAClearReasonWhenNoDeviceAnswers)
{
  FlirConfig config;
  config.link = serialLink("/tmp/ptz_no_such_port", 9600);
  config.session.startup_timeout = 0.3;
  auto backend = makeFlirBackend(config);
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
  PelcoConfig config;
  config.link.kind = LinkKind::TCP;
  config.link.port = 9;  // discard: nothing listens there on 127.0.0.1
  config.session.startup_timeout = 0.5;
  auto backend = makePelcoBackend(config);
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

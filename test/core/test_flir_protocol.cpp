/**
 * \file
 * \brief What only the FLIR backend does, against the FLIR PTU emulator over real pseudo-terminals and TCP (the
 * backend contract suite covers what every device does): the unit's resolution, limits and speeds read at start from
 * a unit that echoes and answers verbosely, velocity goals in the unit's sign, a unit that restarts mid-session (its
 * banner), limit reports that come on their own, garbled replies, an E-series set up after its TCP banner, and 50
 * unplug/replug cycles with file descriptors and resident memory steady.
 */
#include <gtest/gtest.h>

#include <dirent.h>

#include <fstream>

#include "line_test_support.h"
#include "wait_until.h"

#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"

using namespace ptz_action_server;

namespace
{
const double FLIR_RESOLUTION = arcSecondsToRadians(185.1428);
constexpr double WAIT = LINE_TEST_WAIT;

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
    FlirPtuEmulatorConfig emulator_config;  // as at power-up: echo on, verbose replies
    emulator_config.port.link = uniqueLink("flir");
    emulator_config.port.baud = baud;
    emulator_ = std::make_unique<FlirPtuEmulator>(emulator_config);
    FlirConfig config;
    config.link = serialLink(emulator_config.port.link, baud);
    config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
    backend_ = makeFlirBackend(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  }

  std::size_t received(const std::string& command) const
  {
    std::size_t count = 0;
    for (const ReceivedCommand& item : emulator_->received().items())
    {
      count += item.text == command ? 1 : 0;
    }
    return count;
  }
  const FlirCounters& counters() const
  {
    return backend_->protocol<FlirProtocol>().counters();
  }

  std::unique_ptr<FlirPtuEmulator> emulator_;
  std::unique_ptr<DeviceBackend> backend_;
};
}  // namespace

TEST_F(FlirTest, StartupReadsResolutionLimitsAndSpeedsFromAnEchoingVerboseUnit)
{
  // The unit started verbose and echoing: the backend switched it to terse without echo.
  EXPECT_EQ(received("FT"), 1u);
  EXPECT_EQ(received("ED"), 1u);
  EXPECT_EQ(received("CI"), 1u);
  const Capabilities capabilities = backend_->capabilities();
  // The unit's pan is counter-clockwise positive: PX (3090) is the contract's minimum.
  EXPECT_NEAR(capabilities.axes[PAN].range.min, -3090 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[PAN].range.max, 3090 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[TILT].range.min, -907 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[TILT].range.max, 604 * FLIR_RESOLUTION, 1e-9);
  EXPECT_NEAR(capabilities.axes[PAN].max_speed, 1.5, 1e-3);
  EXPECT_FALSE(capabilities.axes[ZOOM].present);
  // The echoed, verbose answers before the set-up took effect were never taken for anything else.
  EXPECT_EQ(counters().unusable_replies, 0u);
  EXPECT_EQ(counters().errors, 0u);
  EXPECT_EQ(backend_->name(), "serial/flir");
}

TEST_F(FlirTest, VelocityGoalsUseVelocityModeWithTheUnitsSign)
{
  emulator_->received().clear();
  backend_->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] > 0.25; }, WAIT));
  EXPECT_EQ(received("CV"), 1u);
  EXPECT_EQ(received("PS-334"), 1u);                   // clockwise 0.3 rad/s is a negative pan speed for the unit
  EXPECT_GT(emulator_->sample().velocity[PAN], 0.25);  // and the unit turns clockwise, as the contract asked
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
}

TEST_F(FlirTest, AUnitThatRestartsMidSessionIsSetUpAgainAndReachesGoals)
{
  backend_->goTo({ 0.3, 0.1, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return atRest(*backend_, 0.3, 0.1); }, WAIT));
  // Power lost and back with the line open: the banner, then echo and verbose replies again.
  emulator_->powerCycle();
  ASSERT_TRUE(waitUntil([&] { return counters().restarts == 1u; }, WAIT));
  ASSERT_TRUE(waitUntil([&] { return received("FT") == 2u && backend_->sample().link_up; }, WAIT));
  EXPECT_GE(counters().banner_lines, 1u);
  EXPECT_EQ(backend_->sample().link_losses, 1u);
  EXPECT_NE(backend_->lastLinkLoss().find("the FLIR PTU restarted"), std::string::npos) << backend_->lastLinkLoss();
  backend_->goTo({ -0.4, -0.2, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, -0.4, -0.2); }, WAIT));
  EXPECT_EQ(counters().unusable_replies, 0u);
  EXPECT_EQ(counters().errors, 0u);
}

TEST_F(FlirTest, LimitReportsComingOnTheirOwnAreCountedAndGoalsStillReached)
{
  // Counter-clockwise and up as fast as the unit goes: each axis runs into its limit, and the unit says `!P`, `!T`
  // whenever that happens, between the replies to the polls.
  backend_->moveAtVelocity({ -1.5, 1.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return counters().limit_hits >= 2u; }, WAIT));
  backend_->stop();
  backend_->goTo({ 0.2, -0.1, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, 0.2, -0.1); }, WAIT));
  EXPECT_EQ(counters().limit_hits, 2u);
  EXPECT_EQ(counters().unusable_replies, 0u);
  EXPECT_EQ(backend_->sample().link_losses, 0u);
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
  config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
  auto backend = makeFlirBackend(config);
  backend->start();
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  // The banner's `Initializing...*` is no reply: it must not have been taken for FT's.
  const std::vector<ReceivedCommand> commands = emulator.received().items();
  ASSERT_FALSE(commands.empty());
  EXPECT_EQ(commands.front().text, "FT");
  const FlirCounters& counters = backend->protocol<FlirProtocol>().counters();
  EXPECT_EQ(counters.banner_lines, 3u);
  EXPECT_EQ(counters.restarts, 0u);
  EXPECT_EQ(counters.errors, 0u);
  EXPECT_NEAR(backend->capabilities().axes[PAN].range.max, 3090 * FLIR_RESOLUTION, 1e-9);
}

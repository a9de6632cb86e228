/**
 * \file
 * \brief The serial backend (FLIR and Pelco-D) against the emulators, over real pseudo-terminals.
 */
#include <gtest/gtest.h>

#include "wait_until.h"

#include <dirent.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <thread>

#include "ptz_action_server/core/goal_monitor.h"
#include "ptz_action_server/core/serial/flir_backend.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"
#include "ptz_action_server/core/serial/pelco_backend.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

using namespace ptz_action_server;

namespace
{
const double FLIR_RESOLUTION = 185.1428 / 3600.0 * M_PI / 180.0;

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

SerialBackendConfig serialConfig(const std::string& path, unsigned baud)
{
  SerialBackendConfig config;
  config.link.path = path;
  config.link.baud = baud;
  config.startup_timeout = 5.0;
  return config;
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
    device_.reset();
    FlirPtuEmulatorConfig device_config;
    device_config.port.link = uniqueLink("flir");
    device_config.port.baud = baud;
    device_ = std::make_unique<FlirPtuEmulator>(device_config);
    FlirConfig config;
    config.serial = serialConfig(device_config.port.link, baud);
    backend_ = std::make_unique<FlirBackend>(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  }

  bool received(const std::string& command) const
  {
    for (const ReceivedCommand& item : device_->received())
    {
      if (item.text == command)
      {
        return true;
      }
    }
    return false;
  }

  std::unique_ptr<FlirPtuEmulator> device_;
  std::unique_ptr<FlirBackend> backend_;
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
  EXPECT_GT(backend_->counters().unexpected_text, 0u);  // the banner
}

TEST_F(FlirTest, GoalBecomesPositionCommandsWithTheSignInverted)
{
  device_->clearReceived();
  backend_->goTo({ 0.5, -0.2, 1.0 });
  ASSERT_TRUE(device_->waitForCommand([](const ReceivedCommand& command) { return command.text == "TP-223"; }, 2.0));
  std::vector<std::string> commands;
  for (const ReceivedCommand& command : device_->received())
  {
    if (command.text != "PP" && command.text != "TP")  // polls
    {
      commands.push_back(command.text);
    }
  }
  const std::vector<std::string> expected = { "CI", "PS1671", "TS1114", "PP-557", "TP-223" };
  EXPECT_EQ(commands, expected);
  ASSERT_TRUE(waitUntil(
      [&] { return !backend_->sample().moving && std::abs(backend_->sample().position[PAN] - 0.5) < 1e-3; }, 5.0));
  EXPECT_NEAR(backend_->sample().position[TILT], -0.2, 1e-3);
  EXPECT_NEAR(device_->sample().position[PAN], 0.5, 1e-3);  // clockwise, as the contract wants
}

TEST_F(FlirTest, CancelHaltsWithinOneExchangeAndTheUnitDecelerates)
{
  backend_->goTo({ -2.0, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] < -0.6; }, 3.0));
  device_->clearReceived();
  const TimePoint cancelled = SteadyClock::now();
  backend_->stop();
  ASSERT_TRUE(device_->waitForCommand([](const ReceivedCommand& command) { return command.text == "H"; }, 1.0));
  TimePoint halt_at{};
  for (const ReceivedCommand& command : device_->received())
  {
    if (command.text == "H")
    {
      halt_at = command.at;
      break;
    }
  }
  // "H " takes 2 byte times; at most one exchange (~12 ms at 9600 baud) may be on the wire before it.
  const double latency = secondsBetween(cancelled, halt_at) - 2 * 10.0 / 9600;
  EXPECT_LT(latency, 0.013) << "halt reached the unit " << latency * 1e3 << " ms after the cancel";
  const double at_halt = device_->sample().position[PAN];
  ASSERT_TRUE(waitUntil([&] { return !device_->sample().moving; }, 2.0));
  EXPECT_LT(device_->sample().position[PAN], at_halt);  // braked on, did not jump
  EXPECT_GT(device_->sample().position[PAN], -2.0 + 0.2);
}

TEST_F(FlirTest, VelocityGoalsUseVelocityModeAndRefusalsAreFaults)
{
  device_->clearReceived();
  backend_->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] > 0.25; }, 3.0));
  EXPECT_TRUE(received("CV"));
  EXPECT_TRUE(received("PS-334"));  // clockwise 0.3 rad/s is a negative pan speed for the unit
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, 3.0));

  // A position beyond the unit's limits: the unit refuses, the backend reports a fault with its words.
  const std::uint64_t faults = backend_->sample().fault_count;
  backend_->goTo({ 3.0, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().fault_count > faults; }, 2.0));
  EXPECT_EQ(backend_->lastFault(), "the FLIR PTU refused 'PP-3342': Maximum allowable Pan position exceeded");
}

TEST_F(FlirTest, UnplugMidGoalAbortsWithinTheDeadlineAndReplugRecovers)
{
  const AxisValues target{ 2.0, 0.0, 1.0 };
  backend_->goTo(target);
  GoalMonitor monitor = GoalMonitor::forPosition(target, backend_->sample(), backend_->capabilities(),
                                                 GoalMonitorConfig(), SteadyClock::now());
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.3; }, 3.0));
  device_->unplug();
  const TimePoint unplugged = SteadyClock::now();
  GoalVerdict verdict;
  ASSERT_TRUE(waitUntil(
      [&] {
        verdict = monitor.update(backend_->sample(), SteadyClock::now());
        return verdict.phase != GoalPhase::ACTIVE;
      },
      2.0));
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_NE(verdict.reason.find("link lost"), std::string::npos);
  EXPECT_LE(secondsBetween(unplugged, SteadyClock::now()), 0.25);

  device_->replug();
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 5.0));
  EXPECT_TRUE(device_->waitForCommand([](const ReceivedCommand& command) { return command.text == "H"; }, 1.0)) << "no "
                                                                                                                   "hal"
                                                                                                                   "t "
                                                                                                                   "aft"
                                                                                                                   "er "
                                                                                                                   "the"
                                                                                                                   " re"
                                                                                                                   "con"
                                                                                                                   "nec"
                                                                                                                   "tio"
                                                                                                                   "n";
  backend_->goTo({ -0.4, 0.1, 1.0 });
  EXPECT_TRUE(waitUntil(
      [&] { return std::abs(backend_->sample().position[PAN] + 0.4) < 1e-3 && !backend_->sample().moving; }, 5.0));
}

TEST_F(FlirTest, SilentUnitDropsTheLinkWithinTheDeadlineAndIsHaltedWhenItAnswersAgain)
{
  device_->port().setSilent(true);
  const TimePoint silenced = SteadyClock::now();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, 1.0));
  EXPECT_LE(secondsBetween(silenced, SteadyClock::now()), 0.25 + 0.01);
  device_->clearReceived();
  device_->port().setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  EXPECT_TRUE(device_->waitForCommand([](const ReceivedCommand& command) { return command.text == "H"; }, 1.0));
}

TEST_F(FlirTest, GarbledRepliesAreSurvived)
{
  device_->port().setGarbleRatio(0.02);
  backend_->goTo({ 0.3, 0.1, 1.0 });
  std::this_thread::sleep_for(std::chrono::seconds(2));
  device_->port().setGarbleRatio(0.0);
  EXPECT_GT(device_->port().bytesGarbled(), 0u);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  backend_->goTo({ -0.3, -0.1, 1.0 });
  EXPECT_TRUE(waitUntil(
      [&] { return std::abs(backend_->sample().position[PAN] + 0.3) < 1e-3 && !backend_->sample().moving; }, 5.0));
}

TEST_F(FlirTest, FiftyUnplugReplugCyclesKeepDescriptorsAndMemorySteady)
{
  startWith(115200);
  // One cycle first, so lazily allocated buffers exist before counting.
  device_->unplug();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, 1.0));
  device_->replug();
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 5.0));
  const std::size_t descriptors = openDescriptors();
  const long memory = residentKilobytes();
  for (int cycle = 0; cycle < 50; ++cycle)
  {
    device_->unplug();
    ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, 1.0)) << "cycle " << cycle;
    device_->replug();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 5.0)) << "cycle " << cycle;
  }
  EXPECT_EQ(openDescriptors(), descriptors);
  EXPECT_LT(residentKilobytes() - memory, 2048) << "resident memory grew by " << residentKilobytes() - memory << " kB";
}

// ---------------------------------------------------------------- Pelco-D

class PelcoTest : public ::testing::TestWithParam<pelco::TiltEncoding>
{
protected:
  void SetUp() override
  {
    PelcoDEmulatorConfig device_config;
    device_config.port.link = uniqueLink("pelco");
    device_config.port.baud = 9600;
    device_config.address = 7;
    device_config.tilt_encoding = GetParam();
    device_ = std::make_unique<PelcoDEmulator>(device_config);
    PelcoConfig config;
    config.serial = serialConfig(device_config.port.link, 9600);
    config.address = 7;
    config.tilt_encoding = GetParam();
    backend_ = std::make_unique<PelcoBackend>(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  }

  std::vector<pelco::Frame> commandsReceived() const
  {
    std::vector<pelco::Frame> frames;
    for (const ReceivedFrame& item : device_->received())
    {
      const std::uint8_t command = item.frame.command2;
      if (command != pelco::QUERY_PAN && command != pelco::QUERY_TILT && command != pelco::QUERY_ZOOM)
      {
        frames.push_back(item.frame);
      }
    }
    return frames;
  }

  bool atRest(double pan, double tilt, double zoom) const
  {
    const PtzSample sample = backend_->sample();
    return !sample.moving && std::abs(sample.position[PAN] - pan) < 2e-3 &&
           std::abs(sample.position[TILT] - tilt) < 2e-3 && std::abs(sample.position[ZOOM] - zoom) < 0.01;
  }

  std::unique_ptr<PelcoDEmulator> device_;
  std::unique_ptr<PelcoBackend> backend_;
};

TEST_P(PelcoTest, GoalBecomesAbsolutePositionFrames)
{
  device_->clearReceived();
  backend_->goTo({ 0.5, -0.2, 4.0 });
  ASSERT_TRUE(waitUntil([&] { return commandsReceived().size() >= 3; }, 2.0));
  const std::vector<pelco::Frame> frames = commandsReceived();
  EXPECT_EQ(frames[0], pelco::withValue(7, pelco::SET_PAN, 2865));  // 28.65 degrees
  EXPECT_EQ(frames[1], pelco::withValue(7, pelco::SET_TILT, pelco::encodeTilt(-11.46, GetParam())));
  EXPECT_EQ(frames[2], pelco::withValue(7, pelco::SET_ZOOM, backend_->zoomToPosition(4.0)));
  EXPECT_TRUE(waitUntil([&] { return atRest(0.5, -0.2, 4.0); }, 5.0))
      << backend_->sample().position[PAN] << " " << backend_->sample().position[TILT] << " "
      << backend_->sample().position[ZOOM];
  EXPECT_NEAR(device_->sample().position[TILT], -0.2, 2e-3);  // the encoding agreed on both sides
}

TEST_P(PelcoTest, VelocityGoalsBecomeMovementFramesAndCancelIsAStopWithinOneFrameTime)
{
  device_->clearReceived();
  backend_->moveAtVelocity({ -0.75, 0.5, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] < -0.6; }, 3.0));
  EXPECT_EQ(commandsReceived().front(), pelco::move(7, -32, 32, 0));  // half and half speed: 0x20

  device_->clearReceived();
  const TimePoint cancelled = SteadyClock::now();
  backend_->stop();
  ASSERT_TRUE(device_->waitForFrame([](const ReceivedFrame& item) { return item.frame == pelco::stop(7); }, 1.0));
  TimePoint stop_at{};
  for (const ReceivedFrame& item : device_->received())
  {
    if (item.frame == pelco::stop(7))
    {
      stop_at = item.at;
      break;
    }
  }
  const double frame_time = 7 * 10.0 / 9600;
  // The stop frame itself takes one frame time; a query already on the wire may delay it by one more.
  const double latency = secondsBetween(cancelled, stop_at) - frame_time;
  EXPECT_LT(latency, frame_time + 0.002) << latency * 1e3 << " ms";
  const double at_stop = device_->sample().position[PAN];
  ASSERT_TRUE(waitUntil([&] { return !device_->sample().moving; }, 2.0));
  EXPECT_LT(device_->sample().position[PAN], at_stop);  // decelerated past the point of the stop
}

TEST_P(PelcoTest, UnplugAbortsWithinTheDeadlineAndReplugRecovers)
{
  const AxisValues target{ 2.0, 0.0, 1.0 };
  backend_->goTo(target);
  GoalMonitor monitor = GoalMonitor::forPosition(target, backend_->sample(), backend_->capabilities(),
                                                 GoalMonitorConfig(), SteadyClock::now());
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.3; }, 3.0));
  device_->unplug();
  const TimePoint unplugged = SteadyClock::now();
  GoalVerdict verdict;
  ASSERT_TRUE(waitUntil(
      [&] {
        verdict = monitor.update(backend_->sample(), SteadyClock::now());
        return verdict.phase != GoalPhase::ACTIVE;
      },
      2.0));
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED);
  EXPECT_LE(secondsBetween(unplugged, SteadyClock::now()), 0.25);
  device_->replug();
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 5.0));
  EXPECT_TRUE(device_->waitForFrame([](const ReceivedFrame& item) { return item.frame == pelco::stop(7); }, 1.0));
  backend_->goTo({ -0.5, 0.3, 2.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(-0.5, 0.3, 2.0); }, 5.0));
}

TEST_P(PelcoTest, GarbledRepliesAreDroppedAndCounted)
{
  device_->port().setGarbleRatio(0.05);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  device_->port().setGarbleRatio(0.0);
  const PelcoCounters counters = backend_->counters();
  EXPECT_GT(counters.parser.bad_checksum + counters.parser.skipped_bytes + counters.parser.wrong_address, 0u);
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, 2.0));
  backend_->goTo({ 0.2, 0.2, 3.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(0.2, 0.2, 3.0); }, 5.0));
}

INSTANTIATE_TEST_SUITE_P(TiltEncodings, PelcoTest,
                         ::testing::Values(pelco::TiltEncoding::WRAP, pelco::TiltEncoding::INVERTED_WRAP),
                         [](const ::testing::TestParamInfo<pelco::TiltEncoding>& info) {
                           return info.param == pelco::TiltEncoding::WRAP ? std::string("Wrap") :
                                                                            std::string("InvertedWrap");
                         });

TEST(PelcoGeneralReplies, CommandsAreAcknowledged)
{
  PelcoDEmulatorConfig device_config;
  device_config.port.link = uniqueLink("pelco_general");
  device_config.general_reply = true;
  PelcoDEmulator device(device_config);
  PelcoConfig config;
  config.serial = serialConfig(device_config.port.link, 9600);
  config.general_reply = true;
  PelcoBackend backend(config);
  backend.start();
  backend.goTo({ -0.3, 0.1, 2.0 });
  EXPECT_TRUE(waitUntil(
      [&] { return !backend.sample().moving && std::abs(backend.sample().position[PAN] + 0.3) < 2e-3; }, 5.0));
  EXPECT_EQ(backend.counters().unexpected_frames, 0u);
  EXPECT_TRUE(backend.sample().link_up);
}

TEST(SerialBackend, StartFailsWithAClearReasonWhenNoDeviceAnswers)
{
  FlirConfig config;
  config.serial = serialConfig("/tmp/ptz_no_such_port", 9600);
  config.serial.startup_timeout = 0.3;
  FlirBackend backend(config);
  try
  {
    backend.start();
    FAIL() << "start() succeeded without a device";
  }
  catch (const BackendError& error)
  {
    EXPECT_NE(std::string(error.what()).find("no answer from a FLIR PTU on /tmp/ptz_no_such_port at 9600 baud"),
              std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("No such file"), std::string::npos) << error.what();
  }
}

}  // namespace

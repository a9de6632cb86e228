/**
 * \file
 * \brief What only the FLIR backend does, against the FLIR PTU emulator over real pseudo-terminals and TCP (the
 * backend contract suite covers what every device does): the unit's resolution, limits and speeds read at start from
 * a unit that echoes and answers verbosely, velocity goals in the unit's sign, a unit that restarts mid-session (its
 * banner), a unit reset by another program (its `!T!T!P!P*` no reply and no error; with and without the banner, echo
 * and verbose replies after the reset), limit reports that come on their own, garbled replies, an E-series set up
 * after its TCP banner, the capabilities declared, and 50 unplug/replug cycles with file descriptors and resident
 * memory steady.
 */
#include <gtest/gtest.h>

#include <dirent.h>

#include <fstream>

#include "line_test_support.h"
#include "wait_until.h"

#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/goal/goal_validation.h"
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
    FlirPtuEmulatorConfig emulator_config;  // as at power-up: echo on, verbose replies
    emulator_config.port.baud = baud;
    startWith(emulator_config);
  }

  /// A D46 at 9600 baud whose reset calibration takes a moment (it runs at the speeds the goals set, which the unit
  /// keeps); \p reset_as_power_up: `R` restarts it first.
  void startQuickUnit(bool reset_as_power_up)
  {
    FlirPtuEmulatorConfig emulator_config;
    emulator_config.pan_max_speed = 20.0;
    emulator_config.tilt_max_speed = 20.0;
    emulator_config.acceleration = 400.0;
    emulator_config.reset_as_power_up = reset_as_power_up;
    FlirSettings settings;
    settings.pan_speed = 20.0;
    settings.tilt_speed = 20.0;
    settings.acceleration = 400.0;
    startWith(emulator_config, settings);
  }

  void startWith(FlirPtuEmulatorConfig emulator_config, const FlirSettings& settings = FlirSettings{})
  {
    backend_.reset();
    emulator_.reset();
    emulator_config.port.link = uniqueLink("flir");
    const unsigned baud = emulator_config.port.baud;
    emulator_ = std::make_unique<FlirPtuEmulator>(emulator_config);
    DeviceConfig<FlirProtocol> config;
    config.settings = settings;
    config.link = serialLink(emulator_config.port.link, baud);
    config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
    backend_ = makeDeviceBackend<FlirProtocol>(config);
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

TEST_F(FlirTest, JointStateVelocitiesAreTheUnitsMeasuredMotionNeverItsSetPoint)
{
  // flir_ptu PR 51: its driver published the configured speed as the joints' velocity, non-zero at rest, and rviz
  // models twitched. Here the velocity is what the unit's reported positions did.
  backend_->goTo({ 0.2, -0.1, 1.0 });  // sets the unit's speeds (PS, TS): a set-point that stays after the move
  ASSERT_TRUE(waitUntil([&] { return std::abs(emulator_->sample().position[PAN] - 0.2) < 1e-3; }, WAIT));
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
  PtzSample rest = backend_->sample();
  EXPECT_EQ(rest.velocity[PAN], 0.0);
  EXPECT_EQ(rest.velocity[TILT], 0.0);

  // Pan stalled (the unit takes the command and does not turn), tilt turning: pan's velocity is 0, not the 0.3 asked.
  SimFaults faults;
  faults.stalled[PAN] = true;
  emulator_->setFaults(faults);
  backend_->moveAtVelocity({ 0.3, 0.2, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[TILT] > 0.15; }, WAIT));
  const PtzSample moving = backend_->sample();
  EXPECT_EQ(moving.velocity[PAN], 0.0);
  EXPECT_NEAR(moving.velocity[TILT], emulator_->sample().velocity[TILT], 0.05);
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
  EXPECT_EQ(backend_->sample().velocity[TILT], 0.0);
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

TEST_F(FlirTest, CapabilitiesArePanAndTiltToPositionsAtSpeedsWithFeedbackAndNoZoom)
{
  const Capabilities capabilities = backend_->capabilities();
  for (Axis axis : { PAN, TILT })
  {
    EXPECT_TRUE(capabilities.axes[axis].present) << axis;
    EXPECT_TRUE(capabilities.axes[axis].absolute) << axis;
    EXPECT_TRUE(capabilities.axes[axis].velocity) << axis;
    EXPECT_TRUE(capabilities.axes[axis].feedback) << axis;
  }
  const AxisCapability& zoom = capabilities.axes[ZOOM];
  EXPECT_FALSE(zoom.present);
  EXPECT_FALSE(zoom.absolute);
  EXPECT_FALSE(zoom.velocity);
  EXPECT_FALSE(zoom.feedback);
  EXPECT_EQ(zoom.limitation, "a FLIR PTU has no zoom");
  // A zoom goal is taken on pan and tilt and the zoom ignored, in those words (the seed names this very unit).
  const ValidatedGoal zoom_goal = validatePositionGoal({ 0.1, 0.1, 4.0 }, capabilities, false);
  EXPECT_TRUE(zoom_goal.accepted);
  EXPECT_EQ(zoom_goal.message, "zoom 4.0000 X ignored: a FLIR PTU has no zoom");
  EXPECT_TRUE(validatePositionGoal({ 0.1, 0.1, 1.0 }, capabilities, false).accepted);
  EXPECT_TRUE(capabilities.relative_moves);  // PO / TO
  EXPECT_FALSE(capabilities.device_presets);
  EXPECT_FALSE(capabilities.device_home);
}

// Another program on the line (a published driver's home()) resets the unit; this one keeps its modes, as the
// published drivers expect.
TEST_F(FlirTest, AUnitResetByAnotherProgramIsSetUpAgainAndReachesGoals)
{
  startQuickUnit(false);
  backend_->goTo({ 0.3, 0.1, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return atRest(*backend_, 0.3, 0.1); }, WAIT));
  PtyClient other(emulator_->path());  // open until the end: nothing the unit says is lost meanwhile
  ASSERT_TRUE(other.isOpen());
  other.write("r ");
  // The unit calibrated, reading nothing meanwhile, and answered `!T!T!P!P*`: neither a reply nor an error. The
  // backend set it up again once it listened.
  ASSERT_TRUE(waitUntil([&] { return received("FT") >= 2u && backend_->sample().link_up; }, WAIT));
  EXPECT_EQ(counters().resets, 1u);
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, 0.0, 0.0); }, WAIT));  // the calibration ends at home
  EXPECT_EQ(backend_->sample().link_losses, 1u);
  backend_->goTo({ -0.4, -0.2, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, -0.4, -0.2); }, WAIT));
  EXPECT_EQ(counters().errors, 0u);
  EXPECT_EQ(counters().unusable_replies, 0u);
  EXPECT_EQ(counters().limit_hits, 0u);  // the calibration's `!T` / `!P` are no limit hits
  EXPECT_EQ(counters().restarts, 0u);
  EXPECT_EQ(backend_->sample().fault_count, 0u);
}

// A unit that resets as it powers up (--reset-as-power-up): its banner, then echo and verbose replies again, then the
// calibration and `!T!T!P!P*`. The `*` must not be taken for the answer to the set-up's `FT` (which the calibrating
// unit never read): `FT` goes out again once the unit listens.
TEST_F(FlirTest, AUnitThatResetsAsAtPowerUpIsSetUpAgainAndReachesGoals)
{
  startQuickUnit(true);
  backend_->goTo({ 0.3, 0.1, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return atRest(*backend_, 0.3, 0.1); }, WAIT));
  PtyClient other(emulator_->path());
  ASSERT_TRUE(other.isOpen());
  other.write("r ");
  ASSERT_TRUE(waitUntil([&] { return counters().restarts == 1u; }, WAIT));  // its banner
  ASSERT_TRUE(waitUntil([&] { return received("FT") >= 2u && backend_->sample().link_up; }, WAIT));
  EXPECT_EQ(counters().resets, 1u);
  EXPECT_GE(counters().banner_lines, 1u);
  EXPECT_NE(backend_->lastLinkLoss().find("the FLIR PTU restarted"), std::string::npos) << backend_->lastLinkLoss();
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, 0.0, 0.0); }, WAIT));
  backend_->goTo({ -0.4, -0.2, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, -0.4, -0.2); }, WAIT));
  EXPECT_EQ(counters().errors, 0u);
  EXPECT_EQ(counters().limit_hits, 0u);
  EXPECT_EQ(backend_->sample().fault_count, 0u);
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
  DeviceConfig<FlirProtocol> config;
  config.link.kind = LinkKind::TCP;
  config.link.port = emulator.port().tcpPort();
  config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
  auto backend = makeDeviceBackend<FlirProtocol>(config);
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

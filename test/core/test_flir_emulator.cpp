/**
 * \file
 * \brief The FLIR PTU emulator as a client on a real pseudo-terminal (or TCP) sees it: no banner kept for a later
 * opener, the banner of a power cycle while the port is open and of every TCP connection, echo and verbose replies by
 * default and their toggles, CR LF line ends, the answers units give (published-wire-facts.md, section 3), the reset
 * calibration answered `!T!T!P!P*` with every mode kept (and, as an option, a reset that restarts the unit as at
 * power-up), and the published drivers' start-up and reset played byte for byte.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "line_test_support.h"
#include "wait_until.h"

#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"

using namespace ptz_action_server;

namespace
{
const double RESOLUTION = arcSecondsToRadians(185.1428);
/// s the published driver waits for each read (its serial timeout).
constexpr double DRIVER_TIMEOUT = 4.0;

FlirPtuEmulatorConfig emulatorConfig(const char* name)
{
  FlirPtuEmulatorConfig config;
  config.port.link = uniqueLink(name);
  return config;
}

/// A unit that calibrates in a moment: the reset's motion, not its length, is under test.
FlirPtuEmulatorConfig quickUnit(const char* name)
{
  FlirPtuEmulatorConfig config = emulatorConfig(name);
  config.port.baud = 115200;
  config.pan_max_speed = 20.0;
  config.tilt_max_speed = 20.0;
  config.acceleration = 400.0;
  return config;
}

/// A unit that calibrates in a moment on a line at the D46's 9600 baud: what the published drivers read is under test.
FlirPtuEmulatorConfig quickUnitAt9600(const char* name)
{
  FlirPtuEmulatorConfig config = quickUnit(name);
  config.port.baud = 9600;
  return config;
}

/// Sends \p command and reads as many bytes as \p expected has.
std::string exchange(LineClient& port, const std::string& command, const std::string& expected)
{
  port.write(command);
  return port.read(expected.size());
}

bool atHome(const FlirPtuEmulator& emulator)
{
  const PtzSample sample = emulator.sample();
  return !sample.moving && std::abs(sample.position[PAN]) < RESOLUTION && std::abs(sample.position[TILT]) < RESOLUTION;
}

/// The text after a reply's `*`, trimmed, as the published driver reads a value.
std::string valueOf(const std::string& line)
{
  const std::size_t first = line.find_first_not_of(" \t\r\n", 1);
  const std::size_t last = line.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : line.substr(first, last - first + 1);
}

/// The published flir_ptu driver's initialize() on a unit at power-up: `ft ` `ed ` `ci ` back to back, then one read
/// of 20 bytes (returning at 20 or after its 4 s timeout), discarded. Returns what that read got.
std::string driverStartUp(PtyClient& port)
{
  port.write("ft ");
  port.write("ed ");
  port.write("ci ");
  return port.read(20, DRIVER_TIMEOUT);
}

struct DriverQuery
{
  const char* command;
  double value;
};

/// Each query as the published drivers make it: the request, one line read, `*` first and at least 3 bytes, the value
/// after it (getRes(), getLimit(), getPosition()).
void expectDriverValues(PtyClient& port, const std::vector<DriverQuery>& queries)
{
  for (const DriverQuery& query : queries)
  {
    port.write(query.command);
    const std::string line = port.readLine(DRIVER_TIMEOUT);
    ASSERT_GE(line.size(), 3u) << query.command;
    EXPECT_EQ(line[0], '*') << query.command << line;
    EXPECT_DOUBLE_EQ(std::stod(valueOf(line)), query.value) << query.command << line;
  }
}

/// getMode(): the third character of the reply to `c ` says position ('i') or velocity ('p').
char driverMode(PtyClient& port)
{
  port.write("c ");
  const std::string mode = port.readLine(DRIVER_TIMEOUT);
  EXPECT_GE(mode.size(), 3u);
  EXPECT_EQ(mode.substr(0, 1), "*") << mode;
  return mode.size() >= 3 ? mode[2] : 0;
}
}  // namespace

TEST(FlirEmulator, APowerUpBannerIsLostWhenNobodyHasThePortOpen)
{
  FlirPtuEmulator emulator(emulatorConfig("flir_banner"));
  EXPECT_GT(emulator.port().bytesLost(), 0u);  // the banner, dropped as a line drops it
  {
    PtyClient port(emulator.path());
    ASSERT_TRUE(port.isOpen());
    // The first bytes the opener sees are the echo and reply of its own first command.
    const std::string expected = "pp * Current pan position is 0\r\n";
    EXPECT_EQ(exchange(port, "pp ", expected), expected);
  }
  // A replugged unit powers up on a pseudo-terminal nobody has opened yet: its banner is lost too.
  emulator.replug();
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  const std::string expected = "tp * Current tilt position is 0\r\n";
  EXPECT_EQ(exchange(port, "tp ", expected), expected);
}

TEST(FlirEmulator, APowerCycleWhileThePortIsOpenPrintsTheBannerAndRestoresThePowerUpModes)
{
  FlirPtuEmulator emulator(emulatorConfig("flir_cycle"));
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  EXPECT_EQ(exchange(port, "ft ed ", "ft *\r\ned *\r\n"), "ft *\r\ned *\r\n");
  emulator.powerCycle();
  const std::string banner = port.readThrough("Initializing...\r\n");
  EXPECT_EQ(banner.rfind("\r\nPan-Tilt Controller", 0), 0u) << banner;
  EXPECT_NE(banner.find("All Rights Reserved\r\n"), std::string::npos) << banner;
  const std::string expected = "pp * Current pan position is 0\r\n";  // echo and verbose again
  EXPECT_EQ(exchange(port, "pp ", expected), expected);
}

TEST(FlirEmulator, EchoAndVerboseRepliesUntilTurnedOffEachLineEndedCrLf)
{
  FlirPtuEmulator emulator(emulatorConfig("flir_echo"));
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  struct Step
  {
    std::string command;
    std::string reply;  ///< everything the unit sends back
  };
  const std::vector<Step> steps = {
    { "pp ", "pp * Current pan position is 0\r\n" },         // power-up: echo, verbose
    { "TP\r", "TP\r\n* Current tilt position is 0\r\n" },    // a CR delimiter is echoed as a line break
    { "TP\r\n", "TP\r\n* Current tilt position is 0\r\n" },  // CR LF as one
    { "pr ", "pr * 185.1428 seconds arc per Pan position\r\n" },
    { "f ", "f * ASCII verbose mode\r\n" },
    { "ft ", "ft *\r\n" },  // terse from its own reply on
    { "pp ", "pp * 0\r\n" },
    { "f ", "f * ASCII terse mode\r\n" },
    { "ed ", "ed *\r\n" },  // still echoed itself
    { "pp ", "* 0\r\n" },
    { "ee ", "*\r\n" },
    { "pp ", "pp * 0\r\n" },
    { "fv ", "fv *\r\n" },
    { "ta ", "ta * Tilt acceleration is " + std::to_string(std::lround(3.0 / RESOLUTION)) + " positions/sec^2\r\n" },
  };
  for (const Step& step : steps)
  {
    EXPECT_EQ(exchange(port, step.command, step.reply), step.reply) << step.command;
  }
}

TEST(FlirEmulator, AnswersWhatUnitsAnswer)
{
  FlirPtuEmulator emulator(emulatorConfig("flir_answers"));
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  ASSERT_EQ(exchange(port, "ft ed ", "ft *\r\ned *\r\n"), "ft *\r\ned *\r\n");
  const std::string acceleration = std::to_string(std::lround(3.0 / RESOLUTION));
  struct Step
  {
    std::string command;
    std::string reply;  ///< without its CR LF
  };
  const std::vector<Step> steps = {
    { "pr ", "* 185.1428" },
    { "tr ", "* 185.1428" },
    { "pn ", "* -3090" },
    { "px ", "* 3090" },
    { "tn ", "* -907" },
    { "tx ", "* 604" },
    { "pu ", "* 1671" },  // 1.5 rad/s
    { "tu ", "* 1114" },
    { "pl ", "* 31" },  // a D46's lower speed bound
    { "tl ", "* 31" },
    { "pl20 ", "! Motor speed cannot be less than 31 pos/sec" },
    { "pl40 ", "*" },
    { "pl ", "* 40" },
    { "ps35 ", "! Motor speed cannot be less than 40 pos/sec" },
    { "ps3300 ", "! Pan speed cannot exceed 1671 positions/sec" },
    { "pb ", "* 1000" },  // base speed
    { "tb ", "* 1000" },
    { "tb900 ", "*" },
    { "tb ", "* 900" },
    { "pa ", "* " + acceleration },
    { "ta ", "* " + acceleration },
    { "pa2000 ", "*" },
    { "pa ", "* 2000" },
    { "pp3200 ", "! Maximum allowable Pan position is 3090" },
    { "tp-1000 ", "! Minimum allowable Tilt position is -907" },
    { "c ", "* independent" },  // the published driver reads 'i' at [2]: position mode
    { "cv ", "*" },
    { "c ", "* pure velocity" },  // 'p': pure velocity
    { "ci ", "*" },
    { "le ", "*" },
    { "h ", "*" },
    { "pq ", "! Illegal Command" },
    { "pp1x ", "! Illegal argument" },
  };
  for (const Step& step : steps)
  {
    const std::string reply = step.reply + "\r\n";
    EXPECT_EQ(exchange(port, step.command, reply), reply) << step.command;
  }
}

TEST(FlirEmulator, AResetCalibratesAnswersWithoutABannerAndKeepsEveryMode)
{
  FlirPtuEmulator emulator(quickUnit("flir_reset"));
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  // Terse, without echo, in velocity mode, a lower speed bound of its own; away from home.
  ASSERT_EQ(exchange(port, "ft ed pp1000 ", "ft *\r\ned *\r\n*\r\n"), "ft *\r\ned *\r\n*\r\n");
  ASSERT_TRUE(waitUntil([&] { return !atHome(emulator) && !emulator.sample().moving; }, LINE_TEST_WAIT));
  ASSERT_EQ(exchange(port, "cv pl40 ", "*\r\n*\r\n"), "*\r\n*\r\n");
  port.write("r ");
  // Each axis hit both its limits (tilt first) and came home; the unit says so, and nothing else.
  EXPECT_EQ(port.readThrough("\r\n"), "!T!T!P!P*\r\n");
  EXPECT_TRUE(atHome(emulator));
  EXPECT_EQ(exchange(port, "pp ", "* 0\r\n"), "* 0\r\n");  // still terse, no echo
  EXPECT_EQ(exchange(port, "c ", "* pure velocity\r\n"), "* pure velocity\r\n");
  EXPECT_EQ(exchange(port, "pl ", "* 40\r\n"), "* 40\r\n");
  EXPECT_EQ(port.available(), 0u);
}

TEST(FlirEmulator, AResetOfAnEchoingVerboseUnitKeepsItEchoingAndVerbose)
{
  FlirPtuEmulator emulator(quickUnit("flir_reset_verbose"));
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  ASSERT_EQ(exchange(port, "tp-300 ", "tp-300 *\r\n"), "tp-300 *\r\n");
  ASSERT_TRUE(waitUntil([&] { return !atHome(emulator) && !emulator.sample().moving; }, LINE_TEST_WAIT));
  port.write("r ");
  EXPECT_EQ(port.readThrough("\r\n"), "r !T!T!P!P*\r\n");  // the echo, then the calibration's answer
  EXPECT_TRUE(atHome(emulator));
  const std::string expected = "tp * Current tilt position is 0\r\n";
  EXPECT_EQ(exchange(port, "tp ", expected), expected);
}

TEST(FlirEmulator, AUnitThatResetsAsAtPowerUpPrintsItsBannerAndRestoresThePowerUpModes)
{
  FlirPtuEmulatorConfig config = quickUnit("flir_reset_power_up");
  config.reset_as_power_up = true;  // --reset-as-power-up
  FlirPtuEmulator emulator(config);
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  ASSERT_EQ(exchange(port, "ft ed pp1000 ", "ft *\r\ned *\r\n*\r\n"), "ft *\r\ned *\r\n*\r\n");
  ASSERT_TRUE(waitUntil([&] { return !atHome(emulator) && !emulator.sample().moving; }, LINE_TEST_WAIT));
  port.write("r ");
  const std::string said = port.readThrough("*\r\n");
  // The unit restarted: its banner first, then each axis hit both its limits (tilt first), then it came home.
  EXPECT_EQ(said.rfind("\r\nPan-Tilt Controller", 0), 0u) << said;
  const std::string calibrated = "Initializing...\r\n!T!T!P!P*\r\n";
  ASSERT_GE(said.size(), calibrated.size());
  EXPECT_EQ(said.substr(said.size() - calibrated.size()), calibrated) << said;
  EXPECT_TRUE(atHome(emulator));
  // The power-up modes are back.
  const std::string expected = "pp * Current pan position is 0\r\n";
  EXPECT_EQ(exchange(port, "pp ", expected), expected);
}

TEST(FlirEmulator, OverTcpEveryNewConnectionIsGreetedWithTheBannerAndAResetPrintsNone)
{
  FlirPtuEmulatorConfig config = quickUnit("flir_tcp");
  config.port.kind = DevicePortConfig::Kind::TCP;
  FlirPtuEmulator emulator(config);
  const std::string banner = "\r\n\r\n### PAN-TILT CONTROLLER\r\n### v3.3.0, (C)2010-2011 FLIR Commercial Systems, "
                             "Inc., "
                             "All Rights Reserved\r\nInitializing...*\r\n";
  for (int connection = 0; connection < 2; ++connection)
  {
    TcpClient client(emulator.port().tcpPort());
    ASSERT_TRUE(client.isConnected()) << connection;
    EXPECT_EQ(client.readThrough("Initializing...*\r\n"), banner) << connection;
    // Each connection starts echoing and verbose, whatever the one before it set.
    const std::string verbose = "pp * Current pan position is 0\r\n";
    EXPECT_EQ(exchange(client, "pp ", verbose), verbose) << connection;
    ASSERT_EQ(exchange(client, "ft ed ", "ft *\r\ned *\r\n"), "ft *\r\ned *\r\n");
    client.write("r ");
    EXPECT_EQ(client.readThrough("\r\n"), "!T!T!P!P*\r\n") << connection;  // no banner: not a new connection
    EXPECT_EQ(exchange(client, "pp ", "* 0\r\n"), "* 0\r\n") << connection;
    EXPECT_EQ(client.available(), 0u);
  }
}

TEST(FlirEmulator, REcalibratesWithoutABannerAndKeepsTheModes)
{
  FlirPtuEmulator emulator(quickUnit("flir_re"));
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  ASSERT_EQ(exchange(port, "ft ed tp-500 ", "ft *\r\ned *\r\n*\r\n"), "ft *\r\ned *\r\n*\r\n");
  ASSERT_TRUE(waitUntil([&] { return !atHome(emulator) && !emulator.sample().moving; }, LINE_TEST_WAIT));
  EXPECT_EQ(exchange(port, "re ", "!T!T!P!P*\r\n"), "!T!T!P!P*\r\n");
  EXPECT_TRUE(atHome(emulator));
  EXPECT_EQ(exchange(port, "tp ", "* 0\r\n"), "* 0\r\n");  // still terse, no echo
}

// The published flir_ptu driver (ros-drivers/flir_ptu 42023c6) as published-wire-facts.md section 3 describes it:
// initialize() writes `ft ` `ed ` `ci ` back to back, reads 20 bytes once (returning at 20 or after 4 s) and discards
// them, then asks each value with one request and one line read, never flushing in between. Anything the emulator had
// queued for the opener, or more than 20 bytes of replies, would shift every later reply.
TEST(FlirPublishedDriver, InitialisesAgainstTheDefaultEmulator)
{
  FlirPtuEmulator emulator(emulatorConfig("flir_driver"));  // banner, echo, verbose, 9600 baud
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  EXPECT_EQ(driverStartUp(port), "ft *\r\ned *\r\n*\r\n");  // 15 bytes: the echo stopped after `ed `
  // getRes() of both axes, getLimit() of the positions and of the speeds.
  expectDriverValues(port, { { "tr ", 185.1428 },
                             { "pr ", 185.1428 },
                             { "pn ", -3090 },
                             { "px ", 3090 },
                             { "tn ", -907 },
                             { "tx ", 604 },
                             { "pl ", 31 },
                             { "pu ", 1671 },
                             { "tl ", 31 },
                             { "tu ", 1114 } });
  EXPECT_EQ(driverMode(port), 'i');
  // setPosition() and getPosition(): the unit moves and tells where it is.
  port.write("pp-500 ");
  EXPECT_EQ(port.readLine(DRIVER_TIMEOUT), "*\r\n");
  EXPECT_TRUE(waitUntil(
      [&] {
        port.write("pp ");
        return port.readLine(DRIVER_TIMEOUT) == "* -500\r\n";
      },
      LINE_TEST_WAIT, std::chrono::milliseconds(50)));
}

// After ` r ` the published drivers read exactly 9 bytes, `!T!T!P!P*`, and go on with their queries without sending
// `ft` or `ed` again: the unit must still answer tersely and without echo. flir_ptu's home() flushes its input,
// writes ` r `, polls available() every 100 ms for up to 30 s until 9 bytes are there, reads them and compares; its
// sendCommand() flushes the input before each request. Player's and flir_pantilt_d46's PTU46 read the 9 bytes one by
// one, compare each, wait 100 ms and flush before their next query.
TEST(FlirPublishedDriver, ResetReadsNineBytesThenGoesOnTerseWithoutFtOrEd)
{
  FlirPtuEmulator emulator(quickUnitAt9600("flir_driver_reset"));  // banner, echo, verbose at power-up
  PtyClient port(emulator.path());
  ASSERT_TRUE(port.isOpen());
  ASSERT_EQ(driverStartUp(port), "ft *\r\ned *\r\n*\r\n");
  expectDriverValues(port, { { "tr ", 185.1428 }, { "pr ", 185.1428 }, { "pn ", -3090 }, { "px ", 3090 } });
  // setPosition(): away from home, so the calibration has somewhere to go back from.
  port.write("pp-500 ");
  ASSERT_EQ(port.readLine(DRIVER_TIMEOUT), "*\r\n");
  port.write("tp300 ");
  ASSERT_EQ(port.readLine(DRIVER_TIMEOUT), "*\r\n");
  ASSERT_TRUE(waitUntil([&] { return !atHome(emulator) && !emulator.sample().moving; }, LINE_TEST_WAIT));

  // home()
  port.flushInput();
  port.write(" r ");
  ASSERT_TRUE(waitUntil([&] { return port.available() >= 9; }, 30.0, std::chrono::milliseconds(100)));
  EXPECT_EQ(port.read(9, DRIVER_TIMEOUT), "!T!T!P!P*");
  EXPECT_TRUE(atHome(emulator));
  // What the drivers flush before their next request: the end of that line, and nothing else (no banner, no echo).
  EXPECT_EQ(port.readLine(DRIVER_TIMEOUT), "\r\n");

  // The driver goes on as before the reset: each reply terse, `*` first, no echo.
  expectDriverValues(port, { { "pp ", 0 }, { "tp ", 0 }, { "tr ", 185.1428 }, { "tn ", -907 }, { "tx ", 604 } });
  EXPECT_EQ(driverMode(port), 'i');
  port.write("tp-200 ");
  EXPECT_EQ(port.readLine(DRIVER_TIMEOUT), "*\r\n");
  EXPECT_TRUE(waitUntil(
      [&] {
        port.write("tp ");
        return port.readLine(DRIVER_TIMEOUT) == "* -200\r\n";
      },
      LINE_TEST_WAIT, std::chrono::milliseconds(50)));
  EXPECT_EQ(port.available(), 0u);
}

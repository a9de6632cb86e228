/**
 * \file
 * \brief What only the Axis backend does, against axis_camera_emulator's camera on 127.0.0.1: the limits, the offered
 * commands and the zoom X-factor found out at start (the camera's table, a configured one, the model family's guess
 * with its warning, none at all: a declared missing capability), velocity goals as continuous moves, one connection
 * for a thousand goals, and the start-up failures (wrong password, no VAPIX, an Error: body, nonsense, nobody
 * there) named.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/read_until.hpp>
#include <boost/asio/streambuf.hpp>
#include <boost/asio/write.hpp>

#include "diagnostic_value.h"
#include "startup_error.h"
#include "goal_supervisor_fixture.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
constexpr double WAIT = 15.0;

DeviceConfig<AxisProtocol> configFor(std::uint16_t port, const std::string& password = "pass")
{
  DeviceConfig<AxisProtocol> config;
  config.link.port = port;
  config.link.http.username = "root";
  config.link.http.password = password;
  config.session.startup_timeout = 5.0;
  config.session.state_timeout = 1.0;
  return config;
}

/// A server answering every request with \p answer (behind Digest).
std::unique_ptr<HttpCameraServer> serverAnswering(const HttpAnswer& answer)
{
  return std::make_unique<HttpCameraServer>(HttpCameraServerConfig(), [answer](const std::string&, const std::string&,
                                                                               const std::string&) { return answer; });
}

std::vector<std::string> targets(HttpCameraServer& server, const std::string& containing)
{
  std::vector<std::string> found;
  for (const HttpExchange& exchange : server.received().items())
  {
    if (exchange.target.find(containing) != std::string::npos)
    {
      found.push_back(exchange.target);
    }
  }
  return found;
}

/// Every warning a backend gave so far, taken as the node takes them (PtzBackend::takeWarnings()).
struct Warnings
{
  std::vector<std::string> texts;

  std::vector<std::string> all(PtzBackend& backend)
  {
    for (const std::string& text : backend.takeWarnings())
    {
      texts.push_back(text);
    }
    return texts;
  }
};

/// The camera of issue 21: firmware without the zoom attributes, a 30X lens (VAPIX zoom 1..9999, linear), \p model.
AxisCameraEmulatorConfig fieldCamera(const std::string& model)
{
  AxisCameraEmulatorConfig camera;
  camera.attributes = false;
  camera.zoom_table = AxisCameraEmulatorConfig::linearZoomTable(30.0);
  camera.model = model;
  return camera;
}

/// A goal the node's supervisor runs on \p backend (validation, the axes it judges, its monitor), to its end.
std::string runGoal(const std::shared_ptr<PtzBackend>& backend, const goal_supervisor_test::GoalConverter& goal)
{
  GoalMonitorConfig config;
  config.stall_timeout = 2.0;
  return goal_supervisor_test::runGoalToItsEnd(backend, goal, config, WAIT);
}

AxisZoomSource zoomSource(const DeviceBackend& backend)
{
  return backend.protocol<AxisProtocol>().zoomSource();
}

/// The body a plain GET of \p target gets from a camera without authentication on 127.0.0.1:\p port.
std::string plainGet(std::uint16_t port, const std::string& target)
{
  boost::asio::io_context context;
  boost::asio::ip::tcp::socket socket(context);
  socket.connect({ boost::asio::ip::make_address("127.0.0.1"), port });
  boost::asio::write(socket, boost::asio::buffer("GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"));
  boost::asio::streambuf buffer;
  const std::size_t header_size = boost::asio::read_until(socket, buffer, "\r\n\r\n");
  std::string text(boost::asio::buffers_begin(buffer.data()), boost::asio::buffers_end(buffer.data()));
  const std::string header = text.substr(0, header_size);
  std::size_t length = 0;
  const std::size_t at = header.find("Content-Length: ");
  if (at != std::string::npos)
  {
    length = std::stoul(header.substr(at + 16));
  }
  if (text.size() < header_size + length)
  {
    boost::asio::read(socket, buffer, boost::asio::transfer_exactly(header_size + length - text.size()));
    text.assign(boost::asio::buffers_begin(buffer.data()), boost::asio::buffers_end(buffer.data()));
  }
  return text.substr(header_size, length);
}

/// The keys of a key=value reply, in order.
std::vector<std::string> keysOf(const std::string& body)
{
  vapix::Reply reply;
  EXPECT_EQ(vapix::parseReply(body, reply), "") << body;
  std::vector<std::string> keys;
  for (const auto& value : reply.values)
  {
    keys.push_back(value.first);
  }
  return keys;
}

TEST(AxisCameraEmulator, TheFieldModeAnswersAsTheFieldCameraDid)
{
  AxisCameraEmulatorConfig config = fieldCamera("Q6155-E");
  config.http.auth = HttpAuth::NONE;
  AxisCameraEmulator camera(config);
  const std::uint16_t port = camera.port();
  const std::string ptz = "/axis-cgi/com/ptz.cgi?camera=1&";
  // info=1 lists the queries the field camera lists: no attributes.
  const std::string info = plainGet(port, ptz + "info=1");
  EXPECT_NE(info.find("\r\nquery={ speed | position | limits | presetposcam | presetposall }\r\n"), std::string::npos)
      << info;
  const vapix::CommandList commands = vapix::readCommandList(info);
  EXPECT_FALSE(commands.offers("query", "attributes"));
  EXPECT_TRUE(commands.has("continuouszoommove") && commands.has("rpan") && commands.offers("move", "home"));
  // Asking for them anyway: the camera's Error: words for an unknown query value.
  const std::string refused = plainGet(port, ptz + "query=attributes&group=zoom");
  EXPECT_EQ(refused, "Error:\r\nquery: unknown value: attributes\r\n");
  vapix::ZoomAttributes attributes;
  ASSERT_EQ(vapix::readZoomAttributes(refused, 1, attributes), "");
  EXPECT_TRUE(attributes.refused);
  // The limits give the zoom 1..9999 and the lens's other limits; the position carries the field camera's keys.
  const std::vector<std::string> limits = keysOf(plainGet(port, ptz + "query=limits"));
  EXPECT_EQ(limits,
            (std::vector<std::string>{ "MinPan", "MaxPan", "MinTilt", "MaxTilt", "MinZoom", "MaxZoom", "MinIris",
                                       "MaxIris", "MinFocus", "MaxFocus", "MinFieldAngle", "MaxFieldAngle" }));
  vapix::Reply reply;
  ASSERT_EQ(vapix::parseReply(plainGet(port, ptz + "query=limits"), reply), "");
  EXPECT_EQ(*reply.find("MinZoom"), "1");
  EXPECT_EQ(*reply.find("MaxZoom"), "9999");
  EXPECT_EQ(
      keysOf(plainGet(port, ptz + "query=position")),
      (std::vector<std::string>{ "pan", "tilt", "zoom", "iris", "focus", "brightness", "autofocus", "autoiris" }));
  // Its model, as param.cgi lists it.
  ASSERT_EQ(vapix::parseReply(plainGet(port, "/axis-cgi/param.cgi?action=list&group=root.Brand"), reply), "");
  vapix::Product product;
  ASSERT_EQ(vapix::readProduct(reply, product), "");
  EXPECT_EQ(product.number, "Q6155-E");
  EXPECT_EQ(plainGet(port, "/axis-cgi/param.cgi?action=list&group=root.Nothing"), "# Error: Error -1 getting param in "
                                                                                  "group 'root.Nothing'\r\n");
}

TEST(AxisCameraEmulator, ByDefaultItAnswersTheAttributesInTheDocumentedSections)
{
  AxisCameraEmulatorConfig config;
  config.http.auth = HttpAuth::NONE;
  AxisCameraEmulator camera(config);
  const std::string body = plainGet(camera.port(), "/axis-cgi/com/ptz.cgi?camera=1&query=attributes&group=zoom");
  EXPECT_EQ(body.rfind("Attributes for camera 1\r\nmaxOpticalZoomMag=18\r\nzoomSteps=value=1 | zoom=1,value=589 | "
                       "zoom=2,value=1177 | zoom=3,",
                       0),
            0u)
      << body;
  vapix::ZoomAttributes attributes;
  ASSERT_EQ(vapix::readZoomAttributes(body, 1, attributes), "");
  vapix::ZoomTable table;
  ASSERT_EQ(vapix::zoomTableOf(attributes, table), "");
  EXPECT_EQ(table.toText(), AxisCameraEmulatorConfig::DEFAULT_ZOOM_TABLE);
  EXPECT_NE(plainGet(camera.port(), "/axis-cgi/com/ptz.cgi?info=1").find("presetposall | attributes }"),
            std::string::npos);
}

TEST(AxisBackend, ReadsTheLimitsTheCommandsAndTheCamerasZoomStepsAtStart)
{
  AxisCameraEmulator camera{ AxisCameraEmulatorConfig() };
  Warnings warnings;
  DeviceConfig<AxisProtocol> config = configFor(camera.port());
  auto backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  const Capabilities capabilities = backend->capabilities();
  EXPECT_NEAR(capabilities.axes[PAN].range.min, toRadians(-170.0), 1e-9);
  EXPECT_NEAR(capabilities.axes[PAN].range.max, toRadians(170.0), 1e-9);
  EXPECT_NEAR(capabilities.axes[TILT].range.min, toRadians(-20.0), 1e-9);
  EXPECT_NEAR(capabilities.axes[TILT].range.max, toRadians(90.0), 1e-9);
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities.axes[axis];
    EXPECT_TRUE(capability.present && capability.absolute && capability.velocity && capability.feedback)
        << axisName(axis);
    EXPECT_EQ(capability.limitation, "") << axisName(axis);
  }
  EXPECT_NEAR(capabilities.axes[ZOOM].range.min, 1.0, 1e-9);
  EXPECT_NEAR(capabilities.axes[ZOOM].range.max, 18.0, 1e-9);
  // info=1 lists rpan/rtilt, the preset queries and move=home.
  EXPECT_TRUE(capabilities.relative_moves);
  EXPECT_TRUE(capabilities.device_presets);
  EXPECT_TRUE(capabilities.device_home);
  EXPECT_EQ(zoomSource(*backend), AxisZoomSource::CAMERA_TABLE);
  EXPECT_EQ(diagnosticValue(*backend, "zoom X-factor"), "the camera's zoomSteps (18 points, 1..18X)");
  EXPECT_EQ(targets(camera.server(), "query=attributes&group=zoom").size(), 1u);
  EXPECT_EQ(targets(camera.server(), "info=1").size(), 1u);
  EXPECT_TRUE(targets(camera.server(), "group=root.Brand").empty());  // the camera's table needs no model
  EXPECT_TRUE(warnings.all(*backend).empty());

  // 4X goes out as the camera's step for 4X, and the camera gets to 4X.
  backend->goTo({ 0.1, 0.05, 4.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend->sample().position[ZOOM] - 4.0) < 0.02; }, WAIT));
  EXPECT_NEAR(camera.sample().position[ZOOM], 4.0, 0.02);
  const std::vector<std::string> moves = targets(camera.server(), "&pan=");
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_NE(moves[0].find("&zoom=1765&"), std::string::npos) << moves[0];
}

TEST(AxisBackend, AFieldCameraWithoutAttributesGetsItsModelFamilysZoomAsAGuessWarnedOnce)
{
  AxisCameraEmulator camera(fieldCamera("Q6155-E"));
  Warnings warnings;
  DeviceConfig<AxisProtocol> config = configFor(camera.port());
  std::shared_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  EXPECT_EQ(zoomSource(*backend), AxisZoomSource::MODEL_GUESS);
  const AxisCapability zoom = backend->capabilities().axes[ZOOM];
  EXPECT_TRUE(zoom.present && zoom.absolute && zoom.velocity && zoom.feedback);
  EXPECT_NEAR(zoom.range.max, 30.0, 1e-9);
  EXPECT_NE(zoom.limitation.find("a guess"), std::string::npos) << zoom.limitation;
  EXPECT_EQ(zoom.remedy, "set axis/zoom_max_factor to its optical zoom, or axis/zoom_table");
  ASSERT_EQ(warnings.all(*backend).size(), 1u);
  const std::string warning = warnings.all(*backend)[0];
  EXPECT_EQ(warning.rfind("AXIS Q6155-E PTZ Network Camera gives no zoom table (query=attributes&group=zoom: "
                          "query: unknown value: attributes): its zoom X-factor is a guess, 30X optical",
                          0),
            0u)
      << warning;
  EXPECT_NE(warning.find("set axis/zoom_max_factor"), std::string::npos) << warning;
  EXPECT_EQ(diagnosticValue(*backend, "zoom X-factor").rfind("GUESS: 30X optical at VAPIX zoom 9999, linear", 0), 0u)
      << diagnosticValue(*backend, "zoom X-factor");
  EXPECT_EQ(diagnosticValue(*backend, "model"), "AXIS Q6155-E PTZ Network Camera");

  // The goal of the field report: zoom 4 now reaches 4X on the camera itself (its lens is what the family has).
  EXPECT_EQ(runGoal(backend, goal_supervisor_test::positionGoal(0.2, 0.1, 4.0)).rfind("SUCCEEDED: reached", 0), 0u);
  EXPECT_NEAR(camera.sample().position[ZOOM], 4.0, 0.02);

  // A new connection asks again, and does not warn again.
  camera.server().setListening(false);
  camera.server().dropConnections();
  ASSERT_TRUE(waitUntil([&] { return !backend->sample().link_up; }, WAIT));
  const std::size_t asked = targets(camera.server(), "group=root.Brand").size();
  camera.server().setListening(true);
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  EXPECT_EQ(targets(camera.server(), "group=root.Brand").size(), asked + 1);
  EXPECT_EQ(warnings.all(*backend).size(), 1u);
}

TEST(AxisBackend, WithoutAnyZoomTableTheZoomIsADeclaredMissingCapabilityNeverASilentOneX)
{
  for (const bool guess : { true, false })
  {
    // A model without a family default; and a known family with guessing turned off.
    AxisCameraEmulator camera(fieldCamera(guess ? "Q8665-E" : "Q6155-E"));
    Warnings warnings;
    DeviceConfig<AxisProtocol> config = configFor(camera.port());
    config.settings.zoom_guess = guess;
    std::shared_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(config);
    backend->start();
    EXPECT_EQ(zoomSource(*backend), AxisZoomSource::UNKNOWN);
    const AxisCapability zoom = backend->capabilities().axes[ZOOM];
    EXPECT_TRUE(zoom.present);
    EXPECT_FALSE(zoom.absolute);
    EXPECT_FALSE(zoom.feedback);
    EXPECT_TRUE(zoom.velocity);  // info=1 lists continuouszoommove
    EXPECT_EQ(zoom.limitation, "this Axis camera gives no zoom table");
    ASSERT_EQ(warnings.all(*backend).size(), 1u);
    EXPECT_NE(warnings.all(*backend)[0].find(guess ? "its model family has no default" : "zoom_guess is off"),
              std::string::npos)
        << warnings.all(*backend)[0];
    EXPECT_EQ(diagnosticValue(*backend, "zoom X-factor").rfind("UNKNOWN: no zoom table", 0), 0u);

    // The field report's goal is refused, naming what to set; nothing moves.
    EXPECT_EQ(runGoal(backend, goal_supervisor_test::positionGoal(0.2, 0.1, 4.0)), "REJECTED: this Axis camera gives "
                                                                                   "no zoom table: zoom goals are not "
                                                                                   "supported; set axis/zoom_table (or "
                                                                                   "axis/zoom_max_factor, its optical "
                                                                                   "zoom)");
    EXPECT_TRUE(targets(camera.server(), "&pan=").empty());
    // A goal that leaves the zoom alone runs, and no zoom= goes out.
    EXPECT_EQ(runGoal(backend, goal_supervisor_test::positionGoal(0.2, 0.1, 0.0)).rfind("SUCCEEDED: reached", 0), 0u);
    const std::vector<std::string> moves = targets(camera.server(), "&pan=");
    ASSERT_EQ(moves.size(), 1u);
    EXPECT_EQ(moves[0], "/axis-cgi/com/ptz.cgi?camera=1&pan=11.4592&tilt=5.7296&speed=100");
    // Velocity goals zoom.
    backend->moveAtVelocity({ 0.0, 0.0, 4.0 });
    ASSERT_TRUE(waitUntil([&] { return !targets(camera.server(), "continuouszoommove=50").empty(); }, WAIT));
    ASSERT_TRUE(waitUntil([&] { return camera.sample().position[ZOOM] > 1.5; }, WAIT));
    backend->stop();
    ASSERT_TRUE(waitUntil([&] { return !camera.sample().moving; }, WAIT));
    // Zoom 1, the widest view, it can still go to (issue 32): `zoom=` the limits' MinZoom; NaN sends no zoom=.
    EXPECT_TRUE(zoom.widest_view);
    backend->goTo({ -0.1, 0.0, 1.0 });
    ASSERT_TRUE(waitUntil([&] { return !targets(camera.server(), "&zoom=").empty(); }, WAIT));
    EXPECT_EQ(targets(camera.server(), "&zoom=")[0], "/axis-cgi/com/ptz.cgi?camera=1&pan=-5.7296&tilt=0.0000&zoom=1&"
                                                     "speed=100");
    ASSERT_TRUE(
        waitUntil([&] { return camera.sample().position[ZOOM] < 1.0 + 1e-6 && !camera.sample().moving; }, WAIT));
    backend->goTo({ 0.1, 0.0, std::nan("") });
    ASSERT_TRUE(waitUntil([&] { return targets(camera.server(), "&pan=").size() == 3; }, WAIT));
    EXPECT_EQ(targets(camera.server(), "&pan=")[2], "/axis-cgi/com/ptz.cgi?camera=1&pan=5.7296&tilt=0.0000&speed=100");
  }
}

TEST(AxisBackend, ACameraWhoseLimitsGiveNoZoomHasNone)
{
  AxisCameraEmulatorConfig camera_config;
  camera_config.zoom_table.clear();
  AxisCameraEmulator camera(camera_config);
  Warnings warnings;
  DeviceConfig<AxisProtocol> config = configFor(camera.port());
  std::shared_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  EXPECT_EQ(zoomSource(*backend), AxisZoomSource::NO_ZOOM);
  const AxisCapability zoom = backend->capabilities().axes[ZOOM];
  EXPECT_FALSE(zoom.present);
  EXPECT_FALSE(zoom.velocity);
  EXPECT_TRUE(targets(camera.server(), "query=attributes").empty());
  EXPECT_TRUE(warnings.all(*backend).empty());
  // The seed: a camera without zoom ignores the zoom field; the goal says so and no zoom goes to the camera.
  EXPECT_EQ(runGoal(backend, goal_supervisor_test::positionGoal(0.2, 0.1, 4.0)), "SUCCEEDED: reached pan 0.2000 rad, "
                                                                                 "tilt 0.1000 rad (zoom 4.0000 X "
                                                                                 "ignored: this Axis camera's limits "
                                                                                 "give no zoom)");
  for (const std::string& move : targets(camera.server(), "&pan="))
  {
    EXPECT_EQ(move.find("zoom="), std::string::npos) << move;
  }
  backend->moveAtVelocity({ 0.1, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return !targets(camera.server(), "continuouspantiltmove").empty(); }, WAIT));
  EXPECT_EQ(targets(camera.server(), "continuouspantiltmove")[0], "/axis-cgi/com/"
                                                                  "ptz.cgi?camera=1&continuouspantiltmove=7,0");
  backend->stop();
}

TEST(AxisBackend, AConfiguredTableOrOpticalZoomWinsOverTheCameraAndIsNoGuess)
{
  {
    AxisCameraEmulator camera{ AxisCameraEmulatorConfig() };
    DeviceConfig<AxisProtocol> configured = configFor(camera.port());
    configured.settings.zoom_table = "1:1,9999:20";
    auto backend = makeDeviceBackend<AxisProtocol>(configured);
    EXPECT_NEAR(backend->capabilities().axes[ZOOM].range.max, 20.0, 1e-9);  // known before the start
    backend->start();
    EXPECT_EQ(zoomSource(*backend), AxisZoomSource::CONFIGURED_TABLE);
    EXPECT_NEAR(backend->capabilities().axes[ZOOM].range.max, 20.0, 1e-9);
    EXPECT_TRUE(targets(camera.server(), "query=attributes").empty());
    EXPECT_EQ(diagnosticValue(*backend, "zoom X-factor"), "zoom_table 1:1,9999:20");
  }
  {
    AxisCameraEmulator camera(fieldCamera("Q8665-E"));
    Warnings warnings;
    DeviceConfig<AxisProtocol> configured = configFor(camera.port());
    configured.settings.zoom_max_factor = 30.0;
    std::shared_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(configured);
    backend->start();
    EXPECT_EQ(zoomSource(*backend), AxisZoomSource::CONFIGURED_MAXIMUM);
    const AxisCapability zoom = backend->capabilities().axes[ZOOM];
    EXPECT_TRUE(zoom.absolute && zoom.feedback);
    EXPECT_EQ(zoom.limitation, "");
    EXPECT_TRUE(warnings.all(*backend).empty());
    EXPECT_TRUE(targets(camera.server(), "query=attributes").empty());
    EXPECT_TRUE(targets(camera.server(), "group=root.Brand").empty());
    EXPECT_EQ(runGoal(backend, goal_supervisor_test::positionGoal(-0.2, 0.0, 12.0)).rfind("SUCCEEDED: reached", 0), 0u);
    EXPECT_NEAR(camera.sample().position[ZOOM], 12.0, 0.02);
  }
  DeviceConfig<AxisProtocol> both = configFor(1);
  both.settings.zoom_table = "1:1,9999:20";
  both.settings.zoom_max_factor = 20.0;
  EXPECT_THROW(makeDeviceBackend<AxisProtocol>(both), ConfigError);
  DeviceConfig<AxisProtocol> flat = configFor(1);
  flat.settings.zoom_max_factor = 1.0;
  EXPECT_THROW(makeDeviceBackend<AxisProtocol>(flat), ConfigError);
}

/// A camera answering each request by the first of \p answers whose key its target contains (else `Error:`).
std::unique_ptr<HttpCameraServer> cannedCamera(const std::vector<std::pair<std::string, HttpAnswer>>& answers)
{
  return std::make_unique<HttpCameraServer>(
      HttpCameraServerConfig(), [answers](const std::string&, const std::string& target, const std::string&) {
        for (const auto& answer : answers)
        {
          if (target.find(answer.first) != std::string::npos)
          {
            return answer.second;
          }
        }
        return HttpAnswer{ 200, "text/plain", "Error:\r\nunknown\r\n" };
      });
}

const HttpAnswer CANNED_LIMITS{ 200, "text/plain",
                                "MinPan=-180\r\nMaxPan=180\r\nMinTilt=-90\r\nMaxTilt=20\r\nMinZoom=1\r\nMaxZoom="
                                "19999\r\n" };

TEST(AxisBackend, TheCamerasOpticalMaximumAndAPositionWithoutZoomAreTakenAsTheyAre)
{
  // maxOpticalZoomMag only (no zoomSteps): linear, digital range cut at the optical end; no info=1 answer: VAPIX's
  // documented commands assumed, the informative ones not declared.
  auto camera = cannedCamera(
      { { "query=limits", CANNED_LIMITS },
        { "query=attributes", { 200, "text/plain", "Attributes for camera 1\r\nmaxOpticalZoomMag=20\r\n" } },
        { "query=position", { 200, "text/plain", "pan=0\r\ntilt=0\r\nzoom=5000\r\n" } } });
  std::shared_ptr<DeviceBackend> backend = makeDeviceBackend<AxisProtocol>(configFor(camera->port()));
  backend->start();
  EXPECT_EQ(zoomSource(*backend), AxisZoomSource::CAMERA_MAXIMUM);
  Capabilities capabilities = backend->capabilities();
  EXPECT_NEAR(capabilities.axes[ZOOM].range.max, 20.0, 1e-9);
  EXPECT_TRUE(capabilities.axes[ZOOM].absolute && capabilities.axes[ZOOM].velocity);
  EXPECT_FALSE(capabilities.relative_moves || capabilities.device_presets || capabilities.device_home);
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  EXPECT_NEAR(backend->sample().position[ZOOM], 1.0 + 4999.0 * 19.0 / 9998.0, 1e-6);

  // A table, but a position without zoom=: nothing to see a zoom goal reached by.
  auto blind = cannedCamera({ { "query=limits", CANNED_LIMITS },
                              { "query=attributes", { 200, "text/plain", "maxOpticalZoomMag=20\r\n" } },
                              { "query=position", { 200, "text/plain", "pan=0\r\ntilt=0\r\n" } } });
  Warnings warnings;
  DeviceConfig<AxisProtocol> config = configFor(blind->port());
  backend = makeDeviceBackend<AxisProtocol>(config);
  backend->start();
  const AxisCapability zoom = backend->capabilities().axes[ZOOM];
  EXPECT_TRUE(zoom.present && zoom.velocity);
  EXPECT_FALSE(zoom.absolute || zoom.feedback);
  EXPECT_EQ(zoom.limitation, "this Axis camera reports no zoom position");
  EXPECT_TRUE(zoom.widest_view);  // zoom= MinZoom is still its widest view
  ASSERT_EQ(warnings.all(*backend).size(), 1u);
}

TEST(AxisBackendStartup, UnreadableZoomAttributesAreNamed)
{
  auto camera =
      cannedCamera({ { "query=limits", CANNED_LIMITS },
                     { "query=attributes", { 200, "text/plain", "zoomSteps=value=1 | zoom=2,value=2 | zoom=1\r\n" } },
                     { "query=position", { 200, "text/plain", "pan=0\r\ntilt=0\r\nzoom=1\r\n" } } });
  EXPECT_EQ(startupError(*makeDeviceBackend<AxisProtocol>(configFor(camera->port()))),
            "an Axis camera on http://127.0.0.1:" + std::to_string(camera->port()) +
                ": query=attributes&group=zoom: point 2 '2:1': values and X must increase (set axis/zoom_table or "
                "axis/zoom_max_factor to override it)");
}

TEST(AxisBackend, VelocityGoalsAreContinuousMovesScaledByTheCamerasSpeeds)
{
  AxisCameraEmulator camera{ AxisCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<AxisProtocol>(configFor(camera.port()));
  backend->start();
  backend->moveAtVelocity({ 0.3, -0.2, 4.0 });
  ASSERT_TRUE(waitUntil([&] { return !targets(camera.server(), "continuouspantiltmove").empty(); }, WAIT));
  EXPECT_EQ(targets(camera.server(), "continuouspantiltmove")[0], "/axis-cgi/com/"
                                                                  "ptz.cgi?camera=1&continuouspantiltmove=20,-20&"
                                                                  "continuouszoommove=50");
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera.sample().velocity[PAN] - 0.3) < 0.02; }, WAIT));
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !targets(camera.server(), "move=stop").empty(); }, WAIT));
  ASSERT_TRUE(waitUntil([&] { return !camera.sample().moving; }, WAIT));
}

TEST(AxisBackend, AThousandGoalsTravelOverOneConnectionWithOneChallenge)
{
  AxisCameraEmulator camera{ AxisCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<AxisProtocol>(configFor(camera.port()));
  backend->start();
  for (int index = 0; index < 1000; ++index)
  {
    backend->goTo({ 0.001 * (index % 100), 0.0, 1.0 });
  }
  ASSERT_TRUE(waitUntil([&] { return targets(camera.server(), "&pan=").size() == 1000; }, 60.0))
      << targets(camera.server(), "&pan=").size();
  EXPECT_EQ(camera.server().counters().connections, 1u);
  EXPECT_EQ(camera.server().counters().challenges, 1u);
  EXPECT_EQ(backend->sample().fault_count, 0u);
}

TEST(AxisBackend, AnHttpErrorDuringAGoalIsItsFault)
{
  AxisCameraEmulator camera{ AxisCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<AxisProtocol>(configFor(camera.port()));
  backend->start();
  camera.server().setErrorStatus(500);
  backend->goTo({ 0.5, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count > 0; }, WAIT));
  EXPECT_EQ(backend->lastFault(), "HTTP 500 answering 'pan=28.6479&tilt=0.0000&zoom=1&speed=100'");
  camera.server().setErrorStatus(0);
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
}

TEST(AxisBackendStartup, AWrongPasswordIsNamedWithoutThePassword)
{
  AxisCameraEmulator camera{ AxisCameraEmulatorConfig() };
  const std::string error = startupError(*makeDeviceBackend<AxisProtocol>(configFor(camera.port(), "hunter2")));
  EXPECT_EQ(error, "an Axis camera on http://127.0.0.1:" + std::to_string(camera.port()) +
                       ": HTTP 401 Unauthorized: the camera refused the credentials of user 'root' for 'query=limits'");
  EXPECT_EQ(error.find("hunter2"), std::string::npos);
}

TEST(AxisBackendStartup, ForbiddenMissingErrorAndNonsenseAreNamed)
{
  struct Case
  {
    HttpAnswer answer;
    std::string expected;
  };
  const std::vector<Case> cases = {
    { { 403, "text/plain", "" }, "HTTP 403 Forbidden: user 'root' may not control PTZ ('query=limits')" },
    { { 404, "text/html", "<html/>" }, "HTTP 404 Not Found: /axis-cgi/com/ptz.cgi (no VAPIX PTZ at this address?)" },
    { { 200, "text/plain", "Error:\nquery: unknown value: limits\n" },
      "the Axis camera refused 'query=limits': query: unknown value: limits" },
    { { 200, "text/html", "<html>hello</html>" },
      "malformed answer to 'query=limits': line 1 '<html>hello</html>' is not key=value" },
    { { 200, "text/plain", "MinPan=-170\nMaxPan=170\n" }, "query=limits: no MinTilt" },
  };
  for (const Case& tried : cases)
  {
    auto server = serverAnswering(tried.answer);
    const std::string error = startupError(*makeDeviceBackend<AxisProtocol>(configFor(server->port())));
    EXPECT_EQ(error, "an Axis camera on http://127.0.0.1:" + std::to_string(server->port()) + ": " + tried.expected);
  }
}

TEST(AxisBackendStartup, NobodyThereEndsInTheStartupTimeoutWithTheLinksError)
{
  std::uint16_t port = 0;
  {
    AxisCameraEmulator camera{ AxisCameraEmulatorConfig() };
    port = camera.port();
  }
  DeviceConfig<AxisProtocol> config = configFor(port);
  config.session.startup_timeout = 0.5;
  const std::string error = startupError(*makeDeviceBackend<AxisProtocol>(config));
  EXPECT_EQ(error.rfind("no answer from an Axis camera on http://127.0.0.1:" + std::to_string(port) +
                            " within 0.5 s: http://127.0.0.1:" + std::to_string(port) +
                            ": GET /axis-cgi/com/ptz.cgi?camera=1&query=limits: ",
                        0),
            0u)
      << error;
}

}  // namespace
}  // namespace ptz_action_server

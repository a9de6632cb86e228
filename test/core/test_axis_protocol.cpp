/**
 * \file
 * \brief What only the Axis backend does with goals and at start, against axis_camera_emulator's camera on
 * 127.0.0.1: velocity goals as continuous moves, one connection for a thousand goals, an HTTP error as the goal's
 * fault, and the start-up failures (wrong password, no VAPIX, an Error: body, nonsense, nobody there) named. Its zoom
 * is test_axis_zoom.cpp's, the emulator's answers test_axis_emulator.cpp's.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "axis_backend_test_support.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "startup_error.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace axis_backend_test;

/// A server answering every request with \p answer (behind Digest).
std::unique_ptr<HttpCameraServer> serverAnswering(const HttpAnswer& answer)
{
  return std::make_unique<HttpCameraServer>(HttpCameraServerConfig(), [answer](const std::string&, const std::string&,
                                                                               const std::string&) { return answer; });
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

/**
 * \file
 * \brief The Axis backend's zoom, against axis_camera_emulator's camera and canned cameras on 127.0.0.1: the limits,
 * the offered commands and the zoom X-factor found out at start (the camera's table, a configured one, its optical
 * maximum, the model family's guess with its warning, none at all: a declared missing capability), and unreadable
 * attributes named.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "axis_backend_test_support.h"
#include "diagnostic_value.h"
#include "goal_supervisor_fixture.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "startup_error.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace axis_backend_test;

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

}  // namespace
}  // namespace ptz_action_server

/**
 * \file
 * \brief The ONVIF backend with the cheap cameras of the field, as the emulator plays them (its --mode): Stop answered
 * and not obeyed, a zoom-only AbsoluteMove that moves pan and tilt, a PTZTimeout range, AbsoluteMove answered and never
 * moved, a zoom range not honoured, Axis's 401 to GetSystemDateAndTime; and the cameras that must not be taken for
 * them (one that brakes on Stop, a blocked motor).
 */
#include <gtest/gtest.h>

#include <cmath>

#include "onvif_backend_test_support.h"
#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/text.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif_backend_test;

/// The ContinuousMove with zero velocity that stops the cameras that ignore Stop.
constexpr const char* ZERO_VELOCITY = "<tptz:Velocity><tt:PanTilt x=\"0.000000\" y=\"0.000000\"";

TEST(OnvifFieldCameras, ACameraThatKeepsMovingAfterStopGetsAZeroVelocityAndIsToldOnce)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("stop-keeps-moving", camera));
  backend->start();
  backend->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera->sample().velocity[PAN] - 0.3) < 0.02; }, WAIT));
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !camera->sample().moving; }, WAIT))
      << "still turning at " << camera->sample().velocity[PAN] << " rad/s after the Stop";
  EXPECT_LT(camera->sample().position[PAN], 2.5) << "it ran to its end stop (pi)";
  EXPECT_EQ(countOf(camera->server(), "<tptz:Stop>"), 1u);
  EXPECT_EQ(countOf(camera->server(), ZERO_VELOCITY), 1u);
  const std::vector<std::string> told = toldOnce(*backend);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_EQ(told[0].rfind("the camera answered Stop but kept moving (pan at ", 0), 0u) << told[0];
  EXPECT_NE(told[0].find("it stops only on a ContinuousMove with zero velocity, which now follows every Stop"),
            std::string::npos)
      << told[0];

  // From now on the zero velocity follows every Stop at once; the camera is not told of again.
  backend->moveAtVelocity({ -0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera->sample().velocity[PAN] + 0.3) < 0.02; }, WAIT));
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !camera->sample().moving; }, WAIT));
  EXPECT_EQ(countOf(camera->server(), ZERO_VELOCITY), 2u);
  EXPECT_TRUE(backend->takeWarnings().empty());
  EXPECT_EQ(backend->protocol<OnvifProtocol>().counters().zero_velocity_stops, 2u);
}

TEST(OnvifBackend, ACameraThatBrakesOnStopGetsNothingMoreEvenFromItsFullSpeed)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<OnvifProtocol>(configFor(camera));
  backend->start();
  backend->moveAtVelocity({ 1.5, 0.0, 0.0 });  // 0.5 s to brake at its 3 rad/s^2
  ASSERT_TRUE(waitUntil([&] { return camera.sample().velocity[PAN] > 1.45; }, WAIT));
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !camera.sample().moving; }, WAIT));
  const auto& protocol = backend->protocol<OnvifProtocol>();
  const std::uint64_t statuses = protocol.counters().statuses;
  ASSERT_TRUE(waitUntil([&] { return protocol.counters().statuses >= statuses + 10; }, WAIT));
  EXPECT_EQ(countOf(camera.server(), ZERO_VELOCITY), 0u);
  EXPECT_EQ(protocol.counters().zero_velocity_stops, 0u);
  const std::vector<std::string> told = backend->takeWarnings();
  EXPECT_TRUE(told.empty()) << told.front();
}

TEST(OnvifFieldCameras, AZoomOnlyGoalSendsNoPanTiltAndLeavesAPanTiltThatMovesOnOneStill)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("zoom-only-moves-pantilt", camera));
  backend->start();
  const AxisValues at = backend->sample().position;
  camera->server().received().clear();
  // Pan and tilt where they rest, a new zoom (a zoom-only goal, as the node sends it: every axis given).
  backend->goTo({ at[PAN], at[TILT], 3.0 });
  double pan_moved = 0.0;  // the farthest the camera's pan was seen from where it stood
  ASSERT_TRUE(waitUntil(
      [&] {
        pan_moved = std::max(pan_moved, std::abs(camera->sample().position[PAN] - at[PAN]));
        return std::abs(backend->sample().position[ZOOM] - 3.0) < 1e-3 && !backend->sample().moving;
      },
      WAIT));
  const std::string sent = lastBodyOf(camera->server(), "AbsoluteMove");
  EXPECT_EQ(sent.find("PanTilt"), std::string::npos) << sent;
  EXPECT_EQ(pan_moved, 0.0);
  // A goal that moves them still sends them (and this camera takes its 2 degrees of backlash on the way).
  backend->goTo({ at[PAN] + 0.3, at[TILT], 3.0 });
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[PAN] - at[PAN] - 0.3) < 1e-3 && !backend->sample().moving; },
      WAIT));
  EXPECT_NE(lastBodyOf(camera->server(), "AbsoluteMove").find("PanTilt"), std::string::npos);
}

TEST(OnvifFieldCameras, AVelocityTimeoutOutsideTheCamerasRangeIsBroughtIntoItAndTold)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  DeviceConfig<OnvifProtocol> config = configForMode("timeout-range", camera);  // PTZTimeout 1..10 s
  config.settings.velocity_timeout = 30;
  auto backend = makeDeviceBackend<OnvifProtocol>(config);
  backend->start();
  const std::vector<std::string> told = toldOnce(*backend);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_EQ(told[0], "velocity_timeout 30 s is outside the camera's PTZTimeout range [1, 10] s (it refuses a "
                     "ContinuousMove outside it): its ContinuousMoves carry a Timeout of 10 s, re-sent every 5 s");
  backend->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera->sample().velocity[PAN] - 0.3) < 0.02; }, WAIT));
  EXPECT_EQ(backend->sample().fault_count, 0u) << backend->lastFault();
  EXPECT_NE(lastBodyOf(camera->server(), "ContinuousMove").find("<tptz:Timeout>PT10S</tptz:Timeout>"),
            std::string::npos);
  backend->stop();
}

TEST(OnvifFieldCameras, ACameraThatAnswersAbsoluteMoveAndNeverMovesFaultsTheGoalNamingItAndLosesAbsolute)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("absolute-never-moves", camera));
  backend->start();
  ASSERT_TRUE(backend->capabilities().axes[PAN].absolute);  // it lists the spaces, and answers the move
  backend->goTo({ 0.5, 0.1, 3.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count == 1u; }, WAIT));
  EXPECT_EQ(backend->lastFault().rfind("the ONVIF camera answered AbsoluteMove but did not move its pan, tilt and "
                                       "zoom (",
                                       0),
            0u)
      << backend->lastFault();
  EXPECT_NE(backend->lastFault().find("a camera that accepts AbsoluteMove and never moves; from now on position goals "
                                      "are steered on ContinuousMove and its status"),
            std::string::npos);
  const Capabilities capabilities = backend->capabilities();
  for (Axis axis : ALL_AXES)
  {
    EXPECT_FALSE(capabilities.axes[axis].absolute) << axisName(axis);
    EXPECT_TRUE(capabilities.axes[axis].velocity && capabilities.axes[axis].feedback) << axisName(axis);
  }
  EXPECT_EQ(findUnsupported(capabilities, PAN, AxisRequest::POSITION), "this camera answers AbsoluteMove and does not "
                                                                       "move: pan goals are not supported");
  EXPECT_EQ(toldOnce(*backend).size(), 1u);
  // It keeps that name across a reconnection (it lists the spaces again).
  camera->server().setSilent(true);
  ASSERT_TRUE(waitUntil([&] { return !backend->sample().link_up; }, WAIT));
  camera->server().setSilent(false);
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  EXPECT_FALSE(backend->capabilities().axes[PAN].absolute);
  EXPECT_FALSE(backend->capabilities().axes[ZOOM].absolute);
}

TEST(OnvifBackend, AGoalTheCameraTakesAWhileToBeginIsNotTakenForOneItIgnores)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<OnvifProtocol>(configFor(camera));
  backend->start();
  SimFaults blocked;  // a blocked motor: the camera drives it (MoveStatus MOVING) and it does not turn
  blocked.stalled[PAN] = true;
  camera.setFaults(blocked);
  backend->goTo({ 0.5, 0.0, 1.0 });
  const auto& protocol = backend->protocol<OnvifProtocol>();
  const std::uint64_t statuses = protocol.counters().statuses;
  ASSERT_TRUE(waitUntil([&] { return protocol.counters().statuses >= statuses + 15; }, WAIT));
  EXPECT_EQ(backend->sample().fault_count, 0u) << backend->lastFault();  // the node's stall, not a camera fault
  EXPECT_TRUE(backend->capabilities().axes[PAN].absolute);
  camera.setFaults(SimFaults());
}

TEST(OnvifFieldCameras, AZoomThatStopsShortOfItsListedRangeFaultsTheGoalNamingItAndIsNotSentBeyondAgain)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("zoom-range-not-honoured", camera));
  backend->start();
  EXPECT_NEAR(backend->capabilities().axes[ZOOM].range.max, 18.0, 1e-9);  // as listed
  backend->goTo({ 0.0, 0.0, 10.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count == 1u; }, WAIT));
  const double reached = std::pow(18.0, 0.5);
  EXPECT_EQ(backend->lastFault(), formatText("the ONVIF camera stopped its zoom at %.3gX, short of the %.3gX it "
                                             "accepted an AbsoluteMove to: "
                                             "it does not honour the zoom range its GetNodes lists (1X..18X); zoom "
                                             "goals beyond %.3gX are not "
                                             "sent from now on",
                                             reached, 10.0, reached));
  EXPECT_NEAR(backend->sample().position[ZOOM], reached, 1e-3);
  EXPECT_NEAR(backend->capabilities().axes[ZOOM].range.max, reached, 1e-3);
  EXPECT_EQ(toldOnce(*backend).size(), 1u);
  camera->server().received().clear();
  backend->goTo({ 0.0, 0.0, 8.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count == 2u; }, WAIT));
  EXPECT_EQ(backend->lastFault().rfind("not sent: zoom 8X is beyond the 4.24X this ONVIF camera's zoom reaches", 0), 0u)
      << backend->lastFault();
  EXPECT_EQ(countOf(camera->server(), "AbsoluteMove"), 0u);
  backend->goTo({ 0.0, 0.0, 2.0 });  // within what it reaches: as on any camera
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[ZOOM] - 2.0) < 1e-3 && !backend->sample().moving; }, WAIT));
  EXPECT_EQ(backend->sample().fault_count, 2u);
}

TEST(OnvifFieldCameras, AnAxisCameraThatRefusesAnUnauthenticatedGetSystemDateAndTimeStarts)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("axis-401", camera));
  backend->start();
  EXPECT_TRUE(backend->sample().link_up);
  const std::vector<std::string> told = toldOnce(*backend);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_EQ(told[0].rfind("the camera refused GetSystemDateAndTime without authentication (HTTP 401 Unauthorized", 0),
            0u)
      << told[0];
  backend->goTo({ 0.3, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[PAN] - 0.3) < 1e-3 && !backend->sample().moving; }, WAIT));

  // Its clock an hour off: our tokens are refused, and the start fails with the camera's words.
  OnvifCameraEmulatorConfig late;
  ASSERT_TRUE(late.applyMode("axis-401"));
  late.clock_offset = 3600.0;
  OnvifCameraEmulator late_camera(late);
  EXPECT_NE(startupError(configFor(late_camera)).find("the ONVIF camera refused GetCapabilities: ter:NotAuthorized"),
            std::string::npos);
}

}  // namespace
}  // namespace ptz_action_server

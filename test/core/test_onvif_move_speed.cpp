/**
 * \file
 * \brief The speed of ONVIF position goals against onvif_camera_emulator's camera on 127.0.0.1: a camera whose node
 * lists the generic speed spaces takes the speed with AbsoluteMove's Speed (declared DEVICE) and moves at it; a goal
 * without a speed sends no Speed; a camera that lists none is left to the node (NODE) and gets no Speed.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "onvif_backend_test_support.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif_backend_test;

TEST(OnvifMoveSpeed, ACameraListingTheSpeedSpacesTakesTheSpeedWithItsAbsoluteMove)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<OnvifProtocol>(configFor(camera));
  backend->start();
  const MoveSpeedCapability speed = backend->capabilities().speed;
  for (Axis axis : ALL_AXES)
  {
    EXPECT_EQ(speed.control[axis], SpeedControl::DEVICE) << axisName(axis);
    EXPECT_EQ(speed.min_speed[axis], 0.0) << axisName(axis);  // listed 0..1: any speed
  }
  // Pan at a fifth of its 1.5 rad/s, tilt at half of its 1 rad/s, zoom at a quarter of its 8 X/s.
  backend->goToAtSpeed({ 0.3, -0.2, 2.0 }, { 0.3, 0.5, 2.0 });
  ASSERT_TRUE(waitUntil([&] { return countOf(camera.server(), "<tptz:Speed>") == 1; }, WAIT));
  const std::string body = lastBodyOf(camera.server(), "AbsoluteMove");
  EXPECT_NE(body.find("<tptz:Speed><tt:PanTilt x=\"0.200000\" y=\"0.500000\" "
                      "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/GenericSpeedSpace\"/><tt:Zoom "
                      "x=\"0.250000\" space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/ZoomGenericSpeedSpace\"/>"
                      "</tptz:Speed>"),
            std::string::npos)
      << body;
  ASSERT_TRUE(waitUntil([&] { return camera.commandedSpeed()[PAN] > 0.0; }, WAIT));
  const AxisValues commanded = camera.commandedSpeed();
  EXPECT_NEAR(commanded[PAN], 0.3, 1e-6);
  EXPECT_NEAR(commanded[TILT], 0.5, 1e-6);
  EXPECT_NEAR(commanded[ZOOM], 2.0, 1e-6);
  // It moves at that speed: no faster than the pan's 0.3 rad/s while it cruises.
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera.sample().velocity[PAN]) > 0.29; }, WAIT));
  EXPECT_LE(std::abs(camera.sample().velocity[PAN]), 0.3 + 1e-6);
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[PAN] - 0.3) < 1e-3 && !backend->sample().moving; }, WAIT));

  // Without a speed: no Speed element, the camera's default (its top speed).
  backend->goTo({ 0.0, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return countOf(camera.server(), "<tptz:AbsoluteMove>") == 2; }, WAIT));
  EXPECT_EQ(lastBodyOf(camera.server(), "AbsoluteMove").find("Speed"), std::string::npos);
  ASSERT_TRUE(waitUntil([&] { return camera.commandedSpeed()[PAN] > 1.0; }, WAIT));
  EXPECT_NEAR(camera.commandedSpeed()[PAN], 1.5, 1e-6);
}

TEST(OnvifMoveSpeed, ASpeedOnPanOnlyMovesTheOtherAxesAtTheirTop)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  auto backend = makeDeviceBackend<OnvifProtocol>(configFor(camera));
  backend->start();
  backend->goToAtSpeed({ -0.2, 0.1, 1.0 }, { 0.75, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return countOf(camera.server(), "<tptz:Speed>") == 1; }, WAIT));
  const std::string body = lastBodyOf(camera.server(), "AbsoluteMove");
  EXPECT_NE(body.find("<tt:PanTilt x=\"0.500000\" y=\"1.000000\" "
                      "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/GenericSpeedSpace\"/></tptz:Speed>"),
            std::string::npos)
      << body;  // no zoom speed asked: the Speed carries none
}

TEST(OnvifMoveSpeed, ACameraListingNoSpeedSpaceIsLeftToTheNodeAndGetsNoSpeed)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("no-speed-space", camera));
  backend->start();
  for (Axis axis : ALL_AXES)
  {
    EXPECT_EQ(backend->capabilities().speed.control[axis], SpeedControl::NODE) << axisName(axis);
  }
  backend->goToAtSpeed({ 0.2, 0.0, 1.0 }, { 0.3, 0.3, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return countOf(camera->server(), "<tptz:AbsoluteMove>") == 1; }, WAIT));
  EXPECT_EQ(lastBodyOf(camera->server(), "AbsoluteMove").find("Speed"), std::string::npos);
}

}  // namespace
}  // namespace ptz_action_server

/**
 * \file
 * \brief The ONVIF camera's own aim in its picture: RelativeMove in the TranslationSpaceFov (golden request), declared
 * only by a camera whose PTZ configuration options list it, and the backend against onvif_camera_emulator's camera: a
 * point up and right of the centre turns the pan and tilt by the angles its lens puts it at, a box zooms in by its
 * magnification, and the goal ends where the camera says it ended.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "goal_supervisor_fixture.h"
#include "onvif_backend_test_support.h"
#include "ptz_action_server/core/capabilities.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/onvif/onvif_xml.h"
#include "wait_until.h"
#include "view_target_support.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif_backend_test;

constexpr double ANGLE = 1e-3;  // rad: the camera reports generic or degree numbers with six decimals

TEST(OnvifViewAim, RelativeMoveInTheFieldOfViewSpaces)
{
  onvif::Vector translation;
  translation.pan_tilt = true;
  translation.x = 0.5;
  translation.y = -0.25;
  translation.pan_tilt_space = onvif::FOV_PAN_TILT_TRANSLATION;
  translation.zoom = true;
  translation.z = 2.0;
  translation.zoom_space = onvif::FOV_ZOOM_TRANSLATION;
  EXPECT_EQ(onvif::relativeMove("profile_1", translation), "<tptz:RelativeMove><tptz:ProfileToken>profile_1</"
                                                           "tptz:ProfileToken><tptz:Translation><tt:PanTilt "
                                                           "x=\"0.500000\" y=\"-0.250000\" "
                                                           "space=\"http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                                                           "TranslationSpaceFov\"/>"
                                                           "<tt:Zoom x=\"2.000000\" "
                                                           "space=\"http://www.onvif.org/ver10/tptz/ZoomSpaces/"
                                                           "TranslationSpaceFov\"/>"
                                                           "</tptz:Translation></tptz:RelativeMove>");
}

/// A GetConfigurationOptionsResponse listing \p spaces, in the PTZ specification's prefixes.
std::string optionsReply(const std::string& spaces)
{
  return "<env:Envelope xmlns:env=\"http://www.w3.org/2003/05/soap-envelope\" "
         "xmlns:tptz=\"http://www.onvif.org/ver20/ptz/wsdl\" xmlns:tt=\"http://www.onvif.org/ver10/schema\"><env:Body>"
         "<tptz:GetConfigurationOptionsResponse><tptz:PTZConfigurationOptions><tt:Spaces>" +
         spaces +
         "</tt:Spaces><tt:PTZTimeout><tt:Min>PT1S</tt:Min><tt:Max>PT60S</tt:Max></tt:PTZTimeout>"
         "</tptz:PTZConfigurationOptions></tptz:GetConfigurationOptionsResponse></env:Body></env:Envelope>";
}

TEST(OnvifViewAim, TheConfigurationOptionsListTheFieldOfViewSpaces)
{
  onvif::SoapMessage message;
  ASSERT_EQ(onvif::parseSoap(optionsReply("<tt:RelativePanTiltTranslationSpace><tt:URI>http://www.onvif.org/ver10/tptz/"
                                          "PanTiltSpaces/"
                                          "TranslationSpaceFov</tt:URI><tt:XRange><tt:Min>-1</tt:Min><tt:Max>1</"
                                          "tt:Max></tt:XRange>"
                                          "<tt:YRange><tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:YRange>"
                                          "</"
                                          "tt:RelativePanTiltTranslationSpace><tt:RelativeZoomTranslationSpace><tt:URI>"
                                          "http://www.onvif.org/ver10/tptz/ZoomSpaces/TranslationGenericSpace</"
                                          "tt:URI><tt:XRange>"
                                          "<tt:Min>-1</tt:Min><tt:Max>1</tt:Max></tt:XRange></"
                                          "tt:RelativeZoomTranslationSpace>"),
                             message),
            "");
  onvif::Node spaces;
  spaces.token = "kept";
  ASSERT_EQ(onvif::readOptionSpaces(message.content, spaces), "");
  const onvif::Space* fov = onvif::findSpace(spaces.relative_pan_tilt, onvif::FOV_PAN_TILT_TRANSLATION);
  ASSERT_NE(fov, nullptr);
  EXPECT_EQ(fov->x.min, -1.0);
  EXPECT_EQ(fov->y.max, 1.0);
  EXPECT_NE(onvif::findSpace(spaces.relative_zoom, onvif::GENERIC_ZOOM_TRANSLATION), nullptr);
  EXPECT_EQ(spaces.token, "kept");

  ASSERT_EQ(onvif::parseSoap(optionsReply("<tt:RelativePanTiltTranslationSpace><tt:URI>http://www.onvif.org/ver10/tptz/"
                                          "PanTiltSpaces/TranslationSpaceFov</tt:URI><tt:XRange><tt:Min>left</tt:Min>"
                                          "<tt:Max>1</tt:Max></tt:XRange></tt:RelativePanTiltTranslationSpace>"),
                             message),
            "");
  EXPECT_NE(onvif::readOptionSpaces(message.content, spaces).find("RelativePanTiltTranslationSpace"),
            std::string::npos);
}

/// A camera at rest at pan 0, tilt 0 and \p zoom X, its backend started.
struct AimingCamera
{
  explicit AimingCamera(const OnvifCameraEmulatorConfig& config = OnvifCameraEmulatorConfig(), double zoom = 1.0)
    : camera(config), backend(makeDeviceBackend<OnvifProtocol>(configFor(camera)))
  {
    backend->start();
    backend->goTo({ 0.0, 0.0, zoom });
    EXPECT_TRUE(waitUntil(
        [&] {
          const PtzSample state = camera.sample();
          return !state.moving && std::abs(state.position[PAN]) < 1e-6 && std::abs(state.position[ZOOM] - zoom) < 1e-3;
        },
        WAIT));
  }

  static ViewTarget at(double x, double y, double box = 0.0)
  {
    return viewTargetAt(x, y, box);
  }

  OnvifCameraEmulator camera;
  std::shared_ptr<DeviceBackend> backend;
};

TEST(OnvifViewAim, ACameraWhoseOptionsListTheSpaceDeclaresIt)
{
  AimingCamera listing;
  const Capabilities capabilities = listing.backend->capabilities();
  EXPECT_TRUE(capabilities.view_centre);
  EXPECT_TRUE(capabilities.view_box_zoom);
  EXPECT_EQ(capabilities.view_command, "ONVIF RelativeMove in TranslationSpaceFov");
  EXPECT_NE(describeExtras(capabilities).find("centres and box-zooms in its own picture"), std::string::npos)
      << describeExtras(capabilities);

  OnvifCameraEmulatorConfig without;
  without.fov_space = false;
  AimingCamera plain(without);
  EXPECT_FALSE(plain.backend->capabilities().view_centre);
  EXPECT_FALSE(plain.backend->capabilities().view_box_zoom);
  EXPECT_TRUE(plain.backend->capabilities().relative_moves) << "its generic translation spaces are still listed";
}

TEST(OnvifViewAim, APointUpAndRightTurnsPanAndTiltByItsAnglesInTheLens)
{
  AimingCamera aiming;
  aiming.backend->aimInView(AimingCamera::at(0.75, 0.25));
  ASSERT_TRUE(waitUntil([&] { return !lastBodyOf(aiming.camera.server(), "RelativeMove").empty(); }, WAIT));
  EXPECT_NE(lastBodyOf(aiming.camera.server(), "RelativeMove")
                .find("<tt:PanTilt x=\"0.500000\" y=\"0.500000\" space=\"" +
                      std::string(onvif::FOV_PAN_TILT_TRANSLATION) + "\"/></tptz:Translation>"),
            std::string::npos)
      << lastBodyOf(aiming.camera.server(), "RelativeMove");
  // Half way to the right and top edges of the picture: its ray is (1, right, up) in the camera's axes.
  const FieldOfViewAngles lens = HttpCameraEmulator::defaultFieldOfView();
  const double right = std::tan(lens.horizontal / 2.0) / 2.0;
  const double up = std::tan(lens.vertical / 2.0) / 2.0;
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample state = aiming.backend->sample();
        return !state.moving && std::abs(state.position[PAN] - std::atan(right)) < ANGLE;
      },
      WAIT))
      << aiming.backend->sample().position[PAN];
  EXPECT_NEAR(aiming.backend->sample().position[TILT], std::atan2(up, std::hypot(1.0, right)), ANGLE);
  EXPECT_EQ(aiming.backend->sample().fault_count, 0u);
}

TEST(OnvifViewAim, ABoxZoomsInByItsMagnification)
{
  AimingCamera aiming(OnvifCameraEmulatorConfig(), 2.0);
  aiming.backend->aimInView(AimingCamera::at(0.5, 0.5, 0.25));  // a quarter of the picture: four times closer
  ASSERT_TRUE(waitUntil([&] { return std::abs(aiming.backend->sample().position[ZOOM] - 8.0) < 0.05; }, WAIT))
      << aiming.backend->sample().position[ZOOM];
  EXPECT_NE(lastBodyOf(aiming.camera.server(), "RelativeMove")
                .find("<tt:Zoom x=\"4.000000\" space=\"" + std::string(onvif::FOV_ZOOM_TRANSLATION) + "\"/>"),
            std::string::npos)
      << lastBodyOf(aiming.camera.server(), "RelativeMove");
  EXPECT_NEAR(aiming.backend->sample().position[PAN], 0.0, ANGLE);
}

TEST(OnvifViewAim, TheGoalEndsWhereTheCameraSaysItSettled)
{
  AimingCamera aiming;
  const auto log = goal_supervisor_test::runLoggedGoal(
      aiming.backend, goal_supervisor_test::viewGoal(AimingCamera::at(0.25, 0.5)), GoalMonitorConfig(), WAIT);
  EXPECT_EQ(log->end.rfind("SUCCEEDED: the device aimed itself: ended at pan -0.", 0), 0u) << log->end;
  EXPECT_NE(log->end.find("tilt and zoom did not move"), std::string::npos) << log->end;
  ASSERT_EQ(log->ended.size(), 1u);
  const double expected = -std::atan(std::tan(HttpCameraEmulator::defaultFieldOfView().horizontal / 2.0) / 2.0);
  EXPECT_NEAR(log->ended[0][PAN], expected, ANGLE);
  EXPECT_NEAR(log->ended[0][ZOOM], 1.0, 1e-3) << "not asked to zoom: where it stays";
  EXPECT_NEAR(aiming.camera.sample().position[PAN], log->ended[0][PAN], ANGLE) << "it had settled";
}

}  // namespace
}  // namespace ptz_action_server

/**
 * \file
 * \brief The Axis camera's own aim in its picture: `center` and `areazoom` as the VAPIX PTZ API documents them (golden
 * requests, the documentation's info=1 listing them), declared only by a camera that lists them, and the backend
 * against axis_camera_emulator's camera: a point right of the centre turns the pan by the angle its lens puts it at, a
 * box zooms in by its magnification, also on a camera whose zoom X the node cannot know; the goal ends where the
 * camera says it ended.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "axis_backend_test_support.h"
#include "goal_supervisor_fixture.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/capabilities.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "wait_until.h"
#include "view_target_support.h"

namespace ptz_action_server
{
namespace
{
using namespace axis_backend_test;

constexpr double ANGLE = 2e-4;  // rad: the camera reports degrees with four decimals

/// The VAPIX PTZ API's ptz.cgi table: `center=<int>,<int>` ("pixel coordinates in the client video stream"),
/// `areazoom=<int>,<int>,<int>` ("zooms by a factor of z/100"), `imagewidth=<int>`, `imageheight=<int>` ("required in
/// conjunction with center or areazoom if the image width displayed is different from the default size").
TEST(VapixViewAim, CenterAndAreaZoomCarryThePixelAndThePicturesSize)
{
  std::string out;
  vapix::appendCenter(out, vapix::ImagePoint{ 320, 240, 640, 480 });
  EXPECT_EQ(out, "center=320,240&imagewidth=640&imageheight=480");
  out.clear();
  vapix::appendAreaZoom(out, vapix::ImagePoint{ 1200, 100, 1920, 1080 }, 300);  // to a third of the field of view
  EXPECT_EQ(out, "areazoom=1200,100,300&imagewidth=1920&imageheight=1080");
  out.clear();
  vapix::appendAreaZoom(out, vapix::ImagePoint{ 10, 20, 640, 360 }, 0);  // z is at least 1
  EXPECT_EQ(out, "areazoom=10,20,1&imagewidth=640&imageheight=360");
}

/// The info=1 example of the VAPIX PTZ API lists them, each with its picture's size indented under it.
TEST(VapixViewAim, TheDocumentedInfoListsCenterAndAreaZoom)
{
  const vapix::CommandList commands = vapix::readCommandList("Available commands:\r\n{camera=[n]}\r\nwhoami=yes\r\n"
                                                             "center=[x],[y]\r\n  imagewidth=[n]\r\n  imageheight=[n]"
                                                             "\r\nareazoom=[x],[y],[z]\r\n  imagewidth=[n]\r\n  "
                                                             "imageheight=[n]\r\nmove={ home | up | down | left | "
                                                             "right | upleft | upright | downleft | downright | stop }"
                                                             "\r\npan=[abspos]\r\ntilt=[abspos]\r\nzoom=[n]\r\n");
  EXPECT_TRUE(commands.has("center"));
  EXPECT_TRUE(commands.has("areazoom"));
  EXPECT_TRUE(commands.has("pan"));
}

/// A camera at rest at pan 0, tilt 0 and \p zoom X, its backend started.
struct AimingCamera
{
  explicit AimingCamera(const AxisCameraEmulatorConfig& config = AxisCameraEmulatorConfig(), double zoom = 1.0)
    : camera(config)
  {
    DeviceConfig<AxisProtocol> backend_config = configFor(camera.port());
    backend_config.settings.zoom_guess = false;
    backend = makeDeviceBackend<AxisProtocol>(backend_config);
    backend->start();
    if (zoom != 1.0)
    {
      backend->goTo({ 0.0, 0.0, zoom });
      EXPECT_TRUE(waitUntil([&] { return std::abs(camera.sample().position[ZOOM] - zoom) < 1e-6; }, WAIT));
    }
  }

  static ViewTarget at(double x, double y, double box = 0.0)
  {
    return viewTargetAt(x, y, box);
  }

  AxisCameraEmulator camera;
  std::shared_ptr<DeviceBackend> backend;
};

TEST(AxisViewAim, ACameraThatListsThemDeclaresThem)
{
  AimingCamera listing;
  const Capabilities capabilities = listing.backend->capabilities();
  EXPECT_TRUE(capabilities.view_centre);
  EXPECT_TRUE(capabilities.view_box_zoom);
  EXPECT_EQ(capabilities.view_command, "VAPIX center, areazoom");
  EXPECT_NE(describeExtras(capabilities).find("centres and box-zooms in its own picture (VAPIX center, areazoom)"),
            std::string::npos)
      << describeExtras(capabilities);

  AxisCameraEmulatorConfig without;
  without.area_zoom = false;
  AimingCamera silent(without);
  EXPECT_FALSE(silent.backend->capabilities().view_centre);
  EXPECT_FALSE(silent.backend->capabilities().view_box_zoom);

  AxisCameraEmulatorConfig no_zoom;
  no_zoom.zoom_table = "";
  AimingCamera fixed(no_zoom);
  EXPECT_TRUE(fixed.backend->capabilities().view_centre);
  EXPECT_FALSE(fixed.backend->capabilities().view_box_zoom) << "no zoom: no area zoom";
  EXPECT_EQ(fixed.backend->capabilities().view_command, "VAPIX center");
}

TEST(AxisViewAim, APointRightOfTheCentreTurnsThePanByItsAngleInTheLens)
{
  AimingCamera aiming;
  aiming.backend->aimInView(AimingCamera::at(0.75, 0.5));
  ASSERT_TRUE(waitUntil([&] { return !targets(aiming.camera.server(), "center=").empty(); }, WAIT));
  EXPECT_EQ(targets(aiming.camera.server(), "center=")[0], "/axis-cgi/com/"
                                                           "ptz.cgi?camera=1&center=480,180&imagewidth=640&"
                                                           "imageheight=360");
  // Half way to the right edge of a 60 degree picture: atan(tan(30 deg) / 2) to the right.
  const double expected = std::atan(std::tan(M_PI / 6.0) / 2.0);
  ASSERT_TRUE(waitUntil([&] { return std::abs(aiming.backend->sample().position[PAN] - expected) < ANGLE; }, WAIT))
      << aiming.backend->sample().position[PAN];
  EXPECT_NEAR(aiming.backend->sample().position[TILT], 0.0, ANGLE);
  EXPECT_EQ(aiming.backend->sample().fault_count, 0u);

  // Zoomed in to 3X, a point up and right is a third as far off the axis (an ideal lens: tangents shrink with X): its
  // ray is (1, right, up) in the camera's axes.
  AimingCamera zoomed(AxisCameraEmulatorConfig(), 3.0);
  zoomed.backend->aimInView(AimingCamera::at(0.75, 0.25));
  const double right = std::tan(M_PI / 6.0) / 2.0 / 3.0;
  const double up = std::tan(HttpCameraEmulator::defaultFieldOfView().vertical / 2.0) / 2.0 / 3.0;
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample state = zoomed.camera.sample();
        return !state.moving && std::abs(state.position[PAN] - std::atan(right)) < ANGLE;
      },
      WAIT))
      << zoomed.camera.sample().position[PAN];
  EXPECT_NEAR(zoomed.camera.sample().position[TILT], std::atan2(up, std::hypot(1.0, right)), ANGLE);
}

TEST(AxisViewAim, ABoxZoomsInByItsMagnification)
{
  AimingCamera aiming(AxisCameraEmulatorConfig(), 2.0);
  aiming.backend->aimInView(AimingCamera::at(0.5, 0.5, 0.25));  // a quarter of the picture: four times closer
  ASSERT_TRUE(waitUntil([&] { return !targets(aiming.camera.server(), "areazoom=").empty(); }, WAIT));
  EXPECT_EQ(targets(aiming.camera.server(), "areazoom=")[0], "/axis-cgi/com/"
                                                             "ptz.cgi?camera=1&areazoom=320,180,400&imagewidth=640&"
                                                             "imageheight=360");
  ASSERT_TRUE(waitUntil([&] { return std::abs(aiming.backend->sample().position[ZOOM] - 8.0) < 0.01; }, WAIT))
      << aiming.backend->sample().position[ZOOM];
  EXPECT_NEAR(aiming.backend->sample().position[PAN], 0.0, ANGLE);
}

TEST(AxisViewAim, TheGoalEndsWhereTheCameraSaysEvenWithAZoomTheNodeCannotKnow)
{
  // The field camera without zoom attributes and without a guess: its zoom X is unknown to the node.
  AxisCameraEmulatorConfig field = fieldCamera("Q8665-E");
  AimingCamera aiming(field);
  ASSERT_FALSE(aiming.backend->capabilities().axes[ZOOM].feedback);
  ASSERT_TRUE(aiming.backend->capabilities().view_box_zoom);
  const auto log = goal_supervisor_test::runLoggedGoal(
      aiming.backend, goal_supervisor_test::viewGoal(AimingCamera::at(0.25, 0.5, 0.5)), GoalMonitorConfig(), WAIT);
  EXPECT_EQ(log->end.rfind("SUCCEEDED: the device aimed itself: ended at pan -0.", 0), 0u) << log->end;
  EXPECT_NE(log->end.find("tilt did not move; the device does not report its zoom"), std::string::npos) << log->end;
  ASSERT_EQ(log->ended.size(), 1u);
  EXPECT_NEAR(log->ended[0][PAN], -std::atan(std::tan(M_PI / 6.0) / 2.0), ANGLE);
  EXPECT_TRUE(std::isnan(log->ended[0][ZOOM]));
  EXPECT_NEAR(aiming.camera.sample().position[ZOOM], 2.0, 1e-3) << "the camera zoomed in twice all the same";
}

TEST(AxisViewAim, ACameraThatRefusesItFaultsTheGoalInItsWords)
{
  AimingCamera aiming;
  aiming.camera.setRefuse(true);
  const auto log = goal_supervisor_test::runLoggedGoal(
      aiming.backend, goal_supervisor_test::viewGoal(AimingCamera::at(0.9, 0.1)), GoalMonitorConfig(), WAIT);
  EXPECT_EQ(log->end, std::string("ABORTED: device fault: the Axis camera refused 'center=576,36&imagewidth=640&"
                                  "imageheight=360': ") +
                          AxisCameraEmulator::REFUSAL);
}

}  // namespace
}  // namespace ptz_action_server

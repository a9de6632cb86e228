#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "pixel_aim_test_support.h"
#include "ptz_action_server/core/motion/pixel_aim.h"

using namespace ptz_action_server;
using namespace pixel_aim_test;

namespace
{
PixelGoal box(double u, double v, double width, double height)
{
  PixelGoal goal;
  goal.u = u;
  goal.v = v;
  goal.box_width = width;
  goal.box_height = height;
  goal.image_width = WIDTH;
  goal.image_height = HEIGHT;
  return goal;
}

/// The centre of a WIDTH x HEIGHT image.
constexpr double CX = (WIDTH - 1) / 2.0;
constexpr double CY = (HEIGHT - 1) / 2.0;

class PixelZoomTest : public ::testing::Test
{
protected:
  PixelZoomTest()
    : kinematics(shippedKinematics()), lens(FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE }))
  {
    camera.field_of_view = &lens;
  }

  PixelAim aim(const PixelGoal& goal, const AxisValues& pose) const
  {
    return aimAtPixel(goal, pose, camera, kinematics, limits);
  }

  /**
   * How much of the view at \p aimed's pose and zoom the box \p goal of the image taken at \p pose fills, measured in
   * pixels: the middles of its sides projected into that view (\p then and \p after the intrinsics of the two
   * images), as the larger of its relative width and height about the principal point.
   */
  double measuredFill(const PixelGoal& goal, const AxisValues& pose, const PinholeIntrinsics& then,
                      const PixelAim& aimed, const PinholeIntrinsics& after) const
  {
    const Eigen::Isometry3d camera_then = kinematics.cameraInBase(pose[PAN], pose[TILT]);
    const Eigen::Isometry3d camera_after = kinematics.cameraInBase(aimed.pan, aimed.tilt);
    const std::array<std::array<double, 2>, 4> sides{ { { goal.u - goal.box_width / 2, goal.v },
                                                        { goal.u + goal.box_width / 2, goal.v },
                                                        { goal.u, goal.v - goal.box_height / 2 },
                                                        { goal.u, goal.v + goal.box_height / 2 } } };
    double fill = 0.0;
    for (std::size_t side = 0; side < sides.size(); ++side)
    {
      const Eigen::Vector3d ray = opticalToCameraLink(rayThroughPixel(then, sides[side][0], sides[side][1]));
      const Eigen::Vector3d point = camera_then * ((goal.distance > 0.0 ? goal.distance : 1e6) * ray);
      double u = 0.0;
      double v = 0.0;
      EXPECT_TRUE(project(camera_after, after, point, u, v));
      fill = std::max(fill, side < 2 ? std::abs(u - after.cx) / (after.width / 2.0) :
                                       std::abs(v - after.cy) / (after.height / 2.0));
    }
    return fill;
  }

  PtzKinematics kinematics;
  FieldOfViewModel lens;
  PixelCamera camera;
  Capabilities limits = zoomCamera();
};

TEST_F(PixelZoomTest, TheLargerRelativeSideOfTheBoxFillsTheView)
{
  // Centred at 2 X, a box a quarter of the width wide and an eighth of the height tall: an ideal lens needs 4 times
  // the focal length, 8 X. Half the height tall instead: the height decides, 4 X.
  const PixelAim wide = aim(box(CX, CY, WIDTH / 4.0, HEIGHT / 8.0), { 0.2, 0.0, 2.0 });
  ASSERT_TRUE(wide.ok()) << wide.error;
  EXPECT_NEAR(wide.pan, 0.2, 1e-9);
  EXPECT_NEAR(wide.zoom, 8.0, 1e-7);
  EXPECT_NEAR(wide.box_fill, 1.0, 1e-7);
  EXPECT_EQ(wide.notes, "");
  const PixelAim tall = aim(box(CX, CY, WIDTH / 8.0, HEIGHT / 2.0), { 0.2, 0.0, 2.0 });
  EXPECT_NEAR(tall.zoom, 4.0, 1e-7);
  // A box larger than the image zooms out.
  const PixelAim out = aim(box(CX, CY, 2.0 * WIDTH, HEIGHT), { 0.2, 0.0, 5.0 });
  EXPECT_NEAR(out.zoom, 2.5, 1e-7);
}

TEST_F(PixelZoomTest, TheDividedLawAndATableGiveTheirOwnZoom)
{
  const FieldOfViewModel divided = FieldOfViewModel::fromWideEnd({ 1.2, 0.7 }, ZoomLaw::DIVIDED);
  const FieldOfViewModel table = FieldOfViewModel::fromTable(
      { { 1.0, { 1.1, 0.65 } }, { 3.0, { 0.5, 0.3 } }, { 10.0, { 0.12, 0.07 } }, { 20.0, { 0.05, 0.03 } } });
  for (const FieldOfViewModel* model : { &divided, &table })
  {
    camera.field_of_view = model;
    const PixelAim wide = aim(box(CX, CY, WIDTH / 5.0, HEIGHT / 10.0), { 0.0, 0.0, 2.0 });
    ASSERT_TRUE(wide.ok()) << wide.error;
    // The box spans 2 atan((width / 10) / fx) at 2 X; the new zoom's horizontal field of view is that angle.
    const PinholeIntrinsics then = intrinsicsFor(model->at(2.0), WIDTH, HEIGHT);
    EXPECT_NEAR(model->at(wide.zoom).horizontal, 2.0 * std::atan(WIDTH / 10.0 / then.fx), 1e-8);
    EXPECT_GT(model->at(wide.zoom).vertical, 2.0 * std::atan(HEIGHT / 20.0 / then.fy));
    EXPECT_NEAR(measuredFill(box(CX, CY, WIDTH / 5.0, HEIGHT / 10.0), { 0.0, 0.0, 2.0 }, then, wide,
                             intrinsicsFor(model->at(wide.zoom), WIDTH, HEIGHT)),
                1.0, 1e-6);
  }
}

TEST_F(PixelZoomTest, AnOffCentreBoxFillsTheViewOnceCentred)
{
  const AxisValues pose{ 0.3, 0.35, 1.5 };
  const PinholeIntrinsics then = intrinsicsFor(lens.at(1.5), WIDTH, HEIGHT);
  PixelGoal goal = box(CX + 150.0, CY - 60.0, 80.0, 60.0);
  goal.distance = 7.0;
  const PixelAim aimed = aim(goal, pose);
  ASSERT_TRUE(aimed.ok()) << aimed.error;
  EXPECT_GT(aimed.zoom, 1.5 * HEIGHT / 60.0 * 0.9);  // about six times closer, the box being relatively taller
  EXPECT_LT(aimed.zoom, 1.5 * HEIGHT / 60.0 * 1.1);
  EXPECT_NEAR(measuredFill(goal, pose, then, aimed, intrinsicsFor(lens.at(aimed.zoom), WIDTH, HEIGHT)), 1.0, 1e-6);

  // The same with a calibrated camera_info (off-centre principal point, at 3 X): K follows the zoom.
  CalibratedIntrinsics calibration{ intrinsicsFor(lens.at(3.0), WIDTH, HEIGHT), 3.0 };
  calibration.intrinsics.cx += 12.0;
  calibration.intrinsics.cy -= 7.0;
  camera.calibration = calibration;
  PinholeIntrinsics calibrated_then = calibration.intrinsics;
  calibrated_then.fx *= lens.focalScale(3.0, 1.5).x;
  calibrated_then.fy *= lens.focalScale(3.0, 1.5).y;
  const PixelAim calibrated = aim(goal, pose);
  ASSERT_TRUE(calibrated.ok()) << calibrated.error;
  PinholeIntrinsics calibrated_after = calibration.intrinsics;
  calibrated_after.fx *= lens.focalScale(3.0, calibrated.zoom).x;
  calibrated_after.fy *= lens.focalScale(3.0, calibrated.zoom).y;
  EXPECT_NEAR(measuredFill(goal, pose, calibrated_then, calibrated, calibrated_after), 1.0, 1e-6);
}

TEST_F(PixelZoomTest, TheZoomStaysInTheDevicesRange)
{
  // 4 x 4 px at 2 X: relatively taller than wide, it needs 2 * 360 / 4 = 180 X; the device stops at 30.
  const PixelAim small = aim(box(CX, CY, 4.0, 4.0), { 0.0, 0.0, 2.0 });
  ASSERT_TRUE(small.ok()) << small.error;
  EXPECT_DOUBLE_EQ(small.zoom, 30.0);
  EXPECT_NEAR(small.box_fill, 30.0 / 180.0, 1e-9);
  EXPECT_NE(small.notes.find("the box is smaller than the narrowest view (zoom 30 X, where the device's zoom range "
                             "ends): it fills 17 % of it"),
            std::string::npos)
      << small.notes;
  // Four times the image at 1.5 X needs 0.375 X: the widest view is 1 X.
  const PixelAim large = aim(box(CX, CY, 4.0 * WIDTH, 4.0 * HEIGHT), { 0.0, 0.0, 1.5 });
  EXPECT_DOUBLE_EQ(large.zoom, 1.0);
  EXPECT_GT(large.box_fill, 1.0);
  EXPECT_NE(large.notes.find("the box is larger than the widest view (zoom 1 X"), std::string::npos) << large.notes;
  // A device whose zoom starts at 2 X: the device's range ends first.
  limits.axes[ZOOM].range = AxisRange{ 2.0, 30.0 };
  const PixelAim start = aim(box(CX, CY, 2.0 * WIDTH, 2.0 * HEIGHT), { 0.0, 0.0, 3.0 });
  EXPECT_DOUBLE_EQ(start.zoom, 2.0);
  EXPECT_NE(start.notes.find("where the device's zoom range ends"), std::string::npos) << start.notes;
  // A table that ends at 6 X, on a device that goes to 30.
  const FieldOfViewModel table = FieldOfViewModel::fromTable({ { 1.0, { 1.0, 0.6 } }, { 6.0, { 0.2, 0.12 } } });
  camera.field_of_view = &table;
  const PixelAim table_end = aim(box(CX, CY, 10.0, 10.0), { 0.0, 0.0, 2.0 });
  EXPECT_DOUBLE_EQ(table_end.zoom, 6.0);
  EXPECT_LT(table_end.box_fill, 1.0);
  EXPECT_NE(table_end.notes.find("where the field of view model ends"), std::string::npos) << table_end.notes;
}

TEST_F(PixelZoomTest, TheZoomOfADeviceThatCannotGoToAZoomIsIgnored)
{
  // The seed: "if the camera does not support zoom ... the zoom field is ignored". The box is still centred.
  limits.axes[ZOOM] = absentAxis();
  const PixelAim no_zoom = aim(box(CX + 100.0, CY, 40.0, 40.0), { 0.0, 0.0, 1.0 });
  ASSERT_TRUE(no_zoom.ok()) << no_zoom.error;
  EXPECT_GT(no_zoom.pan, 0.1);
  EXPECT_TRUE(std::isnan(no_zoom.zoom));
  EXPECT_TRUE(std::isnan(no_zoom.box_fill));
  EXPECT_NE(no_zoom.notes.find("the box's zoom is ignored (the device has no zoom"), std::string::npos)
      << no_zoom.notes;
  // A zoom that only moves at a speed.
  limits = zoomCamera();
  limits.axes[ZOOM].absolute = false;
  const PixelAim speed_only = aim(box(CX, CY, 40.0, 40.0), { 0.0, 0.0, 1.0 });
  EXPECT_TRUE(std::isnan(speed_only.zoom));
  EXPECT_NE(speed_only.notes.find("cannot go to a zoom position"), std::string::npos) << speed_only.notes;
  // A calibration and no field of view: the pixel's direction at the calibration's zoom, but no zoom for the box.
  limits = zoomCamera();
  PixelCamera calibrated_only;
  calibrated_only.calibration = CalibratedIntrinsics{ intrinsicsFor(lens.at(1.0), WIDTH, HEIGHT), 1.0 };
  const PixelAim no_model = aimAtPixel(box(CX, CY, 40.0, 40.0), { 0.0, 0.0, 1.0 }, calibrated_only, kinematics, limits);
  ASSERT_TRUE(no_model.ok()) << no_model.error;
  EXPECT_TRUE(std::isnan(no_model.zoom));
  EXPECT_NE(no_model.notes.find("no field of view is configured"), std::string::npos) << no_model.notes;
}

}  // namespace

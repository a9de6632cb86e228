#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "pixel_aim_test_support.h"
#include "ptz_action_server/core/motion/pixel_aim.h"

using namespace ptz_action_server;
using namespace pixel_aim_test;

namespace
{
class PixelAimTest : public ::testing::Test
{
protected:
  PixelAimTest()
    : kinematics(shippedKinematics()), lens(FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE }))
  {
    camera.field_of_view = &lens;
  }

  PixelGoal click(double u, double v) const
  {
    PixelGoal goal;
    goal.u = u;
    goal.v = v;
    goal.image_width = WIDTH;
    goal.image_height = HEIGHT;
    return goal;
  }

  PinholeIntrinsics intrinsicsAt(double zoom) const
  {
    return intrinsicsFor(lens.at(zoom), WIDTH, HEIGHT);
  }

  PtzKinematics kinematics;
  FieldOfViewModel lens;
  PixelCamera camera;
  Capabilities limits = zoomCamera();
};

TEST_F(PixelAimTest, TheCentrePixelAimsWhereTheCameraAlreadyLooks)
{
  const AxisValues pose{ 0.3, -0.2, 2.0 };
  const PinholeIntrinsics intrinsics = intrinsicsAt(2.0);
  const PixelAim aim = aimAtPixel(click(intrinsics.cx, intrinsics.cy), pose, camera, kinematics, limits);
  ASSERT_TRUE(aim.ok()) << aim.error;
  EXPECT_NEAR(aim.pan, 0.3, 1e-9);
  EXPECT_NEAR(aim.tilt, -0.2, 1e-9);
  EXPECT_TRUE(std::isnan(aim.zoom));  // centre only: the zoom stays
  EXPECT_TRUE(std::isnan(aim.box_fill));
  EXPECT_EQ(aim.notes, "");
  const Eigen::Vector3d axis = kinematics.cameraInBase(0.3, -0.2).linear() * Eigen::Vector3d::UnitX();
  EXPECT_TRUE(aim.direction.isApprox(axis, 1e-12)) << aim.direction.transpose();
}

TEST_F(PixelAimTest, RightOfCentreIsALargerPanAndAboveALargerTilt)
{
  const AxisValues pose{ 0.3, -0.2, 1.0 };
  const PinholeIntrinsics intrinsics = intrinsicsAt(1.0);
  const PixelAim right = aimAtPixel(click(intrinsics.cx + 100.0, intrinsics.cy), pose, camera, kinematics, limits);
  ASSERT_TRUE(right.ok()) << right.error;
  EXPECT_GT(right.pan, 0.3 + 0.05);
  const PixelAim left = aimAtPixel(click(intrinsics.cx - 100.0, intrinsics.cy), pose, camera, kinematics, limits);
  EXPECT_LT(left.pan, 0.3 - 0.05);
  // The centre column lies in the vertical plane of the optical axis: only the tilt changes.
  const PixelAim above = aimAtPixel(click(intrinsics.cx, intrinsics.cy - 80.0), pose, camera, kinematics, limits);
  ASSERT_TRUE(above.ok()) << above.error;
  EXPECT_GT(above.tilt, -0.2 + 0.05);
  EXPECT_NEAR(above.pan, 0.3, 1e-9);
  const PixelAim below = aimAtPixel(click(intrinsics.cx, intrinsics.cy + 80.0), pose, camera, kinematics, limits);
  EXPECT_LT(below.tilt, -0.2 - 0.05);
}

TEST_F(PixelAimTest, TheImageEdgeIsHalfTheFieldOfViewAway)
{
  // Level, the right edge of the image is half the horizontal field of view to the right, whatever the zoom.
  for (const double zoom : { 1.0, 4.0 })
  {
    const AxisValues pose{ -0.4, 0.0, zoom };
    const PixelAim edge = aimAtPixel(click(WIDTH - 0.5, intrinsicsAt(zoom).cy), pose, camera, kinematics, limits);
    ASSERT_TRUE(edge.ok()) << edge.error;
    EXPECT_NEAR(edge.pan, -0.4 + lens.at(zoom).horizontal / 2.0, 1e-9) << zoom;
    EXPECT_NEAR(edge.tilt, 0.0, 1e-9);
    const PixelAim top = aimAtPixel(click(intrinsicsAt(zoom).cx, -0.5), pose, camera, kinematics, limits);
    EXPECT_NEAR(top.tilt, lens.at(zoom).vertical / 2.0, 1e-9) << zoom;
  }
}

TEST_F(PixelAimTest, APointSeenAtAnEarlierPoseEndsOnTheOpticalAxis)
{
  // The image was taken at this pose, while the camera was on its way elsewhere; the aim depends on it alone.
  const AxisValues image_pose{ 0.2, 0.1, 3.0 };
  const Eigen::Isometry3d camera_then = kinematics.cameraInBase(image_pose[PAN], image_pose[TILT]);
  for (const Eigen::Vector3d& point : { Eigen::Vector3d(6.0, -2.0, 0.9), Eigen::Vector3d(2.0, -0.3, 0.25) })
  {
    double u = 0.0;
    double v = 0.0;
    ASSERT_TRUE(project(camera_then, intrinsicsAt(3.0), point, u, v));
    ASSERT_TRUE(u > 0.0 && u < WIDTH && v > 0.0 && v < HEIGHT) << u << ", " << v;
    PixelGoal goal = click(u, v);
    // The distance known: the URDF's offsets are taken into account, and the point lands on the axis exactly.
    goal.distance = (point - camera_then.translation()).norm();
    const PixelAim at_distance = aimAtPixel(goal, image_pose, camera, kinematics, limits);
    ASSERT_TRUE(at_distance.ok()) << at_distance.error;
    EXPECT_LT(offAxis(kinematics.cameraInBase(at_distance.pan, at_distance.tilt), point), 1e-8);
    // Far away (no distance): the direction is centred, off by the parallax of the camera's 9 cm offset at most.
    goal.distance = 0.0;
    const PixelAim far = aimAtPixel(goal, image_pose, camera, kinematics, limits);
    ASSERT_TRUE(far.ok()) << far.error;
    const double parallax = offAxis(kinematics.cameraInBase(far.pan, far.tilt), point);
    EXPECT_LT(parallax, 0.09 / (point - camera_then.translation()).norm());
    EXPECT_GT(parallax, 1e-6);  // the offset is real: this is what the distance takes out
  }
  // Far away, a far point lands on the axis.
  const Eigen::Vector3d far_point = camera_then.translation() + 1e5 * Eigen::Vector3d(0.9, -0.25, 0.12).normalized();
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(project(camera_then, intrinsicsAt(3.0), far_point, u, v));
  const PixelAim aim = aimAtPixel(click(u, v), image_pose, camera, kinematics, limits);
  EXPECT_LT(offAxis(kinematics.cameraInBase(aim.pan, aim.tilt), far_point), 1e-6);
}

TEST_F(PixelAimTest, ACalibratedCameraInfoIsCarriedToTheImagesZoomAndSize)
{
  // Calibrated at 2 X on 1280 x 720 with an off-centre principal point; the image is 640 x 360 at 5 X.
  CalibratedIntrinsics calibration;
  calibration.intrinsics = intrinsicsFor(lens.at(2.0), 1280, 720);
  calibration.intrinsics.cx = 655.0;
  calibration.intrinsics.cy = 350.0;
  calibration.zoom = 2.0;
  camera.calibration = calibration;
  // The full-size image at 5 X: the focal lengths grow by the model's focal scale, the principal point stays.
  PinholeIntrinsics full = calibration.intrinsics;
  full.fx *= lens.focalScale(2.0, 5.0).x;
  full.fy *= lens.focalScale(2.0, 5.0).y;
  const AxisValues image_pose{ -0.5, 0.2, 5.0 };
  const Eigen::Isometry3d camera_then = kinematics.cameraInBase(image_pose[PAN], image_pose[TILT]);
  const Eigen::Vector3d point = camera_then * Eigen::Vector3d(8.0, 0.3, -0.2);
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(project(camera_then, full, point, u, v));
  // The same place in the half-size image: pixel edges, not centres, scale (the first pixel's outer edge is -0.5).
  PixelGoal goal = click((u + 0.5) / 2.0 - 0.5, (v + 0.5) / 2.0 - 0.5);
  goal.distance = (point - camera_then.translation()).norm();
  const PixelAim aim = aimAtPixel(goal, image_pose, camera, kinematics, limits);
  ASSERT_TRUE(aim.ok()) << aim.error;
  EXPECT_LT(offAxis(kinematics.cameraInBase(aim.pan, aim.tilt), point), 1e-8);
  // Without the image's size, the calibration's is taken.
  PixelGoal full_size = goal;
  full_size.u = u;
  full_size.v = v;
  full_size.image_width = 0;
  full_size.image_height = 0;
  const PixelAim same = aimAtPixel(full_size, image_pose, camera, kinematics, limits);
  ASSERT_TRUE(same.ok()) << same.error;
  EXPECT_NEAR(same.pan, aim.pan, 1e-9);
  EXPECT_NEAR(same.tilt, aim.tilt, 1e-9);
}

TEST_F(PixelAimTest, AnUpsideDownPictureIsTurnedBack)
{
  // mount: inverted on a device that does not turn its picture: the pose is the contract's (MountedBackend maps
  // it), but the sensor hangs upside down, half a turn about the optical axis from the URDF's camera link.
  const AxisValues image_pose{ 0.6, -0.3, 1.5 };
  const Eigen::Isometry3d upright = kinematics.cameraInBase(image_pose[PAN], image_pose[TILT]);
  const Eigen::Isometry3d sensor = upright * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d point = upright * Eigen::Vector3d(5.0, 0.8, 0.5);  // left of and above the axis
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(project(sensor, intrinsicsAt(1.5), point, u, v));
  EXPECT_GT(u, intrinsicsAt(1.5).cx);  // the picture shows it right of and below the centre
  EXPECT_GT(v, intrinsicsAt(1.5).cy);
  PixelGoal goal = click(u, v);
  goal.distance = (point - upright.translation()).norm();
  camera.image_upside_down = true;
  const PixelAim aim = aimAtPixel(goal, image_pose, camera, kinematics, limits);
  ASSERT_TRUE(aim.ok()) << aim.error;
  EXPECT_LT(aim.pan, image_pose[PAN]);    // left
  EXPECT_GT(aim.tilt, image_pose[TILT]);  // up
  EXPECT_LT(offAxis(kinematics.cameraInBase(aim.pan, aim.tilt), point), 1e-8);
  // Taken upright, the same click would turn the camera away from the point.
  camera.image_upside_down = false;
  const PixelAim wrong = aimAtPixel(goal, image_pose, camera, kinematics, limits);
  EXPECT_GT(offAxis(kinematics.cameraInBase(wrong.pan, wrong.tilt), point), 0.2);
}

TEST_F(PixelAimTest, AnAxisTheDeviceCannotPositionStays)
{
  limits.axes[TILT] = absentAxis();
  const AxisValues pose{ 0.1, 0.0, 1.0 };
  const PinholeIntrinsics intrinsics = intrinsicsAt(1.0);
  const PixelAim aim = aimAtPixel(click(intrinsics.cx + 50.0, intrinsics.cy - 50.0), pose, camera, kinematics, limits);
  ASSERT_TRUE(aim.ok()) << aim.error;
  EXPECT_GT(aim.pan, 0.1);
  EXPECT_EQ(aim.tilt, 0.0);
  EXPECT_NE(aim.notes.find("the tilt stays (the device has no tilt"), std::string::npos) << aim.notes;
}

TEST_F(PixelAimTest, BadClicksAreRefusedWithTheirReason)
{
  const AxisValues pose{ 0.0, 0.0, 1.0 };
  const auto refusal = [&](const PixelGoal& goal, const AxisValues& at, const PixelCamera& with) {
    const PixelAim aim = aimAtPixel(goal, at, with, kinematics, limits);
    EXPECT_FALSE(aim.ok());
    return aim.error;
  };
  const auto expectRefused = [&](const PixelGoal& goal, const std::string& words) {
    const std::string error = refusal(goal, pose, camera);
    EXPECT_NE(error.find(words), std::string::npos) << error;
  };
  const double not_a_number = std::numeric_limits<double>::quiet_NaN();
  // Off the image: pixel indices run from -0.5 to size - 0.5.
  expectRefused(click(-0.6, 10.0), "pixel (-0.6, 10) is not on the 640 x 360 px image");
  expectRefused(click(10.0, HEIGHT - 0.4), "is not on the 640 x 360 px image");
  expectRefused(click(not_a_number, 10.0), "pixel (nan, 10) is not on");
  EXPECT_TRUE(aimAtPixel(click(-0.5, HEIGHT - 0.5), pose, camera, kinematics, limits).ok());
  PixelGoal no_size = click(10.0, 10.0);
  no_size.image_width = 0;
  expectRefused(no_size, "the image size 0 x 360 px must be positive");
  // Boxes: both sides positive, or 0 x 0.
  for (const auto& box : { std::make_pair(-20.0, 10.0), std::make_pair(20.0, 0.0), std::make_pair(not_a_number, 5.0),
                           std::make_pair(20.0, HUGE_VAL) })
  {
    PixelGoal goal = click(100.0, 100.0);
    goal.box_width = box.first;
    goal.box_height = box.second;
    expectRefused(goal, "both sides must be positive");
  }
  for (const double distance : { -1.0, not_a_number })
  {
    PixelGoal goal = click(100.0, 100.0);
    goal.distance = distance;
    expectRefused(goal, "must be positive, or 0 for far away");
  }
  // The pose: outside the history the ROS layer refuses with PoseLookup::error; an unknown axis is refused here.
  EXPECT_NE(refusal(click(1.0, 1.0), { not_a_number, 0.0, 1.0 }, camera)
                .find("the camera's pan when the image was "
                      "taken is unknown"),
            std::string::npos);
  EXPECT_NE(refusal(click(1.0, 1.0), { 0.0, 0.0, not_a_number }, camera).find("zoom when the image was taken"),
            std::string::npos);
  // No field of view: no intrinsics; a calibration alone does not reach another zoom.
  EXPECT_NE(refusal(click(1.0, 1.0), pose, PixelCamera()).find("no field of view is configured"), std::string::npos);
  PixelCamera calibrated_only;
  calibrated_only.calibration = CalibratedIntrinsics{ intrinsicsAt(1.0), 1.0 };
  EXPECT_TRUE(aimAtPixel(click(1.0, 1.0), pose, calibrated_only, kinematics, limits).ok());
  EXPECT_NE(refusal(click(1.0, 1.0), { 0.0, 0.0, 2.0 }, calibrated_only)
                .find("the camera_info holds at zoom 1 X and no field of view is configured to carry it to zoom 2 X"),
            std::string::npos);
}

TEST_F(PixelAimTest, ADeviceWithoutZoomHasAFixedLens)
{
  // A pan-tilt unit reports no zoom (NaN): its lens is the wide end, or the calibration's.
  limits.axes[ZOOM] = absentAxis();
  const AxisValues pose{ 0.0, 0.0, std::numeric_limits<double>::quiet_NaN() };
  const PixelAim edge = aimAtPixel(click(WIDTH - 0.5, intrinsicsAt(1.0).cy), pose, camera, kinematics, limits);
  ASSERT_TRUE(edge.ok()) << edge.error;
  EXPECT_NEAR(edge.pan, lens.at(1.0).horizontal / 2.0, 1e-9);
  PixelCamera calibrated_only;
  calibrated_only.calibration = CalibratedIntrinsics{ intrinsicsAt(1.0), 3.0 };
  EXPECT_TRUE(aimAtPixel(click(1.0, 1.0), pose, calibrated_only, kinematics, limits).ok());
}

}  // namespace

#include <cmath>

#include <gtest/gtest.h>

#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/motion/pinhole_view.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
namespace
{
const FieldOfViewAngles WIDE{ 1.0, 0.6 };

TEST(PinholeView, TheImageCentreLooksAlongTheOpticalAxis)
{
  const PinholeIntrinsics intrinsics = intrinsicsFor(WIDE, 640, 360);
  EXPECT_DOUBLE_EQ(intrinsics.cx, 319.5);
  EXPECT_DOUBLE_EQ(intrinsics.cy, 179.5);
  const Eigen::Vector3d ray = rayThroughPixel(intrinsics, intrinsics.cx, intrinsics.cy);
  EXPECT_NEAR(ray.z(), 1.0, 1e-12);
  EXPECT_NEAR(ray.x(), 0.0, 1e-12);
}

TEST(PinholeView, TheImageEdgesAreHalfTheFieldOfViewAway)
{
  const PinholeIntrinsics intrinsics = intrinsicsFor(WIDE, 640, 360);
  // The outer edge of the rightmost pixel is at u = width - 0.5, the bottom edge of the last row at v = height - 0.5.
  const Eigen::Vector3d right = rayThroughPixel(intrinsics, 639.5, intrinsics.cy);
  EXPECT_NEAR(std::atan2(right.x(), right.z()), 0.5, 1e-12);
  const Eigen::Vector3d top = rayThroughPixel(intrinsics, intrinsics.cx, -0.5);
  EXPECT_NEAR(std::atan2(top.y(), top.z()), -0.3, 1e-12);
  const FieldOfViewAngles back = fieldOfViewOf(intrinsics);
  EXPECT_NEAR(back.horizontal, WIDE.horizontal, 1e-12);
  EXPECT_NEAR(back.vertical, WIDE.vertical, 1e-12);
}

TEST(PinholeView, APixelsRayComesBackToThatPixel)
{
  const PinholeIntrinsics intrinsics = intrinsicsFor(WIDE, 1280, 720);
  for (const double u : { 0.0, 17.25, 640.0, 1279.0 })
  {
    for (const double v : { 0.0, 359.5, 719.0 })
    {
      double back_u = -1.0;
      double back_v = -1.0;
      ASSERT_TRUE(pixelOf(intrinsics, rayThroughPixel(intrinsics, u, v), back_u, back_v));
      EXPECT_NEAR(back_u, u, 1e-9);
      EXPECT_NEAR(back_v, v, 1e-9);
    }
  }
}

TEST(PinholeView, ARayBehindTheCameraHasNoPixel)
{
  const PinholeIntrinsics intrinsics = intrinsicsFor(WIDE, 64, 36);
  double u = 7.0;
  double v = 8.0;
  EXPECT_FALSE(pixelOf(intrinsics, Eigen::Vector3d(0.1, 0.0, -1.0), u, v));
  EXPECT_FALSE(pixelOf(intrinsics, Eigen::Vector3d(1.0, 0.0, 0.0), u, v));
  EXPECT_EQ(u, 7.0);
  EXPECT_EQ(v, 8.0);
}

TEST(PinholeView, RightAndDownInTheImageAreRightAndDownForTheCamera)
{
  const PinholeIntrinsics intrinsics = intrinsicsFor(WIDE, 640, 360);
  // A pixel right of the centre: in the camera link's axes (x forward, y left, z up) the ray points to -y.
  const Eigen::Vector3d right = opticalToCameraLink(rayThroughPixel(intrinsics, 600.0, intrinsics.cy));
  EXPECT_GT(right.x(), 0.0);
  EXPECT_LT(right.y(), 0.0);
  EXPECT_NEAR(right.z(), 0.0, 1e-12);
  // A pixel below the centre points to -z.
  const Eigen::Vector3d down = opticalToCameraLink(rayThroughPixel(intrinsics, intrinsics.cx, 300.0));
  EXPECT_LT(down.z(), 0.0);
  EXPECT_NEAR(down.y(), 0.0, 1e-12);
  // The contract's pan is clockwise seen from above: a pixel to the right of the centre is at a larger pan.
  const Eigen::Vector3d forward(1.0, 0.0, 0.0);
  EXPECT_GT(directionOf(0.1, 0.0).dot(right.normalized()), directionOf(-0.1, 0.0).dot(right.normalized()));
  EXPECT_TRUE(cameraLinkToOptical(right).isApprox(rayThroughPixel(intrinsics, 600.0, 179.5)));
  EXPECT_TRUE(cameraLinkToOptical(forward).isApprox(Eigen::Vector3d(0.0, 0.0, 1.0)));
}

TEST(PinholeView, ABadSizeOrAngleIsRefused)
{
  EXPECT_THROW(intrinsicsFor(WIDE, 0, 360), ConfigError);
  EXPECT_THROW(intrinsicsFor({ 0.0, 0.5 }, 640, 360), ConfigError);
  EXPECT_THROW(intrinsicsFor({ 1.0, M_PI }, 640, 360), ConfigError);
  EXPECT_THROW(intrinsicsFor({ NAN, 0.5 }, 640, 360), ConfigError);
}

}  // namespace
}  // namespace ptz_action_server

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/motion/pinhole_view.h"
#include "ptz_action_server/render/camera_renderer.h"

namespace ptz_action_server
{
namespace
{
constexpr int WIDTH = 640;
constexpr int HEIGHT = 360;

const PtzKinematics& shippedKinematics()
{
  static const PtzKinematics kinematics = [] {
    std::ifstream file(std::string(PTZ_SOURCE_DIR) + "/urdf/ptz.urdf");
    std::stringstream text;
    text << file.rdbuf();
    return PtzKinematics::fromUrdf(text.str());
  }();
  return kinematics;
}

/// The sim's lens: 60 degrees across at zoom 1, square pixels at 640x360.
const FieldOfViewModel& lens()
{
  static const FieldOfViewModel model =
      FieldOfViewModel::fromWideEnd({ M_PI / 3.0, 2.0 * std::atan(std::tan(M_PI / 6.0) * HEIGHT / WIDTH) });
  return model;
}

struct Pose
{
  double pan;
  double tilt;
  double zoom;
};

/// A camera at \p pose as the node renders it: the URDF's camera link, the lens at the zoom.
struct View
{
  explicit View(const Pose& pose, int width = WIDTH, int height = HEIGHT)
    : camera(shippedKinematics().cameraInBase(pose.pan, pose.tilt))
    , intrinsics(intrinsicsFor(lens().at(pose.zoom), width, height))
  {
  }

  /// Where, \p distance m from the camera, pixel (\p u, \p v)'s ray goes (base frame).
  Eigen::Vector3d pointThrough(double u, double v, double distance) const
  {
    return camera * (distance * opticalToCameraLink(rayThroughPixel(intrinsics, u, v)));
  }

  Eigen::Isometry3d camera;
  PinholeIntrinsics intrinsics;
};

/// The centroid of the pixels of exactly \p colour; false if there are none.
bool centroidOf(const cv::Mat& image, const Rgb& colour, double& u, double& v, int* count = nullptr)
{
  double sum_u = 0.0;
  double sum_v = 0.0;
  int pixels = 0;
  for (int row = 0; row < image.rows; ++row)
  {
    for (int column = 0; column < image.cols; ++column)
    {
      const cv::Vec3b& pixel = image.at<cv::Vec3b>(row, column);
      if (pixel[0] == colour.r && pixel[1] == colour.g && pixel[2] == colour.b)
      {
        sum_u += column;
        sum_v += row;
        ++pixels;
      }
    }
  }
  if (count != nullptr)
  {
    *count = pixels;
  }
  if (pixels == 0)
  {
    return false;
  }
  u = sum_u / pixels;
  v = sum_v / pixels;
  return true;
}

/// The angle (rad) between two directions.
double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

const std::vector<Pose> POSES = {
  { 0.0, 0.0, 1.0 }, { 0.6, 0.35, 3.0 },    { -2.5, -0.8, 1.0 }, { 3.1, 0.2, 24.0 },
  { 1.2, 1.3, 8.0 }, { -0.4, 1.5707, 1.0 }, { 2.0, -1.5, 2.0 },  { -3.14, -0.05, 12.0 }
};

TEST(CameraRenderer, AMarkerIsDrawnWhereThePixelsRayPoints)
{
  cv::Mat image;
  for (const Pose& pose : POSES)
  {
    const View view(pose);
    // Discs of 12 px at every zoom: whole, not cut by the image's edge.
    RenderSettings settings;
    settings.marker_radius = std::atan(12.0 / view.intrinsics.fx);
    CameraRenderer renderer(settings);
    // Two markers, 3 m and 7.5 m away, through pixels off the grid of whole pixels.
    const double targets[2][2] = { { 201.3, 97.8 }, { 455.6, 260.25 } };
    std::vector<SceneMarker> markers(2);
    for (int index = 0; index < 2; ++index)
    {
      markers[index].name = "target_" + std::to_string(index);
      markers[index].position = view.pointThrough(targets[index][0], targets[index][1], 3.0 + 4.5 * index);
      markers[index].present = true;
    }
    renderer.render(view.camera, view.intrinsics, markers, image);
    for (int index = 0; index < 2; ++index)
    {
      SCOPED_TRACE(::testing::Message() << "pan " << pose.pan << " tilt " << pose.tilt << " zoom " << pose.zoom
                                        << " marker " << index);
      double u = 0.0;
      double v = 0.0;
      ASSERT_TRUE(centroidOf(image, markerColour(index), u, v));
      EXPECT_NEAR(u, targets[index][0], 0.1);
      EXPECT_NEAR(v, targets[index][1], 0.1);
      // The same from the other side: the ray through the centroid, turned by the camera's pose, points at the marker.
      const Eigen::Vector3d ray = view.camera.linear() * opticalToCameraLink(rayThroughPixel(view.intrinsics, u, v));
      const Eigen::Vector3d towards = markers[index].position - view.camera.translation();
      EXPECT_LT(angleBetween(ray, towards) * view.intrinsics.fx, 0.1) << "pixels off";
      // And pixelOf() of the marker's direction is where it is drawn.
      double expected_u = 0.0;
      double expected_v = 0.0;
      ASSERT_TRUE(pixelOf(view.intrinsics, cameraLinkToOptical(view.camera.linear().transpose() * towards), expected_u,
                          expected_v));
      EXPECT_NEAR(u, expected_u, 0.1);
      EXPECT_NEAR(v, expected_v, 0.1);
    }
  }
}

TEST(CameraRenderer, TheBackdropIsWhereEachPixelsRayPoints)
{
  CameraRenderer renderer;
  cv::Mat image;
  for (const Pose& pose : POSES)
  {
    SCOPED_TRACE(::testing::Message() << "pan " << pose.pan << " tilt " << pose.tilt << " zoom " << pose.zoom);
    const View view(pose);
    renderer.render(view.camera, view.intrinsics, {}, image);
    const DirectionLookup& lookup = renderer.lookup();
    double worst = 0.0;
    for (int v = 0; v < HEIGHT; ++v)
    {
      for (int u = 0; u < WIDTH; ++u)
      {
        const Eigen::Vector3d ray = view.camera.linear() * opticalToCameraLink(rayThroughPixel(view.intrinsics, u, v));
        const double azimuth = std::atan2(-ray.y(), ray.x()) - lookup.referenceAzimuth();
        const double elevation = std::asin(std::clamp(ray.z(), -1.0, 1.0));
        const cv::Vec4f& drawn = lookup.directions().at<cv::Vec4f>(v, u);
        const PixelDirection exact = lookup.exactAt(u, v);
        // Off by how many pixels: the angle's error times the pixels per rad across its marks.
        const double azimuth_off = std::abs(std::remainder(drawn[0] - azimuth, 2.0 * M_PI)) * exact.azimuth_scale;
        const double elevation_off = std::abs(drawn[1] - elevation) * exact.elevation_scale;
        worst = std::max({ worst, azimuth_off, elevation_off });
      }
    }
    // A pole in view (the zenith or the nadir): the elevation is a cone there, which a bilinear interpolation follows
    // less closely; the cells where the azimuth wraps or turns fast around it are computed exactly.
    const bool pole_in_view = std::abs(pose.tilt) + lens().at(pose.zoom).vertical / 2.0 > M_PI_2 - 0.1;
    EXPECT_LT(worst, pole_in_view ? 0.25 : 0.05) << "pixels off";
  }
}

TEST(CameraRenderer, MarksComeCloserWithZoomButStayApart)
{
  CameraRenderer renderer;
  cv::Mat image;
  double last_step = INFINITY;
  for (const double zoom : { 1.0, 4.0, 24.0 })
  {
    const View view({ 0.3, 0.1, zoom });
    renderer.render(view.camera, view.intrinsics, {}, image);
    EXPECT_LT(renderer.markStep(), last_step);
    EXPECT_GE(renderer.markStep() * view.intrinsics.fx, CameraRenderer::MIN_MARK_SPACING);
    last_step = renderer.markStep();
  }
}

TEST(CameraRenderer, SkyAboveTheHorizonGroundBelow)
{
  CameraRenderer renderer;
  cv::Mat image;
  for (const double pan : { -2.0, 0.0, 0.7 })
  {
    const View view({ pan, 0.0, 1.0 });
    renderer.render(view.camera, view.intrinsics, {}, image);
    const cv::Vec3b above = image.at<cv::Vec3b>(100, 300);
    const cv::Vec3b below = image.at<cv::Vec3b>(260, 300);
    EXPECT_GT(above[2], above[0]) << "sky is blue";
    EXPECT_GT(below[0], below[2]) << "ground is brown";
    // Tilt 0: the horizon runs through the image's middle row (between rows 179 and 180), brighter than either side.
    const auto brightness = [&](int row) { return image.at<cv::Vec3b>(row, 50)[1]; };
    EXPECT_GT(brightness(179), brightness(175));
    EXPECT_GT(brightness(180), brightness(184));
  }
}

TEST(CameraRenderer, PanningRightMovesTheWorldLeft)
{
  CameraRenderer renderer;
  cv::Mat image;
  const View start({ 0.0, 0.1, 2.0 });
  std::vector<SceneMarker> markers(1);
  markers[0].name = "ahead";
  markers[0].position = start.pointThrough(320.0, 180.0, 5.0);
  markers[0].present = true;
  double last_u = INFINITY;
  for (const double pan : { 0.0, 0.05, 0.1 })
  {
    const View view({ pan, 0.1, 2.0 });
    renderer.render(view.camera, view.intrinsics, markers, image);
    double u = 0.0;
    double v = 0.0;
    ASSERT_TRUE(centroidOf(image, markerColour(0), u, v));
    EXPECT_LT(u, last_u - 10.0);
    last_u = u;
  }
}

TEST(CameraRenderer, OnlyMarkersHaveMarkerColours)
{
  CameraRenderer renderer;
  cv::Mat image;
  for (const Pose& pose : POSES)
  {
    const View view(pose);
    renderer.render(view.camera, view.intrinsics, {}, image);
    int coloured = 0;
    for (int v = 0; v < HEIGHT; ++v)
    {
      for (int u = 0; u < WIDTH; ++u)
      {
        const cv::Vec3b& pixel = image.at<cv::Vec3b>(v, u);
        const bool saturated = std::max({ pixel[0], pixel[1], pixel[2] }) == 255;
        const bool empty = std::min({ pixel[0], pixel[1], pixel[2] }) == 0;
        coloured += saturated && empty ? 1 : 0;
      }
    }
    EXPECT_EQ(coloured, 0) << "pan " << pose.pan << " tilt " << pose.tilt << " zoom " << pose.zoom;
  }
}

TEST(CameraRenderer, MarkersBehindAbsentOrOutOfViewAreNotDrawn)
{
  CameraRenderer renderer;
  cv::Mat image;
  const View view({ 0.4, 0.2, 1.0 });
  std::vector<SceneMarker> markers(4);
  markers[0].position = view.camera * Eigen::Vector3d(-2.0, 0.0, 0.0);  // behind
  markers[0].present = true;
  markers[1].position = view.pointThrough(100.0, 100.0, 2.0);          // not (yet) in tf
  markers[2].position = view.camera * Eigen::Vector3d(1.0, 3.0, 0.0);  // far to the left of the view
  markers[2].present = true;
  markers[3].position = view.pointThrough(500.0, 300.0, 2.0);
  markers[3].present = true;
  renderer.render(view.camera, view.intrinsics, markers, image);
  double u = 0.0;
  double v = 0.0;
  for (int index = 0; index < 3; ++index)
  {
    EXPECT_FALSE(centroidOf(image, markerColour(index), u, v)) << "marker " << index;
  }
  EXPECT_TRUE(centroidOf(image, markerColour(3), u, v));
}

TEST(CameraRenderer, ANearerMarkerCoversAFartherOne)
{
  CameraRenderer renderer;
  cv::Mat image;
  const View view({ -0.2, 0.1, 4.0 });
  std::vector<SceneMarker> markers(2);
  markers[0].position = view.pointThrough(300.0, 200.0, 2.0);  // near
  markers[1].position = view.pointThrough(305.0, 200.0, 9.0);  // far, mostly behind it
  markers[0].present = markers[1].present = true;
  renderer.render(view.camera, view.intrinsics, markers, image);
  int near_pixels = 0;
  int far_pixels = 0;
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(centroidOf(image, markerColour(0), u, v, &near_pixels));
  EXPECT_NEAR(u, 300.0, 0.1);
  centroidOf(image, markerColour(1), u, v, &far_pixels);
  EXPECT_LT(far_pixels, near_pixels / 4);
}

TEST(CameraRenderer, MarkerColoursAreDistinctAndRepeat)
{
  for (std::size_t a = 0; a < MARKER_COLOURS; ++a)
  {
    for (std::size_t b = a + 1; b < MARKER_COLOURS; ++b)
    {
      const Rgb first = markerColour(a);
      const Rgb second = markerColour(b);
      EXPECT_FALSE(first.r == second.r && first.g == second.g && first.b == second.b) << a << " and " << b;
    }
  }
  EXPECT_EQ(markerColour(MARKER_COLOURS + 2).g, markerColour(2).g);
}

}  // namespace
}  // namespace ptz_action_server

#include "ptz_action_server/render/camera_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "ptz_action_server/core/motion/kinematics.h"

namespace ptz_action_server
{
namespace
{
/// Each with a channel at 255 and one at 0: nothing else in the picture has both.
constexpr std::array<Rgb, MARKER_COLOURS> PALETTE = { {
    { 255, 0, 255 },  // magenta
    { 255, 255, 0 },  // yellow
    { 0, 255, 255 },  // cyan
    { 255, 0, 0 },    // red
    { 0, 255, 0 },    // green
    { 0, 0, 255 },    // blue
    { 255, 128, 0 },  // orange
    { 128, 0, 255 },  // violet
} };

constexpr double MIN_MARKER_HALF_SIZE = 2.0;  ///< px: a disc stays findable however small its angle
constexpr int FIXED_POINT_BITS = 8;           ///< the discs' centres and sizes to 1/256 px (cv::ellipse's shift)

}  // namespace

Rgb markerColour(std::size_t index)
{
  return PALETTE[index % MARKER_COLOURS];
}

CameraRenderer::CameraRenderer(const RenderSettings& settings) : settings_(settings)
{
  written_labels_.reserve(256);
}

void CameraRenderer::render(const Eigen::Isometry3d& camera_in_base, const PinholeIntrinsics& intrinsics,
                            const std::vector<SceneMarker>& markers, cv::Mat& image)
{
  image.create(intrinsics.height, intrinsics.width, CV_8UC3);
  intrinsics_ = intrinsics;
  const Eigen::Matrix3d base_to_link = camera_in_base.linear().transpose();
  for (int axis = 0; axis < 3; ++axis)
  {
    base_to_optical_.col(axis) = cameraLinkToOptical(base_to_link.col(axis));
  }
  lookup_.update(intrinsics, camera_in_base.linear());

  // The finest of these steps (degrees) whose marks stay MIN_MARK_SPACING pixels apart at the image centre.
  constexpr std::array<double, 14> STEPS = { 90, 45, 30, 15, 10, 5, 2, 1, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01 };
  const double pixels_per_rad = std::min(intrinsics.fx, intrinsics.fy);
  mark_step_ = STEPS.front() * M_PI / 180.0;
  for (const double step : STEPS)
  {
    if (step * M_PI / 180.0 * pixels_per_rad < MIN_MARK_SPACING)
    {
      break;
    }
    mark_step_ = step * M_PI / 180.0;
  }

  drawBackdrop(image);
  written_labels_.clear();
  drawMarkLabels(image);
  drawMarkers(camera_in_base, markers, image);
}

void CameraRenderer::drawMarkers(const Eigen::Isometry3d& camera_in_base, const std::vector<SceneMarker>& markers,
                                 cv::Mat& image)
{
  projected_.clear();
  const double tan_radius = std::tan(settings_.marker_radius);
  for (std::size_t index = 0; index < markers.size(); ++index)
  {
    const SceneMarker& marker = markers[index];
    if (!marker.present)
    {
      continue;
    }
    const Eigen::Vector3d offset = marker.position - camera_in_base.translation();
    Projected projected;
    projected.index = index;
    projected.distance = offset.norm();
    projected.half_width = std::max(MIN_MARKER_HALF_SIZE, intrinsics_.fx * tan_radius);
    projected.half_height = std::max(MIN_MARKER_HALF_SIZE, intrinsics_.fy * tan_radius);
    // A frame at the camera itself (one of its own links) has no direction to be seen in.
    if (projected.distance < 1e-6 || !pixelOf(intrinsics_, base_to_optical_ * offset, projected.u, projected.v))
    {
      continue;
    }
    if (projected.u < -projected.half_width || projected.u > intrinsics_.width - 1 + projected.half_width ||
        projected.v < -projected.half_height || projected.v > intrinsics_.height - 1 + projected.half_height)
    {
      continue;
    }
    projected_.push_back(projected);
  }
  std::sort(projected_.begin(), projected_.end(),
            [](const Projected& a, const Projected& b) { return a.distance > b.distance; });

  // Names first, discs over them: a disc is never covered but by a nearer disc, so its colour's pixels are all of it.
  for (const Projected& projected : projected_)
  {
    label_ = markers[projected.index].name;
    writeLabel(image, projected.u + projected.half_width + 3.0, projected.v - 6.0);
  }
  constexpr double SCALE = 1 << FIXED_POINT_BITS;
  for (const Projected& projected : projected_)
  {
    const Rgb colour = markerColour(projected.index);
    const cv::Point centre(static_cast<int>(std::lround(projected.u * SCALE)),
                           static_cast<int>(std::lround(projected.v * SCALE)));
    const cv::Size axes(static_cast<int>(std::lround(projected.half_width * SCALE)),
                        static_cast<int>(std::lround(projected.half_height * SCALE)));
    cv::ellipse(image, centre, axes, 0.0, 0.0, 360.0, cv::Scalar(colour.r, colour.g, colour.b), cv::FILLED, cv::LINE_8,
                FIXED_POINT_BITS);
  }
}

void CameraRenderer::writeLabel(cv::Mat& image, double u, double v)
{
  constexpr int FONT = cv::FONT_HERSHEY_SIMPLEX;
  constexpr double FONT_SCALE = 0.4;
  const cv::Scalar light(250, 250, 250);
  const cv::Scalar dark(25, 25, 25);
  int baseline = 0;
  const cv::Size size = cv::getTextSize(label_, FONT, FONT_SCALE, 1, &baseline);
  const cv::Rect box(static_cast<int>(std::lround(u)), static_cast<int>(std::lround(v)), size.width + 2,
                     size.height + baseline + 2);
  if ((box & cv::Rect(0, 0, image.cols, image.rows)).empty())
  {
    return;
  }
  for (const cv::Rect& written : written_labels_)
  {
    if (!(box & written).empty())
    {
      return;
    }
  }
  written_labels_.push_back(box);
  const cv::Point origin(box.x + 1, box.y + 1 + size.height);
  cv::rectangle(image, box, dark, cv::FILLED);
  cv::putText(image, label_, origin, FONT, FONT_SCALE, light, 1, cv::LINE_AA);
}

bool CameraRenderer::pixelOfDirection(double azimuth, double elevation, double& u, double& v) const
{
  return pixelOf(intrinsics_, base_to_optical_ * directionOf(azimuth, elevation), u, v);
}

}  // namespace ptz_action_server

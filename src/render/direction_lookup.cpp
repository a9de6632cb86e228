#include "ptz_action_server/render/direction_lookup.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <opencv2/imgproc.hpp>

namespace ptz_action_server
{
namespace
{
/// A cell whose corners' azimuths spread wider than this (rad) is computed per pixel: it holds the azimuth's wrap or
/// lies so near a pole that the azimuth turns too fast for a bilinear interpolation.
constexpr double EXACT_SPREAD = 0.2;

/// \p angle in (-pi, pi].
double wrapped(double angle)
{
  const double folded = std::remainder(angle, 2.0 * M_PI);
  return folded <= -M_PI ? folded + 2.0 * M_PI : folded;
}

cv::Vec4f toCell(const PixelDirection& direction)
{
  return { direction.azimuth, direction.elevation, direction.azimuth_scale, direction.elevation_scale };
}
}  // namespace

PixelDirection DirectionLookup::exactAt(double u, double v) const
{
  // The shared model's ray, scaled to optical z = 1: its base-frame direction d is then linear in (u, v), with
  // derivatives optical_to_base's first two columns over fx and fy. Azimuth and elevation do not depend on the scale.
  const Eigen::Vector3d ray = rayThroughPixel(intrinsics_, u, v);
  const Eigen::Vector3d d = optical_to_base_ * (ray / ray.z());
  const Eigen::Vector3d d_u = optical_to_base_.col(0) / intrinsics_.fx;
  const Eigen::Vector3d d_v = optical_to_base_.col(1) / intrinsics_.fy;
  const double horizontal_squared = std::max(d.x() * d.x() + d.y() * d.y(), 1e-24);
  const double horizontal = std::sqrt(horizontal_squared);
  const double length_squared = horizontal_squared + d.z() * d.z();
  // Azimuth atan2(-y, x) (pan is clockwise from above), elevation atan2(z, |(x, y)|); their derivatives along u and v.
  const auto azimuth_along = [&](const Eigen::Vector3d& step) {
    return (d.y() * step.x() - d.x() * step.y()) / horizontal_squared;
  };
  const auto elevation_along = [&](const Eigen::Vector3d& step) {
    const double horizontal_step = (d.x() * step.x() + d.y() * step.y()) / horizontal;
    return (horizontal * step.z() - d.z() * horizontal_step) / length_squared;
  };
  PixelDirection direction;
  direction.azimuth = static_cast<float>(wrapped(std::atan2(-d.y(), d.x()) - reference_azimuth_));
  direction.elevation = static_cast<float>(std::atan2(d.z(), horizontal));
  // Pixels per rad: the inverse of the gradient's length, smooth everywhere (0 at a pole, where the azimuth turns
  // infinitely fast), so that the renderer multiplies rather than divides per pixel.
  direction.azimuth_scale =
      static_cast<float>(1.0 / std::max(std::hypot(azimuth_along(d_u), azimuth_along(d_v)), 1e-12));
  direction.elevation_scale =
      static_cast<float>(1.0 / std::max(std::hypot(elevation_along(d_u), elevation_along(d_v)), 1e-12));
  return direction;
}

void DirectionLookup::update(const PinholeIntrinsics& intrinsics, const Eigen::Matrix3d& camera_rotation)
{
  intrinsics_ = intrinsics;
  for (int axis = 0; axis < 3; ++axis)
  {
    optical_to_base_.col(axis) = camera_rotation * opticalToCameraLink(Eigen::Vector3d::Unit(axis));
  }
  const Eigen::Vector3d centre = optical_to_base_.col(2);
  reference_azimuth_ = std::atan2(-centre.y(), centre.x());

  constexpr int STEP = GRID_STEP;
  const int columns = (intrinsics.width + STEP - 1) / STEP + 2;
  const int rows = (intrinsics.height + STEP - 1) / STEP + 2;
  grid_.create(rows, columns, CV_32FC4);
  for (int row = 0; row < rows; ++row)
  {
    auto* node = grid_.ptr<cv::Vec4f>(row);
    for (int column = 0; column < columns; ++column)
    {
      node[column] = toCell(exactAt((column - 0.5) * STEP - 0.5, (row - 0.5) * STEP - 0.5));
    }
  }
  // cv::resize maps destination pixel x to source (x + 0.5) / STEP - 0.5, so node i lands on padded pixel
  // (i + 0.5) STEP - 0.5, i.e. image pixel (i - 0.5) STEP - 0.5 once the margin of STEP is cut off. Every image pixel
  // lies strictly between two nodes: no border rule is ever used.
  padded_.create(rows * STEP, columns * STEP, CV_32FC4);
  cv::resize(grid_, padded_, padded_.size(), 0.0, 0.0, cv::INTER_LINEAR);
  view_ = padded_(cv::Rect(STEP, STEP, intrinsics.width, intrinsics.height));

  exact_cells_ = 0;
  for (int row = 0; row + 1 < rows; ++row)
  {
    const auto* top = grid_.ptr<cv::Vec4f>(row);
    const auto* bottom = grid_.ptr<cv::Vec4f>(row + 1);
    for (int column = 0; column + 1 < columns; ++column)
    {
      const float corners[] = { top[column][0], top[column + 1][0], bottom[column][0], bottom[column + 1][0] };
      const auto [lowest, highest] = std::minmax_element(std::begin(corners), std::end(corners));
      if (*highest - *lowest > EXACT_SPREAD)
      {
        computeCellExactly(column, row);
      }
    }
  }
}

void DirectionLookup::computeCellExactly(int column, int row)
{
  // The cell between nodes column and column + 1 holds the pixels from (column - 0.5) STEP to (column + 0.5) STEP - 1.
  constexpr int STEP = GRID_STEP;
  const int left = std::max(0, column * STEP - STEP / 2);
  const int right = std::min(intrinsics_.width, column * STEP + STEP / 2);
  const int top = std::max(0, row * STEP - STEP / 2);
  const int bottom = std::min(intrinsics_.height, row * STEP + STEP / 2);
  if (left >= right || top >= bottom)
  {
    return;
  }
  ++exact_cells_;
  for (int v = top; v < bottom; ++v)
  {
    auto* pixel = view_.ptr<cv::Vec4f>(v);
    for (int u = left; u < right; ++u)
    {
      pixel[u] = toCell(exactAt(u, v));
    }
  }
}

void DirectionLookup::range(double& min_azimuth, double& max_azimuth, double& min_elevation,
                            double& max_elevation) const
{
  min_azimuth = max_azimuth = min_elevation = max_elevation = 0.0;
  if (grid_.empty())
  {
    return;
  }
  min_azimuth = min_elevation = INFINITY;
  max_azimuth = max_elevation = -INFINITY;
  for (int row = 0; row < grid_.rows; ++row)
  {
    const auto* node = grid_.ptr<cv::Vec4f>(row);
    for (int column = 0; column < grid_.cols; ++column)
    {
      min_azimuth = std::min<double>(min_azimuth, node[column][0]);
      max_azimuth = std::max<double>(max_azimuth, node[column][0]);
      min_elevation = std::min<double>(min_elevation, node[column][1]);
      max_elevation = std::max<double>(max_elevation, node[column][1]);
    }
  }
}

}  // namespace ptz_action_server

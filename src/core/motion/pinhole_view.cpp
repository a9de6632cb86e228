#include "ptz_action_server/core/motion/pinhole_view.h"

#include <cmath>
#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
PinholeIntrinsics intrinsicsFor(const FieldOfViewAngles& field_of_view, int width, int height)
{
  if (width <= 0 || height <= 0)
  {
    throw ConfigError("image size " + std::to_string(width) + "x" + std::to_string(height) + " must be positive");
  }
  const auto in_open_range = [](double angle) { return std::isfinite(angle) && angle > 0.0 && angle < M_PI; };
  if (!in_open_range(field_of_view.horizontal) || !in_open_range(field_of_view.vertical))
  {
    throw ConfigError("field of view " + std::to_string(field_of_view.horizontal) + " x " +
                      std::to_string(field_of_view.vertical) + " rad must be in (0, pi)");
  }
  PinholeIntrinsics intrinsics;
  intrinsics.width = width;
  intrinsics.height = height;
  // The angle spans the outer edges of the edge pixels: half the image is width / 2 pixels from the centre.
  intrinsics.fx = 0.5 * width / std::tan(0.5 * field_of_view.horizontal);
  intrinsics.fy = 0.5 * height / std::tan(0.5 * field_of_view.vertical);
  intrinsics.cx = 0.5 * (width - 1);
  intrinsics.cy = 0.5 * (height - 1);
  return intrinsics;
}

FieldOfViewAngles fieldOfViewOf(const PinholeIntrinsics& intrinsics)
{
  return { 2.0 * std::atan(0.5 * intrinsics.width / intrinsics.fx),
           2.0 * std::atan(0.5 * intrinsics.height / intrinsics.fy) };
}

Eigen::Vector3d rayThroughPixel(const PinholeIntrinsics& intrinsics, double u, double v)
{
  return Eigen::Vector3d((u - intrinsics.cx) / intrinsics.fx, (v - intrinsics.cy) / intrinsics.fy, 1.0).normalized();
}

bool pixelOf(const PinholeIntrinsics& intrinsics, const Eigen::Vector3d& ray_in_optical, double& u, double& v)
{
  if (!(ray_in_optical.z() > 0.0))
  {
    return false;
  }
  u = intrinsics.cx + intrinsics.fx * ray_in_optical.x() / ray_in_optical.z();
  v = intrinsics.cy + intrinsics.fy * ray_in_optical.y() / ray_in_optical.z();
  return true;
}

Eigen::Vector3d opticalToCameraLink(const Eigen::Vector3d& in_optical)
{
  // Optical z (forward) is the link's x, optical x (right) its -y, optical y (down) its -z.
  return { in_optical.z(), -in_optical.x(), -in_optical.y() };
}

Eigen::Vector3d cameraLinkToOptical(const Eigen::Vector3d& in_camera_link)
{
  return { -in_camera_link.y(), -in_camera_link.z(), in_camera_link.x() };
}

}  // namespace ptz_action_server

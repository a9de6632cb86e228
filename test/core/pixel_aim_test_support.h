/**
 * \file
 * \brief What the pixel-aiming tests share: the shipped URDF, a device's limits, and projecting a point into an image.
 */
#pragma once

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/motion/pinhole_view.h"
#include "ptz_action_server/core/types.h"

namespace pixel_aim_test
{
using ptz_action_server::AxisRange;
using ptz_action_server::Capabilities;
using ptz_action_server::PinholeIntrinsics;
using ptz_action_server::PtzKinematics;

constexpr double DEGREE = M_PI / 180.0;
constexpr int WIDTH = 640;
constexpr int HEIGHT = 360;

/// urdf/ptz.urdf: the camera link 0.09 m ahead of the tilt axis, 0.12 m above the base.
inline PtzKinematics shippedKinematics()
{
  std::ifstream file(std::string(PTZ_SOURCE_DIR) + "/urdf/ptz.urdf");
  std::stringstream text;
  text << file.rdbuf();
  return PtzKinematics::fromUrdf(text.str());
}

/// A camera that goes to every pan and tilt of the contract and zooms from 1 to \p max_zoom X.
inline Capabilities zoomCamera(double max_zoom = 30.0)
{
  Capabilities capabilities;
  capabilities.axes[ptz_action_server::PAN] = ptz_action_server::fullAxis(AxisRange{ -M_PI, M_PI }, 1.0, 0.0);
  capabilities.axes[ptz_action_server::TILT] = ptz_action_server::fullAxis(AxisRange{ -M_PI / 2, M_PI / 2 }, 1.0, 0.0);
  capabilities.axes[ptz_action_server::ZOOM] = ptz_action_server::fullAxis(AxisRange{ 1.0, max_zoom }, 5.0, 0.0);
  return capabilities;
}

/// Where \p camera (a camera link's pose in the base frame) sees \p point with \p intrinsics; false if behind it.
inline bool project(const Eigen::Isometry3d& camera, const PinholeIntrinsics& intrinsics, const Eigen::Vector3d& point,
                    double& u, double& v)
{
  return ptz_action_server::pixelOf(
      intrinsics, ptz_action_server::cameraLinkToOptical(Eigen::Vector3d(camera.inverse() * point)), u, v);
}

/// The angle (rad) between the optical axis of \p camera and the direction from it to \p point.
inline double offAxis(const Eigen::Isometry3d& camera, const Eigen::Vector3d& point)
{
  const Eigen::Vector3d in_camera = camera.inverse() * point;
  return std::atan2(in_camera.tail<2>().norm(), in_camera.x());
}

}  // namespace pixel_aim_test

/**
 * \file
 * \brief The pinhole camera of an image: intrinsics from a field of view, a pixel's ray and a ray's pixel.
 *
 * One model for everything that maps between pixels and directions (the simulated camera's renderer, its camera_info,
 * aiming at a pixel), so that what is drawn at a pixel is what a click on that pixel aims at.
 */
#pragma once

#include <Eigen/Geometry>

#include "ptz_action_server/core/motion/field_of_view.h"

namespace ptz_action_server
{
/// A distortion-free pinhole camera in pixel-index coordinates: pixel (0, 0) is the centre of the top-left pixel.
struct PinholeIntrinsics
{
  int width = 0;    ///< px
  int height = 0;   ///< px
  double fx = 0.0;  ///< px
  double fy = 0.0;  ///< px
  double cx = 0.0;  ///< px, principal point
  double cy = 0.0;  ///< px
};

/// The intrinsics of a \p width x \p height image spanning \p field_of_view, principal point at the image's centre
/// ((width - 1) / 2, (height - 1) / 2). Throws ConfigError unless the size is positive and the angles in (0, pi).
PinholeIntrinsics intrinsicsFor(const FieldOfViewAngles& field_of_view, int width, int height);

/// The field of view (full angles, rad) that \p intrinsics span, edge to edge of its pixels.
FieldOfViewAngles fieldOfViewOf(const PinholeIntrinsics& intrinsics);

/// Unit ray through pixel (\p u, \p v) in the optical frame (REP-103 optical: z forward, x right, y down).
Eigen::Vector3d rayThroughPixel(const PinholeIntrinsics& intrinsics, double u, double v);

/// The pixel (\p u, \p v) a ray in the optical frame goes through. False (u, v untouched) if it points behind the
/// image plane; the pixel may lie outside the image.
bool pixelOf(const PinholeIntrinsics& intrinsics, const Eigen::Vector3d& ray_in_optical, double& u, double& v);

/// A direction in the optical frame expressed in the camera link's axes (REP-103: x forward, y left, z up).
Eigen::Vector3d opticalToCameraLink(const Eigen::Vector3d& in_optical);

/// A direction in the camera link's axes expressed in the optical frame.
Eigen::Vector3d cameraLinkToOptical(const Eigen::Vector3d& in_camera_link);

}  // namespace ptz_action_server

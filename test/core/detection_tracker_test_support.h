/**
 * \file
 * \brief What the detection-tracking tests share: the sim's lens, a camera that sees a target and reports a box of it
 * in its image, and a pose history of where it looked.
 */
#pragma once

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "pixel_aim_test_support.h"
#include "ptz_action_server/core/motion/detection_tracker.h"
#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/motion/pinhole_view.h"
#include "ptz_action_server/core/motion/pose_history.h"

namespace detection_tracker_test
{
using pixel_aim_test::HEIGHT;
using pixel_aim_test::WIDTH;
using ptz_action_server::AxisValues;
using ptz_action_server::HeaderStamp;
using ptz_action_server::ImageDetection;
using ptz_action_server::ImageDetections;
using ptz_action_server::PinholeIntrinsics;
using ptz_action_server::PixelCamera;
using ptz_action_server::PtzKinematics;

/// The sim's lens: 60 degrees across at zoom 1, square pixels at 640x360.
inline const ptz_action_server::FieldOfViewModel& simLens()
{
  static const ptz_action_server::FieldOfViewModel model = ptz_action_server::FieldOfViewModel::fromWideEnd(
      { M_PI / 3.0, 2.0 * std::atan(std::tan(M_PI / 6.0) * HEIGHT / WIDTH) });
  return model;
}

inline PixelCamera simCamera()
{
  PixelCamera camera;
  camera.field_of_view = &simLens();
  return camera;
}

/// A header stamp \p seconds after an epoch of 1000 s (a header clock far from 0, as ros::Time is).
inline HeaderStamp stampAt(double seconds)
{
  return ptz_action_server::headerStampFromSeconds(1000.0 + seconds);
}

/// A point \p distance m from the base's origin in the direction \p azimuth, \p elevation (the contract's pan and
/// tilt that look there).
inline Eigen::Vector3d pointAt(double azimuth, double elevation, double distance = 50.0)
{
  return distance * ptz_action_server::directionOf(azimuth, elevation);
}

/// The intrinsics of a \p WIDTH x \p HEIGHT image at \p zoom through the sim's lens.
inline PinholeIntrinsics viewAt(double zoom)
{
  return ptz_action_server::intrinsicsFor(simLens().at(zoom), WIDTH, HEIGHT);
}

/**
 * \brief The box a detector finds around \p point (a ball of angular radius \p radius) in the image of a camera at
 * \p pose; false if it is not in the image.
 */
inline bool detect(const PtzKinematics& kinematics, const AxisValues& pose, const Eigen::Vector3d& point, double radius,
                   ImageDetection& detection)
{
  const PinholeIntrinsics view = viewAt(pose[ptz_action_server::ZOOM]);
  double u = 0.0;
  double v = 0.0;
  if (!pixel_aim_test::project(kinematics.cameraInBase(pose[ptz_action_server::PAN], pose[ptz_action_server::TILT]),
                               view, point, u, v) ||
      u < -0.5 || u > WIDTH - 0.5 || v < -0.5 || v > HEIGHT - 0.5)
  {
    return false;
  }
  detection.u = u;
  detection.v = v;
  detection.width = 2.0 * view.fx * std::tan(radius);
  detection.height = 2.0 * view.fy * std::tan(radius);
  return true;
}

/// An image at \p stamp with \p detections.
inline ImageDetections imageOf(HeaderStamp stamp, std::initializer_list<ImageDetection> detections)
{
  ImageDetections image;
  image.stamp = stamp;
  image.width = WIDTH;
  image.height = HEIGHT;
  image.detections = detections;
  return image;
}

/// A detection of \p id with \p score at (\p u, \p v), a \p size px square box.
inline ImageDetection boxAt(const std::string& id, double score, double u, double v, double size = 20.0)
{
  ImageDetection detection;
  detection.id = id;
  detection.score = score;
  detection.u = u;
  detection.v = v;
  detection.width = size;
  detection.height = size;
  return detection;
}

/// The angle (rad) between where a camera at \p pose looks and the direction from it to \p point.
inline double offAxis(const PtzKinematics& kinematics, const AxisValues& pose, const Eigen::Vector3d& point)
{
  return pixel_aim_test::offAxis(kinematics.cameraInBase(pose[ptz_action_server::PAN], pose[ptz_action_server::TILT]),
                                 point);
}

}  // namespace detection_tracker_test

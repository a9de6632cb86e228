/**
 * \file
 * \brief A gimbal attitude as MAVLink carries it (a quaternion, FRD) and the pan and tilt it points the camera at.
 */
#pragma once

#include <array>

namespace ptz_action_server
{
namespace mavlink
{
/// A rotation, w first (MAVLink's order).
using Quaternion = std::array<float, 4>;

/// Pan (yaw, positive right) and tilt (pitch, positive up) of a gimbal attitude, rad.
struct PanTilt
{
  double pan = 0.0;
  double tilt = 0.0;
};

/// The attitude with roll 0, yaw \p pan and pitch \p tilt (FRD: yaw about z down, pitch about y right).
Quaternion quaternionFromPanTilt(double pan, double tilt);
/**
 * \brief Yaw and pitch of the camera's optical axis (body x) under \p q, from the axis itself rather than from
 * Euler angles, so they stay exact near pitch -90 degrees (a gimbal looking straight down); exactly there, the yaw
 * comes from the camera's right axis. The quaternion need not be normalised.
 */
PanTilt panTiltFromQuaternion(const Quaternion& q);

}  // namespace mavlink
}  // namespace ptz_action_server

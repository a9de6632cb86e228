#include "ptz_action_server/core/mavlink/mavlink_quaternion.h"

#include <cmath>

namespace ptz_action_server
{
namespace mavlink
{
Quaternion quaternionFromPanTilt(double pan, double tilt)
{
  const double cy = std::cos(pan / 2.0), sy = std::sin(pan / 2.0);
  const double cp = std::cos(tilt / 2.0), sp = std::sin(tilt / 2.0);
  // q_yaw(z) * q_pitch(y), FRD: (cos p cos y, -sin p sin y, sin p cos y, cos p sin y).
  return Quaternion{ { static_cast<float>(cp * cy), static_cast<float>(-sp * sy), static_cast<float>(sp * cy),
                       static_cast<float>(cp * sy) } };
}

PanTilt panTiltFromQuaternion(const Quaternion& q)
{
  double w = q[0], x = q[1], y = q[2], z = q[3];
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  if (norm > 0.0)
  {
    w /= norm;
    x /= norm;
    y /= norm;
    z /= norm;
  }
  // The optical axis is body x; the rotation's first column.
  const double forward_x = 1.0 - 2.0 * (y * y + z * z);
  const double forward_y = 2.0 * (x * y + w * z);
  const double forward_z = 2.0 * (x * z - w * y);
  const double horizontal = std::hypot(forward_x, forward_y);
  PanTilt result;
  result.tilt = std::atan2(-forward_z, horizontal);  // z points down: up is -z
  if (horizontal > 1e-3)  // below: float noise in q would swing the yaw (1e-3 is 0.06 degrees from vertical)
  {
    result.pan = std::atan2(forward_y, forward_x);
  }
  else
  {
    // Straight up or down: the right axis (body y, the second column) still points where the yaw does.
    const double right_x = 2.0 * (x * y - w * z);
    const double right_y = 1.0 - 2.0 * (x * x + z * z);
    result.pan = std::atan2(-right_x, right_y);
  }
  return result;
}

}  // namespace mavlink
}  // namespace ptz_action_server

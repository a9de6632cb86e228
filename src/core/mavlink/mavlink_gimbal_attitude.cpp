/**
 * \file
 * \brief MavlinkGimbalProtocol: the gimbal's attitude, its yaw read in the frame it is really in, and the vehicle's
 * heading that relates the frames.
 */
#include <cmath>

#include "mavlink_gimbal_internal.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/core/mavlink/mavlink_vehicle_messages.h"

namespace ptz_action_server
{
namespace
{
using namespace mavlink;
using namespace mavlink_gimbal_detail;

/// s a vehicle heading stays good to convert a yaw with.
constexpr double VEHICLE_YAW_MAX_AGE = 1.0;

double wrapGimbalAngle(double angle)
{
  return std::remainder(angle, 2.0 * M_PI);
}
}  // namespace

// ---------------------------------------------------------------- the attitude

bool MavlinkGimbalProtocol::isOurAttitude(const Frame& frame, const GimbalDeviceAttitudeStatus& attitude) const
{
  if (!chosen_ || frame.header.system_id != gimbal_.system_id)
  {
    return false;
  }
  const std::uint8_t sender = frame.header.component_id;
  const std::uint8_t id = attitude.gimbal_device_id;
  if (gimbal_.device_id == 0 || isInternalGimbalId(gimbal_.device_id))
  {
    // A gimbal inside its manager: the manager's component sends its attitude with its id.
    return sender == gimbal_.manager_component && namesOurGimbal(id);
  }
  // A MAVLink gimbal device sends its own, with 0 (the protocol's value; its own id is taken too); a manager that
  // relays it names it.
  return (sender == gimbal_.device_id && (id == 0 || id == gimbal_.device_id)) ||
         (sender == gimbal_.manager_component && id == gimbal_.device_id);
}

void MavlinkGimbalProtocol::handleAttitude(const Frame& frame, const GimbalDeviceAttitudeStatus& attitude)
{
  if (!chosen_)
  {
    return;  // no gimbal of ours yet
  }
  if (!isOurAttitude(frame, attitude))
  {
    ++counters_.other_attitudes;
    return;
  }
  const PanTilt angles = panTiltFromQuaternion(attitude.q);
  const bool earth = attitudeInEarthFrame(attitude);
  attitude_frame_ = earth ? 1 : 0;
  double pan = angles.pan;
  if (earth != settings_.yaw_lock)
  {
    // delta_yaw relates the frames (North = vehicle + delta_yaw); PX4 never fills it (0), nor do devices from before
    // it existed (NaN, or 0 when cut off the wire): then the heading of the vehicle's ATTITUDE.
    double delta = 0.0;
    if (std::isfinite(attitude.delta_yaw) && (attitude.delta_yaw != 0.0f || !px4GimbalOutput(attitude)))
    {
      delta = attitude.delta_yaw;
    }
    else if (vehicle_yaw_known_ && !due(vehicle_yaw_at_, VEHICLE_YAW_MAX_AGE))
    {
      delta = vehicle_yaw_;
    }
    else
    {
      ++counters_.unusable_attitudes;  // nothing to relate the frames: the state stays the last one
      return;
    }
    pan += earth ? -delta : delta;
  }
  ++counters_.attitudes;
  session_.reportState(AxisValues{ { wrapGimbalAngle(pan), angles.tilt, 1.0 } });
}

bool MavlinkGimbalProtocol::px4GimbalOutput(const GimbalDeviceAttitudeStatus& attitude) const
{
  const auto manager = heard_.find(componentKey(gimbal_.system_id, gimbal_.manager_component));
  return manager != heard_.end() && manager->second.autopilot == MAV_AUTOPILOT_PX4 &&
         isInternalGimbalId(attitude.gimbal_device_id);
}

bool MavlinkGimbalProtocol::attitudeInEarthFrame(const GimbalDeviceAttitudeStatus& attitude) const
{
  switch (settings_.attitude_yaw_frame)
  {
    case MavlinkYawFrame::VEHICLE:
      return false;
    case MavlinkYawFrame::EARTH:
      return true;
    case MavlinkYawFrame::AUTO:
      if ((attitude.flags & (gimbal_flags::YAW_IN_EARTH_FRAME | gimbal_flags::YAW_IN_VEHICLE_FRAME)) == 0 &&
          px4GimbalOutput(attitude))
      {
        return false;  // PX4's gimbal module: YAW_LOCK on every attitude, angles relative to the vehicle
      }
      break;
    case MavlinkYawFrame::FLAGS:
      break;
  }
  // The frame flags say, or (before those flags existed) YAW_LOCK means North.
  return yawInEarthFrame(attitude.flags);
}

void MavlinkGimbalProtocol::handleVehicleAttitude(const Frame& frame)
{
  // The heading of the gimbal's vehicle, from its autopilot.
  if (!chosen_ || frame.header.system_id != gimbal_.system_id || frame.header.component_id != MAV_COMP_ID_AUTOPILOT1)
  {
    return;
  }
  const Attitude attitude = decode<Attitude>(frame);
  if (std::isfinite(attitude.yaw))
  {
    vehicle_yaw_ = attitude.yaw;
    vehicle_yaw_at_ = session_.now();
    vehicle_yaw_known_ = true;
  }
}

}  // namespace ptz_action_server

/**
 * \file
 * \brief MavlinkGimbalEmulator: what its components send, on their own (heartbeats, manager statuses, attitudes on
 * the port's tick) and when asked. What they receive is in mavlink_gimbal_emulator.cpp, what the managers do with
 * commands and setpoints in mavlink_gimbal_emulator_commands.cpp.
 */
#include <cmath>

#include "mavlink_gimbal_emulator_internal.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
using namespace mavlink_emulator;

template <class Message>
void MavlinkGimbalEmulator::send(std::uint8_t component, const Message& message)
{
  // With mutex_ held.
  if (silent())
  {
    return;
  }
  const EncodedFrame frame = encode(FrameHeader{ sequence_++, config_.system_id, component }, message);
  port_->send(frame.data(), frame.size);  // udp: to the controller, once one has sent something
}
// The commands' acknowledgements go out from mavlink_gimbal_emulator_commands.cpp.
template void MavlinkGimbalEmulator::send<CommandAck>(std::uint8_t component, const CommandAck& message);

void MavlinkGimbalEmulator::tick()
{
  const TimePoint now = clock_->now();
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& gimbal : gimbals_)
  {
    if (gimbal->rates_active && now >= gimbal->rates_until)
    {
      gimbal->rates_active = false;
      ++counters_.rate_timeouts;
      gimbal->model.stop(now);
    }
  }
  if (secondsBetween(heartbeat_at_, now) >= config_.heartbeat_period)
  {
    heartbeat_at_ = now;
    for (std::uint8_t component : components_)
    {
      Heartbeat heartbeat;
      const bool autopilot = component == MAV_COMP_ID_AUTOPILOT1;
      heartbeat.type = autopilot ? MAV_TYPE_QUADROTOR : MAV_TYPE_GIMBAL;
      heartbeat.autopilot = !autopilot              ? MAV_AUTOPILOT_INVALID :
                            config_.v1_mount_status ? MAV_AUTOPILOT_ARDUPILOTMEGA :
                                                      MAV_AUTOPILOT_PX4;
      send(component, heartbeat);
    }
  }
  if (secondsBetween(status_at_, now) >= config_.status_period && !config_.gimbal_v1)
  {
    status_at_ = now;
    for (const auto& gimbal : gimbals_)
    {
      sendStatus(*gimbal);
    }
  }
  for (const auto& gimbal : gimbals_)
  {
    if (gimbal->attitude_interval > 0.0 && secondsBetween(gimbal->attitude_at, now) >= gimbal->attitude_interval)
    {
      sendAttitude(*gimbal, now);
    }
  }
}

void MavlinkGimbalEmulator::sendStatus(const Gimbal& gimbal)
{
  GimbalManagerStatus status;
  status.time_boot_ms = millisecondsOf(clock_->now());
  status.gimbal_device_id = gimbal.device_id;
  status.primary_control_sysid = gimbal.primary_system;
  status.primary_control_compid = gimbal.primary_component;
  send(gimbal.manager, status);
}

void MavlinkGimbalEmulator::sendInformation(const Gimbal& gimbal)
{
  GimbalManagerInformation information;
  information.time_boot_ms = millisecondsOf(clock_->now());
  information.cap_flags = CAPABILITIES;
  information.roll_min = information.roll_max = 0.0f;  // no roll axis
  information.pitch_min = static_cast<float>(gimbal.device.axes[TILT].range.min);
  information.pitch_max = static_cast<float>(gimbal.device.axes[TILT].range.max);
  information.yaw_min = static_cast<float>(gimbal.device.axes[PAN].range.min);
  information.yaw_max = static_cast<float>(gimbal.device.axes[PAN].range.max);
  information.gimbal_device_id = gimbal.device_id;
  send(gimbal.manager, information);
}

void MavlinkGimbalEmulator::sendAttitude(Gimbal& gimbal, TimePoint now)
{
  gimbal.attitude_at = now;
  const PtzSample state = gimbal.model.sample(now);
  if (config_.gimbal_v1)
  {
    sendMountAttitude(gimbal, state, now);
    return;
  }
  if (config_.px4_gimbal_output)
  {
    sendPx4Attitude(gimbal, state, now);
    return;
  }
  GimbalDeviceAttitudeStatus attitude;
  attitude.time_boot_ms = millisecondsOf(now);
  const double yaw = state.position[PAN] + (config_.report_earth_frame ? config_.vehicle_yaw : 0.0);
  attitude.q = quaternionFromPanTilt(yaw, state.position[TILT]);
  attitude.angular_velocity_x = 0.0f;
  attitude.angular_velocity_y = static_cast<float>(state.velocity[TILT]);
  attitude.angular_velocity_z = static_cast<float>(state.velocity[PAN]);
  attitude.flags = static_cast<std::uint16_t>(config_.report_earth_frame ? gimbal_flags::YAW_IN_EARTH_FRAME :
                                                                           gimbal_flags::YAW_IN_VEHICLE_FRAME);
  attitude.delta_yaw = static_cast<float>(config_.vehicle_yaw);
  // 1..6 when the manager's component sends it for a gimbal inside it; 0 from a gimbal device's own component.
  attitude.gimbal_device_id = gimbal.separate() ? 0 : gimbal.device_id;
  for (unsigned copy = 0; copy < floodCopies(); ++copy)
  {
    send(gimbal.attitudeComponent(), attitude);
  }
}

void MavlinkGimbalEmulator::sendMountAttitude(const Gimbal& gimbal, const PtzSample& state, TimePoint now)
{
  if (config_.v1_mount_status)
  {
    MountStatus status;  // centidegrees: pitch, roll, yaw
    status.pointing_a = static_cast<std::int32_t>(std::lround(toDegrees(state.position[TILT]) * 100.0));
    status.pointing_c = static_cast<std::int32_t>(std::lround(toDegrees(state.position[PAN]) * 100.0));
    send(gimbal.manager, status);
    return;
  }
  MountOrientation orientation;
  orientation.time_boot_ms = millisecondsOf(now);
  orientation.pitch = static_cast<float>(toDegrees(state.position[TILT]));
  orientation.yaw = static_cast<float>(toDegrees(state.position[PAN]));
  orientation.yaw_absolute = static_cast<float>(toDegrees(state.position[PAN] + config_.vehicle_yaw));
  send(gimbal.manager, orientation);
}

void MavlinkGimbalEmulator::sendPx4Attitude(const Gimbal& gimbal, const PtzSample& state, TimePoint now)
{
  // As PX4's gimbal module: the output angles (relative to the vehicle), the same flags every time, no delta_yaw.
  GimbalDeviceAttitudeStatus attitude;
  attitude.time_boot_ms = millisecondsOf(now);
  attitude.q = quaternionFromPanTilt(state.position[PAN], state.position[TILT]);
  attitude.flags = static_cast<std::uint16_t>(gimbal_flags::NEUTRAL | gimbal_flags::ROLL_LOCK |
                                              gimbal_flags::PITCH_LOCK | gimbal_flags::YAW_LOCK);
  attitude.delta_yaw = 0.0f;
  attitude.delta_yaw_velocity = 0.0f;
  attitude.gimbal_device_id = gimbal.device_id;
  Attitude vehicle;  // PX4 streams the vehicle's ATTITUDE on every link
  vehicle.time_boot_ms = attitude.time_boot_ms;
  vehicle.yaw = static_cast<float>(config_.vehicle_yaw);
  for (unsigned copy = 0; copy < floodCopies(); ++copy)
  {
    send(gimbal.attitudeComponent(), attitude);
    send(MAV_COMP_ID_AUTOPILOT1, vehicle);
  }
}

}  // namespace ptz_action_server

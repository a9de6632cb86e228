/**
 * \file
 * \brief What else a vehicle says that the gimbal client listens to: its heading (ATTITUDE), and the messages of the
 * old gimbal protocol (v1: MOUNT_STATUS, MOUNT_ORIENTATION) by which an autopilot without a gimbal manager is known.
 * Ids, CRC_EXTRA and lengths as MAVLink's common.xml (and ardupilotmega.xml for MOUNT_STATUS) give them.
 */
#pragma once

#include "ptz_action_server/core/mavlink/mavlink_messages.h"

namespace ptz_action_server
{
namespace mavlink
{
namespace message_id
{
constexpr std::uint32_t ATTITUDE = 30;
constexpr std::uint32_t MOUNT_STATUS = 158;       ///< gimbal protocol v1 (ardupilotmega.xml)
constexpr std::uint32_t MOUNT_ORIENTATION = 265;  ///< gimbal protocol v1 (common.xml, deprecated)
}  // namespace message_id

/// MAV_AUTOPILOT values of the autopilots this client tells apart.
constexpr std::uint8_t MAV_AUTOPILOT_ARDUPILOTMEGA = 3;
constexpr std::uint8_t MAV_AUTOPILOT_PX4 = 12;

/// The vehicle's attitude: its yaw is the heading between the vehicle frame and North.
struct Attitude
{
  static constexpr std::uint32_t ID = message_id::ATTITUDE;
  std::uint32_t time_boot_ms = 0;
  float roll = 0.0f, pitch = 0.0f, yaw = 0.0f;                 ///< rad; yaw from North, positive clockwise
  float rollspeed = 0.0f, pitchspeed = 0.0f, yawspeed = 0.0f;  ///< rad/s

  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.time_boot_ms);
    visit(4, self.roll);
    visit(8, self.pitch);
    visit(12, self.yaw);
    visit(16, self.rollspeed);
    visit(20, self.pitchspeed);
    visit(24, self.yawspeed);
  }
};

/// Gimbal protocol v1: a mount's orientation in degrees.
struct MountOrientation
{
  static constexpr std::uint32_t ID = message_id::MOUNT_ORIENTATION;
  std::uint32_t time_boot_ms = 0;
  float roll = 0.0f, pitch = 0.0f, yaw = 0.0f;  ///< deg; yaw relative to the vehicle
  float yaw_absolute = UNSET;                   ///< deg from North (extension)

  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.time_boot_ms);
    visit(4, self.roll);
    visit(8, self.pitch);
    visit(12, self.yaw);
    visit(16, self.yaw_absolute);
  }
};

/// Gimbal protocol v1 (ArduPilot): a mount's pointing in centidegrees.
struct MountStatus
{
  static constexpr std::uint32_t ID = message_id::MOUNT_STATUS;
  std::int32_t pointing_a = 0;  ///< pitch, cdeg
  std::int32_t pointing_b = 0;  ///< roll, cdeg
  std::int32_t pointing_c = 0;  ///< yaw, cdeg
  std::uint8_t target_system = 0;
  std::uint8_t target_component = 0;
  std::uint8_t mount_mode = 0;  ///< MAV_MOUNT_MODE (extension)

  template <class Self, class Visitor>
  static void fields(Self& self, Visitor& visit)
  {
    visit(0, self.pointing_a);
    visit(4, self.pointing_b);
    visit(8, self.pointing_c);
    visit(12, self.target_system);
    visit(13, self.target_component);
    visit(14, self.mount_mode);
  }
};

}  // namespace mavlink
}  // namespace ptz_action_server

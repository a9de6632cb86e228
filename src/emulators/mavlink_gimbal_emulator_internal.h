/**
 * \file
 * \brief What the MAVLink gimbal emulator's sources share: protocol constants, and one gimbal with its manager's state
 * for it.
 */
#pragma once

#include <chrono>

#include "ptz_action_server/core/mavlink/mavlink_vehicle_messages.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

namespace ptz_action_server
{
namespace mavlink_emulator
{
using namespace mavlink;

constexpr float UNCHANGED = -1.0f;
constexpr float MANAGER_ITSELF = -2.0f;
constexpr float RELEASE = -3.0f;
/// GIMBAL_MANAGER_CAP_FLAGS of a two-axis gimbal that goes to neutral, follows or locks pitch and yaw.
constexpr std::uint32_t CAPABILITIES =
    gimbal_caps::HAS_NEUTRAL | gimbal_caps::HAS_PITCH_AXIS | gimbal_caps::HAS_PITCH_FOLLOW |
    gimbal_caps::HAS_PITCH_LOCK | gimbal_caps::HAS_YAW_AXIS | gimbal_caps::HAS_YAW_FOLLOW | gimbal_caps::HAS_YAW_LOCK;
constexpr std::uint8_t MAV_TYPE_QUADROTOR = 2;

inline std::uint32_t millisecondsOf(TimePoint at)
{
  return static_cast<std::uint32_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(at.time_since_epoch()).count());
}
}  // namespace mavlink_emulator

/// One gimbal and its manager's state for it.
struct MavlinkGimbalEmulator::Gimbal
{
  Gimbal(const MavlinkEmulatedGimbal& config, std::uint8_t manager, double attitude_interval, TimePoint now)
    : device_id(config.device_id)
    , manager(manager)
    , device(config.device)
    , model(config.device, now)
    , attitude_interval(attitude_interval)
  {
  }
  /// A MAVLink gimbal device of its own (not inside its manager's component).
  bool separate() const
  {
    return !mavlink::isInternalGimbalId(device_id);
  }
  /// The component that sends its attitude.
  std::uint8_t attitudeComponent() const
  {
    return separate() ? device_id : manager;
  }

  const std::uint8_t device_id;
  const std::uint8_t manager;
  const SimDeviceConfig device;
  SimDeviceModel model;
  std::uint8_t primary_system = 0;
  std::uint8_t primary_component = 0;
  bool control_kept = false;  ///< another controller holds control and refuses to give it up
  double attitude_interval;
  TimePoint attitude_at{};
  bool rates_active = false;
  TimePoint rates_until{};
};

}  // namespace ptz_action_server

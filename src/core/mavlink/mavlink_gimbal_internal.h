/**
 * \file
 * \brief What the sources of MavlinkGimbalProtocol share: the keys of its maps.
 */
#pragma once

#include <cstdint>

#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"

namespace ptz_action_server
{
namespace mavlink_gimbal_detail
{
/// An index of a component.
inline std::uint16_t componentKey(std::uint8_t system_id, std::uint8_t component_id)
{
  return static_cast<std::uint16_t>(system_id << 8 | component_id);
}

inline std::uint32_t gimbalKey(const MavlinkGimbalAddress& address)
{
  return static_cast<std::uint32_t>(address.system_id) << 16 |
         static_cast<std::uint32_t>(address.manager_component) << 8 | address.device_id;
}
}  // namespace mavlink_gimbal_detail
}  // namespace ptz_action_server

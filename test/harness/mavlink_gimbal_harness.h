/**
 * \file
 * \brief The MAVLink gimbal harness: MavlinkGimbalEmulator (gimbal managers and devices) over UDP or a
 * pseudo-terminal, the mavlink_gimbal backend with no gimbal named (the only one found is chosen).
 */
#pragma once

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

namespace ptz_action_server
{
class MavlinkGimbalHarness
  : public PushHarness<MavlinkGimbalEmulator, MavlinkGimbalEmulatorConfig, MavlinkGimbalProtocol>
{
public:
  explicit MavlinkGimbalHarness(MavlinkGimbalEmulatorConfig emulator, DeviceConfig<MavlinkGimbalProtocol> backend = {})
    : PushHarness(emulator, std::move(backend), emulator.transport == LinkKind::SERIAL, "mavlink")
  {
  }

  /// The first gimbal's state.
  PtzSample deviceState() const override
  {
    return emulator_->gimbal();
  }
  void setFaults(const SimFaults& faults) override
  {
    emulator_->setFaults(faults);
  }
};

}  // namespace ptz_action_server

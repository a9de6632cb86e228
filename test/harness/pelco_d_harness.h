/**
 * \file
 * \brief The Pelco-D harness: PelcoDEmulator on a pseudo-terminal (RS-485) or a TCP server (a serial-to-Ethernet
 * server), the pelco_d backend at its address and tilt encoding.
 */
#pragma once

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

namespace ptz_action_server
{
class PelcoDHarness : public LineHarness<PelcoDEmulator, PelcoDEmulatorConfig, PelcoProtocol>
{
public:
  explicit PelcoDHarness(PelcoDEmulatorConfig emulator, DeviceConfig<PelcoProtocol> backend = {})
    : LineHarness(std::move(emulator), std::move(backend), "pelco")
  {
    config_.settings.address = emulator_config_.address;
    config_.settings.tilt_encoding = emulator_config_.tilt_encoding;
  }
};

}  // namespace ptz_action_server

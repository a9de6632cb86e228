/**
 * \file
 * \brief The VISCA harness: ViscaEmulator on a pseudo-terminal, raw over TCP, or over UDP (raw or with Sony's VISCA
 * over IP header), the visca backend at its address, model and framing.
 */
#pragma once

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/emulators/visca_emulator.h"

namespace ptz_action_server
{
class ViscaHarness : public LineHarness<ViscaEmulator, ViscaEmulatorConfig, ViscaProtocol>
{
public:
  explicit ViscaHarness(ViscaEmulatorConfig emulator, DeviceConfig<ViscaProtocol> backend = {})
    : LineHarness(std::move(emulator), std::move(backend), "visca")
  {
    config_.settings.address = emulator_config_.address;
    config_.settings.framing = emulator_config_.framing;
    config_.settings.model = emulator_config_.model;
  }
};

}  // namespace ptz_action_server

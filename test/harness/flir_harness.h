/**
 * \file
 * \brief The FLIR PTU's harness: FlirPtuEmulator on a pseudo-terminal or a TCP server (E-series), the flir backend.
 */
#pragma once

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"

namespace ptz_action_server
{
class FlirHarness : public LineHarness<FlirPtuEmulator, FlirPtuEmulatorConfig, FlirProtocol>
{
public:
  explicit FlirHarness(FlirPtuEmulatorConfig emulator, DeviceConfig<FlirProtocol> backend = {})
    : LineHarness(std::move(emulator), std::move(backend), "flir")
  {
  }
};

}  // namespace ptz_action_server

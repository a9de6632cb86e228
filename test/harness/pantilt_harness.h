/**
 * \file
 * \brief The PanTilt harness: PanTiltEmulator over UDP or in SLIP frames on a pseudo-terminal, the pantilt backend
 * in its wire format.
 */
#pragma once

#include <algorithm>

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"

namespace ptz_action_server
{
class PanTiltHarness : public PushHarness<PanTiltEmulator, PanTiltEmulatorConfig, PanTiltProtocol>
{
public:
  explicit PanTiltHarness(PanTiltEmulatorConfig emulator, DeviceConfig<PanTiltProtocol> backend = {})
    : PushHarness(emulator, std::move(backend), emulator.serial, "pantilt")
  {
    config_.settings.format = emulator_config_.format;
  }

  /// The controller reports as soon as it knows its peer, so the link can come up on the first speed frame, before
  /// the emulator reads the rest; the state request that ends the start-up has arrived once the rest has.
  bool startupReceived() const override
  {
    const std::vector<ClassifiedCommand> received = commands();
    return std::any_of(received.begin(), received.end(),
                       [](const ClassifiedCommand& command) { return command.kind == ClassifiedCommand::Kind::QUERY; });
  }
  PtzSample deviceState() const override
  {
    return emulator_->panTilt().sample();
  }
  void setFaults(const SimFaults& faults) override
  {
    emulator_->panTilt().setFaults(faults);
  }
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief The DigiView harness: DigiViewEmulator over TCP or UDP in one message format, the digiview backend in the
 * same format and angle unit.
 */
#pragma once

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/digiview/digiview_protocol.h"
#include "ptz_action_server/emulators/digiview_emulator.h"

namespace ptz_action_server
{
class DigiViewHarness : public EmulatorHarness<DigiViewEmulator, DigiViewEmulatorConfig, DigiViewProtocol>
{
public:
  explicit DigiViewHarness(DigiViewEmulatorConfig emulator, DeviceConfig<DigiViewProtocol> backend = {})
    : EmulatorHarness(std::move(emulator), std::move(backend))
  {
    startEmulator();
    emulator_config_.port = emulator_->port();  // a restart takes the same port
    config_.link.kind = emulator_config_.transport;
    config_.link.port = emulator_config_.port;
    config_.settings.wire = emulator_config_.wire;
    config_.settings.acceleration = emulator_config_.acceleration;  // as the emulator turns
  }

  std::uint16_t port() const override
  {
    return emulator_config_.port;
  }
  std::string link() const override
  {
    return "";
  }
  void clearCommands() override
  {
    emulator_->received().clear();
  }
  /// The main view; its zoom is the backend's X (the emulator's zoom slot holds the field of view).
  PtzSample deviceState() const override
  {
    PtzSample view = emulator_->view("main", 0);
    view.position[ZOOM] = config_.settings.fov_wide / view.position[ZOOM];
    return view;
  }
  /// Every view's.
  void setFaults(const SimFaults& faults) override
  {
    emulator_->setFaults(faults);
  }
  bool setFlood(unsigned copies) override
  {
    emulator_->setFlood(copies);
    return true;
  }
  /// TCP: the connections drop; UDP: DigiView is gone.
  void breakLink() override
  {
    if (config_.link.kind == LinkKind::TCP)
    {
      emulator_->dropConnections();
      return;
    }
    emulator_.reset();
  }
  void restoreLink() override
  {
    if (!emulator_)
    {
      startEmulator();
    }
  }
  bool breaksAtOnce() const override
  {
    return config_.link.kind == LinkKind::TCP;
  }
};

}  // namespace ptz_action_server

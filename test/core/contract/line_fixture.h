/**
 * \file
 * \brief What the FLIR and Pelco-D fixtures share: an emulator on a pseudo-terminal (38400 baud) or a TCP port.
 */
#pragma once

#include <gtest/gtest.h>

#include "../line_test_support.h"
#include "device_fixtures_internal.h"
#include "ptz_action_server/emulators/ports/device_port.h"

namespace ptz_action_server
{
template <class Emulator>
class LineFixture : public DeviceFixture
{
protected:
  /// Starts the emulator on a \p kind port and fills \p link to reach it.
  template <class EmulatorConfig>
  void startEmulator(EmulatorConfig config, DevicePortConfig::Kind kind, const char* name, LinkConfig& link)
  {
    config.port.kind = kind;
    config.port.link = uniqueLink(name);
    config.port.baud = 38400;
    emulator_ = std::make_unique<Emulator>(config);
    if (kind == DevicePortConfig::Kind::TCP)
    {
      link.kind = LinkKind::TCP;
      link.port = emulator_->port().tcpPort();
    }
    else
    {
      link.path = config.port.link;
      link.baud = config.port.baud;
    }
    link_ = link;
  }

  void clearCommands() override
  {
    emulator_->received().clear();
  }
  PtzSample deviceState() const override
  {
    return emulator_->sample();
  }
  void setSilent(bool silent) override
  {
    emulator_->port().setSilent(silent);
  }
  double replyDeadline() const override
  {
    // The most the reply deadline learns beyond the exchange's wire time: twice its floor of 100 ms (reply_timeout 0).
    return 0.2;
  }
  bool setEndlessReplies(bool endless) override
  {
    emulator_->port().setEndless(endless);
    return true;
  }
  bool setFaults(const SimFaults& faults) override
  {
    emulator_->setFaults(faults);
    return true;
  }
  void breakLink() override
  {
    emulator_->unplug();
  }
  void restoreLink() override
  {
    emulator_->replug();
  }
  std::string linkLossWords() const override
  {
    return link_.kind == LinkKind::TCP ? "connection to 127.0.0.1" : link_.path;
  }

  std::unique_ptr<Emulator> emulator_;
  LinkConfig link_;
};

}  // namespace ptz_action_server

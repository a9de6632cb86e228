/**
 * \file
 * \brief The typed harnesses the protocols' harnesses build on: one emulator and one backend configuration
 * (EmulatorHarness), the emulators on a DevicePort (LineHarness: FLIR, Pelco-D, VISCA), those that push their
 * state over UDP or a serial line (PushHarness: PanTilt, MAVLink) and the IP cameras behind their HTTP server
 * (HttpCameraHarness: Axis, ONVIF).
 */
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "harness/device_harness.h"
#include "ptz_action_server/core/transport/http_link.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
/// \p Emulator (made from its \p Config) and a DeviceConfig of \p Protocol pointed at it: what every harness has.
template <class Emulator, class Config, class Protocol>
class EmulatorHarness : public DeviceHarness
{
public:
  /// The running emulator (for a fixture's expectations: a refusal, the raw log).
  Emulator& emulator() const
  {
    return *emulator_;
  }
  const Config& emulatorConfig() const
  {
    return emulator_config_;
  }
  /// The backend's configuration (a test may tighten its timing before makeBackend()).
  DeviceConfig<Protocol>& config()
  {
    return config_;
  }
  const DeviceConfig<Protocol>& config() const
  {
    return config_;
  }

  std::unique_ptr<DeviceBackend> makeBackend() const override
  {
    return makeDeviceBackend<Protocol>(config_);
  }
  std::vector<ClassifiedCommand> commands() const override
  {
    return emulator_ ? emulator_->classify() : std::vector<ClassifiedCommand>();
  }
  EmulatorFaults* faults() override
  {
    return emulator_.get();
  }

protected:
  EmulatorHarness(Config emulator, DeviceConfig<Protocol> backend)
    : emulator_config_(std::move(emulator)), config_(std::move(backend))
  {
  }
  /// Starts the emulator (again, after the device went away) as emulatorConfig() says.
  void startEmulator()
  {
    emulator_ = std::make_unique<Emulator>(emulator_config_);
  }

  Config emulator_config_;
  DeviceConfig<Protocol> config_;
  std::unique_ptr<Emulator> emulator_;
};

/**
 * \brief A line emulator (LineEmulator: FLIR PTU, Pelco-D, VISCA) on its DevicePort: a pseudo-terminal, a TCP server
 * or a UDP socket on 127.0.0.1; the backend's link reaches it there.
 */
template <class Emulator, class Config, class Protocol>
class LineHarness : public EmulatorHarness<Emulator, Config, Protocol>
{
public:
  /// \p emulator on its port (a pseudo-terminal at port.link, or at a harnessLink() of \p name where that is empty).
  LineHarness(Config emulator, DeviceConfig<Protocol> backend, const char* name)
    : EmulatorHarness<Emulator, Config, Protocol>(std::move(emulator), std::move(backend))
  {
    DevicePortConfig& port = this->emulator_config_.port;
    if (port.kind == PortKind::PTY && port.link.empty())
    {
      port.link = harnessLink(name);
    }
    this->startEmulator();
    LinkConfig& link = this->config_.link;
    if (port.kind == PortKind::PTY)
    {
      link.kind = LinkKind::SERIAL;
      link.path = port.link;
      link.baud = port.baud;
      return;
    }
    link.kind = port.kind == PortKind::TCP ? LinkKind::TCP : LinkKind::UDP;
    link.port = port.kind == PortKind::TCP ? this->emulator_->port().tcpPort() : this->emulator_->port().udpPort();
    if (port.kind == PortKind::UDP)
    {
      link.local_host = "127.0.0.1";
    }
    port.port = link.port;  // a restart takes the same port
  }

  std::uint16_t port() const override
  {
    return this->config_.link.kind == LinkKind::SERIAL ? 0 : this->config_.link.port;
  }
  std::string link() const override
  {
    return this->config_.link.kind == LinkKind::SERIAL ? this->config_.link.path : "";
  }
  void clearCommands() override
  {
    this->emulator_->received().clear();
  }
  PtzSample deviceState() const override
  {
    return this->emulator_->sample();
  }
  void setFaults(const SimFaults& faults) override
  {
    this->emulator_->setFaults(faults);
  }
  /// A pseudo-terminal's link disappears, a TCP server stops listening (LineEmulator::unplug()); on UDP the device is
  /// gone.
  void breakLink() override
  {
    if (this->emulator_config_.port.kind == PortKind::UDP)
    {
      this->emulator_.reset();
      return;
    }
    this->emulator_->unplug();
  }
  void restoreLink() override
  {
    if (!this->emulator_)
    {
      this->startEmulator();
      return;
    }
    this->emulator_->replug();
  }
  bool breaksAtOnce() const override
  {
    return this->emulator_config_.port.kind != PortKind::UDP;
  }

private:
  using PortKind = DevicePortConfig::Kind;
};

/**
 * \brief An emulator that pushes its state (PanTilt, the MAVLink gimbal) over UDP on 127.0.0.1, or on a
 * pseudo-terminal (its config's line); the backend's link reaches it there.
 */
template <class Emulator, class Config, class Protocol>
class PushHarness : public EmulatorHarness<Emulator, Config, Protocol>
{
public:
  std::uint16_t port() const override
  {
    return serial_ ? 0 : this->emulator_config_.port;
  }
  std::string link() const override
  {
    return serial_ ? this->emulator_config_.line.link : "";
  }
  void clearCommands() override
  {
    this->emulator_->received().clear();
  }
  bool setFlood(unsigned copies) override
  {
    if (serial_)
    {
      return false;  // a serial line carries what its baud rate allows: no flood
    }
    this->emulator_->setFlood(copies);
    return true;
  }
  /// The serial port vanishes; over UDP the device is gone (a controller, an autopilot rebooting).
  void breakLink() override
  {
    if (serial_)
    {
      this->emulator_->unplug();
      return;
    }
    this->emulator_.reset();
  }
  void restoreLink() override
  {
    if (serial_)
    {
      this->emulator_->replug();
    }
    else if (!this->emulator_)
    {
      this->startEmulator();
    }
  }
  bool breaksAtOnce() const override
  {
    return serial_;
  }

protected:
  /// \p emulator over UDP, or (\p serial) on a pseudo-terminal at line.link (a harnessLink() of \p name if empty).
  PushHarness(Config emulator, DeviceConfig<Protocol> backend, bool serial, const char* name)
    : EmulatorHarness<Emulator, Config, Protocol>(std::move(emulator), std::move(backend)), serial_(serial)
  {
    DevicePortConfig& line = this->emulator_config_.line;
    LinkConfig& link = this->config_.link;
    if (serial_)
    {
      if (line.link.empty())
      {
        line.link = harnessLink(name);
      }
      link.kind = LinkKind::SERIAL;
      link.path = line.link;
      link.baud = line.baud;
    }
    this->startEmulator();
    if (!serial_)
    {
      this->emulator_config_.port = this->emulator_->udpPort();  // a restart takes the same port
      link.port = this->emulator_config_.port;
      link.local_host = "127.0.0.1";
    }
  }

private:
  const bool serial_;
};

/// An emulated IP camera (Axis, ONVIF) behind its HTTP server on 127.0.0.1, reached over http or (its certificate
/// pinned, as a self-signed camera is configured) https.
template <class Emulator, class Config, class Protocol>
class HttpCameraHarness : public EmulatorHarness<Emulator, Config, Protocol>
{
public:
  std::uint16_t port() const override
  {
    return this->emulator_->port();
  }
  std::string link() const override
  {
    return "";
  }
  void clearCommands() override
  {
    this->emulator_->server().received().clear();
  }
  long connectionsOpened() const override
  {
    return static_cast<long>(this->emulator_->server().counters().connections);
  }
  PtzSample deviceState() const override
  {
    return this->emulator_->sample();
  }
  void setFaults(const SimFaults& faults) override
  {
    this->emulator_->setFaults(faults);
  }
  /// The camera vanishes: its connections close and nothing listens (a closed keep-alive connection alone is no
  /// loss on HTTP: the next request opens another).
  void breakLink() override
  {
    this->emulator_->server().setListening(false);
    this->emulator_->server().dropConnections();
  }
  void restoreLink() override
  {
    this->emulator_->server().setListening(true);
  }
  /// A connection that closes and reopens at once is ordinary HTTP: only a request that fails, or silence, is a loss.
  bool breaksAtOnce() const override
  {
    return false;
  }

protected:
  /// Starts \p emulator and points the backend's link at it with \p username and \p password.
  HttpCameraHarness(Config emulator, DeviceConfig<Protocol> backend, const std::string& username,
                    const std::string& password)
    : EmulatorHarness<Emulator, Config, Protocol>(std::move(emulator), std::move(backend))
  {
    this->startEmulator();
    LinkConfig& link = this->config_.link;
    link.host = "127.0.0.1";
    link.port = this->emulator_->port();
    link.http.username = username;
    link.http.password = password;
    const HttpCameraServer& server = this->emulator_->server();
    link.http.tls = !server.fingerprint().empty();
    link.http.fingerprint = parseCertificateFingerprint(server.fingerprint());
  }
};

}  // namespace ptz_action_server

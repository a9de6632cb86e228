/**
 * \file
 * \brief One harness per device protocol and transport, shared by the backend contract suite (test/core/contract/)
 * and the benchmarks (bench/): it starts the protocol's emulator, gives the backend's configuration for it and the
 * node's equivalent parameters, and shows what the emulator received, classified (its classify()).
 */
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/emulators/emulator_faults.h"
#include "ptz_action_server/emulators/ports/device_port.h"
#include "ptz_action_server/emulators/ports/received_log.h"

namespace ptz_action_server
{
/// An emulator running for a backend to drive over one transport. Thread-safe where its emulator is.
class DeviceHarness
{
public:
  virtual ~DeviceHarness() = default;

  /// A new backend configured for the emulator (not started).
  virtual std::unique_ptr<DeviceBackend> makeBackend() const = 0;
  /// Where the backend finds the emulator: the UDP or TCP port (0 on a pseudo-terminal) ...
  virtual std::uint16_t port() const = 0;
  /// ... or the pseudo-terminal's link ("" on a socket).
  virtual std::string link() const = 0;

  /// What the emulator received since the last clearCommands(), classified (its classify()), oldest first.
  virtual std::vector<ClassifiedCommand> commands() const = 0;
  virtual void clearCommands() = 0;
  /// True once the emulator has read all a backend sends at start-up. By default the link coming up tells (the
  /// device answers the last of it); a device that reports before it has read everything (PanTilt) says otherwise.
  virtual bool startupReceived() const
  {
    return true;
  }
  /// The emulator's own state: pan, tilt (rad) and zoom (X, or 1 without zoom).
  virtual PtzSample deviceState() const = 0;
  /// TCP connections the emulator accepted so far (IP cameras), or -1 where that is not a figure.
  virtual long connectionsOpened() const
  {
    return -1;
  }

  /// The emulator's fault switch (bench/soak); nullptr while the device is gone (breakLink() on UDP).
  virtual EmulatorFaults* faults() = 0;
  /// Turns \p fault on or off (EmulatorFaults::setFault()); false, changing nothing, where there is no such mode.
  bool setFault(EmulatorFault fault, bool on);
  /// The device stops answering (it reads and ignores everything), or answers again.
  void setSilent(bool silent)
  {
    setFault(EmulatorFault::SILENCE, silent);
  }
  /// Every reply of the device one that never ends (EmulatorFault::ENDLESS), or ends them again; false where the
  /// emulator cannot.
  bool setEndless(bool endless)
  {
    return setFault(EmulatorFault::ENDLESS, endless);
  }
  /// Gives the emulated device \p faults (a stalled axis, a lag, a reported offset, a reply delay).
  virtual void setFaults(const SimFaults& faults) = 0;
  /// Makes the device send every state \p copies times (1: normally), a flood; false where it cannot (a device that
  /// only answers requests, or a serial line, whose baud rate bounds what it carries).
  virtual bool setFlood(unsigned copies)
  {
    (void)copies;
    return false;
  }

  /// The link vanishes as it does on this transport: a port unplugged, a connection closed, a device gone.
  virtual void breakLink() = 0;
  /// The link can come back (the port replugged, the device listening again).
  virtual void restoreLink() = 0;
  /// True where breakLink() closes something the backend notices at once (a port, a connection); false where only
  /// the silence tells (UDP, or HTTP, where a closed connection is ordinary).
  virtual bool breaksAtOnce() const
  {
    return true;
  }
};

/// A node parameter's value (the ROS parameter server's types the harnesses need).
using ParamValue = std::variant<std::string, int, double>;

/// A parameter under the node's private namespace that makes the node's backend reach a harness's device.
struct HarnessParam
{
  enum class Source
  {
    VALUE,          ///< value as it is
    EMULATOR_PORT,  ///< the running emulator's port (an int)
    EMULATOR_LINK,  ///< the running emulator's pseudo-terminal link (a string)
  };
  std::string name;  ///< relative to the private namespace: "flir/port"
  ParamValue value;
  Source source = Source::VALUE;

  /// The value for \p harness: its port or link where the source says so.
  ParamValue valueFor(const DeviceHarness& harness) const;
};

/// What ptz_bench counts of a harness's commands (the MOVEs of a goal, the STOPs of a cancel) and aims at.
struct HarnessFigures
{
  std::string summary;        ///< what runs, for --list
  std::string goal_items;     ///< which commands are the MOVEs, and their wire time, for --list
  std::string stop_items;     ///< which one is the stop, for --list
  std::string goal_target;    ///< the target column of "goal -> first command"
  std::string stop_target;    ///< the target column of "cancel -> stop"
  double goal_pause = 0.002;  ///< s between goals, for a goal's remaining commands to go out before the next
  int goals = 1000;           ///< goals for "goal -> first command" unless --goals says otherwise
  /// The protocol has no stop: a cancel holds the device by aiming it where it comes to rest (a MOVE).
  bool holds_aim = false;
};

/// A protocol's harness on one transport, as the benchmarks name it, ready to start.
struct HarnessEntry
{
  std::string name;                  ///< "flir_tcp"
  std::string plugin;                ///< the node's ~backend: the protocol's plugin name
  std::vector<HarnessParam> params;  ///< under ~ (besides ~backend): the same device as the harness's configuration
  HarnessFigures figures;
  /// Starts the emulator; \p link names its pseudo-terminal's link if it has one ("": one of its own). Without a
  /// start function, no emulator (the bench's sim row).
  std::function<std::unique_ptr<DeviceHarness>(const std::string& link)> start;
};

/// Every protocol's harnesses, in the order of their registration (cmake/protocols.cmake, HARNESS).
const std::vector<HarnessEntry>& allHarnesses();

/// What the harness files share: \p name's value ...
HarnessParam paramValue(const std::string& name, const ParamValue& value);
/// ... the emulator's port, its link ...
HarnessParam emulatorPort(const std::string& name);
HarnessParam emulatorLink(const std::string& name);
/// ... ~<protocol>/... on the emulator's pseudo-terminal at \p baud, or over TCP (\p baud 0) ...
std::vector<HarnessParam> serialParams(const std::string& protocol, unsigned baud);
/// ... a row of \p plugin's device on a pseudo-terminal at \p baud ("<plugin>_serial_<baud>", 300 goals), or over
/// TCP (\p baud 0: "<plugin>_tcp"), with serialParams() and a summary that names \p emulator and the port; \p start
/// makes the harness on the port it is given (at the row's link on a pseudo-terminal). The figures' texts, targets and
/// pause are the protocol's ...
HarnessEntry serialEntry(const std::string& plugin, unsigned baud, const std::string& emulator,
                         std::function<std::unique_ptr<DeviceHarness>(const DevicePortConfig& port)> start);
/// ... seconds a byte takes at \p baud on \p kind (8N1; 0 on a socket), how --list names the port ...
double byteTime(DevicePortConfig::Kind kind, unsigned baud);
std::string portSummary(DevicePortConfig::Kind kind, unsigned baud);
/// ... and a path for a pseudo-terminal's link named after \p name, unique in this process (in the temporary
/// directory).
std::string harnessLink(const std::string& name);

}  // namespace ptz_action_server

/**
 * \file
 * \brief The devices ptz_bench measures, one row each: the plugin, its emulator, the parameters the node gets, and
 * which of what the emulator receives count as goal commands and as the stop.
 */
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/core/types.h"
#include "ptz_action_server/emulators/ports/device_port.h"
#include "ptz_action_server/emulators/emulator_faults.h"

namespace ptz_bench
{
/// A command as it reached an emulator: when its last byte arrived, and its own time on the wire (s).
struct Arrival
{
  ptz_action_server::TimePoint at;
  double wire = 0.0;
};

/// A misbehaviour bench/soak makes an emulator show: the emulators' own (see EmulatorFaults).
using Fault = ptz_action_server::EmulatorFault;
inline constexpr const auto& ALL_FAULTS = ptz_action_server::ALL_EMULATOR_FAULTS;
inline const char* faultName(Fault fault)
{
  return ptz_action_server::toString(fault);
}

/// An emulator running in the bench's process, as the device figures see it. Thread-safe.
class EmulatedDevice
{
public:
  virtual ~EmulatedDevice() = default;
  /// Where the backend finds it: the UDP or TCP port (0 on a pseudo-terminal) ...
  virtual std::uint16_t port() const = 0;
  /// ... or the pseudo-terminal's link ("" on a socket).
  virtual std::string link() const = 0;
  /// Goal commands received so far, oldest first (polls, state requests and stops left out).
  virtual std::vector<Arrival> goalCommands() const = 0;
  /// Stop commands received so far, oldest first.
  virtual std::vector<Arrival> stopCommands() const = 0;
  /// TCP connections the emulator accepted so far (IP cameras), or -1 where that is not a figure.
  virtual long connectionsOpened() const
  {
    return -1;
  }
  /// Turns \p fault on or off (bench/soak); false, changing nothing, where the emulator has no such mode. One
  /// caller at a time.
  bool setFault(Fault fault, bool on)
  {
    ptz_action_server::EmulatorFaults* switches = faults();
    return switches != nullptr && switches->setFault(fault, on);
  }

protected:
  /// The emulator's fault switch (nullptr: none).
  virtual ptz_action_server::EmulatorFaults* faults()
  {
    return nullptr;
  }
};

/// How a row's emulator starts, and what the figures count of what it receives.
struct EmulatorSpec
{
  std::string summary;        ///< what runs, for --list
  std::string goal_items;     ///< which received items count as goal commands, and their wire time, for --list
  std::string stop_items;     ///< which one is the stop, for --list
  std::string goal_target;    ///< the target column of "goal -> first command"
  std::string stop_target;    ///< the target column of "cancel -> stop"
  double goal_pause = 0.002;  ///< s between goals, for a goal's remaining commands to go out before the next
  /// Starts the emulator; \p row names its pseudo-terminal link, if it has one.
  std::function<std::unique_ptr<EmulatedDevice>(const std::string& row)> start;
};

/// What the emulator specs share: seconds a byte takes at \p baud (8N1; 0 on a socket), ...
double byteTime(ptz_action_server::DevicePortConfig::Kind kind, unsigned baud);
/// ... the port of a pseudo-terminal (a link named after the row and this process) or of a TCP server or UDP socket
/// on 127.0.0.1 (an ephemeral port), ...
ptz_action_server::DevicePortConfig portConfig(ptz_action_server::DevicePortConfig::Kind kind, unsigned baud,
                                               const std::string& row);
/// ... and how --list names it.
std::string portSummary(ptz_action_server::DevicePortConfig::Kind kind, unsigned baud);

EmulatorSpec panTiltEmulator();
EmulatorSpec digiViewEmulator();
EmulatorSpec mavlinkGimbalEmulator();
EmulatorSpec flirEmulator(ptz_action_server::DevicePortConfig::Kind kind, unsigned baud);
EmulatorSpec pelcoEmulator(ptz_action_server::DevicePortConfig::Kind kind, unsigned baud);
/// A VISCA camera on a pseudo-terminal (raw), or over UDP with Sony's VISCA over IP header (\p baud unused).
EmulatorSpec viscaEmulator(ptz_action_server::DevicePortConfig::Kind kind, unsigned baud);
EmulatorSpec axisEmulator();
EmulatorSpec onvifEmulator();

/// A parameter a row sets under the node's private namespace before the node starts.
struct BenchParam
{
  enum class Source
  {
    VALUE,          ///< value as it is
    EMULATOR_PORT,  ///< the running emulator's port (an int)
    EMULATOR_LINK,  ///< the running emulator's pseudo-terminal link (a string)
  };
  std::string name;  ///< relative to the private namespace: "flir/port"
  XmlRpc::XmlRpcValue value;
  Source source = Source::VALUE;
};

/// One device ptz_bench measures.
struct DeviceRow
{
  std::string name;                ///< --device NAME
  std::string plugin;              ///< the node's ~backend
  std::vector<BenchParam> params;  ///< under ~ (besides ~backend)
  EmulatorSpec emulator;           ///< no start function: no emulator (the sim backend)
  int goals = 1000;                ///< goals for "goal -> first command", unless --goals says otherwise
};

/// Every row, in the order bench/run runs them.
const std::vector<DeviceRow>& deviceTable();
/// The row called \p name, or nullptr.
const DeviceRow* findDevice(const std::string& name);
/// The names, comma-separated, for messages.
std::string deviceNames();
/// Prints the table as markdown (--list).
void printDeviceTable();

}  // namespace ptz_bench

/**
 * \file
 * \brief The devices ptz_bench measures, one row each: the simulated camera, and every protocol's harnesses
 * (test/harness/: the plugin, its emulator, the parameters the node gets, and what the emulator received,
 * classified: a goal's commands are its MOVEs, a cancel's its STOP).
 */
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "harness/device_harness.h"
#include "ptz_action_server/emulators/emulator_faults.h"

namespace ptz_bench
{
/// A misbehaviour bench/soak makes an emulator show: the emulators' own (see EmulatorFaults).
using Fault = ptz_action_server::EmulatorFault;
inline constexpr const auto& ALL_FAULTS = ptz_action_server::ALL_EMULATOR_FAULTS;
inline const char* faultName(Fault fault)
{
  return ptz_action_server::toString(fault);
}

/// One device ptz_bench measures: a harness, or (no start function) the sim backend with its parameters.
using DeviceRow = ptz_action_server::HarnessEntry;
using ptz_action_server::ClassifiedCommand;
using ptz_action_server::DeviceHarness;
using ptz_action_server::HarnessParam;

/// The commands \p device received that the figures count: a goal's (MOVEs), or a cancel's (\p stops: the STOPs, or
/// the MOVEs that hold the device where the protocol has no stop).
std::vector<ClassifiedCommand> countedCommands(const DeviceHarness& device, const DeviceRow& row, bool stops);

/// Every row, in the order bench/run runs them: sim, then the harnesses as their protocols registered them.
const std::vector<DeviceRow>& deviceTable();
/// The row called \p name, or nullptr.
const DeviceRow* findDevice(const std::string& name);
/// The names, comma-separated, for messages.
std::string deviceNames();
/// Prints the table as markdown (--list).
void printDeviceTable();
/// Starts \p row's emulator (a pseudo-terminal's link named after the row and this process, removed on a fatal
/// signal).
std::unique_ptr<DeviceHarness> startDevice(const DeviceRow& row);

}  // namespace ptz_bench

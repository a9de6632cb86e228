/**
 * \file
 * \brief ptz_bench's child processes: the node (loaded as the ptz_action_server executable loads it, its backend
 * wrapped by a recorder) and the ptz_state observer.
 */
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

#include "bench_common.h"
#include "device_table.h"

namespace ptz_bench
{
/// The node's namespace and name: its parameters live under NODE_NAMESPACE/NODE_NAME/ as a launch file puts them.
constexpr const char* NODE_NAMESPACE = "/ptz";
constexpr const char* NODE_NAME = "ptz_action_server";

/**
 * \brief Forks the node and, for the sim row, an observer that stamps each ptz_state arrival.
 *
 * Construct it before the parent starts any thread (an emulator, roscpp): a forked child has only the forking
 * thread. The children wait at a gate until release(), so the parent can check the rosmaster, start the emulator
 * and set the parameters first; unreleased, they exit. stop(), or the destructor, interrupts the children and
 * waits for them; they also die with the parent. Children print their logs on stderr, so stdout carries only the
 * figures.
 */
class BenchProcesses
{
public:
  BenchProcesses(SharedCounters* counters, bool with_observer);
  ~BenchProcesses();
  BenchProcesses(const BenchProcesses&) = delete;
  BenchProcesses& operator=(const BenchProcesses&) = delete;

  /// Lets the children start: the node's parameters are on the rosmaster.
  void release();
  pid_t node() const
  {
    return node_;
  }
  /// False once the node has exited; then prints how it ended.
  bool nodeRunning();
  /// SIGINT to every child (SIGKILL to one still running after 10 s) and waits for all. Idempotent.
  void stop();

private:
  /// Forks a child that waits at the gate (reading \p gate_read), runs \p body and exits with its result, never
  /// returning into the parent's frames.
  pid_t spawn(const std::function<int()>& body, int gate_read);

  std::vector<pid_t> children_;  ///< not yet waited for
  pid_t node_ = -1;
  int gate_ = -1;  ///< write end of the children's gate pipe; closing it unreleased sends them home
};

/// Sets what a launch file would: the URDF, ~backend and the row's parameters (the emulator's port or link from
/// \p device, which may be null for a row without one), in NODE_NAMESPACE cleared first.
void setNodeParameters(const DeviceRow& row, const DeviceHarness* device, const std::string& urdf);

/// A file to remove if a fatal signal (SIGINT, SIGTERM, SIGHUP) ends the parent before its owner can: an
/// emulator's pseudo-terminal link. One at a time.
void removeOnFatalSignal(const std::string& path);

/// Waits up to 30 s for \p server_up (which may block a little) while the node runs; false, with a message, if not.
bool waitForNode(BenchProcesses& processes, const std::function<bool()>& server_up);

}  // namespace ptz_bench

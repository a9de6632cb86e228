/**
 * \file
 * \brief The figures ptz_bench measures: the sim backend's, and every emulated device's.
 */
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "bench_common.h"
#include "bench_processes.h"
#include "device_table.h"

namespace ptz_bench
{
/**
 * \brief Sim row: idle CPU, reach time against the closed-form minimum, zero-length goal -> result, goal -> first
 * backend command, cancel -> backend stop(), then ptz_state (as the observer process sees it), goals and CPU under a
 * storm of goals, and the node's peak RSS. Prints a table; returns 0, or 1 if the node did not come up.
 */
int runSimFigures(const BenchOptions& options, SharedCounters* counters, BenchProcesses& processes);

/// A process's CPU time (every thread's, from schedstat), its state tick thread's, and how often its threads slept.
struct ProcessSample
{
  double cpu_seconds = 0.0;
  double tick_seconds = 0.0;  ///< the thread sampleProcess() was given (0 if none)
  std::uint64_t sleeps = 0;   ///< voluntary context switches: each is a wake-up to come
  double wall_seconds = 0.0;  ///< CLOCK_MONOTONIC
};
/// Samples \p pid now; \p tick_thread (a thread id of \p pid, or 0) is counted apart as well.
ProcessSample sampleProcess(pid_t pid, std::int64_t tick_thread = 0);
/// % of one core \p from -> \p to.
double cpuPercent(const ProcessSample& from, const ProcessSample& to);

/// Sim row: the node at rest for \p seconds while the observer listens to every topic (ptz_state, joint_states,
/// /tf, field_of_view, /diagnostics) and this process to move_ptz/position_abs: its CPU, the share of the state
/// tick's thread and of the others (roscpp's), and its wake-ups per second. \p when says which rest ("before the
/// goals").
Row restFigure(SharedCounters* counters, pid_t node, double seconds, const std::string& when);

/// Sim row: the state tick measured part by part (TickCosts) for \p seconds with every topic listened: CPU per tick
/// of each part and per message each sent.
std::vector<Row> tickCostFigures(SharedCounters* counters, double seconds);

/// Sim row: move_ptz/track_frame on a frame the bench circles around the camera at 0.5 rad/s; the angular error
/// between the optical axis of each joint state and the frame's true direction at its stamp, after the first second.
Row trackFigure(ros::NodeHandle& node_handle);

/// Sim row: a Joy message with the dead-man held and a stick deflected -> the backend's first command, through a
/// PtzTeleop with the default mapping in this process (the Joy hop is in-process, the velocity goal goes over TCP),
/// 200 times.
Row teleopFigure(SharedCounters* counters);

/**
 * \brief Device rows: goal -> first goal command at the emulator and cancel -> stop command at the emulator (their
 * own wire time subtracted), and the ptz_state rate while a goal runs. Prints a table; returns 0, or 1 if the node
 * did not come up.
 */
int runDeviceFigures(const DeviceRow& row, const DeviceHarness& device, const BenchOptions& options,
                     BenchProcesses& processes);

}  // namespace ptz_bench

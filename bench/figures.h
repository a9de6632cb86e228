/**
 * \file
 * \brief The figures ptz_bench measures: the sim backend's, and every emulated device's.
 */
#pragma once

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
int runDeviceFigures(const DeviceRow& row, const EmulatedDevice& device, const BenchOptions& options,
                     BenchProcesses& processes);

}  // namespace ptz_bench

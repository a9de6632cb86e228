/**
 * \file
 * \brief What the parts of ptz_bench share: its options, the counters its processes share, percentiles and tables.
 */
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "ptz_action_server/ros/tick_costs.h"

namespace ptz_bench
{
/// The command line, checked (see usage()).
struct BenchOptions
{
  std::string urdf_file;
  std::string device;           ///< a row of the device table
  double idle_seconds = 10.0;   ///< sim: idle CPU window
  int zero_goals = 1000;        ///< sim: zero-length goals
  double storm_seconds = 30.0;  ///< sim: the goal storm
  int goals = 0;                ///< devices: goals for goal -> first command; 0: the row's default
  int cancels = 100;            ///< every row: cancelled goals for cancel -> stop
};

constexpr std::size_t MAX_STATE_ARRIVALS = 4096;

/// In shared memory: the node process stamps backend commands, the observer process stamps ptz_state arrivals.
struct SharedCounters
{
  std::atomic<std::uint64_t> commands{ 0 };  ///< goTo, moveAtVelocity and stop calls
  std::atomic<std::int64_t> last_command_ns{ 0 };
  std::atomic<std::uint64_t> stops{ 0 };  ///< stop calls
  std::atomic<std::int64_t> last_stop_ns{ 0 };
  std::atomic<std::int64_t> last_report_ns{ 0 };  ///< the backend's last report of new state (its sample listener)
  std::atomic<bool> record_states{ false };
  std::atomic<std::uint32_t> state_count{ 0 };
  std::int64_t state_arrivals_ns[MAX_STATE_ARRIVALS];
  /// Set: the observer also listens to joint_states, /tf, field_of_view and /diagnostics (and counts them).
  std::atomic<bool> listen_all{ false };
  std::atomic<bool> listening_all{ false };        ///< the observer's answer: every subscription is connected
  std::atomic<std::uint64_t> other_messages{ 0 };  ///< what the observer received on those topics
  ptz_action_server::TickCosts tick_costs;         ///< the node's state tick, measured while enabled
};

/// CLOCK_MONOTONIC (steady_clock) in ns: one clock for every process.
std::int64_t monotonicNanoseconds();

/// The value below which \p share of \p values lie (0 for none).
double percentile(std::vector<double> values, double share);
/// "p50 0.42 ms, p99 1.10 ms, max 1.30 ms" of \p milliseconds.
std::string percentiles(const std::vector<double>& milliseconds);

/// One line of a figures table.
struct Row
{
  std::string figure;
  std::string value;
  std::string target;
};

/// Prints a markdown table of figures under \p title, and flushes.
void printTable(const std::string& title, const std::vector<Row>& rows);

}  // namespace ptz_bench

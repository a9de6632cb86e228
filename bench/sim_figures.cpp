#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/action_client.h>
#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>

#include "figures.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/core/motion/motion_profile.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;
using PtzClient = actionlib::SimpleActionClient<PtzAction>;

long peakRssKilobytes(pid_t pid)
{
  std::ifstream file("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(file, line))
  {
    if (line.rfind("VmHWM:", 0) == 0)
    {
      return std::stol(line.substr(6));
    }
  }
  return -1;
}

/// Waits up to \p timeout s for \p counter to pass \p before.
bool waitForCount(const std::atomic<std::uint64_t>& counter, std::uint64_t before, double timeout)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (counter <= before && ros::WallTime::now() < deadline)
  {
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  return counter > before;
}

/// 1 rad pan goals: reach time against the trapezoid's closed-form minimum, and the backend's report that the device
/// settled -> the result at the client.
void reachFigures(PtzClient& client, SharedCounters* counters, std::vector<Row>& rows)
{
  constexpr int GOALS = 30;
  client.sendGoal(makePtzGoal(-0.5, 0.0, 1.0));
  client.waitForResult(ros::Duration(10.0));
  const double minimum = TrapezoidProfile::minimumDuration(1.0, AxisMotionLimits{ 1.5, 3.0, 0.0 });
  std::vector<double> ratios;
  std::vector<double> settled_to_result_ms;
  for (int run = 0; run < GOALS; ++run)
  {
    const double target = run % 2 == 0 ? 0.5 : -0.5;
    const std::int64_t sent_ns = monotonicNanoseconds();
    client.sendGoal(makePtzGoal(target, 0.0, 1.0));
    client.waitForResult(ros::Duration(10.0));
    const std::int64_t done_ns = monotonicNanoseconds();
    ratios.push_back((done_ns - sent_ns) / 1e9 / minimum);
    const std::int64_t settled_ns = counters->last_report_ns;
    if (settled_ns > sent_ns)
    {
      settled_to_result_ms.push_back((done_ns - settled_ns) / 1e6);
    }
  }
  std::sort(ratios.begin(), ratios.end());
  rows.push_back({ "1 rad goal: reach time / closed-form minimum",
                   formatText("p50 %.3f, max %.3f (minimum %.3f s, %d goals)", ratios[ratios.size() / 2], ratios.back(),
                              minimum, GOALS),
                   "<= 1.02" });
  rows.push_back({ "device settled (backend report) -> result", percentiles(settled_to_result_ms), "p99 <= 20 ms" });
}

/// Zero-length goals: goal -> result, and goal -> first backend command.
void zeroGoalFigures(PtzClient& client, SharedCounters* counters, int zero_goals, std::vector<Row>& rows)
{
  std::vector<double> result_ms;
  std::vector<double> command_ms;
  int zero_failed = 0;
  client.sendGoal(makePtzGoal(-1.0, 0.0, 1.0));  // untimed: the goals below are then zero-length
  client.waitForResult(ros::Duration(10.0));
  for (int index = 0; index < zero_goals; ++index)
  {
    const std::uint64_t commands_before = counters->commands;
    const std::int64_t sent_ns = monotonicNanoseconds();
    client.sendGoal(makePtzGoal(-1.0, 0.0, 1.0));
    client.waitForResult(ros::Duration(5.0));
    const std::int64_t done_ns = monotonicNanoseconds();
    if (client.getState() != actionlib::SimpleClientGoalState::SUCCEEDED)
    {
      ++zero_failed;
      continue;
    }
    result_ms.push_back((done_ns - sent_ns) / 1e6);
    if (counters->commands > commands_before)
    {
      command_ms.push_back((counters->last_command_ns - sent_ns) / 1e6);
    }
  }
  rows.push_back(
      { "zero-length goal -> result",
        formatText("%s (%d goals, %d not succeeded)", percentiles(result_ms).c_str(), zero_goals, zero_failed),
        "p99 <= status_hold (20 ms) + 5 ms" });
  rows.push_back({ "goal -> first backend command", percentiles(command_ms), "" });
}

/// Cancel -> the backend's stop(), over \p cancels goals each cancelled 0 to 90 ms after its first command (and
/// after the client saw it accepted).
Row cancelFigure(PtzClient& client, SharedCounters* counters, int cancels)
{
  std::vector<double> stop_ms;
  for (int index = 0; index < cancels; ++index)
  {
    const std::uint64_t commands_before = counters->commands;
    client.sendGoal(makePtzGoal(index % 2 == 0 ? 0.6 : -0.6, 0.0, 1.0));
    waitForCount(counters->commands, commands_before, 1.0);
    // A cancel the client sends before it has seen the goal accepted may end the goal LOST (actionlib).
    const ros::WallTime accepted_deadline = ros::WallTime::now() + ros::WallDuration(1.0);
    while (client.getState() == actionlib::SimpleClientGoalState::PENDING && ros::WallTime::now() < accepted_deadline)
    {
      ros::WallDuration(0.0005).sleep();
    }
    ros::WallDuration(0.01 * (index % 10)).sleep();
    const std::uint64_t stops_before = counters->stops;
    const std::int64_t cancelled_ns = monotonicNanoseconds();
    client.cancelGoal();
    const bool stopped = waitForCount(counters->stops, stops_before, 2.0);
    if (stopped)
    {
      stop_ms.push_back((counters->last_stop_ns - cancelled_ns) / 1e6);
    }
    client.waitForResult(ros::Duration(10.0));
    if (!stopped)
    {
      const actionlib::SimpleClientGoalState state = client.getState();
      std::fprintf(stderr, "ptz_bench: cancel %d saw no stop() within 2 s; the goal ended %s ('%s')\n", index,
                   state.toString().c_str(), state.getText().c_str());
    }
  }
  return { "cancel -> backend stop()",
           formatText("%s (%zu of %d cancels)", percentiles(stop_ms).c_str(), stop_ms.size(), cancels), "" };
}

/// The storm: 4 clients at ~50 Hz each for \p seconds, while the observer process times ptz_state arrivals.
void stormFigures(ros::NodeHandle& node_handle, SharedCounters* counters, pid_t node, double seconds,
                  std::vector<Row>& rows)
{
  std::atomic<bool> storming{ true };
  counters->state_count = 0;
  counters->record_states = true;
  std::vector<std::thread> threads;
  std::atomic<int> goals_sent{ 0 };
  std::atomic<int> goals_done{ 0 };
  const ProcessSample storm_start = sampleProcess(node);
  const ProcessSample clients_start = sampleProcess(getpid());
  for (int index = 0; index < 4; ++index)
  {
    threads.emplace_back([&, index]() {
      actionlib::ActionClient<PtzAction> storm_client(node_handle, "move_ptz/position_abs");
      storm_client.waitForActionServerToStart(ros::Duration(10.0));
      // Each goal counts once as it ends; ended handles are let go, since actionlib's client matches every status
      // list against every handle it tracks (keeping them all made its cost grow with the square of the storm's
      // length, until a 40 s storm's last results came after the deadline).
      using Handle = actionlib::ClientGoalHandle<PtzAction>;
      std::vector<Handle> handles;
      const auto count_done = [&goals_done](Handle handle) {
        goals_done += handle.getCommState() == actionlib::CommState::DONE;
      };
      ros::WallRate rate(50.0);
      int round = 0;
      while (storming)
      {
        handles.erase(
            std::remove_if(handles.begin(), handles.end(),
                           [](const Handle& handle) { return handle.getCommState() == actionlib::CommState::DONE; }),
            handles.end());
        ++goals_sent;
        handles.push_back(
            storm_client.sendGoal(makePtzGoal(0.5 * std::sin(0.05 * round + index), 0.1 * index, 1.0), count_done));
        ++round;
        rate.sleep();
      }
      const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
      for (Handle& handle : handles)
      {
        while (handle.getCommState() != actionlib::CommState::DONE && ros::WallTime::now() < deadline)
        {
          ros::WallDuration(0.01).sleep();
        }
      }
    });
  }
  ros::WallDuration(seconds).sleep();
  const ProcessSample storm_end = sampleProcess(node);
  const ProcessSample clients_end = sampleProcess(getpid());
  counters->record_states = false;
  storming = false;
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  std::vector<double> intervals_ms;
  const std::size_t arrivals = std::min<std::size_t>(counters->state_count, MAX_STATE_ARRIVALS);
  for (std::size_t index = 1; index < arrivals; ++index)
  {
    intervals_ms.push_back((counters->state_arrivals_ns[index] - counters->state_arrivals_ns[index - 1]) / 1e6);
  }
  const double rate_hz =
      arrivals > 1 ?
          (arrivals - 1) / ((counters->state_arrivals_ns[arrivals - 1] - counters->state_arrivals_ns[0]) / 1e9) :
          0.0;
  rows.push_back({ "ptz_state rate under the storm", formatText("%.3f Hz", rate_hz), "10 Hz +- 2 %" });
  rows.push_back({ "ptz_state interval under the storm",
                   formatText("p50 %.1f ms, p99 %.1f ms, max %.1f ms", percentile(intervals_ms, 0.5),
                              percentile(intervals_ms, 0.99), percentile(intervals_ms, 1.0)),
                   "p99 <= 120 ms" });
  rows.push_back(
      { "storm goals (4 clients x ~50 Hz)",
        formatText("%d sent, %d ended (%.0f goals/s)", goals_sent.load(), goals_done.load(), goals_sent / seconds),
        "none lost" });
  rows.push_back({ "node CPU under the storm", formatText("%.1f %%", cpuPercent(storm_start, storm_end)), "" });
  rows.push_back(
      { "client process CPU under the storm", formatText("%.1f %%", cpuPercent(clients_start, clients_end)), "" });
}
}  // namespace

int runSimFigures(const BenchOptions& options, SharedCounters* counters, BenchProcesses& processes)
{
  ros::NodeHandle node_handle(NODE_NAMESPACE);
  ros::AsyncSpinner spinner(2);
  spinner.start();
  PtzClient client(node_handle, "move_ptz/position_abs", true);
  if (!waitForNode(processes, [&client] { return client.waitForServer(ros::Duration(0.5)); }))
  {
    return 1;
  }
  const pid_t node = processes.node();
  std::vector<Row> rows;

  // Idle CPU: nothing but the 10 Hz state, listened to by the observer (ptz_state) and this process's client (the
  // position_abs status list), then by a subscriber of every topic; then each part of the tick.
  ros::WallDuration(1.0).sleep();
  const ProcessSample idle_start = sampleProcess(node);
  ros::WallDuration(options.idle_seconds).sleep();
  rows.push_back({ formatText("node CPU, idle (%g s)", options.idle_seconds),
                   formatText("%.2f %%", cpuPercent(idle_start, sampleProcess(node))), "<= 1 %" });
  rows.push_back(restFigure(counters, node, options.idle_seconds, "before the goals"));
  for (Row& row : tickCostFigures(counters, options.idle_seconds))
  {
    rows.push_back(std::move(row));
  }

  reachFigures(client, counters, rows);
  zeroGoalFigures(client, counters, options.zero_goals, rows);
  rows.push_back(cancelFigure(client, counters, options.cancels));
  rows.push_back(trackFigure(node_handle));
  rows.push_back(teleopFigure(counters));
  stormFigures(node_handle, counters, node, options.storm_seconds, rows);
  // A camera at rest after it was used: what goals leave behind (threads, timers) costs here.
  ros::WallDuration(1.0).sleep();
  rows.push_back(restFigure(counters, node, options.idle_seconds, "after the goals"));
  rows.push_back({ "node peak RSS", formatText("%.1f MB", peakRssKilobytes(node) / 1024.0), "" });
  printTable("sim (sim backend)", rows);
  return 0;
}

}  // namespace ptz_bench

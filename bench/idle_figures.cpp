#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

#include <ros/ros.h>

#include "figures.h"
#include "ptz_action_server/core/text.h"

namespace ptz_bench
{
namespace
{
using ptz_action_server::TickCosts;

/// The first number of /proc/PID/task/TID/schedstat: the thread's time on a CPU, in ns.
double threadCpuSeconds(const std::string& task)
{
  std::ifstream file(task + "/schedstat");
  double nanoseconds = 0.0;
  return file >> nanoseconds ? nanoseconds * 1e-9 : 0.0;
}

/// voluntary_ctxt_switches of /proc/PID/task/TID/status: how often the thread went to sleep (and so woke up again).
std::uint64_t threadSleeps(const std::string& task)
{
  std::ifstream file(task + "/status");
  std::string line;
  while (std::getline(file, line))
  {
    if (line.rfind("voluntary_ctxt_switches:", 0) == 0)
    {
      return std::stoull(line.substr(line.find(':') + 1));
    }
  }
  return 0;
}

/// Enables the node's tick measurement until one tick was measured, and returns its thread id (0 if none came).
std::int64_t tickThread(SharedCounters* counters)
{
  TickCosts& costs = counters->tick_costs;
  costs.clear();
  costs.enabled = true;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
  while (costs.ticks == 0 && ros::WallTime::now() < deadline)
  {
    ros::WallDuration(0.01).sleep();
  }
  costs.enabled = false;
  return costs.tick_thread;
}

/// Sets the observer listening to every topic of the camera and waits until it is connected to each.
void listenToAll(SharedCounters* counters, bool on)
{
  counters->listen_all = on;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  while (counters->listening_all != on && ros::WallTime::now() < deadline)
  {
    ros::WallDuration(0.02).sleep();
  }
  ros::WallDuration(0.5).sleep();  // roscpp's connect callbacks in the node
}

}  // namespace

ProcessSample sampleProcess(pid_t pid, std::int64_t tick_thread)
{
  ProcessSample sample;
  const std::string tasks = "/proc/" + std::to_string(pid) + "/task";
  if (DIR* directory = opendir(tasks.c_str()))
  {
    while (const dirent* entry = readdir(directory))
    {
      if (entry->d_name[0] == '.')
      {
        continue;
      }
      const std::string task = tasks + "/" + entry->d_name;
      const double seconds = threadCpuSeconds(task);
      sample.cpu_seconds += seconds;
      if (tick_thread != 0 && std::to_string(tick_thread) == entry->d_name)
      {
        sample.tick_seconds = seconds;
      }
      sample.sleeps += threadSleeps(task);
    }
    closedir(directory);
  }
  sample.wall_seconds =
      ptz_action_server::secondsBetween(ptz_action_server::TimePoint(), ptz_action_server::SteadyClock::now());
  return sample;
}

double cpuPercent(const ProcessSample& from, const ProcessSample& to)
{
  return 100.0 * (to.cpu_seconds - from.cpu_seconds) / (to.wall_seconds - from.wall_seconds);
}

Row restFigure(SharedCounters* counters, pid_t node, double seconds, const std::string& when)
{
  const std::int64_t tick_thread = tickThread(counters);
  listenToAll(counters, true);
  const std::uint64_t others_before = counters->other_messages;
  const ProcessSample from = sampleProcess(node, tick_thread);
  ros::WallDuration(seconds).sleep();
  const ProcessSample to = sampleProcess(node, tick_thread);
  const double wall = to.wall_seconds - from.wall_seconds;
  const double tick_percent = 100.0 * (to.tick_seconds - from.tick_seconds) / wall;
  const double total = cpuPercent(from, to);
  listenToAll(counters, false);
  return { ptz_action_server::formatText("node CPU at rest %s, every topic listened (%g s)", when.c_str(), seconds),
           ptz_action_server::formatText("%.2f %% (state tick's thread %.2f %%, other threads %.2f %%); %.0f "
                                         "wake-ups/s; %.0f other messages/s at the observer",
                                         total, tick_percent, total - tick_percent, (to.sleeps - from.sleeps) / wall,
                                         (counters->other_messages - others_before) / wall),
           "<= 0.25 %" };
}

std::vector<Row> tickCostFigures(SharedCounters* counters, double seconds)
{
  listenToAll(counters, true);
  TickCosts& costs = counters->tick_costs;
  costs.clear();
  costs.enabled = true;
  ros::WallDuration(seconds).sleep();
  costs.enabled = false;
  const double ticks = static_cast<double>(std::max<std::uint64_t>(1, costs.ticks));
  static const char* const NAMES[TickCosts::PARTS] = { "sample",        "ptz_state",   "joint_states", "tf",
                                                       "field_of_view", "diagnostics", "status lists", "hand-over" };
  double total_us = 0.0;
  std::string per_tick;
  std::string per_message;
  for (int part = 0; part < TickCosts::PARTS; ++part)
  {
    const double part_us = costs.nanoseconds[part] / 1000.0;
    total_us += part_us;
    per_tick += ptz_action_server::formatText("%s%s %.1f", per_tick.empty() ? "" : ", ", NAMES[part], part_us / ticks);
    if (costs.messages[part] > 0)
    {
      per_message += ptz_action_server::formatText("%s%s %.1f (%.1f/s)", per_message.empty() ? "" : ", ", NAMES[part],
                                                   part_us / costs.messages[part], costs.messages[part] / seconds);
    }
  }
  listenToAll(counters, false);
  return { { ptz_action_server::formatText("state tick, CPU per tick on its thread, us (%.0f ticks, every topic "
                                           "listened)",
                                           ticks),
             ptz_action_server::formatText("%.1f: %s", total_us / ticks, per_tick.c_str()), "" },
           { "state tick, CPU per message sent, us (messages/s)", per_message, "" } };
}

}  // namespace ptz_bench

#include <chrono>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/action_client.h>
#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>

#include "figures.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;
using PtzActionClient = actionlib::ActionClient<PtzAction>;
using Arrivals = std::function<std::vector<ClassifiedCommand>()>;

/// Waits up to \p timeout s for \p arrivals() to hold an item beyond the first \p before ones; that item, or none.
bool waitForArrival(const Arrivals& arrivals, std::size_t before, double timeout, ClassifiedCommand& arrival)
{
  const TimePoint deadline = addSeconds(SteadyClock::now(), timeout);
  std::vector<ClassifiedCommand> now = arrivals();
  while (now.size() <= before && SteadyClock::now() < deadline)
  {
    std::this_thread::sleep_for(std::chrono::microseconds(100));
    now = arrivals();
  }
  if (now.size() <= before)
  {
    return false;
  }
  arrival = now[before];
  return true;
}

/// Goal -> first goal command at the emulator (its wire time subtracted), over \p goals goals that preempt each other.
Row goalFigure(PtzActionClient& client, const DeviceHarness& device, const DeviceRow& row, int goals)
{
  const Arrivals commands = [&device, &row] { return countedCommands(device, row, false); };
  std::vector<double> latency_ms;
  std::vector<double> wire_ms;
  std::vector<actionlib::ClientGoalHandle<PtzAction>> handles;
  for (int index = 0; index < goals; ++index)
  {
    const std::size_t before = commands().size();
    const TimePoint sent = SteadyClock::now();
    handles.push_back(client.sendGoal(makePtzGoal(index % 2 == 0 ? 0.10 : 0.12, 0.0, 1.0)));
    ClassifiedCommand first;
    if (waitForArrival(commands, before, 1.0, first))
    {
      latency_ms.push_back((secondsBetween(sent, first.at) - first.wire) * 1e3);
      wire_ms.push_back(first.wire * 1e3);
    }
    ros::WallDuration(row.figures.goal_pause).sleep();  // the goal's remaining commands go out before the next goal
    if (handles.size() > 100)
    {
      handles.erase(handles.begin(), handles.begin() + 50);
    }
  }
  return { "goal -> first command at the emulator",
           formatText("%s (%zu of %d goals; wire time %.2f ms subtracted)", percentiles(latency_ms).c_str(),
                      latency_ms.size(), goals, percentile(wire_ms, 0.5)),
           row.figures.goal_target };
}

/**
 * \brief Cancel -> stop command at the emulator (its wire time subtracted), over \p cancels goals each cancelled 0
 * to 90 ms after its first command reached the emulator and the client saw it accepted, so that the cancel meets
 * the goal's own commands and the polls on the line.
 */
Row cancelFigure(PtzActionClient& client, const DeviceHarness& device, const DeviceRow& row, int cancels)
{
  const Arrivals commands = [&device, &row] { return countedCommands(device, row, false); };
  const Arrivals stops = [&device, &row] { return countedCommands(device, row, true); };
  std::vector<double> latency_ms;
  std::vector<double> wire_ms;
  int not_ended = 0;
  for (int index = 0; index < cancels; ++index)
  {
    const std::size_t before = commands().size();
    auto handle = client.sendGoal(makePtzGoal(index % 2 == 0 ? 0.6 : -0.6, 0.0, 1.0));
    ClassifiedCommand first;
    waitForArrival(commands, before, 1.0, first);
    // A cancel the client sends before it has seen the goal accepted may end the goal LOST (actionlib).
    const ros::WallTime accepted_deadline = ros::WallTime::now() + ros::WallDuration(1.0);
    while ((handle.getCommState() == actionlib::CommState::WAITING_FOR_GOAL_ACK ||
            handle.getCommState() == actionlib::CommState::PENDING) &&
           ros::WallTime::now() < accepted_deadline)
    {
      ros::WallDuration(0.0005).sleep();
    }
    ros::WallDuration(0.01 * (index % 10)).sleep();
    const std::size_t stops_before = stops().size();
    const TimePoint cancelled = SteadyClock::now();
    handle.cancel();
    ClassifiedCommand stop;
    if (waitForArrival(stops, stops_before, 2.0, stop))
    {
      latency_ms.push_back((secondsBetween(cancelled, stop.at) - stop.wire) * 1e3);
      wire_ms.push_back(stop.wire * 1e3);
    }
    // The goal ends once the device rests.
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
    while (handle.getCommState() != actionlib::CommState::DONE && ros::WallTime::now() < deadline)
    {
      ros::WallDuration(0.002).sleep();
    }
    not_ended += handle.getCommState() != actionlib::CommState::DONE;
  }
  return { "cancel -> stop command at the emulator",
           formatText("%s (%zu of %d cancels%s; wire time %.2f ms subtracted)", percentiles(latency_ms).c_str(),
                      latency_ms.size(), cancels,
                      not_ended > 0 ? formatText(", %d goals not ended within 10 s", not_ended).c_str() : "",
                      percentile(wire_ms, 0.5)),
           row.figures.stop_target };
}

/// The ptz_state rate while a goal runs from one side of pan to the other (about 2 s).
Row stateRateFigure(ros::NodeHandle& node_handle)
{
  std::mutex arrivals_mutex;
  std::vector<double> state_times;
  bool recording = false;
  const ros::Subscriber state_subscriber =
      node_handle.subscribe<PtzState>("ptz_state", 100, [&](const PtzState::ConstPtr&) {
        std::lock_guard<std::mutex> lock(arrivals_mutex);
        if (recording)
        {
          state_times.push_back(secondsBetween(TimePoint(), SteadyClock::now()));
        }
      });
  actionlib::SimpleActionClient<PtzAction> mover(node_handle, "move_ptz/position_abs", true);
  mover.waitForServer(ros::Duration(5.0));
  mover.sendGoal(makePtzGoal(-1.2, 0.0, 1.0));
  mover.waitForResult(ros::Duration(10.0));
  {
    std::lock_guard<std::mutex> lock(arrivals_mutex);
    recording = true;
  }
  mover.sendGoal(makePtzGoal(1.2, 0.0, 1.0));
  mover.waitForResult(ros::Duration(10.0));
  std::lock_guard<std::mutex> lock(arrivals_mutex);
  recording = false;
  const double rate =
      state_times.size() > 1 ? (state_times.size() - 1) / (state_times.back() - state_times.front()) : 0.0;
  return { "ptz_state rate while a goal runs", formatText("%.2f Hz (%zu messages)", rate, state_times.size()),
           "10 Hz" };
}
}  // namespace

int runDeviceFigures(const DeviceRow& row, const DeviceHarness& device, const BenchOptions& options,
                     BenchProcesses& processes)
{
  ros::NodeHandle node_handle(NODE_NAMESPACE);
  ros::AsyncSpinner spinner(2);
  spinner.start();
  PtzActionClient client(node_handle, "move_ptz/position_abs");
  if (!waitForNode(processes, [&client] { return client.waitForActionServerToStart(ros::Duration(0.5)); }))
  {
    return 1;
  }
  ros::WallDuration(1.0).sleep();  // the link is up and the setup is done
  std::vector<Row> rows;
  rows.push_back(goalFigure(client, device, row, options.goals > 0 ? options.goals : row.figures.goals));
  rows.push_back(cancelFigure(client, device, row, options.cancels));
  rows.push_back(stateRateFigure(node_handle));
  if (device.connectionsOpened() >= 0)
  {
    rows.push_back({ "TCP connections the camera accepted (start-up, every goal and cancel)",
                     std::to_string(device.connectionsOpened()), "1" });
  }
  printTable(row.name + " (" + row.plugin + " backend, " + row.figures.summary + ")", rows);
  return 0;
}

}  // namespace ptz_bench

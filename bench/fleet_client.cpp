/**
 * \file
 * \brief bench/fleet's client: measures a fleet of running cameras (cam_00 .. cam_NN), idle and under goals.
 *
 * Usage: bench_fleet_client CAMERAS SECONDS NODE... (the nodes whose processes make the fleet: the camera nodes, or
 * the nodelet manager then its loaders). Prints one line of figures, key=value, for bench/fleet to tabulate:
 *   idle_cpu    % of one core used by the processes over SECONDS with nobody listening or sending goals;
 *   listened_cpu  the same while this client listens to every camera's ptz_state (and nothing else);
 *   load_cpu    the same while every camera gets one position goal per second (their sends spread over the second)
 *               and this client listens to every camera's ptz_state and goal status;
 *   worst_rate  the lowest ptz_state rate of any camera over the loaded spell (Hz);
 *   p50, p99, max  goal -> accepted (ms): from the goal's publication here to the first status that shows it active
 *               here, with status_hold 0 (bench/fleet sets it): the node sends the first device command right after
 *               accepting, in the same callback, so this bounds goal -> first device command from above (it adds the
 *               status message's trip back);
 *   rss_mb      resident memory of the processes; threads, and first_threads (the first node's: the manager).
 * Goals go straight to each action's goal topic, as an actionlib client sends them.
 */
#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/ros.h>

#include "ptz_action_server/PtzActionGoal.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/ros/node_process.h"

using ptz_action_server::pidOfNode;

namespace
{

/// utime + stime of \p pid, in clock ticks.
long cpuTicks(int pid)
{
  std::ifstream file("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::istringstream fields(text.substr(text.rfind(')') + 2));
  std::string field;
  long utime = 0;
  long stime = 0;
  for (int index = 0; index < 13 && fields >> field; ++index)
  {
    if (index == 11)
    {
      utime = std::stol(field);
    }
    if (index == 12)
    {
      stime = std::stol(field);
    }
  }
  return utime + stime;
}

long totalTicks(const std::vector<int>& pids)
{
  long total = 0;
  for (int pid : pids)
  {
    total += cpuTicks(pid);
  }
  return total;
}

/// A field of /proc/PID/status ("VmRSS", "Threads") as a number.
long statusField(int pid, const std::string& key)
{
  std::ifstream file("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(file, line))
  {
    if (line.compare(0, key.size() + 1, key + ":") == 0)
    {
      return std::stol(line.substr(key.size() + 1));
    }
  }
  return 0;
}

double percentile(std::vector<double> values, double fraction)
{
  if (values.empty())
  {
    return -1.0;
  }
  std::sort(values.begin(), values.end());
  const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(fraction * values.size()));
  return values[index];
}

struct Camera
{
  std::string ns;
  ros::Subscriber state;
  ros::Subscriber status;
  ros::Publisher goal;
  std::atomic<int> states{ 0 };
};
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "bench_fleet_client", ros::init_options::AnonymousName);
  if (argc < 4)
  {
    std::fprintf(stderr, "usage: bench_fleet_client CAMERAS SECONDS NODE...\n");
    return 2;
  }
  const int count = std::stoi(argv[1]);
  const double seconds = std::stod(argv[2]);
  ros::NodeHandle node_handle;
  std::vector<int> pids;
  for (int index = 3; index < argc; ++index)
  {
    const int pid = pidOfNode(argv[index]);
    if (pid <= 0)
    {
      std::fprintf(stderr, "no pid for %s\n", argv[index]);
      return 1;
    }
    pids.push_back(pid);
  }
  const double hz = static_cast<double>(sysconf(_SC_CLK_TCK));

  // Idle: nobody listens, nobody sends.
  long start = totalTicks(pids);
  ros::WallDuration(seconds).sleep();
  const double idle_cpu = 100.0 * (totalTicks(pids) - start) / hz / seconds;

  // Listened: every camera's ptz_state, nothing else.
  std::vector<std::unique_ptr<Camera>> cameras;
  for (int index = 0; index < count; ++index)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "/cam_%02d", index);
    auto camera = std::make_unique<Camera>();
    Camera* raw = camera.get();
    camera->ns = name;
    camera->state = node_handle.subscribe<ptz_action_server::PtzState>(
        camera->ns + "/ptz_state", 10, [raw](const ptz_action_server::PtzState::ConstPtr&) { ++raw->states; });
    cameras.push_back(std::move(camera));
  }
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const ros::WallTime listen_deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::WallTime::now() < listen_deadline &&
         !std::all_of(cameras.begin(), cameras.end(),
                      [](const std::unique_ptr<Camera>& camera) { return camera->state.getNumPublishers() > 0; }))
  {
    ros::WallDuration(0.1).sleep();
  }
  ros::WallDuration(1.0).sleep();
  start = totalTicks(pids);
  ros::WallDuration(seconds).sleep();
  const double listened_cpu = 100.0 * (totalTicks(pids) - start) / hz / seconds;

  // Loaded: every camera listened to and sent one goal a second.
  std::mutex mutex;
  std::map<std::string, ros::WallTime> sent;  ///< goal id -> when it was published
  std::vector<double> latencies;              ///< ms
  for (auto& camera : cameras)
  {
    camera->status = node_handle.subscribe<actionlib_msgs::GoalStatusArray>(
        camera->ns + "/move_ptz/position_abs/status", 10, [&](const actionlib_msgs::GoalStatusArray::ConstPtr& array) {
          const ros::WallTime now = ros::WallTime::now();
          std::lock_guard<std::mutex> lock(mutex);
          for (const actionlib_msgs::GoalStatus& status : array->status_list)
          {
            const auto found = sent.find(status.goal_id.id);
            if (found != sent.end() && status.status != actionlib_msgs::GoalStatus::PENDING)
            {
              latencies.push_back((now - found->second).toSec() * 1000.0);
              sent.erase(found);
            }
          }
        });
    camera->goal =
        node_handle.advertise<ptz_action_server::PtzActionGoal>(camera->ns + "/move_ptz/position_abs/goal", 10);
  }
  const ros::WallTime connect_deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::WallTime::now() < connect_deadline &&
         !std::all_of(cameras.begin(), cameras.end(), [](const std::unique_ptr<Camera>& camera) {
           return camera->goal.getNumSubscribers() > 0 && camera->state.getNumPublishers() > 0 &&
                  camera->status.getNumPublishers() > 0;
         }))
  {
    ros::WallDuration(0.1).sleep();
  }
  ros::WallDuration(1.0).sleep();

  for (auto& camera : cameras)
  {
    camera->states = 0;
  }
  start = totalTicks(pids);
  const ros::WallTime began = ros::WallTime::now();
  int sends = 0;
  const int rounds = static_cast<int>(seconds);
  for (int round = 0; round < rounds; ++round)
  {
    for (int index = 0; index < count; ++index)
    {
      const ros::WallTime due = began + ros::WallDuration(round + static_cast<double>(index) / count);
      const ros::WallDuration wait = due - ros::WallTime::now();
      if (wait > ros::WallDuration(0))
      {
        wait.sleep();
      }
      ptz_action_server::PtzActionGoal goal;
      goal.header.stamp = ros::Time::now();
      goal.goal_id.stamp = goal.header.stamp;
      goal.goal_id.id = "fleet_" + std::to_string(index) + "_" + std::to_string(round);
      goal.goal.pan = (round % 2 == 0) ? 0.5 : -0.5;
      goal.goal.tilt = 0.0;
      goal.goal.zoom = 1.0;
      {
        std::lock_guard<std::mutex> lock(mutex);
        sent[goal.goal_id.id] = ros::WallTime::now();
      }
      cameras[index]->goal.publish(goal);
      ++sends;
    }
  }
  const ros::WallDuration rest = began + ros::WallDuration(rounds) - ros::WallTime::now();
  if (rest > ros::WallDuration(0))
  {
    rest.sleep();
  }
  const double elapsed = (ros::WallTime::now() - began).toSec();
  const double load_cpu = 100.0 * (totalTicks(pids) - start) / hz / elapsed;
  double worst_rate = 1e9;
  for (auto& camera : cameras)
  {
    worst_rate = std::min(worst_rate, camera->states / elapsed);
  }
  ros::WallDuration(0.5).sleep();  // the last goals' statuses
  long rss_kb = 0;
  long threads = 0;
  for (int pid : pids)
  {
    rss_kb += statusField(pid, "VmRSS");
    threads += statusField(pid, "Threads");
  }
  spinner.stop();  // no status callback from here on
  std::printf("idle_cpu=%.1f listened_cpu=%.1f load_cpu=%.1f worst_rate=%.2f p50=%.2f p99=%.2f max=%.2f goals=%d "
              "accepted=%zu "
              "rss_mb=%.0f threads=%ld first_threads=%ld processes=%zu\n",
              idle_cpu, listened_cpu, load_cpu, worst_rate, percentile(latencies, 0.5), percentile(latencies, 0.99),
              percentile(latencies, 1.0), sends, latencies.size(), rss_kb / 1024.0, threads,
              statusField(pids.front(), "Threads"), pids.size());
  return 0;
}

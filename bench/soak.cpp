/**
 * \file
 * \brief bench_soak: one device of ptz_bench's table for a long run, under a goal mix from 4 clients while its
 * emulator misbehaves every few seconds. Prints what became of every goal, the node's RSS and open fds over the run
 * and the ptz_state rate; asserts nothing, but exits 1 if a goal never ended or the node died.
 *
 * The node is forked as ptz_bench forks it (BenchProcesses: the ptz_action_server executable's BackendLoader); the
 * emulator (the row's harness, in this process) takes its faults through DeviceHarness::setFault(). A rosmaster must be
 * running: bench/soak starts one in a network namespace of its own.
 */
#include <dirent.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "bench_common.h"
#include "bench_processes.h"
#include "device_table.h"
#include "soak_client.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzPresetAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/SavePreset.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace
{
using namespace ptz_bench;
using namespace ptz_action_server;

const char* const USAGE = "usage: bench_soak URDF_FILE --device NAME --seconds S [--clients N] [--fault-period S]\n"
                          "\n"
                          "Runs the node on one device of ptz_bench's table (ptz_bench --list) for S seconds while N "
                          "clients (default 4)\n"
                          "send a goal mix (absolute, relative, velocity, frame, preset; some cancelled, 5 % invalid) "
                          "and the emulator\n"
                          "shows one fault every --fault-period seconds (default 4: 2 s of fault, then 2 s clean), the "
                          "faults it has in\n"
                          "turn: silence, drop, garbage, endless, flood, slow, impossible. Prints one markdown table "
                          "row and the details.\n"
                          "A rosmaster must be running (bench/soak starts one).\n";

constexpr int CLIENTS = 4;
constexpr double FAULT_ON = 2.0;  ///< s each fault lasts

[[noreturn]] void usageError(const std::string& message)
{
  std::fprintf(stderr, "bench_soak: %s\n\n%s", message.c_str(), USAGE);
  std::exit(2);
}

double positive(const std::string& option, const char* text)
{
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value > 0.0 && value <= 24 * 3600.0))
  {
    usageError(option + " needs a number of seconds in (0, 86400]");
  }
  return value;
}

/// The node's RSS (MB) and open fds, from /proc.
struct ProcessFigures
{
  double rss_mb = -1.0;
  int fds = -1;
  int threads = -1;
};

ProcessFigures processFigures(pid_t pid)
{
  ProcessFigures figures;
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmRSS:", 0) == 0)
    {
      figures.rss_mb = std::atof(line.c_str() + 6) / 1024.0;
    }
    else if (line.rfind("Threads:", 0) == 0)
    {
      figures.threads = std::atoi(line.c_str() + 8);
    }
  }
  if (DIR* directory = ::opendir(("/proc/" + std::to_string(pid) + "/fd").c_str()))
  {
    figures.fds = 0;
    while (const dirent* entry = ::readdir(directory))
    {
      figures.fds += entry->d_name[0] != '.';
    }
    ::closedir(directory);
  }
  return figures;
}

/// Publishes the frames the frame goals aim at: 4 m away, either side of the camera.
void publishFrames(tf2_ros::StaticTransformBroadcaster& broadcaster)
{
  std::vector<geometry_msgs::TransformStamped> transforms;
  const double positions[2][3] = { { 4.0, 1.0, 0.5 }, { 3.0, -1.5, -0.3 } };
  for (int index = 0; index < 2; ++index)
  {
    geometry_msgs::TransformStamped transform;
    transform.header.stamp = ros::Time::now();
    transform.header.frame_id = "ptz_base_link";
    transform.child_frame_id = FRAMES[index];
    transform.transform.translation.x = positions[index][0];
    transform.transform.translation.y = positions[index][1];
    transform.transform.translation.z = positions[index][2];
    transform.transform.rotation.w = 1.0;
    transforms.push_back(transform);
  }
  broadcaster.sendTransform(transforms);
}

/// Saves the preset the preset goals go to, once the device reports its pose (retries while the link comes up).
bool savePreset(ros::NodeHandle& node_handle)
{
  ros::ServiceClient client = node_handle.serviceClient<SavePreset>("move_ptz/save_preset");
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  SavePreset service;
  service.request.name = PRESET;
  while (ros::WallTime::now() < deadline)
  {
    if (client.call(service) && service.response.success)
    {
      return true;
    }
    ros::WallDuration(0.2).sleep();
  }
  std::fprintf(stderr, "bench_soak: could not save the preset: %s\n", service.response.message.c_str());
  return false;
}

std::string joined(const std::map<std::string, long>& counts)
{
  std::vector<std::pair<long, std::string>> sorted;
  for (const auto& entry : counts)
  {
    sorted.emplace_back(-entry.second, entry.first);
  }
  std::sort(sorted.begin(), sorted.end());
  std::string text;
  for (const auto& entry : sorted)
  {
    text += (text.empty() ? "" : ", ") + entry.second + " " + std::to_string(-entry.first);
  }
  return text;
}
}  // namespace

int main(int argc, char** argv)
{
  std::string urdf_file, device_name;
  double seconds = 0.0;
  double fault_period = 4.0;
  int clients = CLIENTS;
  for (int index = 1; index < argc; ++index)
  {
    const std::string argument = argv[index];
    if (argument == "--help" || argument == "-h")
    {
      std::printf("%s", USAGE);
      return 0;
    }
    if (argument.rfind("--", 0) != 0)
    {
      urdf_file = argument;
      continue;
    }
    if (index + 1 >= argc)
    {
      usageError(argument + " needs a value");
    }
    const char* value = argv[++index];
    if (argument == "--device")
    {
      if (findDevice(value) == nullptr)
      {
        usageError(std::string("unknown device '") + value + "'; devices: " + deviceNames());
      }
      device_name = value;
    }
    else if (argument == "--seconds")
    {
      seconds = positive(argument, value);
    }
    else if (argument == "--fault-period")
    {
      fault_period = positive(argument, value);
      if (fault_period <= FAULT_ON)
      {
        usageError("--fault-period must be longer than a fault (2 s)");
      }
    }
    else if (argument == "--clients")
    {
      clients = std::max(1, std::min(16, std::atoi(value)));
    }
    else
    {
      usageError("unknown option '" + argument + "'");
    }
  }
  if (urdf_file.empty() || device_name.empty() || seconds <= 0.0)
  {
    usageError("give the URDF file, --device and --seconds");
  }
  std::ifstream file(urdf_file);
  std::stringstream urdf;
  if (!(urdf << file.rdbuf()))
  {
    usageError("cannot read the URDF file '" + urdf_file + "'");
  }
  const DeviceRow& row = *findDevice(device_name);

  auto* counters = static_cast<SharedCounters*>(
      mmap(nullptr, sizeof(SharedCounters), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  new (counters) SharedCounters();
  // The node forks before this process starts any thread.
  BenchProcesses processes(counters, false);
  ros::init(ros::M_string(), "ptz_soak", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  if (!ros::master::check())
  {
    std::fprintf(stderr, "bench_soak: no rosmaster at %s (bench/soak starts one)\n", ros::master::getURI().c_str());
    return 1;
  }
  const std::string presets_file = "/tmp/ptz_soak_" + std::to_string(::getpid()) + "_presets.yaml";
  int status = 0;
  try
  {
    std::unique_ptr<DeviceHarness> device;
    if (row.start)
    {
      device = startDevice(row);
    }
    setNodeParameters(row, device.get(), urdf.str());
    ros::param::set(std::string(NODE_NAMESPACE) + "/" + NODE_NAME + "/presets_file", presets_file);
    processes.release();

    ros::NodeHandle node_handle(NODE_NAMESPACE);
    ros::AsyncSpinner spinner(1);  // the global queue: capabilities, service replies
    spinner.start();
    tf2_ros::StaticTransformBroadcaster broadcaster;
    publishFrames(broadcaster);
    StateRate state_rate(node_handle);

    const ros::WallTime started = ros::WallTime::now();
    Tally tally;
    std::atomic<bool> stop{ false };
    std::vector<std::unique_ptr<SoakClient>> soak_clients;
    PtzCapabilities::ConstPtr capabilities;
    {
      if (!waitForNode(processes, [&node_handle] {
            return ros::topic::waitForMessage<PtzCapabilities>("capabilities", node_handle, ros::Duration(0.5)) !=
                   nullptr;
          }))
      {
        throw std::runtime_error("the node did not come up");
      }
      capabilities = ros::topic::waitForMessage<PtzCapabilities>("capabilities", node_handle, ros::Duration(5.0));
    }
    const Ranges ranges = capabilities ? rangesOf(*capabilities) : Ranges();
    const bool preset_saved = savePreset(node_handle);
    for (int index = 0; index < clients; ++index)
    {
      soak_clients.push_back(std::make_unique<SoakClient>(node_handle, index, ranges, tally, stop, started));
    }
    for (auto& client : soak_clients)
    {
      if (!client->waitForServers(30.0))
      {
        throw std::runtime_error("the action servers did not come up");
      }
    }

    const pid_t node = processes.node();
    const ProcessFigures at_start = processFigures(node);
    ProcessFigures at_middle, at_end;
    state_rate.record(true);
    const ros::WallTime run_start = ros::WallTime::now();
    std::vector<std::thread> threads;
    for (auto& client : soak_clients)
    {
      threads.emplace_back([&client] { client->run(); });
    }

    // The fault injector, here: a fault every fault_period s, FAULT_ON s long, the emulator's faults in turn.
    std::map<std::string, long> injected;
    std::vector<Fault> faults;
    if (device)
    {
      for (Fault fault : ALL_FAULTS)
      {
        if (device->setFault(fault, false))
        {
          faults.push_back(fault);
        }
      }
    }
    bool crashed = false;
    bool middle_taken = false;
    std::size_t next_fault = 0;
    double next_fault_at = fault_period - FAULT_ON;
    double fault_off_at = -1.0;
    Fault active = Fault::SILENCE;
    while (true)
    {
      const double now = (ros::WallTime::now() - run_start).toSec();
      if (!processes.nodeRunning())
      {
        crashed = true;
        break;
      }
      if (now >= seconds)
      {
        break;
      }
      if (!middle_taken && now >= seconds / 2)
      {
        at_middle = processFigures(node);
        middle_taken = true;
      }
      if (fault_off_at >= 0.0 && now >= fault_off_at)
      {
        device->setFault(active, false);
        fault_off_at = -1.0;
      }
      if (!faults.empty() && fault_off_at < 0.0 && now >= next_fault_at && now + FAULT_ON < seconds)
      {
        active = faults[next_fault++ % faults.size()];
        device->setFault(active, true);
        ++injected[faultName(active)];
        fault_off_at = now + FAULT_ON;
        next_fault_at += fault_period;
      }
      ros::WallDuration(0.05).sleep();
    }
    if (fault_off_at >= 0.0)
    {
      device->setFault(active, false);
    }
    state_rate.record(false);
    if (!crashed)
    {
      at_end = processFigures(node);
    }
    stop = true;
    for (std::thread& thread : threads)
    {
      thread.join();  // each waits for its last goal's end (GOAL_DEADLINE at most)
    }
    crashed = crashed || !processes.nodeRunning();
    double mean = 0.0, worst = 0.0, best = 0.0;
    state_rate.figures(mean, worst, best);
    processes.stop();  // the node goes before its device

    std::lock_guard<std::mutex> lock(tally.mutex);
    auto figures = [](const ProcessFigures& f, bool rss) {
      char text[32];
      if (rss)
      {
        std::snprintf(text, sizeof(text), "%.1f", f.rss_mb);
      }
      else
      {
        std::snprintf(text, sizeof(text), "%d", f.fds);
      }
      return std::string(text);
    };
    std::printf("| %s | %.1f | %ld / %ld | %s | %s | %d | %s / %s / %s | %s / %s / %s | %.2f / %.2f Hz |\n",
                row.name.c_str(), seconds / 60.0, tally.goals_sent, tally.goals_ended, joined(tally.ends).c_str(),
                faults.empty() ? "none (no emulator)" : joined(injected).c_str(), crashed ? 1 : 0,
                figures(at_start, true).c_str(), figures(at_middle, true).c_str(), figures(at_end, true).c_str(),
                figures(at_start, false).c_str(), figures(at_middle, false).c_str(), figures(at_end, false).c_str(),
                mean, worst);
    std::printf("\n%s: goals sent by kind: %s; preset saved: %s; node threads start / end: %d / %d; ptz_state best "
                "%.0f s window %.2f Hz\n",
                row.name.c_str(), joined(tally.sent).c_str(), preset_saved ? "yes" : "no", at_start.threads,
                at_end.threads, WINDOW, best);
    for (const std::string& goal : tally.never_ended)
    {
      std::printf("%s: NEVER ENDED: %s\n", row.name.c_str(), goal.c_str());
    }
    std::fflush(stdout);
    status = crashed || !tally.never_ended.empty() || tally.goals_sent != tally.goals_ended ? 1 : 0;
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "bench_soak: %s\n", error.what());
    status = 1;
  }
  processes.stop();
  std::remove(presets_file.c_str());
  return status;
}

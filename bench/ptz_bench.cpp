/**
 * \file
 * \brief Benchmark of the node with the sim or pantilt_udp backend. Prints tables of figures; asserts nothing.
 *
 * The program forks twice. One child is the node: the same PtzActionServer and SimBackend the ptz_action_server
 * executable runs, with the backend wrapped by a recorder that stamps every command into shared memory
 * (CLOCK_MONOTONIC is one clock for all processes). The other child only subscribes to ptz_state and stamps each
 * arrival, as a user's node would see it. The parent is the clients, talking to the node over real ROS connections.
 *
 * Usage: ptz_bench URDF_FILE [--backend sim|pantilt_udp|flir|pelco_d|digiview] [--storm-seconds 30] [--zero-goals 1000]
 *                  [--idle-seconds 10] [--goals 1000] [--baud 9600]
 * With a device backend the node talks to an emulator in the parent process, and the figures are goal -> first
 * command at the emulator (the command's own wire time subtracted) and the PtzState rate while a goal runs.
 * A rosmaster must be running (bench/run starts one).
 */
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <numeric>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/action_client.h>
#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/ros/ptz_goal.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/core/digiview/digiview_protocol.h"
#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/motion_profile.h"
#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/emulators/digiview_emulator.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"
#include "ptz_action_server/core/sim_backend.h"
#include "ptz_action_server/ros/ptz_action_server.h"

namespace
{
using namespace ptz_action_server;
using PtzClient = actionlib::SimpleActionClient<PtzAction>;

constexpr std::size_t MAX_STATE_ARRIVALS = 4096;

/// Shared by the three processes: the node stamps commands, the observer stamps ptz_state arrivals.
struct SharedCounters
{
  std::atomic<std::uint64_t> commands{ 0 };
  std::atomic<std::int64_t> last_command_ns{ 0 };
  std::atomic<bool> record_states{ false };
  std::atomic<std::uint32_t> state_count{ 0 };
  std::int64_t state_arrivals_ns[MAX_STATE_ARRIVALS];
};

std::int64_t monotonicNanoseconds()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(SteadyClock::now().time_since_epoch()).count();
}

/// Passes everything to the real backend and stamps each command.
class RecordingBackend : public PtzBackend
{
public:
  RecordingBackend(std::shared_ptr<PtzBackend> inner, SharedCounters* counters)
    : inner_(std::move(inner)), counters_(counters)
  {
  }
  std::string name() const override
  {
    return inner_->name();
  }
  Capabilities capabilities() const override
  {
    return inner_->capabilities();
  }
  void start() override
  {
    inner_->start();
  }
  void goTo(const AxisValues& position) override
  {
    record();
    inner_->goTo(position);
  }
  void moveAtVelocity(const AxisValues& velocity) override
  {
    record();
    inner_->moveAtVelocity(velocity);
  }
  void stop() override
  {
    record();
    inner_->stop();
  }
  PtzSample sample() const override
  {
    return inner_->sample();
  }
  std::string lastFault() const override
  {
    return inner_->lastFault();
  }

private:
  void record()
  {
    counters_->last_command_ns = monotonicNanoseconds();
    counters_->commands++;
  }
  std::shared_ptr<PtzBackend> inner_;
  SharedCounters* counters_;
};

std::string readFile(const std::string& path)
{
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Which backend the node runs, and where its device is.
struct DeviceTarget
{
  std::string backend = "sim";  ///< sim, pantilt_udp, flir, pelco_d or digiview
  std::uint16_t udp_port = 0;   ///< pantilt_udp, digiview: the emulator's port
  std::string link;             ///< flir, pelco_d: the emulator's pseudo-terminal link
  unsigned baud = 9600;
};

std::shared_ptr<PtzBackend> makeBackend(const DeviceTarget& target, const Capabilities& urdf_limits)
{
  if (target.backend == "pantilt_udp")
  {
    PanTiltConfig config;
    config.link.port = target.udp_port;
    config.link.local_host = "127.0.0.1";
    return makePanTiltBackend(config);
  }
  if (target.backend == "digiview")
  {
    DigiViewConfig config;
    config.link.port = target.udp_port;
    config.digiview.acceleration = 4.0;
    return makeDigiViewBackend(config);
  }
  LinkConfig link;
  link.path = target.link;
  link.baud = target.baud;
  if (target.backend == "flir")
  {
    FlirConfig config;
    config.link = link;
    return makeFlirBackend(config);
  }
  if (target.backend == "pelco_d")
  {
    PelcoConfig config;
    config.link = link;
    return makePelcoBackend(config);
  }
  SimDeviceConfig device = SimDeviceConfig::defaults();
  for (Axis axis : { PAN, TILT })
  {
    device.axes[axis].range = urdf_limits.axes[axis].range;
    device.axes[axis].motion.max_speed = urdf_limits.axes[axis].max_speed;
  }
  return std::make_shared<SimBackend>(device);
}

/// The node process: runs until SIGINT.
int runNode(int argc, char** argv, const std::string& urdf, SharedCounters* counters, const DeviceTarget& target)
{
  ros::init(argc, argv, "ptz_action_server");
  ros::NodeHandle node_handle("/ptz");
  node_handle.setParam("robot_description", urdf);
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(urdf);
  auto backend =
      std::make_shared<RecordingBackend>(makeBackend(target, PtzActionServer::urdfLimits(kinematics)), counters);
  PtzActionServer server(node_handle, NodeConfig(), kinematics, backend);
  server.start();
  ros::spin();
  return 0;
}

/// The observer process: a separate ptz_state subscriber, so the storm clients' own load does not skew arrivals.
int runObserver(int argc, char** argv, SharedCounters* counters)
{
  ros::init(argc, argv, "ptz_bench_observer", ros::init_options::AnonymousName);
  ros::NodeHandle node_handle("/ptz");
  const ros::Subscriber subscriber =
      node_handle.subscribe<PtzState>("ptz_state", 100, [counters](const PtzState::ConstPtr&) {
        if (counters->record_states)
        {
          const std::uint32_t index = counters->state_count++;
          if (index < MAX_STATE_ARRIVALS)
          {
            counters->state_arrivals_ns[index] = monotonicNanoseconds();
          }
        }
      });
  ros::spin();
  return 0;
}

struct CpuSample
{
  double cpu_seconds;
  double wall_seconds;
};

/// CPU time of every thread of \p pid (from schedstat, in ns resolution) and the wall clock.
CpuSample cpuOf(pid_t pid)
{
  double cpu_seconds = 0.0;
  const std::string tasks = "/proc/" + std::to_string(pid) + "/task";
  for (const auto& task : std::filesystem::directory_iterator(tasks))
  {
    std::ifstream file(task.path() / "schedstat");
    double nanoseconds = 0.0;
    if (file >> nanoseconds)
    {
      cpu_seconds += nanoseconds * 1e-9;
    }
  }
  return { cpu_seconds, secondsBetween(TimePoint(), SteadyClock::now()) };
}

double cpuPercent(const CpuSample& from, const CpuSample& to)
{
  return 100.0 * (to.cpu_seconds - from.cpu_seconds) / (to.wall_seconds - from.wall_seconds);
}

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

double percentile(std::vector<double> values, double share)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(share * values.size()));
  return values[index];
}

struct Row
{
  std::string figure;
  std::string value;
  std::string target;
};

void printTable(const char* title, const std::vector<Row>& rows)
{
  std::printf("\n%s\n\n| figure | value | target |\n|---|---|---|\n", title);
  for (const Row& row : rows)
  {
    std::printf("| %s | %s | %s |\n", row.figure.c_str(), row.value.c_str(), row.target.c_str());
  }
  std::fflush(stdout);
}

int runClients(pid_t node, SharedCounters* counters, double storm_seconds, int zero_goals, double idle_seconds)
{
  ros::NodeHandle node_handle("/ptz");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  PtzClient client(node_handle, "move_ptz/position_abs", true);
  if (!client.waitForServer(ros::Duration(30.0)))
  {
    std::fprintf(stderr, "ptz_bench: the node did not come up\n");
    return 1;
  }
  std::vector<Row> rows;
  char text[128];

  // Idle CPU: nothing but the 10 Hz state.
  ros::WallDuration(1.0).sleep();
  const CpuSample idle_start = cpuOf(node);
  ros::WallDuration(idle_seconds).sleep();
  std::snprintf(text, sizeof(text), "%.2f %%", cpuPercent(idle_start, cpuOf(node)));
  rows.push_back({ "node CPU, idle (" + std::to_string(static_cast<int>(idle_seconds)) + " s)", text, "<= 1 %" });

  // Reach time of a 2 rad pan goal against the trapezoid's closed-form minimum.
  client.sendGoal(makePtzGoal(-1.0, 0.0, 1.0));
  client.waitForResult(ros::Duration(10.0));
  const double minimum = TrapezoidProfile::minimumDuration(2.0, AxisMotionLimits{ 1.5, 3.0, 0.0 });
  std::vector<double> ratios;
  for (int run = 0; run < 6; ++run)
  {
    const double target = run % 2 == 0 ? 1.0 : -1.0;
    const ros::WallTime sent = ros::WallTime::now();
    client.sendGoal(makePtzGoal(target, 0.0, 1.0));
    client.waitForResult(ros::Duration(10.0));
    ratios.push_back((ros::WallTime::now() - sent).toSec() / minimum);
  }
  std::snprintf(text, sizeof(text), "%.3f mean, %.3f max (minimum %.3f s)",
                std::accumulate(ratios.begin(), ratios.end(), 0.0) / ratios.size(),
                *std::max_element(ratios.begin(), ratios.end()), minimum);
  rows.push_back({ "2 rad goal: reach time / closed-form minimum", text, "<= 1.10" });

  // Zero-length goals: goal -> result, and goal -> first backend command.
  std::vector<double> result_ms;
  std::vector<double> command_ms;
  int zero_failed = 0;
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
  std::snprintf(text, sizeof(text), "p50 %.2f ms, p99 %.2f ms (%d goals, %d not succeeded)", percentile(result_ms, 0.5),
                percentile(result_ms, 0.99), zero_goals, zero_failed);
  rows.push_back({ "zero-length goal -> result", text, "p99 <= 5 ms" });
  std::snprintf(text, sizeof(text), "p50 %.2f ms, p99 %.2f ms", percentile(command_ms, 0.5),
                percentile(command_ms, 0.99));
  rows.push_back({ "goal -> first backend command", text, "" });

  // The storm: 4 clients at ~50 Hz each for storm_seconds, while the observer process times ptz_state arrivals.
  std::atomic<bool> storming{ true };
  counters->state_count = 0;
  counters->record_states = true;
  std::vector<std::thread> threads;
  std::atomic<int> goals_sent{ 0 };
  std::atomic<int> goals_done{ 0 };
  const CpuSample storm_start = cpuOf(node);
  const CpuSample clients_start = cpuOf(getpid());
  for (int index = 0; index < 4; ++index)
  {
    threads.emplace_back([&, index]() {
      actionlib::ActionClient<PtzAction> storm_client(node_handle, "move_ptz/position_abs");
      storm_client.waitForActionServerToStart(ros::Duration(10.0));
      std::vector<actionlib::ClientGoalHandle<PtzAction>> handles;
      ros::WallRate rate(50.0);
      int round = 0;
      while (storming)
      {
        handles.push_back(storm_client.sendGoal(makePtzGoal(0.5 * std::sin(0.05 * round + index), 0.1 * index, 1.0)));
        ++goals_sent;
        ++round;
        rate.sleep();
      }
      const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
      for (auto& handle : handles)
      {
        while (handle.getCommState() != actionlib::CommState::DONE && ros::WallTime::now() < deadline)
        {
          ros::WallDuration(0.01).sleep();
        }
        goals_done += handle.getCommState() == actionlib::CommState::DONE;
      }
    });
  }
  ros::WallDuration(storm_seconds).sleep();
  const CpuSample storm_end = cpuOf(node);
  const CpuSample clients_end = cpuOf(getpid());
  counters->record_states = false;
  storming = false;
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  counters->record_states = false;
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
  std::snprintf(text, sizeof(text), "%.3f Hz", rate_hz);
  rows.push_back({ "ptz_state rate under the storm", text, "10 Hz +- 2 %" });
  std::snprintf(text, sizeof(text), "p50 %.1f ms, p99 %.1f ms, max %.1f ms", percentile(intervals_ms, 0.5),
                percentile(intervals_ms, 0.99), percentile(intervals_ms, 1.0));
  rows.push_back({ "ptz_state interval under the storm", text, "p99 <= 120 ms" });
  std::snprintf(text, sizeof(text), "%d sent, %d ended (%.0f goals/s)", goals_sent.load(), goals_done.load(),
                goals_sent / storm_seconds);
  rows.push_back({ "storm goals (4 clients x ~50 Hz)", text, "none lost" });
  std::snprintf(text, sizeof(text), "%.1f %%", cpuPercent(storm_start, storm_end));
  rows.push_back({ "node CPU under the storm", text, "" });
  std::snprintf(text, sizeof(text), "%.1f %%", cpuPercent(clients_start, clients_end));
  rows.push_back({ "client process CPU under the storm", text, "" });
  std::snprintf(text, sizeof(text), "%.1f MB", peakRssKilobytes(node) / 1024.0);
  rows.push_back({ "node peak RSS", text, "" });

  printTable("sim backend", rows);
  return 0;
}

/// A goal command as it reached an emulator: when its last byte arrived, and its own time on the wire.
struct Arrival
{
  TimePoint at;
  double wire = 0.0;
};
/// The goal commands an emulator has received so far (polls and state requests left out).
using ArrivalsProbe = std::function<std::vector<Arrival>()>;

/**
 * \brief Goal -> first command at the emulator over \p goals goals (the command's own wire time subtracted), and
 * the PtzState rate while a long goal runs.
 */
int runDeviceClients(const std::string& title, const ArrivalsProbe& arrivals, int goals, double pause)
{
  ros::NodeHandle node_handle("/ptz");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  actionlib::ActionClient<PtzAction> client(node_handle, "move_ptz/position_abs");
  if (!client.waitForActionServerToStart(ros::Duration(30.0)))
  {
    std::fprintf(stderr, "ptz_bench: the node did not come up\n");
    return 1;
  }
  ros::WallDuration(1.0).sleep();  // the link is up and the setup is done
  std::vector<double> latency_ms;
  std::vector<double> wire_ms;
  std::vector<actionlib::ClientGoalHandle<PtzAction>> handles;
  for (int index = 0; index < goals; ++index)
  {
    const std::size_t before = arrivals().size();
    const TimePoint sent = SteadyClock::now();
    handles.push_back(client.sendGoal(makePtzGoal(index % 2 == 0 ? 0.10 : 0.12, 0.0, 1.0)));
    const TimePoint deadline = addSeconds(sent, 1.0);
    std::vector<Arrival> now = arrivals();
    while (now.size() == before && SteadyClock::now() < deadline)
    {
      std::this_thread::sleep_for(std::chrono::microseconds(100));
      now = arrivals();
    }
    if (now.size() > before)
    {
      const Arrival& first = now[before];
      latency_ms.push_back((secondsBetween(sent, first.at) - first.wire) * 1e3);
      wire_ms.push_back(first.wire * 1e3);
    }
    ros::WallDuration(pause).sleep();  // let the goal's remaining commands go out before the next goal
    if (handles.size() > 100)
    {
      handles.erase(handles.begin(), handles.begin() + 50);
    }
  }

  // PtzState while a goal runs: from one pan limit side to the other (about 2 s).
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
  double rate = 0.0;
  {
    std::lock_guard<std::mutex> lock(arrivals_mutex);
    recording = false;
    if (state_times.size() > 1)
    {
      rate = (state_times.size() - 1) / (state_times.back() - state_times.front());
    }
  }

  std::vector<Row> rows;
  char text[160];
  std::snprintf(text, sizeof(text),
                "p50 %.2f ms, p99 %.2f ms, max %.2f ms (%zu of %d goals; wire time %.2f ms subtracted)",
                percentile(latency_ms, 0.5), percentile(latency_ms, 0.99), percentile(latency_ms, 1.0),
                latency_ms.size(), goals, percentile(wire_ms, 0.5));
  rows.push_back({ "goal -> first command at the emulator", text,
                   title == "pantilt_udp" || title == "digiview" ? "p99 <= 5 ms" : "" });
  std::snprintf(text, sizeof(text), "%.2f Hz (%zu messages)", rate, state_times.size());
  rows.push_back({ "ptz_state rate while a goal runs", text, "10 Hz" });
  printTable((title + " backend").c_str(), rows);
  return 0;
}
}  // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: ptz_bench URDF_FILE [--backend sim|pantilt_udp|flir|pelco_d|digiview] "
                         "[--storm-seconds S] "
                         "[--zero-goals N] [--idle-seconds S] [--goals N] [--baud N]\n");
    return 2;
  }
  const std::string urdf = readFile(argv[1]);
  std::string backend = "sim";
  double storm_seconds = 30.0;
  int zero_goals = 1000;
  double idle_seconds = 10.0;
  int goals = 1000;
  unsigned baud = 9600;
  for (int index = 2; index + 1 < argc; index += 2)
  {
    const std::string option = argv[index];
    const std::string value = argv[index + 1];
    if (option == "--backend")
    {
      backend = value;
    }
    else if (option == "--storm-seconds")
    {
      storm_seconds = std::stod(value);
    }
    else if (option == "--zero-goals")
    {
      zero_goals = std::stoi(value);
    }
    else if (option == "--idle-seconds")
    {
      idle_seconds = std::stod(value);
    }
    else if (option == "--goals")
    {
      goals = std::stoi(value);
    }
    else if (option == "--baud")
    {
      baud = static_cast<unsigned>(std::stoul(value));
    }
  }
  auto* counters = static_cast<SharedCounters*>(
      mmap(nullptr, sizeof(SharedCounters), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  new (counters) SharedCounters();

  DeviceTarget target;
  target.backend = backend;
  target.baud = baud;
  if (backend == "pantilt_udp")
  {
    UdpSocket probe;  // an ephemeral port for the emulator, found before the fork
    probe.bind("127.0.0.1", 0);
    target.udp_port = probe.localEndpoint().port();
  }
  else if (backend == "digiview")
  {
    boost::asio::io_context probe_context;  // a free TCP port for the emulator, found before the fork
    boost::asio::ip::tcp::acceptor probe(probe_context,
                                         boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
    target.udp_port = probe.local_endpoint().port();
  }
  else if (backend == "flir" || backend == "pelco_d")
  {
    target.link = "/tmp/ptz_bench_" + backend + "_" + std::to_string(getpid());
  }
  const pid_t node = fork();
  if (node == 0)
  {
    return runNode(argc, argv, urdf, counters, target);
  }
  std::vector<pid_t> children = { node };
  int status = 0;
  const double byte_time = 10.0 / baud;
  if (backend == "pantilt_udp")
  {
    PanTiltEmulatorConfig config;
    config.port = target.udp_port;
    PanTiltEmulator device(config);
    ros::init(argc, argv, "ptz_bench", ros::init_options::AnonymousName);
    status = runDeviceClients(
        "pantilt_udp",
        [&device] {
          std::vector<Arrival> arrivals;
          for (const ReceivedDatagram& datagram : device.received().items())
          {
            if (!datagram.bytes.empty() && datagram.bytes[0] != cr::pantilt::PARAMS_HEADER)
            {
              arrivals.push_back(Arrival{ datagram.at, 0.0 });
            }
          }
          return arrivals;
        },
        goals, 0.002);
  }
  else if (backend == "digiview")
  {
    DigiViewEmulatorConfig config;
    config.port = target.udp_port;
    DigiViewEmulator device(config);
    ros::init(argc, argv, "ptz_bench", ros::init_options::AnonymousName);
    status = runDeviceClients(
        "digiview",
        [&device] {
          std::vector<Arrival> arrivals;
          for (const ReceivedMessage& item : device.received().items())
          {
            if (item.message.message_type == digiview::MessageType::SET_PARAMETERS &&
                item.message.param_type == digiview::ParamType::CAM_TARGETING)
            {
              arrivals.push_back(Arrival{ item.at, 0.0 });
            }
          }
          return arrivals;
        },
        goals, 0.002);
  }
  else if (backend == "flir")
  {
    FlirPtuEmulatorConfig config;
    config.port.link = target.link;
    config.port.baud = baud;
    FlirPtuEmulator device(config);
    ros::init(argc, argv, "ptz_bench", ros::init_options::AnonymousName);
    status = runDeviceClients(
        "serial flir at " + std::to_string(baud) + " baud",
        [&device, byte_time] {
          std::vector<Arrival> arrivals;
          for (const ReceivedCommand& command : device.received().items())
          {
            if (command.text != "PP" && command.text != "TP")  // polls
            {
              arrivals.push_back(Arrival{ command.at, (command.text.size() + 1) * byte_time });
            }
          }
          return arrivals;
        },
        goals, 80 * byte_time + 0.005);
  }
  else if (backend == "pelco_d")
  {
    PelcoDEmulatorConfig config;
    config.port.link = target.link;
    config.port.baud = baud;
    PelcoDEmulator device(config);
    ros::init(argc, argv, "ptz_bench", ros::init_options::AnonymousName);
    status = runDeviceClients(
        "serial pelco_d at " + std::to_string(baud) + " baud",
        [&device, byte_time] {
          std::vector<Arrival> arrivals;
          for (const ReceivedFrame& item : device.received().items())
          {
            const std::uint8_t command = item.frame.command2;
            if (command != pelco::QUERY_PAN && command != pelco::QUERY_TILT && command != pelco::QUERY_ZOOM)
            {
              arrivals.push_back(Arrival{ item.at, pelco::FRAME_SIZE * byte_time });
            }
          }
          return arrivals;
        },
        goals, 6 * pelco::FRAME_SIZE * byte_time + 0.005);
  }
  else
  {
    const pid_t observer = fork();
    if (observer == 0)
    {
      return runObserver(argc, argv, counters);
    }
    children.insert(children.begin(), observer);
    ros::init(argc, argv, "ptz_bench", ros::init_options::AnonymousName);
    status = runClients(node, counters, storm_seconds, zero_goals, idle_seconds);
  }
  for (pid_t child : children)
  {
    kill(child, SIGINT);
    waitpid(child, nullptr, 0);
  }
  return status;
}

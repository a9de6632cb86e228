/**
 * \file
 * \brief Benchmark of the ptz_action_server node, one device of the table at a time. Prints tables of figures;
 * asserts nothing.
 *
 * The program forks. One child is the node: it loads its backend through the same BackendLoader as the
 * ptz_action_server executable, from the parameters this program sets on the rosmaster as a launch file would, and
 * wraps it in a recorder that stamps every command in shared memory (CLOCK_MONOTONIC is one clock for all
 * processes). For the sim row a second child only subscribes to ptz_state and stamps each arrival, as a user's node
 * would see it. The parent runs the device's emulator, if the row has one, and the clients, over real ROS
 * connections. A rosmaster must be running (bench/run starts one).
 */
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>

#include <ros/ros.h>

#include "bench_common.h"
#include "bench_processes.h"
#include "device_table.h"
#include "figures.h"

namespace
{
using namespace ptz_bench;

const char* const USAGE = "usage: ptz_bench --list\n"
                          "       ptz_bench --names\n"
                          "       ptz_bench URDF_FILE [--device NAME] [--goals N] [--cancels N] [--idle-seconds S] "
                          "[--zero-goals N]\n"
                          "                 [--storm-seconds S]\n"
                          "\n"
                          "Benchmarks the ptz_action_server node on one device of the table and prints the figures (it "
                          "asserts nothing).\n"
                          "A rosmaster must be running: bench/run starts one and runs every device.\n"
                          "\n"
                          "  --list             print the device table (plugin, emulator, parameters, what counts as a "
                          "command)\n"
                          "  --names            print the device names, one a line\n"
                          "  --device NAME      the device to run (default sim)\n"
                          "  --goals N          devices: goals for goal -> first command (default: the device's, 300 "
                          "or 1000)\n"
                          "  --cancels N        every device: cancelled goals for cancel -> stop (default 100)\n"
                          "  --idle-seconds S   sim: each of the four idle windows (default 10): CPU, CPU with every "
                          "topic "
                          "listened,\n"
                          "                     the state tick part by part, CPU at rest after the goals\n"
                          "  --zero-goals N     sim: zero-length goals for goal -> result (default 1000)\n"
                          "  --storm-seconds S  sim: the goal storm (default 30, at most 400)\n";

enum class Mode
{
  RUN,
  LIST,
  NAMES,
};

[[noreturn]] void usageError(const std::string& message)
{
  std::fprintf(stderr, "ptz_bench: %s\n\n%s", message.c_str(), USAGE);
  std::exit(2);
}

int wholeNumber(const std::string& option, const std::string& text, int min, int max)
{
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || value < min || value > max)
  {
    usageError(option + " needs a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "], not '" +
               text + "'");
  }
  return static_cast<int>(value);
}

double seconds(const std::string& option, const std::string& text, double max)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value > 0.0 && value <= max))
  {
    usageError(option + " needs seconds in (0, " + std::to_string(static_cast<int>(max)) + "], not '" + text + "'");
  }
  return value;
}

Mode parseOptions(int argc, char** argv, BenchOptions& options)
{
  Mode mode = Mode::RUN;
  options.device = "sim";
  for (int index = 1; index < argc; ++index)
  {
    const std::string argument = argv[index];
    if (argument == "--help" || argument == "-h")
    {
      std::printf("%s", USAGE);
      std::exit(0);
    }
    if (argument == "--list" || argument == "--names")
    {
      mode = argument == "--list" ? Mode::LIST : Mode::NAMES;
      continue;
    }
    if (argument.rfind("-", 0) != 0)
    {
      if (!options.urdf_file.empty())
      {
        usageError("one URDF file only, not '" + options.urdf_file + "' and '" + argument + "'");
      }
      options.urdf_file = argument;
      continue;
    }
    static const char* const WITH_VALUE[] = { "--device",       "--goals",      "--cancels",
                                              "--idle-seconds", "--zero-goals", "--storm-seconds" };
    if (std::find(std::begin(WITH_VALUE), std::end(WITH_VALUE), argument) == std::end(WITH_VALUE))
    {
      usageError("unknown option '" + argument + "'");
    }
    if (index + 1 >= argc)
    {
      usageError(argument + " needs a value");
    }
    const std::string value = argv[++index];
    if (argument == "--device")
    {
      if (findDevice(value) == nullptr)
      {
        usageError("unknown device '" + value + "'; devices: " + deviceNames());
      }
      options.device = value;
    }
    else if (argument == "--goals")
    {
      options.goals = wholeNumber(argument, value, 1, 1000000);
    }
    else if (argument == "--cancels")
    {
      options.cancels = wholeNumber(argument, value, 1, 100000);
    }
    else if (argument == "--idle-seconds")
    {
      options.idle_seconds = seconds(argument, value, 3600.0);
    }
    else if (argument == "--zero-goals")
    {
      options.zero_goals = wholeNumber(argument, value, 1, 1000000);
    }
    else
    {
      // The observer keeps MAX_STATE_ARRIVALS arrivals: 409 s at 10 Hz.
      options.storm_seconds = seconds(argument, value, 400.0);
    }
  }
  if (mode == Mode::RUN && options.urdf_file.empty())
  {
    usageError("give the URDF file (urdf/ptz.urdf)");
  }
  return mode;
}

}  // namespace

int main(int argc, char** argv)
{
  BenchOptions options;
  const Mode mode = parseOptions(argc, argv, options);
  if (mode != Mode::RUN)
  {
    if (mode == Mode::LIST)
    {
      printDeviceTable();
    }
    else
    {
      for (const DeviceRow& row : deviceTable())
      {
        std::printf("%s\n", row.name.c_str());
      }
    }
    return 0;
  }
  std::ifstream file(options.urdf_file);
  std::stringstream urdf;
  if (!(urdf << file.rdbuf()))
  {
    usageError("cannot read the URDF file '" + options.urdf_file + "'");
  }
  const DeviceRow& row = *findDevice(options.device);

  auto* counters = static_cast<SharedCounters*>(
      mmap(nullptr, sizeof(SharedCounters), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  new (counters) SharedCounters();
  int status = 1;
  // The children fork before this process starts any thread.
  BenchProcesses processes(counters, !row.start);
  ros::init(ros::M_string(), "ptz_bench", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  if (!ros::master::check())
  {
    std::fprintf(stderr, "ptz_bench: no rosmaster at %s (bench/run starts one)\n", ros::master::getURI().c_str());
    return 1;
  }
  try
  {
    std::unique_ptr<DeviceHarness> device;
    if (row.start)
    {
      device = startDevice(row);
    }
    setNodeParameters(row, device.get(), urdf.str());
    processes.release();
    status = device ? runDeviceFigures(row, *device, options, processes) : runSimFigures(options, counters, processes);
    processes.stop();  // the node goes before its device
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "ptz_bench: %s\n", error.what());
    status = 1;
  }
  return status;
}

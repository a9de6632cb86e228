#include "device_table.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "bench_processes.h"

namespace ptz_bench
{
namespace
{
using ptz_action_server::paramValue;
using Kind = ClassifiedCommand::Kind;

/// A parameter's value as --list shows it: the emulator's, or YAML-like (strings that read as numbers quoted).
std::string show(const HarnessParam& param)
{
  switch (param.source)
  {
    case HarnessParam::Source::EMULATOR_PORT:
      return "(the emulator's port)";
    case HarnessParam::Source::EMULATOR_LINK:
      return "(the emulator's pty link)";
    case HarnessParam::Source::VALUE:
      break;
  }
  if (const auto* text = std::get_if<std::string>(&param.value))
  {
    char* end = nullptr;
    std::strtod(text->c_str(), &end);
    return end != text->c_str() && *end == '\0' ? "\"" + *text + "\"" : *text;
  }
  if (const auto* number = std::get_if<int>(&param.value))
  {
    return std::to_string(*number);
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%g", std::get<double>(param.value));
  return text;
}
}  // namespace

std::vector<ClassifiedCommand> countedCommands(const DeviceHarness& device, const DeviceRow& row, bool stops)
{
  const Kind kind = stops && !row.figures.holds_aim ? Kind::STOP : Kind::MOVE;
  std::vector<ClassifiedCommand> counted;
  for (const ClassifiedCommand& command : device.commands())
  {
    if (command.kind == kind)
    {
      counted.push_back(command);
    }
  }
  return counted;
}

const std::vector<DeviceRow>& deviceTable()
{
  static const std::vector<DeviceRow> rows = [] {
    std::vector<DeviceRow> table;
    DeviceRow sim;
    sim.name = "sim";
    sim.plugin = "sim";
    // A field of view, so a tick publishes everything a camera can: ptz_state, joint_states, tf, field_of_view.
    sim.params = { paramValue("field_of_view/horizontal", 1.0), paramValue("field_of_view/vertical", 0.6) };
    table.push_back(sim);
    const std::vector<DeviceRow>& harnesses = ptz_action_server::allHarnesses();
    table.insert(table.end(), harnesses.begin(), harnesses.end());
    return table;
  }();
  return rows;
}

const DeviceRow* findDevice(const std::string& name)
{
  for (const DeviceRow& row : deviceTable())
  {
    if (row.name == name)
    {
      return &row;
    }
  }
  return nullptr;
}

std::string deviceNames()
{
  std::string names;
  for (const DeviceRow& row : deviceTable())
  {
    names += (names.empty() ? "" : ", ") + row.name;
  }
  return names;
}

void printDeviceTable()
{
  std::printf("| device | plugin | emulator | parameters under ~ | goal commands | stop | goals |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const DeviceRow& row : deviceTable())
  {
    std::string params = "backend: " + row.plugin;
    for (const HarnessParam& param : row.params)
    {
      params += ", " + param.name + ": " + show(param);
    }
    const ptz_action_server::HarnessFigures& figures = row.figures;
    const bool emulated = static_cast<bool>(row.start);
    std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", row.name.c_str(), row.plugin.c_str(),
                emulated ? figures.summary.c_str() : "none (the backend is the simulation)", params.c_str(),
                emulated ? figures.goal_items.c_str() : "the backend's goTo / moveAtVelocity / stop calls",
                emulated ? figures.stop_items.c_str() : "the backend's stop() call",
                emulated ? std::to_string(figures.goals).c_str() : "-");
  }
  std::fflush(stdout);
}

std::unique_ptr<DeviceHarness> startDevice(const DeviceRow& row)
{
  const std::string link =
      std::filesystem::temp_directory_path() / ("ptz_bench_" + row.name + "_" + std::to_string(::getpid()));
  std::unique_ptr<DeviceHarness> device = row.start(link);
  if (!device->link().empty())
  {
    removeOnFatalSignal(device->link());
  }
  return device;
}

}  // namespace ptz_bench

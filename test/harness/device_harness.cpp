#include "harness/device_harness.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
using PortKind = DevicePortConfig::Kind;

bool DeviceHarness::setFault(EmulatorFault fault, bool on)
{
  EmulatorFaults* switches = faults();
  return switches != nullptr && switches->setFault(fault, on);
}

ParamValue HarnessParam::valueFor(const DeviceHarness& harness) const
{
  switch (source)
  {
    case Source::EMULATOR_PORT:
      return static_cast<int>(harness.port());
    case Source::EMULATOR_LINK:
      return harness.link();
    case Source::VALUE:
      break;
  }
  return value;
}

HarnessParam paramValue(const std::string& name, const ParamValue& value)
{
  return HarnessParam{ name, value, HarnessParam::Source::VALUE };
}

HarnessParam emulatorPort(const std::string& name)
{
  return HarnessParam{ name, 0, HarnessParam::Source::EMULATOR_PORT };
}

HarnessParam emulatorLink(const std::string& name)
{
  return HarnessParam{ name, std::string(), HarnessParam::Source::EMULATOR_LINK };
}

std::vector<HarnessParam> serialParams(const std::string& protocol, unsigned baud)
{
  if (baud == 0)
  {
    return { paramValue(protocol + "/transport", "tcp"), paramValue(protocol + "/host", "127.0.0.1"),
             emulatorPort(protocol + "/port") };
  }
  return { paramValue(protocol + "/transport", "serial"), emulatorLink(protocol + "/port"),
           paramValue(protocol + "/baud", static_cast<int>(baud)) };
}

HarnessEntry serialEntry(const std::string& plugin, unsigned baud, const std::string& emulator,
                         std::function<std::unique_ptr<DeviceHarness>(const DevicePortConfig& port)> start)
{
  const PortKind kind = baud == 0 ? PortKind::TCP : PortKind::PTY;
  HarnessEntry entry;
  entry.name = plugin + (baud == 0 ? "_tcp" : "_serial_" + std::to_string(baud));
  entry.plugin = plugin;
  entry.params = serialParams(plugin, baud);
  entry.figures.summary = emulator + ", " + portSummary(kind, baud);
  entry.figures.goals = baud == 0 ? 1000 : 300;
  entry.start = [kind, baud, start = std::move(start)](const std::string& link) {
    DevicePortConfig port;
    port.kind = kind;
    port.baud = baud;
    port.link = kind == PortKind::PTY ? link : "";
    return start(port);
  };
  return entry;
}

double byteTime(PortKind kind, unsigned baud)
{
  return kind == PortKind::PTY ? 10.0 / baud : 0.0;
}

std::string portSummary(PortKind kind, unsigned baud)
{
  switch (kind)
  {
    case PortKind::TCP:
      return "TCP server on 127.0.0.1, ephemeral port";
    case PortKind::UDP:
      return "UDP on 127.0.0.1, ephemeral port";
    default:
      return formatText("pseudo-terminal at %u baud", baud);
  }
}

std::string harnessLink(const std::string& name)
{
  static std::atomic<int> counter{ 0 };
  return std::filesystem::temp_directory_path() /
         ("ptz_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
}

}  // namespace ptz_action_server

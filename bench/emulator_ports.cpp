#include <unistd.h>

#include <filesystem>
#include <string>

#include "bench_processes.h"
#include "device_table.h"
#include "ptz_action_server/core/text.h"

namespace ptz_bench
{
using ptz_action_server::DevicePortConfig;
using PortKind = DevicePortConfig::Kind;

double byteTime(PortKind kind, unsigned baud)
{
  return kind == PortKind::PTY ? 10.0 / baud : 0.0;
}

DevicePortConfig portConfig(PortKind kind, unsigned baud, const std::string& row)
{
  DevicePortConfig port;
  port.kind = kind;
  port.baud = baud;
  if (kind == PortKind::PTY)
  {
    port.link = std::filesystem::temp_directory_path() / ("ptz_bench_" + row + "_" + std::to_string(::getpid()));
    removeOnFatalSignal(port.link);
  }
  return port;
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
      return ptz_action_server::formatText("pseudo-terminal at %u baud", baud);
  }
}

}  // namespace ptz_bench

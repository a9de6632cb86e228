#include "harness/flir_harness.h"

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
using PortKind = DevicePortConfig::Kind;

/// The unit on a pseudo-terminal at \p baud, or over TCP (\p baud 0).
HarnessEntry flirEntry(unsigned baud)
{
  const PortKind kind = baud == 0 ? PortKind::TCP : PortKind::PTY;
  HarnessEntry entry;
  entry.name = baud == 0 ? "flir_tcp" : "flir_serial_" + std::to_string(baud);
  entry.plugin = "flir";
  entry.params = serialParams("flir", baud);
  HarnessFigures& figures = entry.figures;
  figures.summary = "FlirPtuEmulator, " + portSummary(kind, baud);
  figures.goal_items = "the mode, speed and position commands (CI, PS, TS, PP, TP with a value); wire time: its "
                       "characters and the delimiter";
  figures.stop_items = "H (halt)";
  figures.goal_pause = 80 * byteTime(kind, baud) + 0.005;
  // On a serial line an exchange already on the wire (a poll and its reply, ~12 bytes) may go first; the tests
  // allowed it and 1 ms.
  figures.goal_target = kind == PortKind::TCP ? "p99 <= 5 ms" : "";
  figures.stop_target = kind == PortKind::TCP ? "p99 <= 5 ms" :
                                                formatText("p99 <= one exchange + 1 ms (%.1f ms)",
                                                           (12 * byteTime(kind, baud) + 0.001) * 1e3);
  figures.goals = baud == 0 ? 1000 : 300;
  entry.start = [kind, baud](const std::string& link) {
    FlirPtuEmulatorConfig config;
    config.port.kind = kind;
    config.port.baud = baud;
    config.port.link = kind == PortKind::PTY ? link : "";
    return std::make_unique<FlirHarness>(config);
  };
  return entry;
}
}  // namespace

std::vector<HarnessEntry> flirHarnesses()
{
  return { flirEntry(9600), flirEntry(115200), flirEntry(0) };
}

}  // namespace ptz_action_server

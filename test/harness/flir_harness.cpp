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
  HarnessEntry entry = serialEntry("flir", baud, "FlirPtuEmulator", [](const DevicePortConfig& port) {
    FlirPtuEmulatorConfig config;
    config.port = port;
    return std::make_unique<FlirHarness>(config);
  });
  const PortKind kind = baud == 0 ? PortKind::TCP : PortKind::PTY;
  HarnessFigures& figures = entry.figures;
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
  return entry;
}
}  // namespace

std::vector<HarnessEntry> flirHarnesses()
{
  return { flirEntry(9600), flirEntry(115200), flirEntry(0) };
}

}  // namespace ptz_action_server

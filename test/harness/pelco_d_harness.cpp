#include "harness/pelco_d_harness.h"

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
using PortKind = DevicePortConfig::Kind;

/// The device (address 1) on a pseudo-terminal at \p baud, or over TCP (\p baud 0).
HarnessEntry pelcoEntry(unsigned baud)
{
  const PortKind kind = baud == 0 ? PortKind::TCP : PortKind::PTY;
  HarnessEntry entry;
  entry.name = baud == 0 ? "pelco_d_tcp" : "pelco_d_serial_" + std::to_string(baud);
  entry.plugin = "pelco_d";
  entry.params = serialParams("pelco_d", baud);
  HarnessFigures& figures = entry.figures;
  figures.summary = "PelcoDEmulator (address 1), " + portSummary(kind, baud);
  figures.goal_items = "the set position frames (pan, tilt, zoom); wire time: 7 bytes";
  figures.stop_items = "the stop frame (all zero)";
  figures.goal_pause = 6 * pelco::FRAME_SIZE * byteTime(kind, baud) + 0.005;
  // On a serial line a frame already on the wire (a query) may go first; the tests allowed it and 2 ms.
  figures.goal_target = kind == PortKind::TCP ? "p99 <= 5 ms" : "";
  figures.stop_target = kind == PortKind::TCP ? "p99 <= 5 ms" :
                                                formatText("p99 <= one frame time + 2 ms (%.1f ms)",
                                                           (pelco::FRAME_SIZE * byteTime(kind, baud) + 0.002) * 1e3);
  figures.goals = baud == 0 ? 1000 : 300;
  entry.start = [kind, baud](const std::string& link) {
    PelcoDEmulatorConfig config;
    config.port.kind = kind;
    config.port.baud = baud;
    config.port.link = kind == PortKind::PTY ? link : "";
    return std::make_unique<PelcoDHarness>(config);
  };
  return entry;
}
}  // namespace

std::vector<HarnessEntry> pelcoDHarnesses()
{
  return { pelcoEntry(9600), pelcoEntry(115200), pelcoEntry(0) };
}

}  // namespace ptz_action_server

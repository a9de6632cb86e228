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
  HarnessEntry entry = serialEntry("pelco_d", baud, "PelcoDEmulator (address 1)", [](const DevicePortConfig& port) {
    PelcoDEmulatorConfig config;
    config.port = port;
    return std::make_unique<PelcoDHarness>(config);
  });
  const PortKind kind = baud == 0 ? PortKind::TCP : PortKind::PTY;
  HarnessFigures& figures = entry.figures;
  figures.goal_items = "the set position frames (pan, tilt, zoom); wire time: 7 bytes";
  figures.stop_items = "the stop frame (all zero)";
  figures.goal_pause = 6 * pelco::FRAME_SIZE * byteTime(kind, baud) + 0.005;
  // On a serial line a frame already on the wire (a query) may go first; the tests allowed it and 2 ms.
  figures.goal_target = kind == PortKind::TCP ? "p99 <= 5 ms" : "";
  figures.stop_target = kind == PortKind::TCP ? "p99 <= 5 ms" :
                                                formatText("p99 <= one frame time + 2 ms (%.1f ms)",
                                                           (pelco::FRAME_SIZE * byteTime(kind, baud) + 0.002) * 1e3);
  return entry;
}
}  // namespace

std::vector<HarnessEntry> pelcoDHarnesses()
{
  return { pelcoEntry(9600), pelcoEntry(115200), pelcoEntry(0) };
}

}  // namespace ptz_action_server

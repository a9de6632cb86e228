#include "harness/pantilt_harness.h"

namespace ptz_action_server
{
std::vector<HarnessEntry> pantiltHarnesses()
{
  HarnessEntry entry;
  entry.name = "pantilt_udp";
  entry.plugin = "pantilt";
  entry.params = { paramValue("pantilt/transport", "udp"), paramValue("pantilt/host", "127.0.0.1"),
                   emulatorPort("pantilt/port"), paramValue("pantilt/local_host", "127.0.0.1"),
                   paramValue("pantilt/format", "seed") };
  entry.figures.summary = "PanTiltEmulator, UDP on 127.0.0.1, ephemeral port, format seed";
  entry.figures.goal_items = "every SET_PARAM or COMMAND datagram but STOP and RESTART; no wire time";
  entry.figures.stop_items = "a COMMAND datagram STOP";
  entry.figures.goal_target = entry.figures.stop_target = "p99 <= 5 ms";
  entry.start = [](const std::string&) {
    return std::make_unique<PanTiltHarness>(PanTiltEmulatorConfig());  // 127.0.0.1, ephemeral port, format seed
  };
  return { entry };
}

}  // namespace ptz_action_server

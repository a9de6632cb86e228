#include "harness/digiview_harness.h"

namespace ptz_action_server
{
std::vector<HarnessEntry> digiviewHarnesses()
{
  HarnessEntry entry;
  entry.name = "digiview_tcp";
  entry.plugin = "digiview";
  entry.params = { paramValue("digiview/transport", "tcp"), paramValue("digiview/host", "127.0.0.1"),
                   emulatorPort("digiview/port"), paramValue("digiview/acceleration", 4.0) };
  entry.figures.summary = "DigiViewEmulator, TCP server on 127.0.0.1, ephemeral port";
  entry.figures.goal_items = "SET_PARAMETERS CAM_TARGETING; no wire time";
  entry.figures.stop_items = "the first SET_PARAMETERS CAM_TARGETING after the cancel (DigiView has no stop: the view "
                             "is held)";
  entry.figures.goal_target = entry.figures.stop_target = "p99 <= 5 ms";
  entry.figures.holds_aim = true;
  entry.start = [](const std::string&) {
    return std::make_unique<DigiViewHarness>(DigiViewEmulatorConfig());  // TCP on 127.0.0.1, ephemeral port
  };
  return { entry };
}

}  // namespace ptz_action_server

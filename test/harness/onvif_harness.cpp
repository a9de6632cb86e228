#include "harness/onvif_harness.h"

namespace ptz_action_server
{
std::vector<HarnessEntry> onvifHarnesses()
{
  HarnessEntry entry;
  entry.name = "onvif_http";
  entry.plugin = "onvif";
  const OnvifCameraEmulatorConfig camera;  // its credentials
  entry.params = { paramValue("onvif/host", "127.0.0.1"), emulatorPort("onvif/port"),
                   paramValue("onvif/username", camera.username), paramValue("onvif/password", camera.password) };
  entry.figures.summary = "OnvifCameraEmulator, WS-Security on 127.0.0.1, ephemeral port";
  entry.figures.goal_items = "POST AbsoluteMove";
  entry.figures.stop_items = "POST Stop";
  entry.figures.goal_target = "p99 <= 5 ms with the connection warm";
  entry.figures.stop_target = "p99 <= 5 ms";
  entry.start = [](const std::string&) { return std::make_unique<OnvifHarness>(); };
  return { entry };
}

}  // namespace ptz_action_server

#include "harness/axis_harness.h"

namespace ptz_action_server
{
std::vector<HarnessEntry> axisHarnesses()
{
  HarnessEntry entry;
  entry.name = "axis_http";
  entry.plugin = "axis";
  const HttpCameraServerConfig http;  // the camera's credentials
  entry.params = { paramValue("axis/host", "127.0.0.1"), emulatorPort("axis/port"),
                   paramValue("axis/username", http.username), paramValue("axis/password", http.password) };
  entry.figures.summary = "AxisCameraEmulator, HTTP Digest on 127.0.0.1, ephemeral port";
  entry.figures.goal_items = "GET ptz.cgi with pan= (a 401 challenge is not counted)";
  entry.figures.stop_items = "GET ptz.cgi with move=stop";
  entry.figures.goal_target = "p99 <= 5 ms with the connection warm";
  entry.figures.stop_target = "p99 <= 5 ms";
  entry.start = [](const std::string&) { return std::make_unique<AxisHarness>(); };
  return { entry };
}

}  // namespace ptz_action_server

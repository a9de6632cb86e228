#include "harness/mavlink_gimbal_harness.h"

namespace ptz_action_server
{
std::vector<HarnessEntry> mavlinkGimbalHarnesses()
{
  HarnessEntry entry;
  entry.name = "mavlink_gimbal_udp";
  entry.plugin = "mavlink_gimbal";
  entry.params = { paramValue("mavlink_gimbal/transport", "udp"), paramValue("mavlink_gimbal/host", "127.0.0.1"),
                   emulatorPort("mavlink_gimbal/port") };
  entry.figures.summary = "MavlinkGimbalEmulator (gimbal manager 1/1), UDP on 127.0.0.1, ephemeral port";
  entry.figures.goal_items = "GIMBAL_MANAGER_SET_PITCHYAW with angles; no wire time";
  entry.figures.stop_items = "GIMBAL_MANAGER_SET_PITCHYAW with NaN angles and zero rates";
  entry.figures.goal_target = entry.figures.stop_target = "p99 <= 5 ms";
  entry.start = [](const std::string&) {
    return std::make_unique<MavlinkGimbalHarness>(MavlinkGimbalEmulatorConfig());  // 127.0.0.1, ephemeral port
  };
  return { entry };
}

}  // namespace ptz_action_server

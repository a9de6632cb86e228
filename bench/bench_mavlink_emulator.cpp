#include <cmath>
#include <string>

#include "device_table.h"
#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;
using namespace ptz_action_server::mavlink;

/// The gimbal manager emulator on UDP; SET_PITCHYAW with angles are the goal commands, zero rates the stop.
class MavlinkGimbalDevice : public EmulatedDevice
{
public:
  MavlinkGimbalDevice() : emulator_(MavlinkGimbalEmulatorConfig())  // 127.0.0.1, ephemeral port
  {
  }
  std::uint16_t port() const override
  {
    return emulator_.udpPort();
  }
  std::string link() const override
  {
    return "";
  }
  std::vector<Arrival> goalCommands() const override
  {
    return select([](const GimbalManagerSetPitchYaw& setpoint) {
      return std::isfinite(setpoint.yaw) || std::isfinite(setpoint.pitch);
    });
  }
  std::vector<Arrival> stopCommands() const override
  {
    return select([](const GimbalManagerSetPitchYaw& setpoint) {
      return std::isnan(setpoint.yaw) && setpoint.yaw_rate == 0.0f && setpoint.pitch_rate == 0.0f;
    });
  }
  ptz_action_server::EmulatorFaults* faults() override
  {
    return &emulator_;
  }

private:
  template <class Predicate>
  std::vector<Arrival> select(Predicate predicate) const
  {
    std::vector<Arrival> arrivals;
    for (const ReceivedMavlinkFrame& item : emulator_.received().items())
    {
      if (item.frame.message_id == message_id::GIMBAL_MANAGER_SET_PITCHYAW &&
          predicate(decode<GimbalManagerSetPitchYaw>(item.frame)))
      {
        arrivals.push_back(Arrival{ item.at, 0.0 });
      }
    }
    return arrivals;
  }
  MavlinkGimbalEmulator emulator_;
};
}  // namespace

EmulatorSpec mavlinkGimbalEmulator()
{
  EmulatorSpec spec;
  spec.summary = "MavlinkGimbalEmulator (gimbal manager 1/1), UDP on 127.0.0.1, ephemeral port";
  spec.goal_items = "GIMBAL_MANAGER_SET_PITCHYAW with angles; no wire time";
  spec.stop_items = "GIMBAL_MANAGER_SET_PITCHYAW with NaN angles and zero rates";
  spec.goal_target = spec.stop_target = "p99 <= 5 ms";
  spec.start = [](const std::string&) { return std::make_unique<MavlinkGimbalDevice>(); };
  return spec;
}

}  // namespace ptz_bench

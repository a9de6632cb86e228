#include "device_plugin.h"
#include "ptz_action_server/core/mavlink/mavlink_gimbal_protocol.h"

namespace ptz_action_server
{
/// A drone gimbal through its MAVLink gimbal manager: ~mavlink_gimbal/..., over UDP (port 14550) or serial.
struct MavlinkGimbalPlugin
{
  using Protocol = MavlinkGimbalProtocol;
  static constexpr const char* NAME = "mavlink_gimbal";

  static LinkChoices links()
  {
    return { { { LinkKind::UDP, 14550 }, { LinkKind::SERIAL } }, 0.1 };
  }

  static void read(const DeviceParams& device, const BackendContext& context,
                   DeviceConfig<MavlinkGimbalProtocol>& config)
  {
    const ParamReader& params = device.own;
    MavlinkGimbalSettings& gimbal = config.settings;
    auto id = [&params](const char* name, int value, int min) {
      return static_cast<std::uint8_t>(params.integer(name, value, min, 255));
    };
    gimbal.system_id = id("system_id", gimbal.system_id, 1);
    gimbal.component_id = id("component_id", gimbal.component_id, 1);
    gimbal.target_system = id("target_system", gimbal.target_system, 0);
    gimbal.target_component = id("target_component", gimbal.target_component, 0);
    gimbal.gimbal_device_id = id("gimbal_device_id", gimbal.gimbal_device_id, 0);
    gimbal.yaw_lock = params.choice("yaw_frame", "vehicle", { "vehicle", "north" }) == "north";
    const std::string attitude_frame =
        params.choice("attitude_yaw_frame", "auto", { "auto", "flags", "vehicle", "north" });
    gimbal.attitude_yaw_frame = attitude_frame == "flags"   ? MavlinkYawFrame::FLAGS :
                                attitude_frame == "vehicle" ? MavlinkYawFrame::VEHICLE :
                                attitude_frame == "north"   ? MavlinkYawFrame::EARTH :
                                                              MavlinkYawFrame::AUTO;
    gimbal.heartbeat_period = params.number("heartbeat_period", gimbal.heartbeat_period, 0.1, 5.0);
    gimbal.discovery_time = params.number("discovery_time", gimbal.discovery_time, 0.0, 30.0);
    gimbal.attitude_interval = params.number("attitude_interval", gimbal.attitude_interval, 0.005, 1.0);
    gimbal.rate_period = params.number("rate_period", gimbal.rate_period, 0.01, 1.0);
    gimbal.resend_period = params.number("resend_period", gimbal.resend_period, 0.05, 10.0);
    readAxis(params.child("pan"), context.urdf_limits.axes[PAN].range, M_PI, gimbal.pan);
    readAxis(params.child("tilt"), context.urdf_limits.axes[TILT].range, M_PI / 2.0, gimbal.tilt);
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(MavlinkGimbalPlugin, MavlinkGimbalBackendPlugin)

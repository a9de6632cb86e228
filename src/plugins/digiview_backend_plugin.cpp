#include <ros/console.h>

#include "device_plugin.h"
#include "ptz_action_server/core/digiview/digiview_protocol.h"

namespace ptz_action_server
{
/// A DigiView (Synclair Vision) virtual camera: ~digiview/..., over TCP or UDP (port 5500).
struct DigiViewPlugin
{
  using Protocol = DigiViewProtocol;
  static constexpr const char* NAME = "digiview";

  static LinkChoices links()
  {
    return { { { LinkKind::TCP, 5500 }, { LinkKind::UDP, 5500 } }, 0.15 };
  }

  static void read(const ParamReader& params, const BackendContext& /*context*/, DeviceConfig<DigiViewProtocol>& config)
  {
    DigiViewSettings& digiview = config.settings;
    digiview::Format format = digiview::Format::V0_5;
    digiview::parseFormat(params.choice("format", "0.5", { "0.5", "1.0", "1.1", "1.2" }), format);
    // The unit the format's documentation gives unless set; "1.1" without it says once what changed.
    digiview::AngleUnit angles = digiview::documentedAngleUnit(format);
    digiview::parseAngleUnit(params.choice("angle_unit", digiview::toString(angles), { "radians", "degrees" }), angles);
    const std::string notice = DigiViewSettings::angleUnitNotice(format, params.resolve("angle_unit"));
    if (!params.has("angle_unit") && !notice.empty())
    {
      ROS_WARN("%s", notice.c_str());
    }
    digiview::ChecksumRule checksum = digiview::ChecksumRule::REQUIRED;
    digiview::parseChecksumRule(params.choice("checksum", "required", { "required", "zero_accepted" }), checksum);
    digiview.wire = digiview::Wire(format, checksum, angles);
    digiview.stream_name = params.text("stream_name", digiview.stream_name);
    const std::size_t name_size = digiview::nameSizeOf(format);
    if (digiview.stream_name.empty() || digiview.stream_name.size() > name_size)
    {
      throw ConfigError("parameter " + params.resolve("stream_name") + " must have 1 to " + std::to_string(name_size) +
                        " characters in format " + digiview::toString(format));
    }
    digiview.cam_id = static_cast<std::uint8_t>(params.integer("cam_id", digiview.cam_id, 0, 3));
    digiview.fov_wide = params.number("fov_wide", digiview.fov_wide, 0.1, 3.14);
    digiview.zoom_max = params.number("zoom_max", digiview.zoom_max, 0.0, 1000.0);
    digiview.lock_flags = static_cast<std::uint8_t>(params.integer("lock_flags", digiview.lock_flags, 0, 7));
    digiview.crop_mode = static_cast<std::uint8_t>(params.integer("crop_mode", digiview.crop_mode, 0, 2));
    digiview.slew_rate = params.number("slew_rate", digiview.slew_rate, 1e-3, 100.0);
    digiview.acceleration = params.number("acceleration", digiview.acceleration, 0.0, 1e4);
    digiview.velocity_period = params.number("velocity_period", digiview.velocity_period, 0.02, 5.0);
  }
};

}  // namespace ptz_action_server

PTZ_DEVICE_PLUGIN(DigiViewPlugin, DigiViewBackendPlugin)

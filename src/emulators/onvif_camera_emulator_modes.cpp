/**
 * \file
 * \brief The ONVIF camera emulator's configuration: its default device and the modes of the cameras in the field, by
 * name.
 */
#include <cmath>
#include <string>

#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
const char* const OnvifCameraEmulatorConfig::MODES = "standard, generic-status, continuous-only, refuse-absolute-move, "
                                                     "no-position, no-presets, wrong-generic-range, "
                                                     "no-relative, generic-only, wrong-address, ptz-profile-second, "
                                                     "timeout-range, axis-401, stop-keeps-moving, "
                                                     "absolute-never-moves, speed-ignores-magnitude, "
                                                     "zoom-only-moves-pantilt, zoom-range-not-honoured, "
                                                     "no-speed-space, no-imaging";

SimDeviceConfig OnvifCameraEmulatorConfig::defaultDevice()
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  device.axes[ZOOM].range = { 1.0, 18.0 };
  device.axes[PAN].resolution = 0.0;
  device.axes[TILT].resolution = 0.0;
  return device;
}

bool OnvifCameraEmulatorConfig::applyMode(const std::string& mode)
{
  if (mode == "generic-status")
  {
    degree_space = true;
    degrees_default = false;
  }
  else if (mode == "continuous-only")
  {
    absolute = false;
  }
  else if (mode == "refuse-absolute-move")
  {
    refuse_absolute_move = true;
  }
  else if (mode == "no-position")
  {
    status_position = false;
  }
  else if (mode == "no-presets")
  {
    presets = false;
  }
  else if (mode == "wrong-generic-range")
  {
    degree_space = true;  // the camera of the field report: degrees listed, its status in the generic space
    degrees_default = false;
    listed_generic_pan_min = 0.0;
    listed_generic_pan_max = 1.0;
    device.axes[PAN].initial_position = -0.864666 * M_PI;
  }
  else if (mode == "no-relative")
  {
    relative = false;
  }
  else if (mode == "generic-only")
  {
    degree_space = false;
  }
  else if (mode == "wrong-address")
  {
    advertised_host = "127.0.0.2";  // wrong, as some firmware's, and still on this machine
  }
  else if (mode == "ptz-profile-second")
  {
    ptz_profile_first = false;
  }
  else if (mode == "timeout-range")
  {
    min_timeout = 1.0;
    max_timeout = 10.0;
  }
  else if (mode == "axis-401")
  {
    open_clock = false;
  }
  else if (mode == "stop-keeps-moving")
  {
    stop_keeps_moving = true;
  }
  else if (mode == "absolute-never-moves")
  {
    absolute_never_moves = true;
  }
  else if (mode == "speed-ignores-magnitude")
  {
    fixed_speed_share = 0.5;
    // Such cameras' steppers start and stop at once.
    device.axes[PAN].motion.acceleration = 20.0;
    device.axes[TILT].motion.acceleration = 20.0;
  }
  else if (mode == "zoom-only-moves-pantilt")
  {
    backlash = toRadians(2.0);
  }
  else if (mode == "zoom-range-not-honoured")
  {
    honoured_zoom = 0.5;
  }
  else if (mode == "no-imaging")
  {
    imaging = false;
  }
  else if (mode == "no-speed-space")
  {
    speed_space = false;
  }
  else if (mode != "standard")
  {
    return false;
  }
  return true;
}

}  // namespace ptz_action_server

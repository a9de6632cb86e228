/**
 * \file
 * \brief onvif_camera_emulator: an ONVIF PTZ camera (device, media and PTZ services) on a real HTTP server, over the
 * sim motion model.
 */
#include <cstdio>
#include <string>

#include "ip_camera_options.h"

#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace
{
const char* PROGRAM = "onvif_camera_emulator";
const char* OWN_USAGE = R"(usage: onvif_camera_emulator [options]

Answers as an ONVIF PTZ camera does (protocols.md section 7), SOAP 1.2 over HTTP POST: /onvif/device_service
(GetSystemDateAndTime without authentication, GetCapabilities), /onvif/media_service (GetProfiles: profile_1 has
PTZ), /onvif/ptz_service (GetNodes, GetConfigurationOptions, AbsoluteMove, ContinuousMove with its Timeout, Stop,
GetStatus). Every request but GetSystemDateAndTime needs a WS-Security UsernameToken (PasswordDigest, Created
within 5 s of the camera's clock); a wrong one is refused with ter:NotAuthorized. --user and --password set the
WS-Security credentials (default admin / admin); --auth digest demands HTTP Digest as well (default none).
Pan -180..180, tilt -90..90 degrees, zoom 1..18X (generic zoom z is 18^z X).

Camera options:
  --generic-only         list only the generic spaces (no SphericalPositionSpaceDegrees)
  --clock-offset S       the camera's clock runs S seconds ahead (tokens must be stamped in its time)
  --refuse               refuse every move with ter:InvalidArgVal "PTZ is locked by another user"
)";
}  // namespace

int main(int argc, char** argv)
{
  ptz_action_server::OnvifCameraEmulatorConfig config;
  emulator_main::HttpCameraOptions options;
  options.http = config.http;
  options.http.port = 8081;
  options.http.username = config.username;
  options.http.password = config.password;
  bool refuse = false;
  const std::string usage = emulator_main::httpCameraUsage(OWN_USAGE, 8081);
  emulator_main::parseArguments(argc, argv, PROGRAM, usage,
                                [&](const std::string& arg, const emulator_main::Value& value) {
                                  if (emulator_main::parseHttpCameraOption(arg, value, PROGRAM, usage.c_str(), options))
                                  {
                                    return true;
                                  }
                                  if (arg == "--generic-only")
                                  {
                                    config.degree_space = false;
                                  }
                                  else if (arg == "--clock-offset")
                                  {
                                    config.clock_offset = std::strtod(value(), nullptr);
                                  }
                                  else if (arg == "--refuse")
                                  {
                                    refuse = true;
                                  }
                                  else
                                  {
                                    return false;
                                  }
                                  return true;
                                });
  config.http = options.http;
  config.username = options.http.username;
  config.password = options.http.password;
  const sigset_t signals = emulator_main::blockSignals();
  try
  {
    ptz_action_server::OnvifCameraEmulator camera(config);
    camera.setRefuse(refuse);
    return emulator_main::runHttpCamera(PROGRAM, signals, camera.server(), options,
                                        config.degree_space ? "ONVIF, degree and generic spaces" :
                                                              "ONVIF, generic spaces only");
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", PROGRAM, error.what());
    return 1;
  }
}

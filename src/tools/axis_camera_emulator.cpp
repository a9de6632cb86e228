/**
 * \file
 * \brief axis_camera_emulator: an Axis PTZ camera's VAPIX ptz.cgi on a real HTTP server, over the sim motion model.
 */
#include <cstdio>
#include <string>

#include "ip_camera_options.h"

#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace
{
const char* PROGRAM = "axis_camera_emulator";
const char* OWN_USAGE = R"(usage: axis_camera_emulator [options]

Answers /axis-cgi/com/ptz.cgi as an Axis PTZ camera does (protocols.md section 6), behind HTTP Digest (MD5,
qop=auth) by default: pan, tilt (fractional degrees), zoom (1..9999), speed, rpan, rtilt, rzoom,
continuouspantiltmove, continuouszoommove, move=stop|home (204 No Content); query=position|limits|speed and
query=attributes&group=zoom (key=value lines); Error: bodies for what it does not take; 404 for other paths.
Pan -170..170, tilt -20..90 degrees, zoom 1..18X through its zoom table.

Camera options:
  --zoom-table TABLE     VALUE:X,VALUE:X,... (default an 18X table); "" = no zoom attributes (no zoom)
  --refuse               answer every move with "Error: PTZ control is locked by another user"
)";
}  // namespace

int main(int argc, char** argv)
{
  ptz_action_server::AxisCameraEmulatorConfig config;
  emulator_main::HttpCameraOptions options;
  options.http.port = 8080;
  bool refuse = false;
  const std::string usage = emulator_main::httpCameraUsage(OWN_USAGE, 8080);
  emulator_main::parseArguments(argc, argv, PROGRAM, usage,
                                [&](const std::string& arg, const emulator_main::Value& value) {
                                  if (emulator_main::parseHttpCameraOption(arg, value, PROGRAM, usage.c_str(), options))
                                  {
                                    return true;
                                  }
                                  if (arg == "--zoom-table")
                                  {
                                    config.zoom_table = value();
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
  const sigset_t signals = emulator_main::blockSignals();
  try
  {
    ptz_action_server::AxisCameraEmulator camera(config);
    camera.setRefuse(refuse);
    return emulator_main::runHttpCamera(PROGRAM, signals, camera.server(), options,
                                        config.zoom_table.empty() ? "VAPIX, no zoom" : "VAPIX, zoom 1..18X");
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", PROGRAM, error.what());
    return 1;
  }
}

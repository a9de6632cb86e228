/**
 * \file
 * \brief axis_camera_emulator: an Axis PTZ camera's VAPIX ptz.cgi on a real HTTP server, over the sim motion model.
 */
#include <cstdio>
#include <string>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "ptz_action_server/emulators/emulator_main.h"

namespace
{
const char* PROGRAM = "axis_camera_emulator";
const char* OWN_USAGE = R"(usage: axis_camera_emulator [options]

Answers /axis-cgi/com/ptz.cgi as an Axis PTZ camera does (protocols.md section 6), behind HTTP Digest (MD5,
qop=auth) by default: pan, tilt (fractional degrees), zoom (1..9999), speed, rpan, rtilt, rzoom,
continuouspantiltmove, continuouszoommove, move=stop|home (204 No Content); query=position (pan, tilt, zoom,
iris, focus, brightness, autofocus, autoiris), query=limits|speed|presetposcam|presetposall (key=value lines);
query=attributes&group=zoom in the documented sections ("Attributes for camera 1", maxOpticalZoomMag,
zoomSteps=value=1 | zoom=1,value=589 | zoom=2,...); info=1 (the commands it takes); Error: bodies for what it
does not take; /axis-cgi/param.cgi?action=list&group=root.Brand (root.Brand.ProdNbr=...); 404 for other paths.
Pan -170..170, tilt -20..90 degrees; by default an 18X lens (VAPIX zoom 1..9999, even steps per X), the zoom
attributes, and model P5534-E.

Camera options:
  --zoom-table TABLE     the lens, VALUE:X,VALUE:X,... (VAPIX zoom -> X); "" = no zoom at all (no MinZoom/MaxZoom
                         in the limits, no zoom= in the position)
  --optical-zoom X       the lens: X at VAPIX zoom 9999, linear from 1X at 1 (instead of --zoom-table)
  --no-attributes        a firmware without query=attributes, as cameras in the field: info=1 lists
                         query={ speed | position | limits | presetposcam | presetposall }, and asking for the
                         attributes answers "Error:" / "query: unknown value: attributes"; the zoom is still in
                         query=limits (MinZoom=1, MaxZoom=9999) and query=position (zoom=)
  --model PRODNBR        root.Brand.ProdNbr of param.cgi (default P5534-E), e.g. Q6155-E (a Q61, whose family the
                         backend takes for 30X when the camera gives no zoom table) or Q8665-E (no family default)
  --refuse               answer every move with "Error: PTZ control is locked by another user"
  --control-queue        PTZ control queueing on (root.PTZ.Various.V1.CtlQueueing=true, VAPIX Queuing API): a
                         cookie per client, /axis-cgi/com/ptzqueue.cgi?control=request|query|drop, and moves from
                         a client without control answered 204 and not carried out; control lasts 60 s after the
                         holder's last move or request

The field camera of issue 21 (no zoom attributes, a 30X lens, a model the backend guesses from):
  axis_camera_emulator --no-attributes --optical-zoom 30 --model Q6155-E
)";
}  // namespace

int main(int argc, char** argv)
{
  ptz_action_server::AxisCameraEmulatorConfig config;
  emulator_main::HttpCameraOptions options;
  options.http.port = 8080;
  bool refuse = false;
  int lens_options = 0;
  double optical_zoom = 0.0;
  const std::string usage = emulator_main::httpCameraUsage(OWN_USAGE, 8080);
  emulator_main::parseArguments(
      argc, argv, PROGRAM, usage, [&](const std::string& arg, const emulator_main::Value& value) {
        if (emulator_main::parseHttpCameraOption(arg, value, PROGRAM, usage.c_str(), options))
        {
          return true;
        }
        if (arg == "--zoom-table")
        {
          config.zoom_table = value();
          ++lens_options;
        }
        else if (arg == "--optical-zoom")
        {
          optical_zoom = emulator_main::numberIn(PROGRAM, value(), arg, 1.0001, 1000.0, usage.c_str());
          ++lens_options;
        }
        else if (arg == "--no-attributes")
        {
          config.attributes = false;
        }
        else if (arg == "--model")
        {
          config.model = value();
        }
        else if (arg == "--refuse")
        {
          refuse = true;
        }
        else if (arg == "--control-queue")
        {
          config.control_queue = true;
        }
        else
        {
          return false;
        }
        return true;
      });
  config.http = options.http;
  if (lens_options > 1)
  {
    std::fprintf(stderr, "%s: --zoom-table and --optical-zoom both give the lens: give one\n%s", PROGRAM,
                 usage.c_str());
    return 2;
  }
  const sigset_t signals = emulator_main::blockSignals();
  try
  {
    if (optical_zoom > 0.0)
    {
      config.zoom_table = ptz_action_server::AxisCameraEmulatorConfig::linearZoomTable(optical_zoom);
    }
    ptz_action_server::AxisCameraEmulator camera(config);
    camera.setRefuse(refuse);
    ptz_action_server::vapix::ZoomTable lens;
    ptz_action_server::vapix::ZoomTable::parse(config.zoom_table, lens);
    const std::string zoom =
        lens.empty() ? "no zoom" : ptz_action_server::formatText("zoom %g..%gX", lens.minFactor(), lens.maxFactor());
    return emulator_main::runHttpCamera(PROGRAM, signals, camera.server(), options,
                                        "VAPIX, " + zoom +
                                            (config.attributes ? ", zoom attributes" : ", no zoom attributes") +
                                            ", model " + config.model);
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", PROGRAM, error.what());
    return 1;
  }
}

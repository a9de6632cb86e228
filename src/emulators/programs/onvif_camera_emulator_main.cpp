/**
 * \file
 * \brief onvif_camera_emulator: an ONVIF PTZ camera (device, media and PTZ services) on a real HTTP server, over the
 * sim motion model, in the modes of the cameras found in the field.
 */
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ptz_action_server/emulators/emulator_main.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace
{
const char* PROGRAM = "onvif_camera_emulator";
constexpr unsigned DEFAULT_PORT = 8081;
/// The whole help: the HTTP options' defaults are this camera's own (WS-Security admin / admin, no HTTP auth).
const char* USAGE_FORMAT = R"(usage: onvif_camera_emulator [options]

Answers as an ONVIF PTZ camera does (protocols.md section 7), SOAP 1.2 over HTTP POST, for the ONVIF clients people
use as well as for this package's backend:
  /onvif/device_service  GetSystemDateAndTime (without authentication), GetCapabilities, GetServices,
                         GetDeviceInformation
  /onvif/media_service   GetProfiles, GetProfile (profile_1 with PTZ, profile_0 without), GetVideoSources
  /onvif/ptz_service     GetServiceCapabilities, GetNodes, GetNode, GetConfigurations, GetConfiguration,
                         GetConfigurationOptions, AbsoluteMove, RelativeMove, ContinuousMove (with its Timeout),
                         Stop, GetStatus, GetPresets, SetPreset, GotoPreset, RemovePreset, GotoHomePosition,
                         SetHomePosition
Every request but GetSystemDateAndTime needs a WS-Security UsernameToken (PasswordDigest, Created within 5 s of the
camera's clock, any xsd:dateTime: ...Z, ...+00:00); a wrong one is refused with ter:NotAuthorized. Pan -180..180,
tilt -90..90 degrees, zoom 1..18X (generic zoom z is 18^z X). GetStatus reports in the PTZ configuration's default
space, and moves that name no space go in it. Its XAddrs name the address and port it listens on; GetProfiles lists
profile_1 (with PTZ) first.

Options:
  --host HOST            address to listen on (default 127.0.0.1)
  --port PORT            port (default %u; 0 = any free port)
  --user NAME            the WS-Security user (default admin)
  --password TEXT        its password (default admin)
  --auth MODE            none (default: WS-Security only) or digest (HTTP Digest as well, with the same
                         credentials, as some cameras demand)
  --nonce-uses N         with --auth digest: a nonce goes stale after N requests (default 0: never)
  --secrets-file PATH    append every credential-derived value requests carried there, one a line (WS-Security
                         Nonces and PasswordDigests; Digest nonces, responses, cnonces): for leak tests
Camera options:
  --mode MODE            a camera as found in the field (default standard; may be given more than once):
                           generic-status        lists SphericalPositionSpaceDegrees, but its default space, and so
                                                 its status, is the generic one
                           continuous-only       lists no position spaces: ContinuousMove only (cameras on Goke
                                                 GK7102 chips); AbsoluteMove, presets and home are not supported
                           refuse-absolute-move  lists the position spaces, answers AbsoluteMove with
                                                 ter:ActionNotSupported
                           no-position           GetStatus carries no Position
                           no-presets            preset operations answer ter:ActionNotSupported (GetNodes still
                                                 lists MaximumNumberOfPresets 64)
                           wrong-generic-range   the field report's camera: generic-status, with the generic pan
                                                 range listed as 0..1 while it moves, and reports, over -1..1
                                                 (starts at pan -0.864666)
                           no-relative           lists no translation spaces; RelativeMove is not supported
                           generic-only          lists only the generic spaces (no SphericalPositionSpaceDegrees)
                           wrong-address         its XAddrs name 127.0.0.2 (a wrong address, as some firmware
                                                 advertises; still this machine), not the address it listens on
                           ptz-profile-second    GetProfiles lists profile_0 (no PTZ) first
                           timeout-range         PTZTimeout 1..10 s: a ContinuousMove whose Timeout is outside is
                                                 refused (ter:TimeoutNotSupported)
                           axis-401              Axis: GetSystemDateAndTime without a valid WS-Security
                                                 UsernameToken is answered HTTP 401 (with a Digest challenge)
                           stop-keeps-moving     Stop is answered, but a ContinuousMove's motion goes on, past its
                                                 Timeout too, until a ContinuousMove with zero velocity (or its
                                                 end stop)
                           absolute-never-moves  AbsoluteMove is answered, and nothing moves (ContinuousMove works)
                           speed-ignores-magnitude  any non-zero ContinuousMove velocity moves at one speed, half
                                                 the axis' max speed (pan 0.75, tilt 0.5 rad/s, zoom 4 X/s)
                           zoom-only-moves-pantilt  every AbsoluteMove with a PanTilt moves pan and tilt, even to
                                                 where they are: it approaches each position from 2 degrees below
                                                 (backlash), so only a zoom-only AbsoluteMove leaves them still
                           zoom-range-not-honoured  GetNodes lists the generic zoom 0..1, the lens stops at 0.5
                                                 (4.24X): a move beyond is answered, and the zoom stops there
  --generic-only         the same as --mode generic-only
  --clock-offset S       the camera's clock runs S seconds ahead (tokens must be stamped in its time)
  --refuse               refuse every move with ter:InvalidArgVal "PTZ is locked by another user"
)";
}  // namespace

int main(int argc, char** argv)
{
  ptz_action_server::OnvifCameraEmulatorConfig config;
  emulator_main::HttpCameraOptions options;
  options.http = config.http;  // admin / admin, no HTTP authentication
  options.http.port = DEFAULT_PORT;
  bool refuse = false;
  std::string modes;
  char usage_text[16384];
  std::snprintf(usage_text, sizeof(usage_text), USAGE_FORMAT, DEFAULT_PORT);
  const std::string usage = std::string(usage_text) + emulator_main::HTTP_FAULTS_HELP;
  emulator_main::parseArguments(
      argc, argv, PROGRAM, usage, [&](const std::string& arg, const emulator_main::Value& value) {
        if (arg == "--auth")
        {
          // ONVIF authenticates in the message; HTTP Digest is what some cameras add (never Basic).
          const std::string auth = emulator_main::choice(PROGRAM, value(), arg, { "none", "digest" }, usage.c_str());
          options.http.auth =
              auth == "digest" ? ptz_action_server::HttpAuth::DIGEST : ptz_action_server::HttpAuth::NONE;
          return true;
        }
        if (emulator_main::parseHttpCameraOption(arg, value, PROGRAM, usage.c_str(), options))
        {
          return true;
        }
        if (arg == "--mode" || arg == "--generic-only")
        {
          const std::string mode = arg == "--mode" ? value() : "generic-only";
          if (!config.applyMode(mode))
          {
            emulator_main::fail(PROGRAM, "--mode " + mode + " is none of " + config.MODES, usage.c_str());
          }
          modes += (modes.empty() ? "" : ", ") + mode;
        }
        else if (arg == "--clock-offset")
        {
          const char* text = value();
          char* end = nullptr;
          config.clock_offset = std::strtod(text, &end);  // may be negative: a clock behind
          if (end == text || *end != '\0' || !std::isfinite(config.clock_offset))
          {
            emulator_main::fail(PROGRAM, arg + " needs a number of seconds", usage.c_str());
          }
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
                                        "ONVIF, " + (modes.empty() ? std::string("standard") : modes));
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s: %s\n", PROGRAM, error.what());
    return 1;
  }
}

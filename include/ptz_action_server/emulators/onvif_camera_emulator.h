/**
 * \file
 * \brief An emulated ONVIF PTZ camera: device, media and PTZ services (SOAP 1.2) behind WS-Security UsernameToken
 * (and HTTP Digest if asked), over the shared sim motion model, with the modes of the cameras in the field.
 */
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
namespace onvif
{
struct SoapMessage;
}

/// The camera the emulator plays. The defaults are a camera by the specification; the modes are those of cameras in
/// the field (each names the case it plays).
struct OnvifCameraEmulatorConfig
{
  OnvifCameraEmulatorConfig()
  {
    http.auth = HttpAuth::NONE;  // ONVIF authenticates in the message; HttpAuth::DIGEST makes it demand both
    http.realm = "onvif_camera";
    http.username = username;
    http.password = password;
  }
  HttpCameraServerConfig http;
  std::string username = "admin";  ///< WS-Security user (the program gives HTTP Digest the same credentials)
  std::string password = "admin";
  /// Pan -180..180 deg, tilt -90..90 deg (generic x = pan / 180 deg, y = tilt / 90 deg), zoom 1..18X (generic zoom z
  /// is 18^z X).
  SimDeviceConfig device = defaultDevice();
  bool degree_space = true;  ///< lists SphericalPositionSpaceDegrees (Profile T); false: generic spaces only
  /// The PTZ configuration's DefaultAbsolutePantTiltPositionSpace is the degree space when it is listed (false: the
  /// generic one). GetStatus reports in the default space and moves that name no space go in it. Field case "degrees
  /// listed but generic status": degree_space with degrees_default false.
  bool degrees_default = true;
  /// Lists absolute position spaces (and translation spaces) and takes AbsoluteMove. Field case "continuous only"
  /// (cameras on Goke GK7102 chips): false, and AbsoluteMove, RelativeMove, presets and home answer
  /// ter:ActionNotSupported.
  bool absolute = true;
  /// With absolute: answers AbsoluteMove with ter:ActionNotSupported all the same (the other continuous-only cameras).
  bool refuse_absolute_move = false;
  bool relative = true;         ///< lists the translation spaces and takes RelativeMove (false: a camera without it)
  bool status_position = true;  ///< GetStatus carries a Position (false: field case "no position in the status")
  /// Preset operations work (false: field case "no presets": they answer ter:ActionNotSupported although GetNodes
  /// still lists MaximumNumberOfPresets, as those cameras do).
  bool presets = true;
  int max_presets = 64;  ///< MaximumNumberOfPresets
  bool home = true;      ///< HomeSupported: GotoHomePosition and SetHomePosition
  /// The generic pan range GetNodes lists; the camera moves over [-1, 1] whatever it says. Field case "the wrong
  /// generic range": { 0, 1 }, as a camera in the field lists while its status reports -0.86.
  double listed_generic_pan_min = -1.0;
  double listed_generic_pan_max = 1.0;
  double clock_offset = 0.0;   ///< s the camera's clock runs ahead of the system's (tokens are judged by it)
  double max_token_age = 5.0;  ///< s a UsernameToken's Created may differ from the camera's clock
  std::string advertised_host = "192.0.2.1";  ///< the host its XAddrs name (wrong, as some firmware's)

  static SimDeviceConfig defaultDevice();
  /// The modes by name, for the program's --mode and the tests: "standard", "generic-status" (degrees listed, status in
  /// the generic space), "continuous-only", "refuse-absolute-move", "no-position", "no-presets", "wrong-generic-range"
  /// (the field report's camera: generic-status with the generic pan listed as 0..1, starting at pan -155.6 deg,
  /// generic -0.864666, so the contradiction shows at once), "no-relative", "generic-only". False for another name.
  bool applyMode(const std::string& mode);
  static const char* const MODES;  ///< the names, for help texts
};

/**
 * \brief An ONVIF camera on 127.0.0.1 that other people's ONVIF clients can drive.
 *
 * - `/onvif/device_service` (ver10/device): GetSystemDateAndTime (without authentication), GetCapabilities,
 *   GetServices (with the services' capabilities if asked), GetDeviceInformation.
 * - `/onvif/media_service` (ver10/media): GetProfiles, GetProfile (`profile_0` without PTZ, `profile_1` with `ptz0` on
 *   node `node0`; both on video source `video_source_0`), GetVideoSources.
 * - `/onvif/ptz_service` (ver20/ptz): GetServiceCapabilities, GetNodes, GetNode, GetConfigurations, GetConfiguration,
 *   GetConfigurationOptions, AbsoluteMove, RelativeMove, ContinuousMove (its Timeout), Stop (per axis), GetStatus (in
 *   the default spaces, MoveStatus per axis), GetPresets, SetPreset, GotoPreset, RemovePreset, GotoHomePosition,
 *   SetHomePosition. Moves without a space go in the configuration's default space.
 *
 * Faults as the specifications write them: ter:NotAuthorized (HTTP 400), env:Sender / ter:InvalidArgVal /
 * ter:NoProfile, ter:NoPTZProfile, ter:NoConfig, ter:NoEntity, ter:NoToken, ter:SpaceNotSupported, ter:InvalidPosition,
 * ter:InvalidTranslation, ter:InvalidVelocity, ter:TimeoutNotSupported, ter:PresetExist; env:Receiver / ter:Action /
 * ter:MovingPTZ, ter:TooManyPresets; env:Receiver / ter:ActionNotSupported for what it does not do. Answers use
 * prefixes of their own (`env:`, a default namespace), as cameras differ.
 */
class OnvifCameraEmulator : public HttpCameraFaults<OnvifCameraEmulator>
{
public:
  explicit OnvifCameraEmulator(const OnvifCameraEmulatorConfig& config,
                               std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~OnvifCameraEmulator();

  std::uint16_t port() const
  {
    return server_->port();
  }
  HttpCameraServer& server()
  {
    return *server_;
  }
  const OnvifCameraEmulatorConfig& config() const
  {
    return config_;
  }
  PtzSample sample() const;
  /// Refuses every move with a fault carrying REFUSAL.
  void setRefuse(bool refuse);
  /// Fault hooks of the motion model: a stalled axis accepts every command and silently stays where it is.
  void setFaults(const SimFaults& faults);
  static constexpr const char* REFUSAL = "PTZ is locked by another user";

  /// Tokens the camera refused (a wrong password, a stale Created).
  std::uint64_t refusedTokens() const;

private:
  struct Preset
  {
    std::string name;
    AxisValues position;
  };

  HttpAnswer handle(const std::string& target, const std::string& body);
  HttpAnswer device(const std::string& operation, const onvif::SoapMessage& message);
  HttpAnswer media(const std::string& operation, const onvif::SoapMessage& message);
  HttpAnswer ptz(const std::string& operation, const onvif::SoapMessage& message, TimePoint now);
  /// The reason a token is refused, or "".
  std::string checkToken(const onvif::SoapMessage& message) const;
  void expireVelocity(TimePoint now) const;
  double cameraUtc() const;
  /// The default absolute pan-tilt space of ptz0.
  const char* defaultSpace() const;
  std::string ptzConfiguration(const char* element) const;
  std::string supportedSpaces() const;
  /// A PTZVector (Position, PTZPosition) of \p position in the default spaces.
  std::string positionVector(const char* element, const AxisValues& position) const;
  /// Moves to \p position on every axis (a preset, home).
  void goToAll(const AxisValues& position, TimePoint now);

  const OnvifCameraEmulatorConfig config_;
  const std::shared_ptr<const Clock> clock_;
  mutable std::mutex mutex_;  ///< guards everything below
  mutable SimDeviceModel model_;
  bool refuse_ = false;
  mutable std::array<bool, AXIS_COUNT> velocity_axes_{};  ///< axes a ContinuousMove moves until its timeout
  TimePoint velocity_until_{};
  std::map<int, Preset> presets_;  ///< by token number
  int next_preset_ = 1;
  AxisValues home_{ { 0.0, 0.0, 1.0 } };
  std::uint64_t refused_tokens_ = 0;
  std::unique_ptr<HttpCameraServer> server_;  ///< last: its thread calls handle()
};

}  // namespace ptz_action_server

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
#include "ptz_action_server/core/sim/sim_lens_model.h"
#include "ptz_action_server/emulators/http_camera_emulator.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace tinyxml2
{
class XMLElement;
}

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
  bool relative = true;  ///< lists the translation spaces and takes RelativeMove (false: a camera without it)
  /// With relative: its PTZ configuration options (and node) also list the pan-tilt and zoom TranslationSpaceFov, and
  /// RelativeMove in them centres that point of its picture (x, y from -1 to 1 from its centre to its right and top
  /// edges, through field_of_view at the current zoom) and multiplies the zoom's X by z.
  bool fov_space = true;
  /// The lens at zoom 1 (full angles, rad), narrowing as an ideal zoom lens with the zoom's X.
  FieldOfViewAngles field_of_view = HttpCameraEmulator::defaultFieldOfView();
  /// GetNodes lists PanTiltSpeedSpace and ZoomSpeedSpace (GenericSpeedSpace, 0..1) and AbsoluteMove, RelativeMove
  /// take a Speed in them: each axis moves at that share of its max speed. False: field case "no speed space" (a
  /// Speed is ignored, every move runs at the top speed).
  bool speed_space = true;
  /// An Imaging service (ver20/imaging, `/onvif/imaging_service`, in GetCapabilities and GetServices) drives the
  /// lens below on video_source_0. False: field case "no imaging" (a camera with PTZ only).
  bool imaging = true;
  /// Its focus and iris (either may be absent): focus Position 0..1000 (near..far) and Continuous Speed -5..5, iris
  /// -22..0 dB (0 fully open), as GetOptions and GetMoveOptions list them.
  SimLensConfig lens;
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
  /// The host its XAddrs name: "" = the address and port it listens on (its own URL, what clients that follow XAddrs
  /// need). Field case "advertises a wrong address": a loopback address it does not listen on ("127.0.0.2").
  std::string advertised_host;
  /// GetProfiles lists profile_1 (with PTZ) first, as clients that take the first profile (node-onvif) need; false:
  /// profile_0 (no PTZ) first.
  bool ptz_profile_first = true;
  double min_timeout = 1.0;   ///< s, the PTZTimeout range GetConfigurationOptions lists; a ContinuousMove whose
  double max_timeout = 60.0;  ///< Timeout lies outside it is refused (ter:TimeoutNotSupported). Field case: 1..10
  /// GetSystemDateAndTime is answered without authentication, as the specification says. False: field case "Axis":
  /// HTTP 401 (with a Digest challenge) to one without a valid WS-Security UsernameToken.
  bool open_clock = true;
  /// Field case "stop keeps moving": Stop is answered, but what a ContinuousMove set in motion goes on, past its
  /// Timeout too, until a ContinuousMove with zero velocity (or the end of the travel).
  bool stop_keeps_moving = false;
  /// Field case "AbsoluteMove never moves": AbsoluteMove is answered, and nothing moves (ContinuousMove still works).
  bool absolute_never_moves = false;
  /// > 0: field case "speed ignores the magnitude": any non-zero ContinuousMove velocity moves its axis at this share
  /// of the axis' max speed (the sign is kept).
  double fixed_speed_share = 0.0;
  /// rad > 0: field case "zoom-only AbsoluteMove moves pan and tilt": the camera approaches every pan-tilt position
  /// an AbsoluteMove gives from this far below (it takes up its gears' backlash), so a PanTilt where it already is
  /// still moves pan and tilt.
  double backlash = 0.0;
  /// The generic zoom its lens really reaches (GetNodes lists [0, 1] all the same). Field case "listed zoom range not
  /// honoured": 0.5 (a move beyond is answered, and the zoom stops there).
  double honoured_zoom = 1.0;

  static SimDeviceConfig defaultDevice();
  /// The modes by name, for the program's --mode and the tests (MODES lists them; each sets the fields above that
  /// name it): "standard", "generic-status" (degrees listed, status in the generic space), "continuous-only",
  /// "refuse-absolute-move", "no-position", "no-presets", "wrong-generic-range" (the field report's camera:
  /// generic-status with the generic pan listed as 0..1, starting at pan -155.6 deg, generic -0.864666, so the
  /// contradiction shows at once), "no-relative", "generic-only", "wrong-address", "ptz-profile-second",
  /// "timeout-range", "axis-401", "stop-keeps-moving", "absolute-never-moves", "speed-ignores-magnitude",
  /// "zoom-only-moves-pantilt", "zoom-range-not-honoured", "no-speed-space",
  /// "no-imaging". False for another name.
  bool applyMode(const std::string& mode);
  static const char* const MODES;  ///< the names, for help texts
};

/**
 * \brief An ONVIF camera on 127.0.0.1 that other people's ONVIF clients can drive.
 *
 * - `/onvif/device_service` (ver10/device): GetSystemDateAndTime (without authentication), GetCapabilities,
 *   GetServices (with the services' capabilities if asked), GetDeviceInformation.
 * - `/onvif/media_service` (ver10/media): GetProfiles, GetProfile (`profile_1` with `ptz0` on node `node0`, listed
 *   first, and `profile_0` without PTZ; both on video source `video_source_0`, each with a video encoder
 *   configuration, as clients expect), GetVideoSources.
 *
 * Its XAddrs name the address and port it listens on (advertised_host aside); a token's Created may be any
 * xsd:dateTime.
 * - `/onvif/ptz_service` (ver20/ptz): GetServiceCapabilities, GetNodes, GetNode, GetConfigurations, GetConfiguration,
 *   GetConfigurationOptions, AbsoluteMove, RelativeMove (also in TranslationSpaceFov, fov_space), ContinuousMove (its
 *   Timeout), Stop (per axis), GetStatus (in the default spaces, MoveStatus per axis), GetPresets, SetPreset,
 *   GotoPreset, RemovePreset, GotoHomePosition, SetHomePosition. Moves without a space go in the configuration's
 * default space.
 *
 * Faults as the specifications write them: ter:NotAuthorized (HTTP 400), env:Sender / ter:InvalidArgVal /
 * ter:NoProfile, ter:NoPTZProfile, ter:NoConfig, ter:NoEntity, ter:NoToken, ter:SpaceNotSupported, ter:InvalidPosition,
 * ter:InvalidTranslation, ter:InvalidVelocity, ter:TimeoutNotSupported, ter:PresetExist; env:Receiver / ter:Action /
 * ter:MovingPTZ, ter:TooManyPresets; env:Receiver / ter:ActionNotSupported for what it does not do. Answers use
 * prefixes of their own (`env:`, a default namespace), as cameras differ.
 */
class OnvifCameraEmulator : public HttpCameraEmulator
{
public:
  explicit OnvifCameraEmulator(const OnvifCameraEmulatorConfig& config,
                               std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~OnvifCameraEmulator();

  std::uint16_t port() const
  {
    return server_->port();
  }
  HttpCameraServer& server() override
  {
    return *server_;
  }
  const OnvifCameraEmulatorConfig& config() const
  {
    return config_;
  }
  // sample(), setFaults() and setRefuse() are HttpCameraEmulator's: under setRefuse() every move is refused with a
  // fault carrying REFUSAL.
  /// What the camera was asked, classified (onvif_camera_classify.cpp); challenged requests left out.
  std::vector<ClassifiedCommand> classify() const;
  static constexpr const char* REFUSAL = "PTZ is locked by another user";

  /// The lens now: focus and iris modes and positions (shares 0..1), for tests.
  LensState lensState() const;
  /// The cruise speed of the last position move per axis (rad/s, X/s): its Speed's share of the max speed.
  AxisValues commandedSpeed() const;

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
  /// The Imaging service: focus and iris (onvif_camera_emulator_imaging.cpp).
  HttpAnswer imaging(const std::string& operation, const tinyxml2::XMLElement* request, TimePoint now);
  HttpAnswer setImagingSettings(const tinyxml2::XMLElement* settings, TimePoint now);
  HttpAnswer moveFocus(const tinyxml2::XMLElement* focus, TimePoint now);
  /// The PTZ operations on a profile: moves, status, presets, home.
  HttpAnswer move(const std::string& operation, const tinyxml2::XMLElement* request, TimePoint now);
  HttpAnswer presets(const std::string& operation, const tinyxml2::XMLElement* request, TimePoint now);
  /// The reason a token is refused, or "".
  std::string checkToken(const onvif::SoapMessage& message) const;
  /// Brings the camera's own doings up to \p now: a ContinuousMove's Timeout running out, the second half of a
  /// backlash approach.
  void advance(TimePoint now) const override;
  double cameraUtc() const;
  /// "http://127.0.0.1:8081": where its XAddrs point.
  std::string serviceAddress() const;
  /// The default absolute pan-tilt space of ptz0.
  const char* defaultSpace() const;
  std::string ptzConfiguration(const char* element) const;
  std::string supportedSpaces() const;
  /// A PTZVector (Position, PTZPosition) of \p position in the default spaces.
  std::string positionVector(const char* element, const AxisValues& position) const;
  /// Sets each axis' cruise speed from a move's Speed (nullptr: the default, the top speed); "" or "space" / "speed"
  /// (a space it does not list, a share outside 0..1). mutex_ held.
  std::string setMoveSpeed(const tinyxml2::XMLElement* speed, TimePoint now);
  /// Moves to \p position on every axis (a preset, home).
  void goToAll(const AxisValues& position, TimePoint now);
  /// Moves pan or tilt to \p target as the camera does (from below by the backlash, if it has one).
  void goToPanTilt(Axis axis, double target, TimePoint now);
  /// Moves \p axis at the generic velocity \p x (a ContinuousMove's), as the camera does.
  void moveAxis(Axis axis, double x, TimePoint now);
  /// X at generic zoom 1 (the listed range's end: X = zoomMax() ^ z).
  double zoomMax() const
  {
    return config_.device.axes[ZOOM].range.max;
  }

  const OnvifCameraEmulatorConfig config_;
  const FieldOfViewModel lens_;  ///< config_.field_of_view at every zoom
  // Guarded by mutex_, with the model.
  mutable std::array<bool, AXIS_COUNT> velocity_axes_{};  ///< axes a ContinuousMove moves until its timeout
  TimePoint velocity_until_{};
  /// Backlash: the target each pan-tilt axis goes on to once it has reached the point below it (NaN: none).
  mutable AxisValues approach_{};
  /// Axes a command drives (a position not yet reached, a speed): MoveStatus says MOVING for them, even when a fault
  /// blocks the axis (a blocked motor's controller still drives it).
  mutable std::array<bool, AXIS_COUNT> driving_{};
  AxisValues commanded_speed_{};   ///< the last position move's cruise speeds
  SimLensModel focus_iris_;        ///< the Imaging service's lens
  std::map<int, Preset> presets_;  ///< by token number
  int next_preset_ = 1;
  AxisValues home_{ { 0.0, 0.0, 1.0 } };
  std::uint64_t refused_tokens_ = 0;
  std::unique_ptr<HttpCameraServer> server_;  ///< last: its thread calls handle()
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief ONVIF PTZ cameras (SOAP 1.2 over HTTP POST): bring-up of the clock, services, profile and node; AbsoluteMove,
 * ContinuousMove, Stop and GetStatus, stamped with WS-Security UsernameToken digests in the camera's clock.
 */
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/http/http_device_protocol.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/onvif/onvif_imaging.h"
#include "ptz_action_server/core/onvif/onvif_motion_check.h"

namespace ptz_action_server
{
/// How a generic-space coordinate maps to an angle: angle = sign * scale * x + offset.
struct GenericAxisMapping
{
  double scale = M_PI;  ///< rad of x = 1
  double offset = 0.0;  ///< rad at x = 0
  double sign = 1.0;    ///< -1 for cameras that turn left for a positive pan
};

/// What only the ONVIF protocol needs to know.
struct OnvifSettings
{
  std::string device_path = "/onvif/device_service";  ///< where GetSystemDateAndTime and GetCapabilities go
  std::string profile;                                ///< profile token; "" = the first with a PTZConfiguration
  std::string username;                               ///< WS-Security user ("" = no WS-Security)
  std::string password;                               ///< never printed
  /// AbsoluteMove in SphericalPositionSpaceDegrees when the node lists it, unless the camera reports its status in
  /// the generic space (then goals go in the generic space too: a goal and the status that confirms it in one space)
  bool prefer_degrees = true;
  GenericAxisMapping pan{ M_PI, 0.0, 1.0 };
  GenericAxisMapping tilt{ M_PI / 2.0, 0.0, 1.0 };
  double velocity_sign_pan = 1.0;  ///< a camera may turn its velocities otherwise than its positions
  double velocity_sign_tilt = 1.0;
  double zoom_max = 18.0;       ///< X at generic zoom 1 (zoom 0 is 1X; X = zoom_max ^ z, never linear)
  double pan_max_speed = 1.5;   ///< rad/s at generic velocity 1
  double tilt_max_speed = 1.0;  ///< rad/s
  double zoom_max_rate = 8.0;   ///< X/s at generic zoom velocity 1
  double acceleration = 3.0;    ///< rad/s^2, for goal timeouts and how fast the camera brakes after Stop
  /// s of a ContinuousMove's Timeout (whole seconds), re-sent at half of it; brought into the camera's PTZTimeout
  /// range when outside it
  int velocity_timeout = 2;
  /// s an AbsoluteMove's axes have to begin moving (their position unchanged, their MoveStatus never MOVING): past
  /// it, the camera is taken as one that answers AbsoluteMove and never moves. 0: never judged. Keep it under the
  /// node's stall_timeout.
  double move_start_timeout = 0.5;
};

struct OnvifCounters
{
  Counter statuses;  ///< GetStatus replies read
  Counter faults;    ///< SOAP faults to commands
  Counter error_answers;
  Counter malformed;
  Counter velocity_refreshes;   ///< ContinuousMoves re-sent before their timeout
  Counter refused_locally;      ///< commands for an axis the camera cannot do, refused without sending them
  Counter zero_velocity_stops;  ///< ContinuousMoves with zero velocity sent after a Stop the camera did not obey
};

/**
 * \brief ONVIF PTZ over a DeviceSession's HTTP link.
 *
 * Bring-up at every (re)connection: GetSystemDateAndTime (no authentication; the clock offset), GetCapabilities (the
 * service paths; the configured host is kept), GetProfiles (the profile, its PTZConfiguration's default spaces),
 * GetNodes (the spaces the node lists, their ranges, MaximumNumberOfPresets, HomeSupported), GetConfigurationOptions
 * (the timeout range), GetPresets (when the node has presets; a fault only means none), and a first GetStatus. From
 * what the camera answered it declares its capabilities:
 * - pan-tilt `absolute` when the node lists SphericalPositionSpaceDegrees or PositionGenericSpace (AbsoluteMove),
 *   `velocity` when it lists VelocityGenericSpace (ContinuousMove), `feedback` when GetStatus carries a pan-tilt
 *   position in a space this backend converts; zoom is present with a generic zoom position space.
 * - The status is read in the space its reply names (the configuration's default when it names none; the generic
 *   space when the configuration declares none either) and converted; goals go in one listed space, clamped into its
 *   range. A listed range the camera's own status contradicts is wrong: the status wins, told once (warn +
 * diagnostics).
 *
 * A camera whose PTZ configuration options (GetConfigurationOptions' Spaces) list the pan-tilt TranslationSpaceFov
 * centres points of its picture itself (aimInView(), Capabilities::view_centre): RelativeMove in that space, with a
 * box's zoom where they list the zoom's TranslationSpaceFov or, with a generic zoom, its TranslationGenericSpace.
 *
 * Goals are AbsoluteMove (without the PanTilt when pan and tilt rest where the goal puts them: a zoom-only move);
 * velocity goals ContinuousMove (re-sent before its timeout, which lies in the camera's PTZTimeout range), cancel Stop,
 * state GetStatus at the poll period (a camera without a position in it is kept alive by its answers). A SOAP fault to
 * a command is a device fault with the camera's words; during the bring-up it fails the start with what the camera
 * answered. What the camera does after a command is checked (onvif::MotionCheck): a camera still moving after Stop
 * gets a ContinuousMove with zero velocity (and every Stop from then on is followed by one); a camera that answers
 * AbsoluteMove and does not move faults the goal and is declared without `absolute` (the node's ClosedLoopBackend
 * then steers it); a zoom that stops short of the range the node lists faults the goal and is not sent beyond again.
 * Each is told once (warnings()).
 */
class OnvifProtocol : public HttpDeviceProtocol
{
public:
  /// DeviceConfig<OnvifProtocol> (device_backend.h): these settings, and the defaults of the link and the session
  /// (HttpDeviceProtocol's).
  using Settings = OnvifSettings;
  /// Throws ConfigError for a config this protocol cannot run (not over HTTP, ...).
  static void validate(const DeviceConfig<OnvifProtocol>& config);

  OnvifProtocol(const OnvifSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "onvif";
  }
  std::string deviceName() const override
  {
    return "an ONVIF camera";
  }
  Capabilities capabilities() const override;
  void onConnected() override;
  void poll() override;
  void goTo(const AxisValues& position) override;
  /// AbsoluteMove with a Speed (GenericSpeedSpace, ZoomGenericSpeedSpace: \p speed / the axis' max speed, within the
  /// listed range) on the axes whose speed space the node lists (capabilities().speed says DEVICE for them).
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  /// RelativeMove with the pan-tilt in TranslationSpaceFov (x = 2 X - 1, y = 1 - 2 Y of the picture's shares) and, for
  /// a box, the zoom by its magnification: in the zoom's TranslationSpaceFov where the options list it, else in the
  /// generic translation space by the zoom law (X = zoom_max ^ z).
  void aimInView(const ViewTarget& target) override;
  /// Focus and iris through the Imaging service (onvif_lens.cpp): SetImagingSettings for the modes and the iris (its
  /// Exposure Mode MANUAL with the Iris), Move (Continuous Speed, Absolute Position) and Stop for the focus, after a
  /// SetImagingSettings AutoFocusMode MANUAL where the focus is not known to be manual (some cameras refuse a Move in
  /// AUTO). A refusal is a lens fault, never the goal's.
  void lens(const LensCommand& command) override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const OnvifCounters& counters() const
  {
    return counters_;
  }
  /// The warnings told so far (a range contradicted by the camera's status). Any thread.
  std::vector<std::string> warnings() const;

private:
  /// What a camera that answers AbsoluteMove and does not move lacks.
  static constexpr const char* IGNORES_ABSOLUTE_MOVE = "this camera answers AbsoluteMove and does not move";

  /// How one axis pair (pan-tilt) or the zoom is driven, as the bring-up found it.
  struct PanTiltPlan
  {
    bool absolute = false;     ///< AbsoluteMove in move_space
    bool velocity = false;     ///< ContinuousMove in the generic velocity space
    bool feedback = false;     ///< GetStatus carries a position this backend converts
    std::string move_space;    ///< the listed absolute space goals go in ("" if none)
    onvif::Range x, y;         ///< its ranges as used (the listed ones, unless the status contradicted them)
    std::string status_space;  ///< the space of the first status' position
    std::string limitation;    ///< what the camera lacks, in its terms ("" if nothing)
    bool speed = false;        ///< the node lists GenericSpeedSpace: AbsoluteMove takes a Speed
    onvif::Range speed_range;  ///< its listed range
  };
  struct ZoomPlan
  {
    bool present = false;   ///< the node lists the generic zoom position space
    bool absolute = false;  ///< AbsoluteMove takes it (present, unless the camera refused AbsoluteMove)
    bool velocity = false;
    bool feedback = false;
    std::string limitation;
    bool speed = false;  ///< the node lists ZoomGenericSpeedSpace
    onvif::Range speed_range;
  };
  /// How a point of the camera's picture is centred (PtzBackend::aimInView()), as the node's spaces allow.
  struct ViewPlan
  {
    bool centre = false;  ///< the configuration options list the pan-tilt TranslationSpaceFov
    onvif::Range x, y;    ///< its ranges
    enum class Zoom
    {
      NONE,     ///< a box is only centred
      FOV,      ///< the zoom's TranslationSpaceFov: the magnification itself
      GENERIC,  ///< the generic zoom translation, by the zoom law
    };
    Zoom zoom = Zoom::NONE;
    onvif::Range z;  ///< the zoom space's range
  };
  /// What diagnostics() shows of the bring-up (guarded by report_mutex_: diagnostics() runs on any thread).
  struct Report
  {
    std::string pan_tilt;  ///< "AbsoluteMove in SphericalPositionSpaceDegrees, status in PositionGenericSpace"
    std::string presets;   ///< "12 (GetPresets)", "none: GetPresets answered ter:ActionNotSupported"
    std::vector<std::string> warnings;
  };

  /// POSTs \p body (an operation) to \p path; true with message_.content the response, else \p problem ("" when
  /// the link was lost). Every request goes through it.
  bool call(const std::string& path, const std::string& body, bool secure, std::string& problem);
  /// Sends a command; true if the camera took it. A fault is the current command's.
  bool command(const std::string& path, const std::string& body, const char* operation);
  /// The camera refused AbsoluteMove as an operation it does not have: no more AbsoluteMoves, capabilities told.
  void absoluteMoveRefused(const std::string& answer);
  /// Acts on what the motion check found in a status.
  void onFinding(const onvif::MotionFinding& finding);
  /// Sends the ContinuousMove with zero velocity that stops the cameras that ignore Stop.
  void sendZeroVelocity();
  /// Reads the clock (GetSystemDateAndTime): unauthenticated, else (Axis answers 401) with WS-Security in our clock,
  /// else goes on in our clock. False with \p problem when the link went.
  bool readClock(std::string& problem);
  /// The ContinuousMove Timeout within the camera's PTZTimeout range [\p min, \p max] (s; max 0 = no range).
  void chooseVelocityTimeout(double min, double max);
  /// Everything a (re)connection asks, up to the first GetStatus (\p status).
  bool bringUp(std::string& problem, onvif::Status& status);
  /// Decides the plans from the node, the profile and the first status.
  void plan(const onvif::Status& status);
  /// Decides view_ from the translation spaces the configuration options list (onvif_view_aim.cpp).
  void planView();
  /// "" or why \p status cannot be read (a position in a space this backend cannot convert that it reported before).
  std::string readState(const onvif::Status& status, AxisValues& position);
  /// Tells once of each listed range \p status contradicts, and widens the range in use.
  void checkRanges(const onvif::Status& status, const std::string& space);
  void warnOnce(const std::string& key, const std::string& text);
  Capabilities cameraCapabilities() const;
  /// The speed of position goals: DEVICE where the node lists the generic speed space (and the axis takes
  /// AbsoluteMove), OWN beside one that does, NODE where none does.
  MoveSpeedCapability moveSpeed() const;
  double angleOf(const GenericAxisMapping& mapping, double x) const;
  double genericOf(const GenericAxisMapping& mapping, double angle) const;
  /// The status' pan-tilt space: the one it names, else the configuration's default, else the generic space.
  std::string statusSpace(const onvif::Status& status) const;
  std::string zoomStatusSpace(const onvif::Status& status) const;
  double cameraTime() const;
  /// Asks the Imaging service what the lens has (GetOptions, GetMoveOptions, GetImagingSettings, GetStatus) and
  /// decides lens_; false only when the link went (a camera without it, or refusing it, has no lens).
  bool bringUpLens(std::string& problem);
  /// Reads the lens' settings and, at the next poll, the focus' status into the session's LensReport, every few polls
  /// and after a command.
  void pollLens();
  /// Sends a lens request; false with the lens fault counted.
  bool lensCall(const std::string& body);

  const OnvifSettings settings_;
  OnvifCounters counters_;
  mutable std::mutex report_mutex_;
  Report report_;

  // I/O thread only.
  double clock_offset_ = 0.0;  ///< camera UTC - our UTC, s
  onvif::ServicePaths paths_;
  onvif::Profile profile_;
  onvif::Node node_;
  PanTiltPlan pan_tilt_;
  ZoomPlan zoom_;
  ViewPlan view_;
  onvif::Node option_spaces_;  ///< the translation spaces GetConfigurationOptions lists
  bool device_presets_ = false;
  /// The camera answered AbsoluteMove with ter:ActionNotSupported although it lists position spaces: taken as
  /// continuous-only from then on (kept across reconnections).
  std::string absolute_refused_;
  /// The camera answered AbsoluteMove and did not move its pan-tilt / its zoom (kept across reconnections).
  bool pan_tilt_ignores_absolute_ = false;
  bool zoom_ignores_absolute_ = false;
  /// The highest zoom (X) the camera was seen to reach when sent beyond it (its listed range is not honoured); 0
  /// while none was seen. Kept across reconnections.
  double honoured_zoom_max_ = 0.0;
  /// The camera went on moving after a Stop: every Stop is followed by a ContinuousMove with zero velocity.
  bool stop_needs_zero_velocity_ = false;
  onvif::MotionCheck motion_check_;
  std::uint64_t watched_command_ =
      0;                             ///< the command whose effect the motion check watches (its faults are that one's)
  double velocity_timeout_ = 2.0;    ///< s: the Timeout ContinuousMoves carry (velocity_timeout within the range)
  std::vector<std::string> warned_;  ///< keys of the warnings told (once per backend, across reconnections)
  /// Listed ranges the status contradicted, by space URI: kept across reconnections (the camera lists them again).
  std::vector<onvif::Space> corrected_;
  HttpRequest request_;
  onvif::SoapMessage message_;
  bool unauthorized_ = false;  ///< the last call() was refused for its authentication (HTTP 401, ter:NotAuthorized)
  std::string velocity_body_;  ///< the ContinuousMove in force ("" when none)
  onvif::ImagingOptions imaging_options_;  ///< the lens' ranges and modes (Imaging GetOptions, GetMoveOptions)
  LensCapabilities lens_;                  ///< what the lens takes, as the bring-up found it
  int lens_polls_ = 0;                     ///< polls until the lens is read again
  bool lens_status_next_ = false;          ///< the next poll reads the focus' status (Imaging GetStatus)
  TimePoint velocity_sent_at_{};
};

}  // namespace ptz_action_server

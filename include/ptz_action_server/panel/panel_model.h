/**
 * \file
 * \brief The rviz panel's logic that needs neither Qt nor rviz nor a rosmaster: which namespaces hold a camera, the
 * texts the panel shows, the jog buttons' velocities and which controls are greyed. PtzPanel only wires these to
 * widgets; test_core tests them.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ptz_action_server::panel
{
/// The node's state topic and its type: every namespace holding a publisher of it is a camera.
inline constexpr const char* STATE_TOPIC = "ptz_state";
inline constexpr const char* STATE_TYPE = "ptz_action_server/PtzState";
/// Seconds without a ptz_state after which the panel greys its controls.
inline constexpr double STATE_TIMEOUT = 2.0;
/// What the panel says while it greys its controls for want of ptz_state.
inline constexpr const char* NO_STATE_TEXT = "no ptz_state for 2 s";

/// One published topic as the master lists it.
struct TopicInfo
{
  std::string name;      ///< resolved name, e.g. /left/ptz_state
  std::string datatype;  ///< e.g. ptz_action_server/PtzState
};

/// The namespaces ("/ptz", "/left", "/" for a node at the root) of every ptz_state topic of type PtzState, sorted,
/// each once. Topics of another type or another name are ignored.
std::vector<std::string> cameraNamespaces(const std::vector<TopicInfo>& topics);

/// A name in the camera's namespace: ("/ptz", "move_ptz/velocity") -> "/ptz/move_ptz/velocity"; ("/", x) -> "/x".
std::string inNamespace(const std::string& ns, const std::string& name);

/// The device link as the node's diagnostics report it.
enum class Link
{
  UNKNOWN,  ///< no diagnostics from this camera yet
  UP,
  DOWN,
};

/// Whether a diagnostics status comes from a node directly in `ns`: diagnostic_updater names it "<node name without
/// the leading slash>: <task>", e.g. "ptz/ptz_action_server: Backend" for the node /ptz/ptz_action_server.
bool diagnosticsOfNamespace(const std::string& ns, const std::string& status_name);

/// The mode's name: "idle", "position", "velocity" (PtzState's MODE_*), or "mode N" for anything else.
std::string modeText(int mode);
/// "34.4° (0.600 rad)"; "n/a" for NaN (an axis the device does not report).
std::string angleText(double rad);
/// "3.00 x"; "n/a" for NaN.
std::string zoomText(double zoom);
/// "up", "down", "unknown".
std::string linkText(Link link);

/// Watches the arrival of ptz_state: fresh while the last one is at most STATE_TIMEOUT old.
class StateWatch
{
public:
  /// A ptz_state arrived at `now` (s, any monotonic clock).
  void received(double now);
  /// Forget every arrival (the panel switched to another camera).
  void reset();
  bool fresh(double now) const;
  /// "" while fresh, NO_STATE_TEXT otherwise (also before the first ptz_state).
  std::string banner(double now) const;

private:
  bool received_ = false;  ///< a ptz_state arrived since the last reset
  double last_ = 0.0;      ///< when the last one arrived
};

/// The status of one goal of one of the node's actions, as its status topic lists it.
struct GoalStatusEntry
{
  std::string action;       ///< e.g. "velocity" (the part after move_ptz/)
  std::uint8_t status = 0;  ///< actionlib_msgs/GoalStatus constants
  std::string text;         ///< the goal status text (a rejection's or an abort's reason)
  double stamp = 0.0;       ///< the goal id's stamp (when the client sent it), s
  std::string id;           ///< the goal id's id
};

/// actionlib's name of a goal status: "pending", "active", "preempted", "succeeded", "aborted", "rejected",
/// "preempting", "recalling", "recalled", "lost", or "status N".
std::string goalStatusName(std::uint8_t status);
/// The goal line: the newest active goal ("velocity: active"), else the newest goal of any state
/// ("position_abs: aborted: stalled: ..."), with its text when it has one; "no goal" for an empty list.
std::string goalText(const std::vector<GoalStatusEntry>& goals);

/// What one axis of the camera can do, from its latched capabilities.
struct AxisAbility
{
  bool present = true;   ///< the device has this axis
  bool absolute = true;  ///< position goals move it
  bool velocity = true;  ///< velocity goals move it
  double min = 0.0;      ///< limits (rad, or X for zoom)
  double max = 0.0;
  double max_speed = 0.0;  ///< rad/s or X/s; 0 or NaN = unknown
};

/// The camera's axes; until its capabilities arrive every axis is assumed able (the node rejects what it cannot do).
struct Abilities
{
  bool known = false;  ///< the capabilities message arrived
  AxisAbility pan;
  AxisAbility tilt;
  AxisAbility zoom;
};

/// The jog controls: the four arrows and the zoom rocker's two ends.
enum class Jog
{
  LEFT,
  RIGHT,
  UP,
  DOWN,
  ZOOM_IN,
  ZOOM_OUT,
};

/// A velocity goal: rad/s and X/s.
struct Velocity
{
  double pan = 0.0;
  double tilt = 0.0;
  double zoom = 0.0;
};

/// Jog speeds when the capabilities give none: rad/s for pan and tilt, X/s for zoom.
inline constexpr double DEFAULT_PAN_TILT_SPEED = 0.5;
inline constexpr double DEFAULT_ZOOM_SPEED = 2.0;

/// The velocity goal of a pressed jog control at `fraction` (clamped to [0.05, 1]) of the axis' max speed (the
/// default when unknown). The contract's signs: right = positive pan, up = positive tilt, in = positive zoom.
Velocity jogVelocity(Jog jog, double fraction, const Abilities& abilities);

/// Which controls are usable (the rest are greyed).
struct Enables
{
  bool jog_pan = false;      ///< left and right
  bool jog_tilt = false;     ///< up and down
  bool jog_zoom = false;     ///< the zoom rocker
  bool absolute = false;     ///< the pose fields and their Go
  bool presets = false;      ///< preset go, home, save, delete
  bool look_switch = false;  ///< look_at_clicked_point
};

/// What the greying depends on.
struct EnableInputs
{
  bool fresh = false;           ///< ptz_state arrived within STATE_TIMEOUT
  Link link = Link::UNKNOWN;    ///< the device link (down greys every motion: the node rejects goals then)
  Abilities abilities;          ///< what the axes can do
  bool look_available = false;  ///< the node offers look_at_clicked_point (service or its latched state)
};

/// The greying rules: nothing without a fresh ptz_state; no motion while the link is down; a jog control only for an
/// axis that takes velocity goals, pose and presets only when pan or tilt takes position goals; the switch only when
/// the node offers it.
Enables enables(const EnableInputs& inputs);

/// The aim marker's logic (ptz_aim_marker): the contract's pan and tilt against a marker orientation in the base frame.
struct Aim
{
  double pan = 0.0;   ///< rad, clockwise seen from above
  double tilt = 0.0;  ///< rad, up
};

/// A quaternion (x, y, z, w).
struct Quaternion
{
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  double w = 1.0;
};

/// The orientation whose x axis is the optical axis at `aim` with the URDF's conventions (pan about -z, tilt about -y):
/// a rotation by -pan about z, then by -tilt about the turned y.
Quaternion orientationOfAim(const Aim& aim);
/// The pan and tilt that point the optical axis along the x axis of `orientation` (any quaternion, normalised here;
/// roll about the axis is ignored). Straight up or down keeps pan 0.
Aim aimOfOrientation(const Quaternion& orientation);

/// Lets an event through at most once per `period` seconds (0: never; the drag then sends only on release).
class RateLimiter
{
public:
  explicit RateLimiter(double period) : period_(period)
  {
  }
  /// Whether an event at `now` (s) may pass; if so it counts as the last one.
  bool allow(double now);
  /// Forget the last event (a new drag starts).
  void reset();

private:
  double period_;
  bool any_ = false;
  double last_ = 0.0;
};

}  // namespace ptz_action_server::panel

/**
 * \file
 * \brief Plain types shared by the core: axes, per-axis values, clocks, device samples and errors.
 *
 * Nothing in core/ includes ROS; the ROS layer converts to and from these types.
 */
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "ptz_action_server/core/lens.h"

namespace ptz_action_server
{
/// Index of an axis in every per-axis array of the core.
enum Axis : std::size_t
{
  PAN = 0,
  TILT = 1,
  ZOOM = 2,
};

constexpr std::size_t AXIS_COUNT = 3;
constexpr std::array<Axis, AXIS_COUNT> ALL_AXES = { PAN, TILT, ZOOM };

/// Lower-case axis name for messages ("pan", "tilt", "zoom").
const char* axisName(Axis axis);
/// The unit of an axis' position in messages: "rad" for pan and tilt, "X" (magnification) for zoom.
const char* unitOf(Axis axis);

/// One value per axis: pan and tilt in rad (or rad/s), zoom as X-factor (or X/s).
using AxisValues = std::array<double, AXIS_COUNT>;

/// The monotonic clock the core runs on. Backends take a Clock so tests can drive time by hand.
using SteadyClock = std::chrono::steady_clock;
using TimePoint = SteadyClock::time_point;

/// Seconds between two time points, as double.
inline double secondsBetween(TimePoint from, TimePoint to)
{
  return std::chrono::duration<double>(to - from).count();
}

/// A time point plus a duration in (fractional) seconds.
inline TimePoint addSeconds(TimePoint t, double seconds)
{
  return t + std::chrono::duration_cast<SteadyClock::duration>(std::chrono::duration<double>(seconds));
}

/// \brief Source of time for backends and goal supervision. Thread-safe.
class Clock
{
public:
  virtual ~Clock() = default;
  virtual TimePoint now() const = 0;
};

/// The real steady clock.
class SystemClock : public Clock
{
public:
  TimePoint now() const override
  {
    return SteadyClock::now();
  }
};

/// A clock that only moves when told to: tests and benchmarks drive time by hand with it.
class ManualClock : public Clock
{
public:
  explicit ManualClock(TimePoint start = TimePoint(std::chrono::seconds(1000))) : nanoseconds_(toNanoseconds(start))
  {
  }
  TimePoint now() const override
  {
    return TimePoint(std::chrono::nanoseconds(nanoseconds_.load()));
  }
  /// Moves time forward by \p seconds.
  void advance(double seconds)
  {
    nanoseconds_ += static_cast<std::int64_t>(seconds * 1e9);
  }

private:
  static std::int64_t toNanoseconds(TimePoint t)
  {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
  }
  std::atomic<std::int64_t> nanoseconds_;
};

/// Inclusive range of an axis.
struct AxisRange
{
  double min = 0.0;  ///< lowest allowed value
  double max = 0.0;  ///< highest allowed value

  bool contains(double value) const
  {
    return value >= min && value <= max;
  }
};

/**
 * \brief What a device can do on one axis, as its backend found out (from its settings, or by asking the device).
 *
 * The node refuses a goal that needs what an axis lacks, naming it (see findUnsupported()), and never judges a goal
 * reached on an axis the device cannot move or report.
 */
struct AxisCapability
{
  bool present = true;   ///< false: the device has no such axis (no zoom): goals must leave it alone
  bool absolute = true;  ///< goes to a commanded position (false: it only moves at a speed)
  bool velocity = true;  ///< moves at a commanded speed
  bool feedback = true;  ///< reports where it is (false: the sample's position of this axis means nothing)
  /// Zoom only, for a zoom that cannot go to X-factors (`absolute` or `feedback` false): the device can still go to
  /// its widest view, zoom 1, so a zoom 1 goal reaches goTo() as 1.0 (without it, a zoom 1 goal leaves the zoom alone).
  bool widest_view = false;
  AxisRange range;            ///< position limits
  double max_speed = 1.0;     ///< largest speed the device accepts, per second
  double acceleration = 0.0;  ///< per second squared; 0 means "unknown, treat as instant"
  /// Why the axis is missing or limited, in the device's terms ("this camera reports no zoom position"); "" for the
  /// plain words ("the device has no zoom"). Goes into rejection texts and diagnostics.
  std::string limitation;
  /// What the user can do about it ("set axis/zoom_table"), or "".
  std::string remedy;
};

/// An axis that goes to positions, moves at a speed and reports where it is, within \p range.
inline AxisCapability fullAxis(const AxisRange& range, double max_speed, double acceleration)
{
  AxisCapability axis;
  axis.range = range;
  axis.max_speed = max_speed;
  axis.acceleration = acceleration;
  return axis;
}

/// An axis the device does not have (zoom of a pan-tilt unit): range [1, 1] for zoom, and \p limitation says why.
inline AxisCapability absentAxis(const std::string& limitation = "")
{
  AxisCapability axis;
  axis.present = false;
  axis.absolute = false;
  axis.velocity = false;
  axis.feedback = false;
  axis.range = AxisRange{ 1.0, 1.0 };
  axis.limitation = limitation;
  return axis;
}

/**
 * \brief A point of the device's own current picture, and a box around it to fill the view with: what a device that
 * aims in its own picture (Capabilities::view_centre, PtzBackend::aimInView()) is given.
 *
 * Normalised to the picture, whatever its size: (0, 0) is the top-left corner of its top-left pixel, (1, 1) the
 * bottom-right corner of its bottom-right pixel, (0.5, 0.5) its centre.
 */
struct ViewTarget
{
  double x = 0.5;           ///< 0: the picture's left edge, 1: its right edge
  double y = 0.5;           ///< 0: its top edge, 1: its bottom edge
  double box_width = 0.0;   ///< share of the picture's width; 0 with box_height 0: centre only, the zoom stays
  double box_height = 0.0;  ///< share of its height (a box wider than the picture zooms out)
  int image_width = 0;      ///< px of the picture the point was chosen on (VAPIX counts in its pixels)
  int image_height = 0;     ///< px

  /// True when the target asks for a zoom (a box).
  bool box() const
  {
    return box_width > 0.0 || box_height > 0.0;
  }
  /// How much the box asks the view to magnify: 1 / the larger of its shares (2: to half the field of view); 1 without
  /// a box.
  double magnification() const;
};

/// How a position goal's speed reaches an axis (PtzBackend::goToAtSpeed()).
enum class SpeedControl : std::uint8_t
{
  NODE = 0,    ///< the node shapes the motion: it streams targets along a profile at the speed (SpeedShapingBackend)
  DEVICE = 1,  ///< the device takes the speed with its absolute move (VISCA's speed bytes, Axis `speed=`, ...)
  /// The node steers the axis on speed commands (ClosedLoopBackend, a device that only moves at a speed) and caps
  /// them at the speed.
  STEERED = 2,
  /// The axis moves at its own speed whatever the goal asks (its device takes a speed on other axes only, and the
  /// node does not stream one axis beside the device's own move).
  OWN = 3,
};

/// The speed of position goals, per axis: who applies it and the slowest speed there is. The top speed is each
/// AxisCapability::max_speed.
struct MoveSpeedCapability
{
  std::array<SpeedControl, AXIS_COUNT> control{ { SpeedControl::NODE, SpeedControl::NODE, SpeedControl::NODE } };
  /// The slowest speed of each axis (rad/s, X/s): the device's slowest step (VISCA's speed byte 1); 0: any speed.
  AxisValues min_speed{};

  /// True when the backend applies the speed itself on at least one axis (DEVICE or STEERED): goToAtSpeed() then
  /// goes to it unshaped, and the axes it does not apply it on move at their own speed.
  bool appliedByBackend() const
  {
    for (SpeedControl axis : control)
    {
      if (axis == SpeedControl::DEVICE || axis == SpeedControl::STEERED)
      {
        return true;
      }
    }
    return false;
  }
};

/// What a backend's device can do; the node intersects the ranges with the URDF joint limits.
struct Capabilities
{
  std::array<AxisCapability, AXIS_COUNT> axes;
  MoveSpeedCapability speed;  ///< the speed of position goals (shaped by the node unless the backend says)
  /// Informative, for diagnostics and the capabilities topic (the node's own relative goals, presets and home work
  /// from the reported pose on every device that goes to positions):
  bool relative_moves = false;  ///< the device moves by an offset of its own (VAPIX rpan, ONVIF RelativeMove)
  bool device_presets = false;  ///< the device stores presets of its own
  bool device_home = false;     ///< the device has a home position of its own
  LensCapabilities lens;        ///< focus and iris (none by default)
  /// The device centres a point of its own current picture by a command of its own (PtzBackend::aimInView()): it knows
  /// its lens, so the node needs no field of view, but it works on the picture it shows now only.
  bool view_centre = false;
  bool view_box_zoom = false;  ///< ... and zooms so that a box of it fills the view
  std::string view_command;    ///< the device's commands for it, in its terms ("VAPIX center"), for messages
};

/// \brief One snapshot of the device, as a backend last knew it.
///
/// Small and copyable without allocation, because the node takes one every state tick.
struct PtzSample
{
  TimePoint stamp{};              ///< when the device's state was measured (or received)
  bool link_up = false;           ///< true while the backend hears valid state from the device
  AxisValues position{};          ///< pan, tilt (rad), zoom (X)
  AxisValues velocity{};          ///< pan, tilt (rad/s), zoom (X/s); 0 when the device does not report it
  bool moving = false;            ///< the device is still in motion (false = settled)
  std::uint64_t fault_count = 0;  ///< increments each time the device refuses or fails a command
  std::uint64_t link_losses = 0;  ///< increments each time the link to the device is lost, even if it is back at once
};

/// A configuration value is missing, of the wrong type or out of range. The message names it.
class ConfigError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// A backend could not reach or set up its device.
class BackendError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

}  // namespace ptz_action_server

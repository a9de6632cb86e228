/**
 * \brief The simulated pan-tilt-zoom device: motion of every axis, quantisation and fault hooks.
 *
 * The sim backend and every device emulator (PanTilt, FLIR, Pelco-D, DigiView) move this same model, so a goal
 * behaves alike whichever protocol carries it. Time is passed in, which makes the model deterministic in tests.
 */
#pragma once

#include <array>
#include <deque>

#include "ptz_action_server/core/motion/motion_profile.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// One simulated axis.
struct SimAxisConfig
{
  bool present = true;      ///< false: the device has no such axis; it stays at its initial value
  AxisRange range;          ///< mechanical limits; targets are clamped into them
  AxisMotionLimits motion;  ///< max speed, acceleration, base speed
  double resolution = 0.0;  ///< encoder step; positions are quantised to it (0 = continuous)
  double initial_position = 0.0;
};

/// The whole simulated device.
struct SimDeviceConfig
{
  std::array<SimAxisConfig, AXIS_COUNT> axes;

  /// A generic PTZ camera: pan +-pi at 1.5 rad/s, tilt +-pi/2 at 1 rad/s (3 rad/s^2, FLIR D46 resolution),
  /// zoom 1..24x slewing at 8 X/s.
  static SimDeviceConfig defaults();

  /// Capabilities this device would report to the node.
  Capabilities capabilities() const;
};

/// Faults the model can be told to show.
struct SimFaults
{
  std::array<bool, AXIS_COUNT> stalled{};  ///< a stalled axis freezes where it is and ignores commands
  double lag = 0.0;                        ///< seconds between a command and the moment the device acts on it
  /// Added to the position the device reports, not to where it is: a jump, or a place outside its limits.
  AxisValues report_offset{};
  /// s a device that answers requests takes before each answer (a slow device). Applied by the emulators of
  /// request/reply protocols (FLIR, Pelco-D, VISCA, Axis, ONVIF); devices that push their state ignore it.
  double reply_delay = 0.0;
};

/**
 * \brief Motion model of a simulated PTZ device.
 *
 * Not thread-safe: the owner serialises calls (the sim backend and the emulators hold a mutex).
 * Every call takes the current time; time must not go backwards between calls.
 */
class SimDeviceModel
{
public:
  SimDeviceModel(const SimDeviceConfig& config, TimePoint now);

  /// Moves one axis to \p target (clamped into its range, quantised), retargeting from the current motion.
  void goToAxis(Axis axis, double target, TimePoint now);
  /// Moves every present axis; the same as goToAxis() for each.
  void goTo(const AxisValues& target, TimePoint now);
  /// Moves one axis at \p velocity (clamped to its max speed) until a limit, a stop or another command.
  void moveAxisAtVelocity(Axis axis, double velocity, TimePoint now);
  /// moveAxisAtVelocity() for every present axis.
  void moveAtVelocity(const AxisValues& velocity, TimePoint now);
  /// Decelerates every axis to rest.
  void stop(TimePoint now);
  /// Sets the cruise speed of position moves on one axis (clamped to (0, max_speed]); takes effect on the next move.
  void setCruiseSpeed(Axis axis, double speed, TimePoint now);

  /// Applies a new fault set. Stalling freezes the axis where it is at \p now.
  void setFaults(const SimFaults& faults, TimePoint now);
  const SimFaults& faults() const
  {
    return faults_;
  }

  /// The device's state at \p now: quantised positions, velocities, whether anything still moves.
  PtzSample sample(TimePoint now);
  /// The next moment after \p now at which the state changes on its own without a new command: a lagged command
  /// falls due, or the last moving axis comes to rest. TimePoint::max() if nothing is under way.
  TimePoint nextEvent(TimePoint now) const;

  const SimDeviceConfig& config() const
  {
    return config_;
  }

private:
  enum class CommandKind
  {
    GO_TO,
    VELOCITY,
    STOP,
    CRUISE_SPEED,
  };

  /// A command waiting for the configured lag to pass.
  struct PendingCommand
  {
    TimePoint apply_at;
    CommandKind kind;
    Axis axis;
    double value;
  };

  struct AxisMotion
  {
    TrapezoidProfile profile = TrapezoidProfile::rest(0.0);
    TimePoint planned_at{};
    double cruise_speed = 0.0;
  };

  void submit(CommandKind kind, Axis axis, double value, TimePoint now);
  void apply(const PendingCommand& command);
  void applyDueCommands(TimePoint now);
  AxisMotionState exactState(Axis axis, TimePoint now) const;
  double clampAndQuantise(Axis axis, double value) const;
  double quantise(Axis axis, double value) const;

  SimDeviceConfig config_;
  SimFaults faults_;
  std::array<AxisMotion, AXIS_COUNT> axes_;
  std::deque<PendingCommand> pending_;
};

}  // namespace ptz_action_server

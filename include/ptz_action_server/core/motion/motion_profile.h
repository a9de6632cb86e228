/**
 * \file
 * \brief Symmetric trapezoidal velocity profile of one axis, replannable from any position and velocity.
 */
#pragma once

#include <array>
#include <cstddef>

namespace ptz_action_server
{
/// Motion limits of one axis.
struct AxisMotionLimits
{
  double max_speed = 1.0;     ///< cruise speed ceiling (> 0)
  double acceleration = 1.0;  ///< magnitude of acceleration and deceleration (> 0)
  /// Speed the motor can start from and stop at instantly, as stepper pan-tilt units do (0 <= base <= max).
  double base_speed = 0.0;
};

/// Position and velocity of an axis.
struct AxisMotionState
{
  double position = 0.0;
  double velocity = 0.0;
};

/**
 * \brief A planned move of one axis, as piecewise-constant acceleration segments from t = 0.
 *
 * The velocity may jump between 0 and +-base_speed at segment boundaries. After the last segment the axis rests at
 * finalPosition(). Planning never allocates (fixed capacity), so it can run on every command.
 */
class TrapezoidProfile
{
public:
  /// An axis at rest at \p position.
  static TrapezoidProfile rest(double position);

  /**
   * \brief Plans a move from \p start to rest at \p target, cruising at no more than \p cruise_speed.
   *
   * Moving towards the target with room to stop, the axis keeps going (accelerating, cruising or slowing to the
   * cruise speed). Moving away or too fast to stop in time, it first decelerates to rest, then comes back.
   */
  static TrapezoidProfile plan(const AxisMotionState& start, double target, double cruise_speed,
                               const AxisMotionLimits& limits);

  /// Plans the shortest deceleration from \p start to rest.
  static TrapezoidProfile stop(const AxisMotionState& start, const AxisMotionLimits& limits);

  /// Minimum time to move \p distance from rest to rest (closed form of the symmetric trapezoid or triangle).
  static double minimumDuration(double distance, const AxisMotionLimits& limits);

  /// Position and velocity \p t seconds after the start of the plan.
  AxisMotionState at(double t) const;

  /// Seconds until the axis is at rest.
  double duration() const;

  /// Where the axis comes to rest.
  double finalPosition() const
  {
    return final_position_;
  }

private:
  struct Segment
  {
    double start_time;    ///< seconds from the start of the plan
    double duration;      ///< seconds
    double position;      ///< position at start_time
    double velocity;      ///< velocity at start_time (after any jump)
    double acceleration;  ///< constant within the segment
  };

  void append(double duration, double velocity, double acceleration);
  void appendFromRest(double target, double cruise_speed, const AxisMotionLimits& limits);
  AxisMotionState endOfPlan() const;

  static constexpr std::size_t MAX_SEGMENTS = 5;
  std::array<Segment, MAX_SEGMENTS> segments_{};
  std::size_t segment_count_ = 0;
  double start_position_ = 0.0;
  double final_position_ = 0.0;
};

}  // namespace ptz_action_server

#include "ptz_action_server/core/motion/motion_profile.h"

#include <algorithm>
#include <cmath>

namespace ptz_action_server
{
namespace
{
/// Segments shorter than this are dropped; they only carry rounding noise.
constexpr double MIN_SEGMENT_DURATION = 1e-12;
/// Distances below this count as "already there".
constexpr double MIN_DISTANCE = 1e-12;

double signOf(double value)
{
  return value > 0.0 ? 1.0 : (value < 0.0 ? -1.0 : 0.0);
}

double baseSpeed(const AxisMotionLimits& limits, double cruise_speed)
{
  return std::clamp(limits.base_speed, 0.0, cruise_speed);
}

/// Distance needed to slow from \p speed to the base speed (after which the axis may stop at once).
double stoppingDistance(double speed, double base_speed, double acceleration)
{
  return speed > base_speed ? (speed * speed - base_speed * base_speed) / (2.0 * acceleration) : 0.0;
}
}  // namespace

TrapezoidProfile TrapezoidProfile::rest(double position)
{
  TrapezoidProfile profile;
  profile.start_position_ = position;
  profile.final_position_ = position;
  return profile;
}

TrapezoidProfile TrapezoidProfile::plan(const AxisMotionState& start, double target, double cruise_speed,
                                        const AxisMotionLimits& limits)
{
  const double cruise = std::min(cruise_speed, limits.max_speed);
  if (!(cruise > 0.0))
  {
    return stop(start, limits);
  }
  TrapezoidProfile profile = rest(start.position);
  const double acceleration = limits.acceleration;
  const double base = baseSpeed(limits, cruise);
  const double offset = target - start.position;
  const double direction = signOf(offset);
  const double distance = std::abs(offset);
  const double speed = std::abs(start.velocity);
  const double moving_direction = signOf(start.velocity);

  if (speed > 0.0 && moving_direction == direction && stoppingDistance(speed, base, acceleration) <= distance)
  {
    // Heading the right way with room to stop: keep going, no stop in between.
    const double entry = std::max(speed, base);  // below the base speed the motor may jump up to it
    if (entry > cruise)
    {
      const double slow_down = (entry * entry - cruise * cruise) / (2.0 * acceleration);
      const double final_braking = (cruise * cruise - base * base) / (2.0 * acceleration);
      const double cruising = std::max(0.0, distance - slow_down - final_braking);
      profile.append((entry - cruise) / acceleration, direction * entry, -direction * acceleration);
      profile.append(cruising / cruise, direction * cruise, 0.0);
      profile.append((cruise - base) / acceleration, direction * cruise, -direction * acceleration);
    }
    else
    {
      double peak = std::min(cruise, std::sqrt(acceleration * distance + (entry * entry + base * base) / 2.0));
      peak = std::max(peak, entry);
      const double speeding_up = (peak * peak - entry * entry) / (2.0 * acceleration);
      const double braking = (peak * peak - base * base) / (2.0 * acceleration);
      const double cruising = std::max(0.0, distance - speeding_up - braking);
      profile.append((peak - entry) / acceleration, direction * entry, direction * acceleration);
      profile.append(cruising / peak, direction * peak, 0.0);
      profile.append((peak - base) / acceleration, direction * peak, -direction * acceleration);
    }
  }
  else
  {
    if (speed > 0.0)
    {
      // Moving away, or too fast to stop in time: come to rest first, then plan from there.
      profile.append(speed > base ? (speed - base) / acceleration : 0.0, start.velocity,
                     -moving_direction * acceleration);
    }
    profile.appendFromRest(target, cruise, limits);
  }
  profile.final_position_ = target;
  return profile;
}

TrapezoidProfile TrapezoidProfile::stop(const AxisMotionState& start, const AxisMotionLimits& limits)
{
  TrapezoidProfile profile = rest(start.position);
  const double speed = std::abs(start.velocity);
  if (speed == 0.0)
  {
    return profile;
  }
  const double direction = signOf(start.velocity);
  const double base = baseSpeed(limits, limits.max_speed);
  profile.append(speed > base ? (speed - base) / limits.acceleration : 0.0, start.velocity,
                 -direction * limits.acceleration);
  profile.final_position_ = start.position + direction * stoppingDistance(speed, base, limits.acceleration);
  return profile;
}

double TrapezoidProfile::minimumDuration(double distance, const AxisMotionLimits& limits)
{
  distance = std::abs(distance);
  if (distance < MIN_DISTANCE || !(limits.max_speed > 0.0))
  {
    return 0.0;
  }
  const double acceleration = limits.acceleration;
  const double base = baseSpeed(limits, limits.max_speed);
  const double peak = std::min(limits.max_speed, std::sqrt(acceleration * distance + base * base));
  const double ramps = (peak * peak - base * base) / acceleration;  // distance of both ramps together
  return 2.0 * (peak - base) / acceleration + std::max(0.0, distance - ramps) / peak;
}

void TrapezoidProfile::appendFromRest(double target, double cruise_speed, const AxisMotionLimits& limits)
{
  const double position = endOfPlan().position;
  const double offset = target - position;
  const double distance = std::abs(offset);
  if (distance < MIN_DISTANCE)
  {
    return;
  }
  const double direction = signOf(offset);
  const double acceleration = limits.acceleration;
  const double base = baseSpeed(limits, cruise_speed);
  const double peak = std::min(cruise_speed, std::sqrt(acceleration * distance + base * base));
  const double ramp = (peak * peak - base * base) / (2.0 * acceleration);
  const double cruising = std::max(0.0, distance - 2.0 * ramp);
  append((peak - base) / acceleration, direction * base, direction * acceleration);
  append(cruising / peak, direction * peak, 0.0);
  append((peak - base) / acceleration, direction * peak, -direction * acceleration);
}

void TrapezoidProfile::append(double duration, double velocity, double acceleration)
{
  if (!(duration > MIN_SEGMENT_DURATION) || segment_count_ == MAX_SEGMENTS)
  {
    return;
  }
  double start_time = 0.0;
  double position = start_position_;
  if (segment_count_ > 0)
  {
    const Segment& last = segments_[segment_count_ - 1];
    start_time = last.start_time + last.duration;
    position = endOfPlan().position;
  }
  segments_[segment_count_++] = Segment{ start_time, duration, position, velocity, acceleration };
}

AxisMotionState TrapezoidProfile::endOfPlan() const
{
  if (segment_count_ == 0)
  {
    return AxisMotionState{ start_position_, 0.0 };
  }
  const Segment& last = segments_[segment_count_ - 1];
  const double dt = last.duration;
  return AxisMotionState{ last.position + last.velocity * dt + 0.5 * last.acceleration * dt * dt,
                          last.velocity + last.acceleration * dt };
}

AxisMotionState TrapezoidProfile::at(double t) const
{
  if (segment_count_ == 0 || t >= duration())
  {
    return AxisMotionState{ final_position_, 0.0 };
  }
  if (t <= 0.0)
  {
    return AxisMotionState{ start_position_, segments_[0].velocity };
  }
  std::size_t index = 0;
  while (index + 1 < segment_count_ && t >= segments_[index + 1].start_time)
  {
    ++index;
  }
  const Segment& segment = segments_[index];
  const double dt = t - segment.start_time;
  return AxisMotionState{ segment.position + segment.velocity * dt + 0.5 * segment.acceleration * dt * dt,
                          segment.velocity + segment.acceleration * dt };
}

double TrapezoidProfile::duration() const
{
  if (segment_count_ == 0)
  {
    return 0.0;
  }
  const Segment& last = segments_[segment_count_ - 1];
  return last.start_time + last.duration;
}

}  // namespace ptz_action_server

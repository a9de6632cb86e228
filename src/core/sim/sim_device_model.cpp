#include "ptz_action_server/core/sim/sim_device_model.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// Speeds below this are a stop.
constexpr double MIN_SPEED = 1e-9;
/// FLIR D46 resolution: 185.1428 arc seconds per encoder position.
constexpr double D46_RESOLUTION = arcSecondsToRadians(185.1428);
}  // namespace

SimDeviceConfig SimDeviceConfig::defaults()
{
  SimDeviceConfig config;
  SimAxisConfig& pan = config.axes[PAN];
  pan.range = AxisRange{ -M_PI, M_PI };
  pan.motion = AxisMotionLimits{ 1.5, 3.0, 0.0 };
  pan.resolution = D46_RESOLUTION;

  SimAxisConfig& tilt = config.axes[TILT];
  tilt.range = AxisRange{ -M_PI / 2.0, M_PI / 2.0 };
  tilt.motion = AxisMotionLimits{ 1.0, 3.0, 0.0 };
  tilt.resolution = D46_RESOLUTION;

  // Zoom lenses slew at a constant rate: base speed = max speed, so there is no ramp.
  SimAxisConfig& zoom = config.axes[ZOOM];
  zoom.range = AxisRange{ 1.0, 24.0 };
  zoom.motion = AxisMotionLimits{ 8.0, 1000.0, 8.0 };
  zoom.resolution = 0.0;
  zoom.initial_position = 1.0;
  return config;
}

Capabilities SimDeviceConfig::capabilities() const
{
  Capabilities capabilities;
  for (Axis axis : ALL_AXES)
  {
    const SimAxisConfig& source = axes[axis];
    AxisCapability& target = capabilities.axes[axis];
    if (!source.present)
    {
      target = absentAxis();
      continue;
    }
    target.range = source.range;
    target.max_speed = source.motion.max_speed;
    target.acceleration = source.motion.acceleration;
  }
  return capabilities;
}

SimDeviceModel::SimDeviceModel(const SimDeviceConfig& config, TimePoint now) : config_(config)
{
  for (Axis axis : ALL_AXES)
  {
    AxisMotion& motion = axes_[axis];
    motion.profile = TrapezoidProfile::rest(clampAndQuantise(axis, config_.axes[axis].initial_position));
    motion.planned_at = now;
    motion.cruise_speed = config_.axes[axis].motion.max_speed;
  }
}

void SimDeviceModel::goToAxis(Axis axis, double target, TimePoint now)
{
  submit(CommandKind::GO_TO, axis, target, now);
}

void SimDeviceModel::goTo(const AxisValues& target, TimePoint now)
{
  for (Axis axis : ALL_AXES)
  {
    goToAxis(axis, target[axis], now);
  }
}

void SimDeviceModel::moveAxisAtVelocity(Axis axis, double velocity, TimePoint now)
{
  submit(CommandKind::VELOCITY, axis, velocity, now);
}

void SimDeviceModel::moveAtVelocity(const AxisValues& velocity, TimePoint now)
{
  for (Axis axis : ALL_AXES)
  {
    moveAxisAtVelocity(axis, velocity[axis], now);
  }
}

void SimDeviceModel::stop(TimePoint now)
{
  for (Axis axis : ALL_AXES)
  {
    submit(CommandKind::STOP, axis, 0.0, now);
  }
}

void SimDeviceModel::setCruiseSpeed(Axis axis, double speed, TimePoint now)
{
  submit(CommandKind::CRUISE_SPEED, axis, speed, now);
}

void SimDeviceModel::setFaults(const SimFaults& faults, TimePoint now)
{
  applyDueCommands(now);
  for (Axis axis : ALL_AXES)
  {
    if (faults.stalled[axis] && !faults_.stalled[axis])
    {
      AxisMotion& motion = axes_[axis];
      motion.profile = TrapezoidProfile::rest(exactState(axis, now).position);
      motion.planned_at = now;
    }
  }
  faults_ = faults;
  faults_.lag = std::max(0.0, faults.lag);
}

PtzSample SimDeviceModel::sample(TimePoint now)
{
  applyDueCommands(now);
  PtzSample sample;
  sample.stamp = now;
  sample.link_up = true;
  for (Axis axis : ALL_AXES)
  {
    const AxisMotionState state = exactState(axis, now);
    sample.position[axis] = clampAndQuantise(axis, state.position) + faults_.report_offset[axis];
    sample.velocity[axis] = state.velocity;
    const AxisMotion& motion = axes_[axis];
    sample.moving = sample.moving || secondsBetween(motion.planned_at, now) < motion.profile.duration();
  }
  return sample;
}

TimePoint SimDeviceModel::nextEvent(TimePoint now) const
{
  constexpr double NEVER = 1e6;  ///< s; a profile this long (a velocity move with no limit ahead) never ends
  TimePoint next = TimePoint::max();
  if (!pending_.empty())
  {
    next = std::max(pending_.front().apply_at, now);
  }
  double rest_in = 0.0;
  for (const AxisMotion& motion : axes_)
  {
    rest_in = std::max(rest_in, motion.profile.duration() - secondsBetween(motion.planned_at, now));
  }
  if (rest_in > 0.0 && rest_in < NEVER)
  {
    next = std::min(next, addSeconds(now, rest_in));
  }
  return next;
}

void SimDeviceModel::submit(CommandKind kind, Axis axis, double value, TimePoint now)
{
  applyDueCommands(now);
  const PendingCommand command{ addSeconds(now, faults_.lag), kind, axis, value };
  if (faults_.lag > 0.0)
  {
    pending_.push_back(command);
  }
  else
  {
    apply(command);
  }
}

void SimDeviceModel::applyDueCommands(TimePoint now)
{
  while (!pending_.empty() && pending_.front().apply_at <= now)
  {
    apply(pending_.front());
    pending_.pop_front();
  }
}

void SimDeviceModel::apply(const PendingCommand& command)
{
  const Axis axis = command.axis;
  const SimAxisConfig& config = config_.axes[axis];
  AxisMotion& motion = axes_[axis];
  if (!config.present || faults_.stalled[axis])
  {
    return;
  }
  const AxisMotionState state = exactState(axis, command.apply_at);
  switch (command.kind)
  {
    case CommandKind::GO_TO:
      if (!std::isfinite(command.value))
      {
        return;
      }
      motion.profile =
          TrapezoidProfile::plan(state, clampAndQuantise(axis, command.value), motion.cruise_speed, config.motion);
      break;
    case CommandKind::VELOCITY: {
      const double velocity = std::clamp(command.value, -config.motion.max_speed, config.motion.max_speed);
      if (!(std::abs(velocity) > MIN_SPEED))  // also catches NaN
      {
        motion.profile = TrapezoidProfile::stop(state, config.motion);
        break;
      }
      // Velocity mode is a move towards the limit in that direction at that speed: it stops at the limit.
      const double limit = velocity > 0.0 ? config.range.max : config.range.min;
      motion.profile = TrapezoidProfile::plan(state, clampAndQuantise(axis, limit), std::abs(velocity), config.motion);
      break;
    }
    case CommandKind::STOP:
      motion.profile = TrapezoidProfile::stop(state, config.motion);
      break;
    case CommandKind::CRUISE_SPEED:
      if (command.value > MIN_SPEED)
      {
        motion.cruise_speed = std::min(command.value, config.motion.max_speed);
      }
      return;  // the current move keeps its speed
  }
  motion.planned_at = command.apply_at;
}

AxisMotionState SimDeviceModel::exactState(Axis axis, TimePoint now) const
{
  const AxisMotion& motion = axes_[axis];
  return motion.profile.at(secondsBetween(motion.planned_at, now));
}

double SimDeviceModel::quantise(Axis axis, double value) const
{
  const double resolution = config_.axes[axis].resolution;
  return resolution > 0.0 ? std::round(value / resolution) * resolution : value;
}

double SimDeviceModel::clampAndQuantise(Axis axis, double value) const
{
  const SimAxisConfig& config = config_.axes[axis];
  double result = quantise(axis, std::clamp(value, config.range.min, config.range.max));
  // Rounding may step past a limit that is not on the encoder grid: step back inside.
  if (result > config.range.max)
  {
    result -= config.resolution;
  }
  if (result < config.range.min)
  {
    result += config.resolution;
  }
  return result;
}

}  // namespace ptz_action_server

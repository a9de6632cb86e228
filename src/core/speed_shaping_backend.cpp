#include "ptz_action_server/core/speed_shaping_backend.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// Acceleration assumed for the plan when a device states none (it then reaches each target at once).
constexpr double UNKNOWN_ACCELERATION = 1e3;
}  // namespace

SpeedShapingBackend::SpeedShapingBackend(std::shared_ptr<PtzBackend> inner, double period)
  : ForwardingBackend(std::move(inner)), period_(period), timer_(TimerThread::shared())
{
  if (!(period_ > 0.0))
  {
    throw ConfigError("the speed shaping period must be > 0 s");
  }
  step_timer_ = timer_->at(TimerThread::Clock::time_point::max(), [this] { step(); });
}

SpeedShapingBackend::~SpeedShapingBackend()
{
  timer_->cancel(step_timer_);
}

Capabilities SpeedShapingBackend::capabilities() const
{
  Capabilities capabilities = inner().capabilities();
  const bool applied = capabilities.speed.appliedByBackend();
  for (Axis axis : ALL_AXES)
  {
    SpeedControl& control = capabilities.speed.control[axis];
    if (control != SpeedControl::NODE)
    {
      continue;
    }
    if (applied)
    {
      control = SpeedControl::OWN;  // the backend's own move carries the other axes' speeds: this one is not shaped
    }
    else
    {
      double& slowest = capabilities.speed.min_speed[axis];
      slowest = std::max(slowest, MIN_SHAPED_SHARE * capabilities.axes[axis].max_speed);
    }
  }
  return capabilities;
}

void SpeedShapingBackend::goTo(const AxisValues& position)
{
  std::lock_guard<std::mutex> lock(mutex_);
  endLocked();
  inner().goTo(position);
}

void SpeedShapingBackend::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  const Capabilities device = inner().capabilities();
  std::lock_guard<std::mutex> lock(mutex_);
  endLocked();
  if (device.speed.appliedByBackend())
  {
    inner().goToAtSpeed(position, speed);
    return;
  }
  const PtzSample start = inner().sample();
  target_ = position;
  duration_ = 0.0;
  bool any_shaped = false;
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = device.axes[axis];
    shaped_[axis] = capability.present && speed[axis] > 0.0 && std::isfinite(position[axis]);
    if (!shaped_[axis])
    {
      continue;
    }
    AxisMotionLimits limits;
    limits.max_speed = std::max(capability.max_speed, speed[axis]);
    limits.acceleration = capability.acceleration > 0.0 ? capability.acceleration : UNKNOWN_ACCELERATION;
    const AxisMotionState from{ start.position[axis], start.velocity[axis] };
    profiles_[axis] = TrapezoidProfile::plan(from, position[axis], speed[axis], limits);
    duration_ = std::max(duration_, profiles_[axis].duration());
    any_shaped = true;
  }
  if (!any_shaped || !start.link_up)
  {
    inner().goTo(position);  // nothing to shape (or nothing known of where it is): the device's own move
    return;
  }
  shaping_ = true;
  ++moves_;
  started_at_ = TimerThread::Clock::now();
  timer_->move(step_timer_, started_at_);  // the first target at once
}

void SpeedShapingBackend::moveAtVelocity(const AxisValues& velocity)
{
  std::lock_guard<std::mutex> lock(mutex_);
  endLocked();
  inner().moveAtVelocity(velocity);
}

void SpeedShapingBackend::stop()
{
  std::lock_guard<std::mutex> lock(mutex_);
  endLocked();
  inner().stop();
}

bool SpeedShapingBackend::shaping() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return shaping_;
}

void SpeedShapingBackend::step()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!shaping_)
  {
    return;
  }
  if (!inner().sample().link_up)
  {
    endLocked();  // the goal ends as link lost; the stream is not resumed when the device answers again
    return;
  }
  const TimerThread::Clock::time_point now = TimerThread::Clock::now();
  const double elapsed = std::chrono::duration<double>(now - started_at_).count();
  // One step ahead: the device heads for where the profile will be when the next target comes.
  const double ahead = elapsed + period_;
  if (ahead >= duration_)
  {
    inner().goTo(target_);
    ++steps_;
    endLocked();
    return;
  }
  AxisValues next = target_;
  for (Axis axis : ALL_AXES)
  {
    if (shaped_[axis])
    {
      next[axis] = profiles_[axis].at(ahead).position;
    }
  }
  inner().goTo(next);
  ++steps_;
  timer_->move(step_timer_, now + toDuration(period_));
}

void SpeedShapingBackend::endLocked()
{
  if (shaping_)
  {
    shaping_ = false;
    timer_->move(step_timer_, TimerThread::Clock::time_point::max());
  }
}

void SpeedShapingBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  inner().diagnostics(values);
  std::lock_guard<std::mutex> lock(mutex_);
  addCounts(values, { { "speed: moves shaped by the node", moves_ }, { "speed: targets streamed", steps_ } });
}

std::shared_ptr<PtzBackend> withSpeedShaping(std::shared_ptr<PtzBackend> backend)
{
  return std::make_shared<SpeedShapingBackend>(std::move(backend));
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/closed_loop_backend.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// A new speed is sent when it differs from the last by more than this share of it (or of the minimum speed): the
/// device is not flooded with commands that change nothing.
constexpr double RESEND_SHARE = 0.1;
}  // namespace

ClosedLoopBackend::ClosedLoopBackend(std::shared_ptr<PtzBackend> inner, const ClosedLoopConfig& config)
  : ForwardingBackend(std::move(inner)), config_(config), listener_target_(std::make_shared<ListenerTarget>())
{
  listener_target_->backend = this;
}

ClosedLoopBackend::~ClosedLoopBackend()
{
  std::lock_guard<std::mutex> lock(listener_target_->mutex);
  listener_target_->backend = nullptr;
}

bool ClosedLoopBackend::setSampleListener(SampleListener listener)
{
  listener_ = std::move(listener);
  reports_samples_ = inner().setSampleListener([target = listener_target_] {
    std::lock_guard<std::mutex> lock(target->mutex);
    if (target->backend != nullptr)
    {
      target->backend->steer();
      if (target->backend->listener_)
      {
        target->backend->listener_();
      }
    }
  });
  return reports_samples_;
}

void ClosedLoopBackend::start()
{
  inner().start();
  std::lock_guard<std::mutex> lock(mutex_);
  refreshSteeringLocked();
}

Capabilities ClosedLoopBackend::steeredView(Capabilities device, std::array<bool, AXIS_COUNT>& steered) const
{
  steered.fill(false);
  const auto steerable = [](const AxisCapability& axis) { return axis.present && axis.velocity && axis.feedback; };
  const bool needed = std::any_of(device.axes.begin(), device.axes.end(),
                                  [&](const AxisCapability& axis) { return steerable(axis) && !axis.absolute; });
  if (!needed || !reports_samples_)
  {
    return device;  // every axis goes to positions itself, or the state cannot be followed as it comes
  }
  for (Axis axis : ALL_AXES)
  {
    AxisCapability& capability = device.axes[axis];
    steered[axis] = steerable(capability);
    if (steered[axis] && !capability.absolute)
    {
      capability.absolute = true;
      capability.limitation.clear();  // what it lacked is made up for here
      capability.remedy.clear();
    }
  }
  return device;
}

void ClosedLoopBackend::refreshSteeringLocked()
{
  // Asked again before each goal: a camera may turn out to lack the absolute move it listed (it refused one).
  capabilities_ = steeredView(inner().capabilities(), steered_);
}

Capabilities ClosedLoopBackend::capabilities() const
{
  std::array<bool, AXIS_COUNT> steered{};
  return steeredView(inner().capabilities(), steered);
}

bool ClosedLoopBackend::steers() const
{
  return std::any_of(steered_.begin(), steered_.end(), [](bool steered) { return steered; });
}

void ClosedLoopBackend::goTo(const AxisValues& position)
{
  std::lock_guard<std::mutex> lock(mutex_);
  refreshSteeringLocked();
  if (!steers())
  {
    inner().goTo(position);
    return;
  }
  // Axes the device positions itself (not steered here) go there directly; the steered ones are left to steer().
  AxisValues direct = position;
  bool any_direct = false;
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities_.axes[axis];
    if (steered_[axis] || !capability.present || !capability.absolute)
    {
      direct[axis] = std::numeric_limits<double>::quiet_NaN();
    }
    any_direct = any_direct || !std::isnan(direct[axis]);
  }
  target_ = position;
  steering_ = true;
  sent_velocity_ = AxisValues{};
  if (any_direct)
  {
    inner().goTo(direct);
  }
  steerLocked();
}

void ClosedLoopBackend::moveAtVelocity(const AxisValues& velocity)
{
  std::lock_guard<std::mutex> lock(mutex_);
  steering_ = false;
  inner().moveAtVelocity(velocity);
}

void ClosedLoopBackend::stop()
{
  std::lock_guard<std::mutex> lock(mutex_);
  steering_ = false;
  inner().stop();
}

double ClosedLoopBackend::speedFor(Axis axis, double position) const
{
  const AxisCapability& capability = capabilities_.axes[axis];
  const double remaining = target_[axis] - position;
  if (std::isnan(target_[axis]) || std::abs(remaining) <= config_.stop_within[axis])
  {
    return 0.0;
  }
  const double distance = std::abs(remaining);
  const double deceleration =
      0.5 * (capability.acceleration > 0.0 ? capability.acceleration : config_.default_deceleration);
  double speed = std::min({ capability.max_speed, config_.gain * distance, std::sqrt(2.0 * deceleration * distance) });
  speed = std::max(speed, config_.min_speed_share * capability.max_speed);
  return std::copysign(speed, remaining);
}

void ClosedLoopBackend::steer()
{
  std::lock_guard<std::mutex> lock(mutex_);
  steerLocked();
}

void ClosedLoopBackend::steerLocked()
{
  // The wrapped backend's commands only queue work: they are given under the lock, so a steering step that decided
  // to stop can never land after the next goal's first speeds.
  if (!steering_)
  {
    return;
  }
  const PtzSample sample = inner().sample();
  if (!sample.link_up)
  {
    steering_ = false;  // the goal ends as link lost; nothing is resumed when the device answers again
    return;
  }
  AxisValues velocity{};
  bool moving = false;
  bool changed = false;
  for (Axis axis : ALL_AXES)
  {
    if (!steered_[axis])
    {
      continue;
    }
    velocity[axis] = speedFor(axis, sample.position[axis]);
    moving = moving || velocity[axis] != 0.0;
    const double floor = config_.min_speed_share * capabilities_.axes[axis].max_speed;
    changed = changed || std::abs(velocity[axis] - sent_velocity_[axis]) >
                             RESEND_SHARE * std::max(std::abs(sent_velocity_[axis]), floor);
  }
  if (!moving)
  {
    steering_ = false;
    inner().stop();
    return;
  }
  if (changed)
  {
    sent_velocity_ = velocity;
    ++steps_;
    inner().moveAtVelocity(velocity);
  }
}

void ClosedLoopBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  inner().diagnostics(values);
  std::lock_guard<std::mutex> lock(mutex_);
  if (steers())
  {
    std::string axes;
    for (Axis axis : ALL_AXES)
    {
      if (steered_[axis])
      {
        axes += std::string(axes.empty() ? "" : ", ") + axisName(axis);
      }
    }
    values.emplace_back("position goals steered on velocity", axes);
    values.emplace_back("steering speed commands", std::to_string(steps_));
  }
}

std::shared_ptr<PtzBackend> withClosedLoop(std::shared_ptr<PtzBackend> backend, const AxisValues& tolerance)
{
  ClosedLoopConfig config;
  for (Axis axis : ALL_AXES)
  {
    config.stop_within[axis] = 0.5 * tolerance[axis];
  }
  return std::make_shared<ClosedLoopBackend>(std::move(backend), config);
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/closed_loop_backend.h"

#include <algorithm>
#include <chrono>
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

namespace
{
std::array<TimedSteering, AXIS_COUNT> timedSteeringOf(const ClosedLoopConfig& config)
{
  return { TimedSteering(config.stop_within[PAN], config.default_deceleration),
           TimedSteering(config.stop_within[TILT], config.default_deceleration),
           TimedSteering(config.stop_within[ZOOM], config.default_deceleration) };
}
}  // namespace

ClosedLoopBackend::ClosedLoopBackend(std::shared_ptr<PtzBackend> inner, const ClosedLoopConfig& config)
  : ForwardingBackend(std::move(inner))
  , config_(config)
  , listener_target_(std::make_shared<ListenerTarget>())
  , axes_(timedSteeringOf(config))
  , timer_(TimerThread::shared())
{
  listener_target_->backend = this;
  for (Axis axis : ALL_AXES)
  {
    // One timer an axis, unarmed until a timed move; it reaches this object as the listener does.
    timers_[axis] = timer_->at(TimerThread::Clock::time_point::max(), [target = listener_target_, axis] {
      std::lock_guard<std::mutex> lock(target->mutex);
      if (target->backend != nullptr)
      {
        target->backend->timedStop(axis);
      }
    });
  }
}

ClosedLoopBackend::~ClosedLoopBackend()
{
  {
    std::lock_guard<std::mutex> lock(listener_target_->mutex);
    listener_target_->backend = nullptr;
  }
  for (TimerThread::Id id : timers_)
  {
    timer_->cancel(id);  // a run under way finds no backend
  }
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
    if (steered[axis])
    {
      device.speed.control[axis] = SpeedControl::STEERED;  // the steering here caps its speed, not the device
    }
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
  goToAtSpeed(position, AxisValues{});
}

void ClosedLoopBackend::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  std::lock_guard<std::mutex> lock(mutex_);
  endSteeringLocked();
  refreshSteeringLocked();
  const auto go_direct = [&](const AxisValues& where) {
    asksSpeed(speed) ? inner().goToAtSpeed(where, speed) : inner().goTo(where);
  };
  if (!steers())
  {
    go_direct(position);
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
  speed_cap_ = speed;
  steering_ = true;
  sent_velocity_ = AxisValues{};
  const PtzSample now = inner().sample();
  for (Axis axis : ALL_AXES)
  {
    // Its speed now: it may be braking from a goal before, not at a speed this one gave.
    axes_[axis].startGoal(position[axis], capabilities_.axes[axis].acceleration, now.velocity[axis], now.stamp);
  }
  if (any_direct)
  {
    go_direct(direct);
  }
  steerLocked();
}

void ClosedLoopBackend::moveAtVelocity(const AxisValues& velocity)
{
  std::lock_guard<std::mutex> lock(mutex_);
  endSteeringLocked();
  inner().moveAtVelocity(velocity);
}

void ClosedLoopBackend::stop()
{
  std::lock_guard<std::mutex> lock(mutex_);
  endSteeringLocked();
  inner().stop();
}

void ClosedLoopBackend::aimInView(const ViewTarget& target)
{
  std::lock_guard<std::mutex> lock(mutex_);
  endSteeringLocked();
  inner().aimInView(target);
}

void ClosedLoopBackend::endSteeringLocked()
{
  steering_ = false;
  for (TimerThread::Id id : timers_)
  {
    timer_->move(id, TimerThread::Clock::time_point::max());
  }
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
  const double top = speed_cap_[axis] > 0.0 ? std::min(speed_cap_[axis], capability.max_speed) : capability.max_speed;
  double speed = std::min({ top, config_.gain * distance, std::sqrt(2.0 * deceleration * distance) });
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
    endSteeringLocked();  // the goal ends as link lost; nothing is resumed when the device answers again
    return;
  }
  if (last_report_ != TimePoint{} && sample.stamp > last_report_)
  {
    report_period_ = 0.8 * report_period_ + 0.2 * std::min(1.0, secondsBetween(last_report_, sample.stamp));
  }
  last_report_ = sample.stamp;
  AxisValues velocity{};
  bool moving = false;
  bool changed = false;
  for (Axis axis : ALL_AXES)
  {
    if (!steered_[axis])
    {
      continue;
    }
    axes_[axis].observe(sample.stamp, sample.position[axis]);
    if (axes_[axis].rejudged())
    {
      told_[axis] = false;  // told again if it is judged so again
      warnings_.push_back(formatText("the %s moves at the speed it is given after all: position goals steer it on its "
                                     "speeds again",
                                     axisName(axis)));
    }
    if (axes_[axis].fixedSpeed() && !told_[axis])
    {
      told_[axis] = true;
      warnings_.push_back(formatText("the %s moves at one speed (%.3g %s/s) whatever the speed it is given: position "
                                     "goals steer it by timed moves at that speed",
                                     axisName(axis), axes_[axis].speed(), unitOf(axis)));
    }
    velocity[axis] = nextSpeed(axis, sample);
    if (!steering_)
    {
      return;  // it gave up
    }
    const double floor = config_.min_speed_share * capabilities_.axes[axis].max_speed;
    // A timed move's axis may coast, stopped; one that obeys is stopped where it is near enough, and steered on until
    // it rests there (a report held up may have let it pass the target at speed).
    moving = moving || velocity[axis] != 0.0 || axes_[axis].busy() ||
             (!axes_[axis].fixedSpeed() && std::abs(sample.velocity[axis]) > floor);
    // An axis at one speed keeps its speed through a timed move (a command then would only delay the stop); far from
    // its target it is given what an axis that obeys would be, which tells one taken for it wrongly.
    const auto sign = [](double speed) { return speed > 0.0 ? 1 : (speed < 0.0 ? -1 : 0); };
    changed = changed || (axes_[axis].fixedSpeed() && axes_[axis].busy() ?
                              sign(velocity[axis]) != sign(sent_velocity_[axis]) :
                              std::abs(velocity[axis] - sent_velocity_[axis]) >
                                  RESEND_SHARE * std::max(std::abs(sent_velocity_[axis]), floor));
  }
  if (!moving)
  {
    endSteeringLocked();
    inner().stop();
    return;
  }
  if (changed)
  {
    ++steps_;
    command(velocity, sample.stamp);
  }
}

double ClosedLoopBackend::nextSpeed(Axis axis, const PtzSample& sample)
{
  TimedSteering& steering = axes_[axis];
  if (!steering.fixedSpeed())
  {
    return speedFor(axis, sample.position[axis]);
  }
  const TimedSteering::Step step = steering.step(report_period_, speedFor(axis, sample.position[axis]));
  if (step.gave_up)
  {
    giveUpLocked(axis);
    return 0.0;
  }
  if (step.stop_after >= 0.0)
  {
    ++timed_moves_;
    timer_->move(timers_[axis], TimerThread::Clock::now() + std::chrono::duration_cast<TimerThread::Clock::duration>(
                                                                std::chrono::duration<double>(step.stop_after)));
  }
  return step.speed;
}

void ClosedLoopBackend::command(const AxisValues& velocity, TimePoint at)
{
  sent_velocity_ = velocity;
  for (Axis axis : ALL_AXES)
  {
    axes_[axis].commanded(velocity[axis], at);
  }
  if (std::all_of(velocity.begin(), velocity.end(), [](double speed) { return speed == 0.0; }))
  {
    inner().stop();
  }
  else
  {
    inner().moveAtVelocity(velocity);
  }
}

void ClosedLoopBackend::timedStop(Axis axis)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!steering_ || sent_velocity_[axis] == 0.0)
  {
    return;
  }
  axes_[axis].timedStopDone();
  AxisValues velocity = sent_velocity_;
  velocity[axis] = 0.0;
  command(velocity, last_report_);
}

void ClosedLoopBackend::giveUpLocked(Axis axis)
{
  const TimedSteering& steering = axes_[axis];
  endSteeringLocked();
  inner().stop();
  if (std::abs(steering.remaining()) <= 2.0 * config_.stop_within[axis])
  {
    return;  // within the goal's tolerance (twice stop_within): the node judges it reached
  }
  own_fault_ = formatText("the %s moves at one speed (%.3g %s/s) whatever the speed it is given, and its timed moves "
                          "stop it no nearer than %.4f %s to %.4f %s (each goes on %.4f %s past its stop): a tolerance "
                          "above that fits this device",
                          axisName(axis), steering.speed(), unitOf(axis), std::abs(steering.remaining()), unitOf(axis),
                          target_[axis], unitOf(axis), steering.coast(), unitOf(axis));
  inner_faults_at_own_ = inner().sample().fault_count;
  ++own_faults_;
}

PtzSample ClosedLoopBackend::sample() const
{
  PtzSample sample = inner().sample();
  std::lock_guard<std::mutex> lock(mutex_);
  sample.fault_count += own_faults_;
  return sample;
}

std::string ClosedLoopBackend::lastFault() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  // Its own when no fault of the wrapped backend came after it.
  if (own_faults_ > 0 && inner().sample().fault_count == inner_faults_at_own_)
  {
    return own_fault_;
  }
  return inner().lastFault();
}

std::vector<std::string> ClosedLoopBackend::takeWarnings()
{
  std::vector<std::string> warnings = inner().takeWarnings();
  std::lock_guard<std::mutex> lock(mutex_);
  warnings.insert(warnings.end(), warnings_.begin(), warnings_.end());
  warnings_.clear();
  return warnings;
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
    for (Axis axis : ALL_AXES)
    {
      if (steered_[axis] && axes_[axis].fixedSpeed())
      {
        values.emplace_back(std::string(axisName(axis)) + " speed, whatever it is given",
                            formatText("%.3g %s/s (coasts %.4f %s after a stop)", axes_[axis].speed(), unitOf(axis),
                                       axes_[axis].coast(), unitOf(axis)));
      }
    }
    values.emplace_back("timed moves", std::to_string(timed_moves_));
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

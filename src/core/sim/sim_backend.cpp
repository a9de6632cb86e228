#include "ptz_action_server/core/sim/sim_backend.h"

#include <algorithm>
#include <limits>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
Capabilities simCapabilities(const SimDeviceConfig& config, const SimLensConfig& lens)
{
  Capabilities capabilities = config.capabilities();
  capabilities.lens = simLensCapabilities(lens);
  // The simulated device takes the speed of a position move on every axis it has (its model's cruise speed).
  capabilities.speed.control.fill(SpeedControl::DEVICE);
  return capabilities;
}
}  // namespace

SimBackend::SimBackend(const SimDeviceConfig& config, std::shared_ptr<const Clock> clock, const SimLensConfig& lens)
  : clock_(std::move(clock))
  , capabilities_(simCapabilities(config, lens))
  , model_(config, clock_->now())
  , lens_model_(lens, clock_->now())
  , supervisor_(std::numeric_limits<double>::infinity(), clock_)  // the model never falls silent by itself
{
  answers();
}

void SimBackend::answers()
{
  supervisor_.connected();
  supervisor_.ready();
  supervisor_.stateReported();
  supervisor_.refresh();
}

Capabilities SimBackend::capabilities() const
{
  return capabilities_;
}

SimBackend::~SimBackend()
{
  if (timer_)
  {
    timer_->cancel(event_timer_);  // once it returns, no event is being reported or will be
  }
}

bool SimBackend::setSampleListener(SampleListener listener)
{
  listener_ = std::move(listener);
  return true;
}

void SimBackend::start()
{
  if (listener_ && !timer_)
  {
    timer_ = TimerThread::shared();
    event_timer_ = timer_->at(TimerThread::Clock::time_point::max(), [this] { reportEvent(); });
    std::lock_guard<std::mutex> lock(mutex_);
    planChanged();
  }
}

void SimBackend::planChanged()
{
  if (!timer_)
  {
    return;  // no listener: nobody to tell of events
  }
  // Wakes a microsecond after the event, so the sample the listener leads to already shows it.
  constexpr std::chrono::microseconds AFTER_EVENT(1);
  const TimePoint now = clock_->now();
  model_.sample(now);  // applies the lagged commands now due, so they are not found due again
  next_event_ = dropout_ ? TimePoint::max() : model_.nextEvent(now);
  timer_->move(event_timer_, next_event_ == TimePoint::max() ?
                                 TimerThread::Clock::time_point::max() :
                                 TimerThread::Clock::now() + (next_event_ - now) + AFTER_EVENT);
}

void SimBackend::reportEvent()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (dropout_ || clock_->now() < next_event_)
    {
      planChanged();  // the plan moved since this wake-up was set
      return;
    }
  }
  listener_();
  std::lock_guard<std::mutex> lock(mutex_);
  planChanged();
}

void SimBackend::goTo(const AxisValues& position)
{
  goToAtSpeed(position, AxisValues{});
}

void SimBackend::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!dropCommand())
  {
    const TimePoint now = clock_->now();
    for (Axis axis : ALL_AXES)
    {
      const double top = model_.config().axes[axis].motion.max_speed;
      commanded_speed_[axis] = speed[axis] > 0.0 ? std::min(speed[axis], top) : top;
      model_.setCruiseSpeed(axis, commanded_speed_[axis], now);
    }
    model_.goTo(position, now);
    planChanged();
  }
}

void SimBackend::moveAtVelocity(const AxisValues& velocity)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!dropCommand())
  {
    model_.moveAtVelocity(velocity, clock_->now());
    planChanged();
  }
}

void SimBackend::stop()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!dropCommand())
  {
    model_.stop(clock_->now());
    planChanged();
  }
}

PtzSample SimBackend::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (dropout_)
  {
    return frozen_sample_;
  }
  PtzSample sample = model_.sample(clock_->now());
  sample.link_losses = supervisor_.losses();
  return sample;
}

void SimBackend::lens(const LensCommand& command)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (dropCommand() || !lens_model_.present(command.function))
  {
    return;
  }
  const TimePoint now = clock_->now();
  switch (command.kind)
  {
    case LensCommand::Kind::MODE:
      lens_model_.setAuto(command.function, command.automatic(), now);
      break;
    case LensCommand::Kind::ONE_PUSH:
      lens_model_.setAuto(command.function, false, now);  // it focusses once and stays manual
      lens_model_.onePush(now);
      break;
    case LensCommand::Kind::VELOCITY:
      // A manual command takes the function out of auto, as most cameras do when asked to drive it by hand.
      lens_model_.setAuto(command.function, false, now);
      lens_model_.drive(command.function, command.value, now);
      break;
    default:
      lens_model_.setAuto(command.function, false, now);
      lens_model_.goTo(command.function, command.value, now);
      break;
  }
}

LensState SimBackend::lensState() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return lensStateOf(lens_model_, clock_->now());
}

std::string SimBackend::lastFault() const
{
  return {};  // the simulated device never refuses a command
}

std::string SimBackend::lastLinkLoss() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return supervisor_.lastLoss();
}

void SimBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const SimFaults& faults = model_.faults();
  std::string stalled;
  for (Axis axis : ALL_AXES)
  {
    if (faults.stalled[axis])
    {
      stalled += stalled.empty() ? axisName(axis) : std::string(", ") + axisName(axis);
    }
  }
  values.emplace_back("commands received", std::to_string(commands_received_));
  values.emplace_back("commands lost in dropout", std::to_string(commands_lost_));
  values.emplace_back(
      "speed of the last position move (rad/s, rad/s, X/s)",
      formatText("%.4f, %.4f, %.4f", commanded_speed_[PAN], commanded_speed_[TILT], commanded_speed_[ZOOM]));
  values.emplace_back("fault: stalled axes", stalled.empty() ? "none" : stalled);
  values.emplace_back("fault: lag (s)", formatText("%.3f", faults.lag));
  values.emplace_back("fault: dropout", dropout_ ? "yes" : "no");
}

void SimBackend::setFaults(const SimFaults& faults, bool dropout)
{
  std::lock_guard<std::mutex> lock(mutex_);
  const TimePoint now = clock_->now();
  model_.setFaults(faults, now);
  if (dropout && !dropout_)
  {
    supervisor_.disconnected("the simulated device dropped out");
    frozen_sample_ = model_.sample(now);
    frozen_sample_.link_up = false;
    frozen_sample_.link_losses = supervisor_.losses();
  }
  else if (!dropout && dropout_)
  {
    answers();
  }
  dropout_ = dropout;
  planChanged();
}

bool SimBackend::dropCommand()
{
  ++commands_received_;
  if (dropout_)
  {
    ++commands_lost_;
  }
  return dropout_;
}

}  // namespace ptz_action_server

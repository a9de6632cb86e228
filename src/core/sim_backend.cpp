#include "ptz_action_server/core/sim_backend.h"

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
SimBackend::SimBackend(const SimDeviceConfig& config, std::shared_ptr<const Clock> clock)
  : clock_(std::move(clock)), capabilities_(config.capabilities()), model_(config, clock_->now())
{
}

Capabilities SimBackend::capabilities() const
{
  return capabilities_;
}

SimBackend::~SimBackend()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  plan_changed_.notify_all();
  if (notifier_.joinable())
  {
    notifier_.join();
  }
}

bool SimBackend::setSampleListener(SampleListener listener)
{
  listener_ = std::move(listener);
  return true;
}

void SimBackend::start()
{
  if (listener_ && !notifier_.joinable())
  {
    notifier_ = std::thread([this] { notifyEvents(); });
  }
}

void SimBackend::notifyEvents()
{
  // Wakes a microsecond after the event, so the sample the listener leads to already shows it.
  constexpr std::chrono::microseconds AFTER_EVENT(1);
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_)
  {
    const TimePoint now = clock_->now();
    model_.sample(now);  // applies the lagged commands now due, so they are not found due again
    const TimePoint event = dropout_ ? TimePoint::max() : model_.nextEvent(now);
    if (event == TimePoint::max())
    {
      plan_changed_.wait(lock);
      continue;
    }
    plan_changed_.wait_for(lock, event - now + AFTER_EVENT);
    if (!stopping_ && !dropout_ && clock_->now() >= event)
    {
      lock.unlock();
      listener_();
      lock.lock();
    }
  }
}

void SimBackend::goTo(const AxisValues& position)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!dropCommand())
  {
    model_.goTo(position, clock_->now());
    plan_changed_.notify_all();
  }
}

void SimBackend::moveAtVelocity(const AxisValues& velocity)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!dropCommand())
  {
    model_.moveAtVelocity(velocity, clock_->now());
    plan_changed_.notify_all();
  }
}

void SimBackend::stop()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!dropCommand())
  {
    model_.stop(clock_->now());
    plan_changed_.notify_all();
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
  sample.link_losses = link_losses_;
  return sample;
}

std::string SimBackend::lastFault() const
{
  return {};  // the simulated device never refuses a command
}

std::string SimBackend::lastLinkLoss() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return link_losses_ > 0 ? "the simulated device dropped out" : "";
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
    ++link_losses_;
    frozen_sample_ = model_.sample(now);
    frozen_sample_.link_up = false;
    frozen_sample_.link_losses = link_losses_;
  }
  dropout_ = dropout;
  plan_changed_.notify_all();
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

/**
 * \file
 * \brief The simulated backend: a SimDeviceModel behind the PtzBackend interface, with fault hooks.
 */
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/sim_device_model.h"

namespace ptz_action_server
{
/**
 * \brief A pan-tilt-zoom unit that exists only in memory.
 *
 * The model is evaluated in closed form at the clock's current time, so there is no I/O: every call takes the mutex
 * for a few microseconds and returns. Faults (stalls, lag, dropout) can be switched at any time. Only when the node
 * asks for a sample listener does it start one thread, which sleeps until the model's next event (a motion ending,
 * a lagged command falling due) and then calls the listener, as a device would report that it has arrived.
 */
class SimBackend : public PtzBackend
{
public:
  explicit SimBackend(const SimDeviceConfig& config,
                      std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  /// Stops and joins the listener's thread, if there is one.
  ~SimBackend() override;

  std::string name() const override
  {
    return "sim";
  }
  Capabilities capabilities() const override;
  void start() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  PtzSample sample() const override;
  std::string lastFault() const override;
  std::string lastLinkLoss() const override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;
  /// Takes the listener; start() then starts the thread that calls it at each event of the model.
  bool setSampleListener(SampleListener listener) override;

  /// Replaces the fault set. With \p dropout the device falls silent: state freezes, commands are lost.
  void setFaults(const SimFaults& faults, bool dropout);

private:
  /// True (and counts the command as lost) while the device is dropped out. Call with mutex_ held.
  bool dropCommand();
  /// The listener's thread: waits for the model's next event (or a command that changes it), then calls the listener.
  void notifyEvents();

  SampleListener listener_;  ///< set before start()
  std::thread notifier_;
  std::condition_variable plan_changed_;  ///< a command or fault changed the model's plan (with mutex_)
  bool stopping_ = false;                 ///< guarded by mutex_

  const std::shared_ptr<const Clock> clock_;
  const Capabilities capabilities_;
  mutable std::mutex mutex_;      ///< guards everything below
  mutable SimDeviceModel model_;  ///< mutable: sampling applies commands whose lag has passed
  bool dropout_ = false;
  std::uint64_t link_losses_ = 0;  ///< dropouts so far
  PtzSample frozen_sample_;        ///< what the device last said before it dropped out
  std::uint64_t commands_received_ = 0;
  std::uint64_t commands_lost_ = 0;
};

}  // namespace ptz_action_server

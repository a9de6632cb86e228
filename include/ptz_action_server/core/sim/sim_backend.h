/**
 * \file
 * \brief The simulated backend: a SimDeviceModel behind the PtzBackend interface, with fault hooks.
 */
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/device/link_supervisor.h"
#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/core/sim/sim_lens_model.h"
#include "ptz_action_server/core/timer_thread.h"

namespace ptz_action_server
{
/**
 * \brief A pan-tilt-zoom unit that exists only in memory.
 *
 * The model is evaluated in closed form at the clock's current time, so there is no I/O: every call takes the mutex
 * for a few microseconds and returns. Faults (stalls, lag, dropout) can be switched at any time. Only when the node
 * asks for a sample listener does it set a deadline on the process's TimerThread at the model's next event (a motion
 * ending, a lagged command falling due), which then calls the listener, as a device would report that it has arrived.
 */
class SimBackend : public PtzBackend
{
public:
  explicit SimBackend(const SimDeviceConfig& config,
                      std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>(),
                      const SimLensConfig& lens = SimLensConfig());
  /// Cancels the event deadline: once it returns, the listener is not running and will not be called.
  ~SimBackend() override;

  std::string name() const override
  {
    return "sim";
  }
  Capabilities capabilities() const override;
  void start() override;
  void goTo(const AxisValues& position) override;
  /// The model's cruise speeds set to \p speed (its max speed where 0) for this move: the sim takes a speed itself.
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  PtzSample sample() const override;
  /// Focus and iris of the simulated lens (lost in a dropout, as the other commands).
  void lens(const LensCommand& command) override;
  LensState lensState() const override;
  std::string lastFault() const override;
  std::string lastLinkLoss() const override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;
  /// Takes the listener; from start() on it is called (on the TimerThread) at each event of the model.
  bool setSampleListener(SampleListener listener) override;

  /// Replaces the fault set. With \p dropout the device falls silent: state freezes, commands are lost.
  void setFaults(const SimFaults& faults, bool dropout);

private:
  /// True (and counts the command as lost) while the device is dropped out. Call with mutex_ held.
  bool dropCommand();
  /// Sets the event deadline at the model's next event after a command or fault changed it. Call with mutex_ held.
  void planChanged();
  /// The event deadline's work: calls the listener if the event is still due.
  void reportEvent();
  /// The device answers (again): the link is up. Call with mutex_ held (or from the constructor).
  void answers();

  SampleListener listener_;  ///< set before start()
  std::shared_ptr<TimerThread> timer_;
  TimerThread::Id event_timer_ = 0;

  const std::shared_ptr<const Clock> clock_;
  const Capabilities capabilities_;
  mutable std::mutex mutex_;      ///< guards everything below
  mutable SimDeviceModel model_;  ///< mutable: sampling applies commands whose lag has passed
  SimLensModel lens_model_;
  bool dropout_ = false;
  TimePoint next_event_ = TimePoint::max();  ///< the model's next event, as last planned
  LinkSupervisor supervisor_;                ///< a dropout is a loss; no deadline (the model never falls silent)
  PtzSample frozen_sample_;                  ///< what the device last said before it dropped out
  std::uint64_t commands_received_ = 0;
  std::uint64_t commands_lost_ = 0;
  AxisValues commanded_speed_{};  ///< the cruise speeds of the last position move (its max speed where 0)
};

}  // namespace ptz_action_server

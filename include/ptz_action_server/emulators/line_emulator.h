/**
 * \file
 * \brief What the emulated units on a line (a pseudo-terminal, or TCP) share: the port, the motion model and its
 * lock, the log of what they received, and the faults.
 */
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/emulators/ports/device_port.h"
#include "ptz_action_server/emulators/emulator_faults.h"
#include "ptz_action_server/emulators/ports/received_log.h"

namespace ptz_action_server
{
/**
 * \brief The common part of a line emulator (FLIR PTU, Pelco-D, ...); a protocol adds how it reads and answers.
 *
 * \p Item is what the log keeps of each command (a text line, a frame). The port's thread calls back into the
 * derived class, so the derived constructor opens the port last (openPort()) and its destructor closes it first
 * (closePort()).
 */
template <class Item>
class LineEmulator : public EmulatorFaults
{
public:
  LineEmulator(const LineEmulator&) = delete;
  LineEmulator& operator=(const LineEmulator&) = delete;

  /// What a client opens: the pseudo-terminal's link (or path), or host:port.
  std::string path() const
  {
    return port_->path();
  }
  DevicePort& port()
  {
    return *port_;
  }
  /// What the unit received, oldest first.
  ReceivedLog<Item>& received()
  {
    return received_;
  }
  const ReceivedLog<Item>& received() const
  {
    return received_;
  }
  /// The model's state (rad, X), for tests.
  PtzSample sample() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return model_.sample(SteadyClock::now());
  }
  void setFaults(const SimFaults& faults)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    model_.setFaults(faults, SteadyClock::now());
    reply_delay_ = faults.reply_delay;
  }
  /// The port closes, as pulling the cable does (a pseudo-terminal's link disappears; a TCP server stops listening).
  void unplug()
  {
    port_->unplug();
  }
  /// The port is back, and the unit with it as at power-up: it stopped when it lost power.
  void replug()
  {
    port_->replug();
    powerCycle();
  }
  /// The unit loses power and comes back while the port stays open: it stopped, and starts as at power-up (what it
  /// says then, a FLIR PTU's banner, reaches a client that has the port open).
  void powerCycle()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    model_.stop(SteadyClock::now());
    powerUp();
  }

protected:
  explicit LineEmulator(const SimDeviceConfig& model) : model_(model, SteadyClock::now())
  {
  }
  ~LineEmulator() override = default;

  // The faults of the port and the model.
  bool faultSilence(bool on) override
  {
    port_->setSilent(on);
    return true;
  }
  bool faultDrop(bool on) override
  {
    on ? unplug() : replug();
    return true;
  }
  bool faultGarbage(bool on) override
  {
    port_->setGarbleRatio(on ? FAULT_GARBLE_RATIO : 0.0);
    return true;
  }
  bool faultEndless(bool on) override
  {
    port_->setEndless(on);
    return true;
  }
  bool faultModel(EmulatorFault /*fault*/, const SimFaults& faults) override
  {
    setFaults(faults);
    return true;
  }

  /// What the unit does when it starts (called with mutex_ held).
  virtual void powerUp() = 0;
  /// s the unit thinks before it reads \p data (the port's thread, mutex_ not held): SimFaults::reply_delay, unless a
  /// unit takes longer for some requests than for others.
  virtual double thinkingTime(const std::uint8_t* data, std::size_t size)
  {
    (void)data;
    (void)size;
    return reply_delay_;
  }

  /// Creates the port and starts its thread: the last thing the derived constructor does.
  void openPort(const DevicePortConfig& config, DevicePort::Handlers handlers)
  {
    // A slow unit (thinkingTime()) reads each request that long after it arrived, in order: a
    // request that came while the unit was busy with the one before it waits only what is left of its own time, so
    // requests written together (a goal's frames without reply) do not hold back each other's answers.
    handlers.on_bytes = [this, on_bytes = std::move(handlers.on_bytes)](const std::uint8_t* data, std::size_t size,
                                                                        TimePoint arrived_at) {
      const TimePoint until = addSeconds(arrived_at, thinkingTime(data, size));
      std::unique_lock<std::mutex> lock(handler_mutex_);
      closing_changed_.wait_until(lock, until, [this] { return closing_.load(); });
      if (!closing_)  // closePort() may be under way: port_ is going
      {
        on_bytes(data, size, arrived_at);
      }
    };
    port_ = DevicePort::create(config, std::move(handlers));
    port_->start();
  }
  /// Stops the port's thread: the first thing the derived destructor does.
  void closePort()
  {
    {
      std::lock_guard<std::mutex> lock(handler_mutex_);  // waits for a handler under way; none runs after
      closing_ = true;
    }
    closing_changed_.notify_all();  // a slow unit thinking over a request stops at once
    port_.reset();
  }

  mutable std::mutex mutex_;      ///< guards the model and the derived unit's state
  mutable SimDeviceModel model_;  ///< mutable: sampling applies lagged commands
  ReceivedLog<Item> received_;
  std::unique_ptr<DevicePort> port_;
  std::atomic<double> reply_delay_{ 0.0 };   ///< s, SimFaults::reply_delay
  std::atomic<bool> closing_{ false };       ///< closePort() began: no handler runs any more
  std::mutex handler_mutex_;                 ///< held while a received-bytes handler runs (or waits out the delay)
  std::condition_variable closing_changed_;  ///< closePort() began
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief The speed of position goals on a device that takes none with its moves: the node shapes the motion.
 */
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "ptz_action_server/core/forwarding_backend.h"
#include "ptz_action_server/core/motion/motion_profile.h"
#include "ptz_action_server/core/timer_thread.h"

namespace ptz_action_server
{
/**
 * \brief Runs goToAtSpeed() on a device that takes no speed with its absolute moves by streaming targets along a
 * trapezoid profile (TrapezoidProfile) at the speed, every `period`, then the goal's own target.
 *
 * A device whose backend applies the speed itself on some axis (MoveSpeedCapability::appliedByBackend()) gets the
 * call unchanged. Otherwise each axis with a speed is planned from where the device is and how fast it moves, at that
 * cruise speed and the axis' acceleration (the axis' max speed and acceleration bound it as on the device); every
 * step sends goTo() with each such axis where its profile is one step ahead, the others at the goal's target. The
 * device follows the stream at its own speed, so on average it moves at the goal's. The steps run on the process's
 * TimerThread; goTo(), moveAtVelocity(), stop() and a lost link end the stream (nothing is resumed after a loss).
 *
 * capabilities() gives the axes shaped here a slowest speed of MIN_SHAPED_SHARE of their max speed where the device
 * states none: slower, a shaped axis would seem stalled to the goal monitor. Thread-safe.
 */
class SpeedShapingBackend : public ForwardingBackend
{
public:
  /// The slowest speed of a shaped axis, as a share of its max speed.
  static constexpr double MIN_SHAPED_SHARE = 0.01;

  /// Shapes the moves of \p inner, a target every \p period seconds.
  explicit SpeedShapingBackend(std::shared_ptr<PtzBackend> inner, double period = 0.05);
  /// Cancels the step timer: once it returns, no step runs.
  ~SpeedShapingBackend() override;
  SpeedShapingBackend(const SpeedShapingBackend&) = delete;
  SpeedShapingBackend& operator=(const SpeedShapingBackend&) = delete;

  Capabilities capabilities() const override;
  void goTo(const AxisValues& position) override;
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  /// The device's, then how many moves were shaped and the targets streamed.
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  /// True while a shaped move streams its targets.
  bool shaping() const;

private:
  /// On the TimerThread: sends the next targets, or the goal's target at the end.
  void step();
  /// Ends the stream (the timer disarmed; a step under way finds nothing to do). Call with mutex_ held.
  void endLocked();

  const double period_;
  std::shared_ptr<TimerThread> timer_;
  TimerThread::Id step_timer_ = 0;

  mutable std::mutex mutex_;  ///< guards everything below
  bool shaping_ = false;
  AxisValues target_{};
  std::array<bool, AXIS_COUNT> shaped_{};  ///< axes streamed along their profile
  std::array<TrapezoidProfile, AXIS_COUNT> profiles_{ { TrapezoidProfile::rest(0.0), TrapezoidProfile::rest(0.0),
                                                        TrapezoidProfile::rest(0.0) } };
  double duration_ = 0.0;  ///< s: the longest profile
  TimerThread::Clock::time_point started_at_{};
  std::uint64_t moves_ = 0;  ///< shaped moves so far
  std::uint64_t steps_ = 0;  ///< targets streamed so far
};

/// \p backend wrapped in a SpeedShapingBackend.
std::shared_ptr<PtzBackend> withSpeedShaping(std::shared_ptr<PtzBackend> backend);

}  // namespace ptz_action_server

/**
 * \file
 * \brief Position goals on a device that only moves at a speed (a ContinuousMove-only camera): steered closed-loop on
 * the positions it reports.
 */
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ptz_action_server/core/forwarding_backend.h"
#include "ptz_action_server/core/timed_steering.h"
#include "ptz_action_server/core/timer_thread.h"

namespace ptz_action_server
{
/// How ClosedLoopBackend steers.
struct ClosedLoopConfig
{
  /// Half the node's goal tolerance: the axis is stopped once this close (rad, rad, X).
  AxisValues stop_within{ { 0.0025, 0.0025, 0.025 } };
  double gain = 2.0;  ///< 1/s: commanded speed per unit of remaining distance, until the speed or braking bound
  /// Share of an axis' max speed below which it is not driven slower (a camera may not move at all below it).
  double min_speed_share = 0.02;
  /// Deceleration assumed when the device states none (rad/s^2, X/s^2).
  double default_deceleration = 1.0;
};

/**
 * \brief Runs goTo() as velocity commands on a device whose axes lack `absolute` but have `velocity` and `feedback`.
 *
 * At start() and before each goal, if any present axis of the wrapped device cannot go to a position but can move at
 * a speed and reports where it is (a camera may say so only once it has refused an absolute move), every present axis
 * that can move at a speed and reports itself is steered here: on each state report (the backend's sample listener, on
 * its I/O thread), each axis gets the speed that brings it to the target without overshoot (bounded by the max speed,
 * by braking at half the device's acceleration, and by the gain), and the device is stopped once every axis is within
 * stop_within. Those axes then report `absolute`. The goal itself is judged by the node, as on any device.
 *
 * Some devices move at one speed whatever the magnitude they are given (cheap ONVIF cameras): slowing down as the
 * target nears does nothing, and a stop at a report overshoots by what the axis covers between two reports, back and
 * forth. Each steered axis learns that from its reports (TimedSteering: faster than an axis that obeys could go, over
 * 0.15 s of reports; never from one report held up or bunched with the next), says so once (takeWarnings()), and is
 * from then on steered by timed moves: stopped by a timer on the process's TimerThread when its speed has covered the
 * distance left, less what it goes on after a stop (learnt as it goes). Far from the target it is given the speed an
 * axis that obeys would get: one taken for such an axis wrongly, that then goes at the speed it is given, is judged
 * again (and told) and steered on its speeds.
 * One that cannot come within the goal's tolerance stops where it is, and the goal ends with a fault naming it
 * (lastFault()), never with an endless swing about the target.
 *
 * Devices whose axes all go to positions, and devices that cannot report state as it comes, pass through unchanged.
 * A goal's speed (goToAtSpeed()) caps the speed of its steered axes. moveAtVelocity(), stop() and aimInView() end the
 * steering. A lost link ends it too: the recovery never resumes an old goal. Thread-safe.
 */
class ClosedLoopBackend : public ForwardingBackend
{
public:
  ClosedLoopBackend(std::shared_ptr<PtzBackend> inner, const ClosedLoopConfig& config);
  ~ClosedLoopBackend() override;
  ClosedLoopBackend(const ClosedLoopBackend&) = delete;
  ClosedLoopBackend& operator=(const ClosedLoopBackend&) = delete;

  Capabilities capabilities() const override;
  void start() override;
  void goTo(const AxisValues& position) override;
  /// goTo() at \p speed: a steered axis is driven no faster than its speed; the others get it from the device.
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  void aimInView(const ViewTarget& target) override;
  bool setSampleListener(SampleListener listener) override;
  PtzSample sample() const override;
  std::string lastFault() const override;
  std::vector<std::string> takeWarnings() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  /// True when position goals are steered here (decided at start(), and again at each goTo()).
  bool steers() const;

private:
  /// On the wrapped backend's thread, after each state report: the next speeds, or the stop.
  void steer();
  void steerLocked();
  /// Reads the wrapped device's capabilities and decides which axes are steered here (mutex_ held).
  void refreshSteeringLocked();
  /// \p device as seen through this decorator (the axes steered here go to positions), and which are steered.
  Capabilities steeredView(Capabilities device, std::array<bool, AXIS_COUNT>& steered) const;
  /// The speed that brings \p axis from \p position to the target.
  double speedFor(Axis axis, double position) const;
  /// The speed \p axis gets now: speedFor(), or its timed move's (arming the timer) for one that moves at one speed.
  double nextSpeed(Axis axis, const PtzSample& sample);
  /// Sends \p velocity (all zero: stop()) and records it.
  void command(const AxisValues& velocity, TimePoint at);
  /// The timer of \p axis ran out: stops that axis.
  void timedStop(Axis axis);
  /// Ends the steering: every timer disarmed.
  void endSteeringLocked();
  /// The steering could not bring \p axis within the tolerance: a fault of this decorator's, naming why.
  void giveUpLocked(Axis axis);

  const ClosedLoopConfig config_;
  SampleListener listener_;  ///< the node's, called after each steering step
  bool reports_samples_ = false;
  /// What the wrapped backend's listener reaches this object through; the destructor cuts it (the wrapped backend's
  /// thread may report until it is joined, after this object's members are gone).
  struct ListenerTarget
  {
    std::mutex mutex;
    ClosedLoopBackend* backend = nullptr;
  };
  std::shared_ptr<ListenerTarget> listener_target_;

  mutable std::mutex mutex_;  ///< guards everything below
  Capabilities capabilities_;
  std::array<bool, AXIS_COUNT> steered_{};  ///< axes run here (set once by start())
  bool steering_ = false;                   ///< a goTo() is under way
  AxisValues target_{};
  AxisValues speed_cap_{};                      ///< the goal's speed per axis (0: the max speed)
  AxisValues sent_velocity_{};                  ///< the last speeds commanded while steering
  std::uint64_t steps_ = 0;                     ///< speed commands sent while steering
  std::array<TimedSteering, AXIS_COUNT> axes_;  ///< what each axis taught, and its timed move
  std::array<bool, AXIS_COUNT> told_{};         ///< its one speed was told (warning)
  std::vector<std::string> warnings_;           ///< not yet taken
  double report_period_ = 0.1;                  ///< s between the device's reports (smoothed)
  TimePoint last_report_{};
  std::uint64_t own_faults_ = 0;           ///< faults of this decorator (a goal it could not bring within reach)
  std::uint64_t inner_faults_at_own_ = 0;  ///< the wrapped backend's fault count at the last of them
  std::string own_fault_;
  std::uint64_t timed_moves_ = 0;

  std::shared_ptr<TimerThread> timer_;                ///< the process's
  std::array<TimerThread::Id, AXIS_COUNT> timers_{};  ///< one per axis, armed for a timed move's end
};

/// Wraps \p backend in a ClosedLoopBackend configured for the goal tolerances \p tolerance.
std::shared_ptr<PtzBackend> withClosedLoop(std::shared_ptr<PtzBackend> backend, const AxisValues& tolerance);

}  // namespace ptz_action_server

/**
 * \file
 * \brief The goal state machine of the node, without ROS: one active goal, preemption, cancel then stop, and the
 * verdicts of its GoalMonitor turned into the goal's end.
 */
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/goal/goal_monitor.h"
#include "ptz_action_server/core/goal/move_speed.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// What the goals make the device do; the values are those of PtzState's MODE_* constants.
enum class GoalMode : std::int8_t
{
  IDLE = 0,
  POSITION = 1,
  VELOCITY = 2,
};

/// What a goal asks the device to do, once converted from its action.
struct GoalCommand
{
  bool velocity = false;  ///< values are velocities (rad/s, X/s); else positions (rad, X)
  /// A goal that follows a moving target: values is the first aim (positions, clamped into the limits rather than
  /// rejected); steer() then moves the device and the aim until the goal is cancelled, preempted or aborted.
  bool track = false;
  /// The device aims in its own picture (PtzBackend::aimInView()): values mean nothing, the device alone knows where it
  /// goes, and the goal is judged on what it reports (GoalMonitor::forView()).
  std::optional<ViewTarget> view;
  AxisValues values{};
  /// The speed of a position goal (neither velocity nor track); left at 0, the operator's default speed.
  SpeedRequest speed;
  /// What the conversion left out of the goal ("zoom offset 2.0000 X ignored: ..."): goes into the goal's texts
  /// with the validation's notes.
  std::string note;
};

/// A backend sample and the goal it was taken for.
struct GoalSample
{
  std::uint64_t goal_serial = 0;  ///< the supervisor's goal serial, read before the backend was sampled
  TimePoint taken_at{};           ///< the supervisor's clock just after the backend was sampled: when it is judged
  PtzSample sample;
};

/// A goal converted from its action against the device's state (by the ROS layer): its command, or why it is refused.
struct ConvertedGoal
{
  GoalCommand command;
  std::string rejection;  ///< "": the goal asks for \c command; else why it is rejected (a NaN, an unknown frame)

  /// A goal refused with \p reason.
  static ConvertedGoal rejected(std::string reason)
  {
    ConvertedGoal converted;
    converted.rejection = std::move(reason);
    return converted;
  }
};

/**
 * \brief A goal of any action, as the supervisor sees it. The ROS layer adapts actionlib's goal handle to it.
 *
 * Only the supervisor's thread calls it. Every goal ends with exactly one of reject, succeed, abort or preempt.
 */
class GoalHandle
{
public:
  virtual ~GoalHandle() = default;
  /// Name of the goal's action ("position_abs"), for the status texts and to match cancels.
  virtual const std::string& action() const = 0;
  /// The goal's id, unique among the goals of its action.
  virtual const std::string& id() const = 0;
  /// Accepts the goal; \p text is what validation changed (clamping, a zoom ignored), or empty.
  virtual void accept(const std::string& text) = 0;
  virtual void reject(const std::string& text) = 0;
  /// \p remaining is goal minus current, per axis, in the goal's units.
  virtual void publishFeedback(const AxisValues& remaining) = 0;
  virtual void succeed(const std::string& text) = 0;
  virtual void abort(const std::string& text) = 0;
  /// Ends the goal PREEMPTED: replaced by a new goal, or cancelled.
  virtual void preempt(const std::string& text) = 0;
  /// A goal the device aimed itself (GoalCommand::view): where it \p position ended (NaN: an axis it does not report),
  /// told just before the goal ends. By default nothing.
  virtual void ended(const AxisValues& position)
  {
    (void)position;
  }
};

/**
 * \brief Runs the goals of every action against one backend: at most one is active.
 *
 * A new goal preempts the active one before it is accepted, and the device is retargeted without a stop in between.
 * A cancel stops the device; the goal ends PREEMPTED once the device rests. A goal that fails stops the device.
 *
 * Threads: submit(), cancel(), supervise() and shutdown() run on one thread (the node's main thread); sample(),
 * mode() and goalActive() may be called from any thread. Samples taken on another thread reach supervise() late: each
 * carries the goal serial it was taken under, and a sample of an earlier goal (or from before a cancel) is ignored,
 * so the active goal is only judged on samples taken after the one its monitor starts from.
 */
class GoalSupervisor
{
public:
  /// \p limits are what goals are checked against; \p clamp_goals clamps out-of-range goals instead of rejecting.
  GoalSupervisor(std::shared_ptr<PtzBackend> backend, const Capabilities& limits, const GoalMonitorConfig& config,
                 bool clamp_goals, std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());

  GoalSupervisor(const GoalSupervisor&) = delete;
  GoalSupervisor& operator=(const GoalSupervisor&) = delete;

  /**
   * \brief Rejects \p goal if the link was down in \p current (the backend's sample \p converted was converted
   * against), else with the conversion's rejection, or when the limits refuse its command (a view command on a device
   * that cannot aim in its picture); otherwise preempts the active goal, accepts \p goal, commands the device and
   * judges the goal at once on a fresh sample (a goal the device already satisfies ends here).
   */
  void submit(std::unique_ptr<GoalHandle> goal, const PtzSample& current, const ConvertedGoal& converted);

  /// Sets the speed position goals run at when they ask none (a fraction of each axis' top speed, in (0, 1]); from
  /// the next goal on. Returns "" or why \p fraction is refused (checkDefaultSpeed()), keeping the one it had.
  std::string setDefaultSpeed(double fraction);
  double defaultSpeed() const
  {
    return default_speed_;
  }

  /// Stops the device if the goal \p id of \p action is the active one; it ends once the device rests.
  void cancel(const std::string& action, const std::string& id);

  /// For the active tracking goal \p id of \p action: commands \p command (velocities, or positions) and judges the
  /// goal against \p aim from now on. Returns false, commanding nothing, if that goal is no longer the active one or
  /// is being cancelled.
  bool steer(const std::string& action, const std::string& id, const GoalCommand& command, const AxisValues& aim);

  /// True if the goal \p id of \p action is the active one and not being cancelled.
  bool isRunning(const std::string& action, const std::string& id) const;

  /// Stops the device and aborts the active goal \p id of \p action with \p reason (nothing if it is not active).
  void abort(const std::string& action, const std::string& id, const std::string& reason);

  /// Judges the active goal at \p sample, unless it was taken for another goal: feedback while the goal goes on
  /// (unless \p publish_feedback is false: a sample the backend reported between two ticks), its end on a final
  /// verdict.
  void supervise(const GoalSample& sample, bool publish_feedback = true);

  /// Stops the device and aborts the active goal with \p reason.
  void shutdown(const std::string& reason);

  /// Tells \p listener of each goal it accepts (after its command, before it is first judged) and, with null, each
  /// time no goal is active any more (a goal ended without another taking its place). On the supervisor's thread;
  /// the listener must not call the supervisor back (the tours queue what they do next).
  void setActivityListener(std::function<void(const GoalHandle*)> listener)
  {
    activity_listener_ = std::move(listener);
  }

  /// The backend's latest sample, tagged with the goal it belongs to. Any thread (the state thread calls it).
  GoalSample sample() const;

  /// What the active goal makes the device do. Any thread.
  GoalMode mode() const
  {
    return mode_.load();
  }

  /// True while a goal is active (also while a cancelled one waits for the device to rest). Any thread.
  bool goalActive() const
  {
    return mode_.load() != GoalMode::IDLE;
  }

private:
  /// Makes \p goal the active one and commands the device (a position goal at \p speed, see goToAtSpeed()); the goal
  /// is judged on the \p judged axes only.
  void activate(std::unique_ptr<GoalHandle> goal, const GoalCommand& command,
                const std::array<bool, AXIS_COUNT>& judged, const std::string& note, const AxisValues& speed);
  /// The final status text keeps the note of the accepted goal (clamping, a zoom ignored).
  std::string withNote(const std::string& text) const;
  /// supervise() for a sample known to belong to the active goal, judged as at \p taken_at.
  void judge(const PtzSample& sample, bool publish_feedback, TimePoint taken_at);
  /// The axes \p view asks the device to move: pan, tilt for a point away from the picture's centre, zoom for a box.
  std::array<bool, AXIS_COUNT> askedAxes(const ViewTarget& view) const;
  /// For a view goal, tells it where the device ended in \p sample (GoalHandle::ended()); nothing for other goals.
  void tellEnd(const PtzSample& sample);
  /// Ends the active goal's supervision; tells the activity listener the supervisor is idle unless \p replaced.
  void finish(bool replaced = false);

  const std::shared_ptr<PtzBackend> backend_;
  const Capabilities limits_;
  const GoalMonitorConfig config_;
  const bool clamp_goals_;
  const std::shared_ptr<const Clock> clock_;

  // Touched only on the supervisor's thread.
  double default_speed_ = FULL_SPEED;  ///< the operator's speed of position goals that ask none
  std::unique_ptr<GoalHandle> active_goal_;
  std::string note_;  ///< what validation changed in the active goal (clamping, a zoom ignored), empty if nothing
  std::unique_ptr<GoalMonitor> monitor_;
  bool stopping_ = false;  ///< the active goal was cancelled and waits for the device to rest
  /// Set while the active goal is a GoalCommand::view.
  std::optional<ViewEnding> view_ending_;
  std::function<void(const GoalHandle*)> activity_listener_;  ///< see setActivityListener()

  std::atomic<GoalMode> mode_{ GoalMode::IDLE };
  /// Changes with each goal, and when a cancel starts the stop, after the sample its monitor starts from.
  std::atomic<std::uint64_t> goal_serial_{ 0 };
};

}  // namespace ptz_action_server

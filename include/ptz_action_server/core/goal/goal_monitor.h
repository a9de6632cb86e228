/**
 * \file
 * \brief Decides, sample by sample, whether an active goal has succeeded, failed or goes on.
 *
 * gripper_action_controller's checkForSuccess is the single-axis model: success only when every axis is inside its
 * tolerance and the device has settled; a stall, a timeout, a lost link or a device fault end the goal with a reason.
 */
#pragma once

#include <array>
#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// How goals are judged. The ROS layer fills it from parameters once.
struct GoalMonitorConfig
{
  AxisValues tolerance{ { 0.005, 0.005, 0.05 } };  ///< position tolerance: rad, rad, X
  double stall_timeout = 1.0;                      ///< s an axis may stay still while it still has to move
  double timeout_scale = 1.5;                      ///< goal timeout = expected duration x scale + margin ...
  double timeout_margin = 2.0;                     ///< ... in s
  double fixed_timeout = 0.0;                      ///< > 0: use this timeout (s) instead of the estimate
  double stop_timeout = 5.0;                       ///< s a cancelled goal waits for the device to come to rest
};

enum class GoalPhase
{
  ACTIVE,
  SUCCEEDED,
  ABORTED,
};

/// What a sample means for the goal.
struct GoalVerdict
{
  GoalPhase phase = GoalPhase::ACTIVE;
  AxisValues remaining{};     ///< goal minus current, signed: positions, or velocities for a velocity goal
  std::string reason;         ///< why the goal ended (empty while ACTIVE)
  bool device_fault = false;  ///< the device reported a fault: the caller appends the backend's fault text
  bool link_lost = false;     ///< the link was lost during the goal: the caller appends the backend's reason
  bool stop_device = false;   ///< the caller must stop the device (a velocity goal hit a limit)
};

/// Where a goal the device aimed itself (GoalCommand::view) ended, for its result (GoalHandle::ended()).
struct ViewEnding
{
  AxisValues start{};                    ///< the device's position when the goal started
  std::array<bool, AXIS_COUNT> asked{};  ///< the axes the goal asked the device to move

  /// \p sample's position of each axis \p capabilities has reporting that moved or was not asked to; NaN for the
  /// others: never reached on an axis that did not move or that the device does not report.
  AxisValues at(const PtzSample& sample, const Capabilities& capabilities) const;
};

/// Watches one goal. Not thread-safe: one owner thread calls update().
class GoalMonitor
{
public:
  /// A goal to reach \p target (absent axes are ignored).
  static GoalMonitor forPosition(const AxisValues& target, const PtzSample& start, const Capabilities& capabilities,
                                 const GoalMonitorConfig& config, TimePoint now);
  /// A goal to move at \p velocity; all zeros means "stop", which succeeds once the device rests.
  static GoalMonitor forVelocity(const AxisValues& velocity, const PtzSample& start, const Capabilities& capabilities,
                                 const GoalMonitorConfig& config, TimePoint now);
  /// A goal that follows a moving target, starting at \p aim: it never succeeds on its own (cancel or preempt ends
  /// it); a lost link or a device fault aborts it. remaining is aim minus position; retarget() moves the aim.
  static GoalMonitor forTrack(const AxisValues& aim, const PtzSample& start, const Capabilities& capabilities,
                              const GoalMonitorConfig& config, TimePoint now);
  /**
   * \brief A goal the device aims itself, in its own picture (GoalCommand::view): its target is the device's to know.
   *
   * It succeeds once the device has moved and its reported pose has settled (at rest, and the same in two reports in a
   * row), and says where it ended, which axes did not move, and which it does not report. Before the device has moved,
   * a goal that \p asked some axis to move (a point away from the picture's centre, a box that zooms) aborts when it
   * still rests stall_timeout after the start; one that asked none succeeds then. A device that reports no axis at all
   * succeeds then too, saying so. The timeout allows every axis to cross its whole range; remaining is NaN (unknown).
   */
  static GoalMonitor forView(const PtzSample& start, const Capabilities& capabilities, const GoalMonitorConfig& config,
                             TimePoint now, const std::array<bool, AXIS_COUNT>& asked);
  /// A cancelled goal whose device is being stopped: it ends once the device rests (or stop_timeout passes). Its
  /// final text names the position of the axes \p reported has present and reporting.
  static GoalMonitor forStop(const PtzSample& start, const GoalMonitorConfig& config, TimePoint now,
                             const Capabilities& reported = Capabilities());

  /// A tracking goal's new aim (positions).
  void retarget(const AxisValues& aim)
  {
    goal_ = aim;
  }

  /// Judges the goal at \p sample, taken at \p now (samples may arrive late and out of order). Once it returns a
  /// final verdict, the goal is over.
  GoalVerdict update(const PtzSample& sample, TimePoint now);

  /// The timeout of a position goal in s (0 for goals without one).
  double timeout() const
  {
    return timeout_;
  }

private:
  enum class Kind
  {
    POSITION,
    VELOCITY,
    STOP,
    TRACK,
    VIEW,
  };

  GoalMonitor(Kind kind, const AxisValues& goal, const PtzSample& start, const Capabilities& capabilities,
              const GoalMonitorConfig& config, TimePoint now);

  GoalVerdict updatePosition(const PtzSample& sample, TimePoint now, GoalVerdict verdict);
  GoalVerdict updateVelocity(const PtzSample& sample, TimePoint now, GoalVerdict verdict);
  GoalVerdict updateStop(const PtzSample& sample, TimePoint now, GoalVerdict verdict);
  GoalVerdict updateView(const PtzSample& sample, TimePoint now, GoalVerdict verdict);
  /// Where a view goal ended: the position of the axes it reports, and what did not move or cannot be seen.
  std::string describeViewEnd(const PtzSample& sample) const;
  /// Marks progress on moving axes; returns the axis that has not moved for stall_timeout, or AXIS_COUNT.
  std::size_t findStalledAxis(const PtzSample& sample, TimePoint now, const std::array<bool, AXIS_COUNT>& must_move);
  std::string describePosition(const PtzSample& sample) const;

  Kind kind_;
  AxisValues goal_;  ///< target position or velocity
  Capabilities capabilities_;
  GoalMonitorConfig config_;
  TimePoint started_at_;
  double expected_duration_ = 0.0;
  double timeout_ = 0.0;
  std::uint64_t start_fault_count_ = 0;
  std::uint64_t start_link_losses_ = 0;
  AxisValues start_position_{};                           ///< where the device was at the start
  bool must_move_ = false;                                ///< a view goal that needs the device to move
  bool view_moved_ = false;                               ///< a view goal's device was seen to move
  AxisValues view_last_{};                                ///< a view goal's previous reported position
  TimePoint view_last_stamp_{};                           ///< ... and its stamp
  AxisValues last_moved_position_{};                      ///< position where each axis was last seen moving
  std::array<TimePoint, AXIS_COUNT> last_moved_at_{};     ///< on the monitor's clock
  std::array<TimePoint, AXIS_COUNT> last_moved_stamp_{};  ///< the device's report (PtzSample::stamp) of that moment
};

}  // namespace ptz_action_server

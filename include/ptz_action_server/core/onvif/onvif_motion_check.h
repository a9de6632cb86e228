/**
 * \file
 * \brief What an ONVIF camera did after a command, judged from its GetStatus answers: cameras in the field answer
 * Stop and keep moving, answer AbsoluteMove and never move, or stop their zoom short of the range they list.
 */
#pragma once

#include <array>
#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
namespace onvif
{
/// One GetStatus answer, as the motion check reads it.
struct Observation
{
  TimePoint at{};                           ///< when the answer came
  AxisValues position{};                    ///< pan, tilt (rad), zoom (X)
  std::array<bool, AXIS_COUNT> reported{};  ///< axes whose position the camera reports
  std::string pan_tilt_status;              ///< MoveStatus PanTilt: "IDLE", "MOVING", "UNKNOWN" or "" (not given)
  std::string zoom_status;                  ///< MoveStatus Zoom
};

/// How the motion check judges.
struct MotionCheckConfig
{
  double deceleration = 3.0;   ///< rad/s^2 a camera is taken to brake at after Stop
  double max_speed = 1.5;      ///< rad/s a camera may have moved at before a Stop, when its speed is unknown
  double poll_period = 0.1;    ///< s between two GetStatus
  double start_timeout = 0.5;  ///< s an AbsoluteMove's axes have to begin moving (0: never judged)
  AxisValues expected{ { 0.005, 0.005, 0.05 } };  ///< a target farther than this from where the axis is must move it
};

/// What the camera showed (MotionCheck::observe()).
struct MotionFinding
{
  enum Kind
  {
    NONE,
    /// It answered Stop and was still moving once the time it takes to brake was over.
    KEPT_MOVING_AFTER_STOP,
    /// It answered AbsoluteMove and, start_timeout later, had not moved, its status saying it does nothing.
    ABSOLUTE_MOVE_IGNORED,
    /// Its zoom moved towards an AbsoluteMove's target and came to rest short of it.
    ZOOM_STOPPED_SHORT,
  };
  Kind kind = NONE;
  std::array<bool, AXIS_COUNT> axes{};  ///< KEPT_MOVING_AFTER_STOP: the axes still moving; ABSOLUTE_MOVE_IGNORED: the
                                        ///< axes that never began (both of pan and tilt when the pan-tilt did not)
  AxisValues speed{};                   ///< KEPT_MOVING_AFTER_STOP: each axis' speed then (rad/s, X/s)
  double after = 0.0;                   ///< s since the command
  double zoom = 0.0;                    ///< ZOOM_STOPPED_SHORT: where the zoom stopped (X)
  double zoom_target = 0.0;             ///< and where it was sent (X)
};

/**
 * \brief Watches the statuses after one Stop or one AbsoluteMove (the last command given) for the behaviours of the
 * field's cameras. Not thread-safe: the protocol's I/O thread feeds it.
 *
 * - After a Stop: a camera that rests (two statuses alike, not MOVING) before the time it takes to brake is over is
 *   fine; one still moving then is KEPT_MOVING_AFTER_STOP. That time is counted in statuses, which come a poll period
 *   apart at least, so a busy machine that receives them late only makes the judgement later: its speed before the
 *   Stop / deceleration (twice the speed the reports show, within the max speed: they lag a camera that is speeding
 *   up), plus two poll periods.
 * - After an AbsoluteMove: each axis it sends farther than `expected` must begin within start_timeout (three statuses
 *   at least). One whose position stayed put while its MoveStatus never said MOVING is ABSOLUTE_MOVE_IGNORED (a
 *   blocked motor reports MOVING: that is the node's stall to report, not this). A zoom that moved towards its target
 *   and rests (two statuses alike, not MOVING) short of it is ZOOM_STOPPED_SHORT.
 * Each watch finds one thing at most; any command ends it.
 */
class MotionCheck
{
public:
  explicit MotionCheck(const MotionCheckConfig& config) : config_(config)
  {
  }

  /// A Stop was answered at \p at; \p velocity is what the camera moved at before it (0: unknown).
  void stopSent(TimePoint at, const AxisValues& velocity);
  /// An AbsoluteMove was answered at \p at, sending the camera from \p from to \p target (NaN: an axis left alone).
  void absoluteMoveSent(TimePoint at, const AxisValues& from, const AxisValues& target);
  /// Another command: nothing more to watch.
  void clear()
  {
    watch_ = Watch::NOTHING;
  }
  /// A status; what the watch finds in it.
  MotionFinding observe(const Observation& status);

private:
  enum class Watch
  {
    NOTHING,
    STOP,
    ABSOLUTE_MOVE,
  };
  /// True if \p axis moved between \p before and \p after, or the status says its group is MOVING.
  bool moved(Axis axis, const Observation& before, const Observation& after) const;
  MotionFinding observeStop(const Observation& status);
  MotionFinding observeAbsoluteMove(const Observation& status);

  const MotionCheckConfig config_;
  Watch watch_ = Watch::NOTHING;
  TimePoint sent_at_{};
  AxisValues velocity_{};  ///< before the Stop
  AxisValues from_{};
  AxisValues target_{};
  std::array<bool, AXIS_COUNT> must_move_{};
  std::array<bool, AXIS_COUNT> began_{};
  int statuses_ = 0;  ///< since the command
  bool have_last_ = false;
  Observation last_;  ///< the status before the one observed
};

}  // namespace onvif
}  // namespace ptz_action_server

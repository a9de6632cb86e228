/**
 * \file
 * \brief Keeps the optical axis on a moving point: aim, the point's angular motion fed forward, and the command.
 */
#pragma once

#include <deque>
#include <string>

#include <Eigen/Geometry>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// How a tracking goal steers. The ROS layer fills it from ~track/* once.
struct FrameTrackerConfig
{
  double rate = 20.0;              ///< Hz the node looks the frame up and steers the device
  double gain = 4.0;               ///< 1/s: velocity added per rad of aim error, on top of the feed-forward
  double timeout = 1.0;            ///< s a frame may go without a new position before the goal aborts (track_timeout)
  bool feed_forward = true;        ///< velocity commands with the frame's motion fed forward; false: position commands
  double max_extrapolation = 0.5;  ///< s the aim is carried forward past the frame's newest position, at most
};

/**
 * \brief Follows one point given in the pan base frame, as positions of it arrive (from tf).
 *
 * The aim is the pan and tilt whose optical axis passes through the point (PtzKinematics::aimAt). Its angular rate
 * comes from the positions of the last tenth of a second or more, and carries the aim forward to the moment of the
 * command, so the device is steered toward where the point is, not where tf last saw it. With feed_forward the
 * command is a velocity: that rate plus gain times the aim error; otherwise the aim itself.
 *
 * Not thread-safe: the node's main thread owns it.
 */
class FrameTracker
{
public:
  /// \p zoom is held for the whole goal, as validation commands it (commandedZoom()); \p limits clamp the aim and the
  /// speeds.
  FrameTracker(const PtzKinematics& kinematics, const Capabilities& limits, const FrameTrackerConfig& config,
               double zoom);

  /// A position of the point in the base frame, measured at \p stamp (s, the transform's time), seen at \p now.
  /// A stamp already seen is ignored. Returns "" or why the point cannot be aimed at (too close to the camera).
  std::string observe(const Eigen::Vector3d& point, double stamp, TimePoint now);
  /// An aim at the point (pan, tilt in rad), measured at \p stamp (s), seen at \p now: for a target known by its
  /// direction alone (a detection in an image). A stamp not newer than the newest is ignored: false; true if taken.
  bool observeAim(double pan, double tilt, double stamp, TimePoint now);

  bool hasPosition() const
  {
    return !history_.empty();
  }
  /// When observe() last took a new position.
  TimePoint lastNewPositionAt() const
  {
    return last_new_at_;
  }
  /// Pan and tilt rates of the aim (rad/s) from the recent positions; zero before two.
  AxisValues aimRate() const;
  /// The aim at \p stamp (s, tf time), carried forward from the newest position at aimRate(), pan brought next to
  /// \p current_pan (a turn more or less, within the limits) and clamped into the limits.
  AxisValues aimAt(double stamp, double current_pan) const;
  /// What to command at \p current, \p stamp being now in tf time; \p aim receives the aim it steers to.
  GoalCommand command(const PtzSample& current, double stamp, AxisValues& aim) const;

private:
  struct AimSample
  {
    double stamp;
    double pan;
    double tilt;
  };

  const PtzKinematics kinematics_;
  const Capabilities limits_;
  const FrameTrackerConfig config_;
  const double zoom_;
  std::deque<AimSample> history_;  ///< newest last; pan unwrapped along the history
  TimePoint last_new_at_{};
};

}  // namespace ptz_action_server

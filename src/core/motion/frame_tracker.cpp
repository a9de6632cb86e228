#include "ptz_action_server/core/motion/frame_tracker.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/goal/goal_validation.h"

namespace ptz_action_server
{
namespace
{
constexpr double RATE_WINDOW = 0.1;   ///< s of positions the aim rate is measured over (at least)
constexpr double HISTORY_SPAN = 0.5;  ///< s of positions kept
constexpr double TWO_PI = 2.0 * M_PI;

/// \p angle plus whole turns, nearest to \p reference.
double nearestTurn(double angle, double reference)
{
  return angle + TWO_PI * std::round((reference - angle) / TWO_PI);
}

double clampInto(double value, const AxisRange& range)
{
  return std::min(std::max(value, range.min), range.max);
}
}  // namespace

FrameTracker::FrameTracker(const PtzKinematics& kinematics, const Capabilities& limits,
                           const FrameTrackerConfig& config, double zoom)
  : kinematics_(kinematics), limits_(limits), config_(config), zoom_(commandedZoom(limits.axes[ZOOM], zoom))
{
}

std::string FrameTracker::observe(const Eigen::Vector3d& point, double stamp, TimePoint now)
{
  if (!history_.empty() && stamp <= history_.back().stamp)
  {
    return {};  // nothing new
  }
  double pan = 0.0;
  double tilt = 0.0;
  if (!kinematics_.aimAt(point, pan, tilt))
  {
    return "cannot point at the frame's origin: it is too close to the camera";
  }
  observeAim(pan, tilt, stamp, now);
  return {};
}

bool FrameTracker::observeAim(double pan, double tilt, double stamp, TimePoint now)
{
  if (!history_.empty() && stamp <= history_.back().stamp)
  {
    return false;  // nothing new
  }
  AimSample aim{ stamp, pan, tilt };
  if (!history_.empty())
  {
    aim.pan = nearestTurn(aim.pan, history_.back().pan);  // continuous along the history
  }
  history_.push_back(aim);
  while (history_.size() > 2 && stamp - history_[1].stamp >= HISTORY_SPAN)
  {
    history_.pop_front();
  }
  last_new_at_ = now;
  return true;
}

AxisValues FrameTracker::aimRate() const
{
  AxisValues rate{};
  if (history_.size() < 2)
  {
    return rate;
  }
  const AimSample& newest = history_.back();
  // The newest position at least RATE_WINDOW older than the newest, or the oldest kept.
  auto older = history_.begin();
  for (auto it = history_.begin(); it + 1 != history_.end(); ++it)
  {
    if (newest.stamp - it->stamp >= RATE_WINDOW)
    {
      older = it;
    }
  }
  const double span = newest.stamp - older->stamp;
  if (span > 0.0)
  {
    rate[PAN] = (newest.pan - older->pan) / span;
    rate[TILT] = (newest.tilt - older->tilt) / span;
  }
  return rate;
}

AxisValues FrameTracker::aimAt(double stamp, double current_pan) const
{
  const AimSample& newest = history_.back();
  const AxisValues rate = aimRate();
  const double ahead = std::min(std::max(stamp - newest.stamp, 0.0), config_.max_extrapolation);
  AxisValues aim{ { newest.pan + rate[PAN] * ahead, newest.tilt + rate[TILT] * ahead, zoom_ } };
  aim[PAN] = nearestTurn(aim[PAN], current_pan);
  // The turn nearest the camera may lie past a limit another turn does not (a pan range wider than a turn).
  for (double turn : { -TWO_PI, TWO_PI })
  {
    if (!limits_.axes[PAN].range.contains(aim[PAN]) && limits_.axes[PAN].range.contains(aim[PAN] + turn))
    {
      aim[PAN] += turn;
    }
  }
  for (Axis axis : { PAN, TILT })
  {
    if (limits_.axes[axis].present)
    {
      aim[axis] = clampInto(aim[axis], limits_.axes[axis].range);
    }
  }
  return aim;
}

GoalCommand FrameTracker::command(const PtzSample& current, double stamp, AxisValues& aim) const
{
  aim = aimAt(stamp, current.position[PAN]);
  GoalCommand command;
  if (!config_.feed_forward)
  {
    command.values = aim;
    return command;
  }
  command.velocity = true;
  const AxisValues rate = aimRate();
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = limits_.axes[axis];
    if (!capability.present || !capability.absolute || !capability.feedback)
    {
      continue;  // speed 0: nothing to steer by (a zoom without positions is left alone, or sent to its widest view)
    }
    const double error = aim[axis] - current.position[axis];
    // A clamped aim does not move: feeding the point's motion forward would push the axis into its limit.
    const bool at_limit = aim[axis] <= limits_.axes[axis].range.min || aim[axis] >= limits_.axes[axis].range.max;
    const double feed_forward = axis == ZOOM || at_limit ? 0.0 : rate[axis];
    const double speed = limits_.axes[axis].max_speed;
    command.values[axis] = std::min(std::max(feed_forward + config_.gain * error, -speed), speed);
  }
  return command;
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/goal/goal_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/motion/motion_profile.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// An axis counts as moving when it travels more than this share of its tolerance.
constexpr double MOVEMENT_SHARE_OF_TOLERANCE = 0.25;
/// A reported position that changed by more than this (rad, X) since a view goal's start moved.
constexpr double VIEW_MOVED = 1e-6;
/// Acceleration assumed for the timeout estimate when a device does not state one.
constexpr double UNKNOWN_ACCELERATION = 1e3;

/// Expected duration of a position goal: the slowest axis' closed-form trapezoid, plus braking from its speed.
double expectedDuration(const AxisValues& target, const PtzSample& start, const Capabilities& capabilities)
{
  double longest = 0.0;
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities.axes[axis];
    if (!capability.present || !(capability.max_speed > 0.0))
    {
      continue;
    }
    AxisMotionLimits limits;
    limits.max_speed = capability.max_speed;
    limits.acceleration = capability.acceleration > 0.0 ? capability.acceleration : UNKNOWN_ACCELERATION;
    const double braking = 2.0 * std::abs(start.velocity[axis]) / limits.acceleration;
    const double distance = std::abs(target[axis] - start.position[axis]) + std::abs(start.velocity[axis]) * braking;
    longest = std::max(longest, braking + TrapezoidProfile::minimumDuration(distance, limits));
  }
  return longest;
}
}  // namespace

GoalMonitor GoalMonitor::forPosition(const AxisValues& target, const PtzSample& start, const Capabilities& capabilities,
                                     const GoalMonitorConfig& config, TimePoint now)
{
  return GoalMonitor(Kind::POSITION, target, start, capabilities, config, now);
}

GoalMonitor GoalMonitor::forVelocity(const AxisValues& velocity, const PtzSample& start,
                                     const Capabilities& capabilities, const GoalMonitorConfig& config, TimePoint now)
{
  return GoalMonitor(Kind::VELOCITY, velocity, start, capabilities, config, now);
}

GoalMonitor GoalMonitor::forStop(const PtzSample& start, const GoalMonitorConfig& config, TimePoint now,
                                 const Capabilities& reported)
{
  return GoalMonitor(Kind::STOP, AxisValues{}, start, reported, config, now);
}

GoalMonitor GoalMonitor::forView(const PtzSample& start, const Capabilities& capabilities,
                                 const GoalMonitorConfig& config, TimePoint now,
                                 const std::array<bool, AXIS_COUNT>& asked)
{
  GoalMonitor monitor(Kind::VIEW, AxisValues{}, start, capabilities, config, now);
  monitor.must_move_ = std::any_of(asked.begin(), asked.end(), [](bool axis_asked) { return axis_asked; });
  monitor.view_last_ = start.position;
  monitor.view_last_stamp_ = start.stamp;
  return monitor;
}

AxisValues ViewEnding::at(const PtzSample& sample, const Capabilities& capabilities) const
{
  AxisValues position = sample.position;
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities.axes[axis];
    const bool moved = std::abs(sample.position[axis] - start[axis]) > VIEW_MOVED;
    if (!capability.present || !capability.feedback || (asked[axis] && !moved))
    {
      position[axis] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return position;
}

GoalMonitor GoalMonitor::forTrack(const AxisValues& aim, const PtzSample& start, const Capabilities& capabilities,
                                  const GoalMonitorConfig& config, TimePoint now)
{
  return GoalMonitor(Kind::TRACK, aim, start, capabilities, config, now);
}

GoalMonitor::GoalMonitor(Kind kind, const AxisValues& goal, const PtzSample& start, const Capabilities& capabilities,
                         const GoalMonitorConfig& config, TimePoint now)
  : kind_(kind)
  , goal_(goal)
  , capabilities_(capabilities)
  , config_(config)
  , started_at_(now)
  , start_fault_count_(start.fault_count)
  , start_link_losses_(start.link_losses)
  , start_position_(start.position)
  , last_moved_position_(start.position)
{
  last_moved_at_.fill(now);
  last_moved_stamp_.fill(start.stamp);
  if (kind == Kind::POSITION || kind == Kind::VIEW)
  {
    AxisValues target = goal;
    if (kind == Kind::VIEW)
    {
      // Where the device goes is unknown: as far as the farther end of each axis' range.
      for (Axis axis : ALL_AXES)
      {
        const AxisRange& range = capabilities.axes[axis].range;
        const double position = start.position[axis];
        target[axis] = std::abs(range.max - position) > std::abs(position - range.min) ? range.max : range.min;
      }
    }
    expected_duration_ = expectedDuration(target, start, capabilities);
    timeout_ = config.fixed_timeout > 0.0 ? config.fixed_timeout :
                                            expected_duration_ * config.timeout_scale + config.timeout_margin;
  }
  else if (kind == Kind::STOP)
  {
    timeout_ = config.stop_timeout;
  }
}

GoalVerdict GoalMonitor::update(const PtzSample& sample, TimePoint now)
{
  GoalVerdict verdict;
  if (kind_ == Kind::STOP)
  {
    return updateStop(sample, now, verdict);
  }
  for (Axis axis : ALL_AXES)
  {
    if (kind_ == Kind::VIEW)
    {
      verdict.remaining[axis] = std::numeric_limits<double>::quiet_NaN();  // only the device knows its target
    }
    else if (capabilities_.axes[axis].present)
    {
      verdict.remaining[axis] = goal_[axis] - (kind_ == Kind::VELOCITY ? sample.velocity[axis] : sample.position[axis]);
    }
  }
  // A link that broke and came back at once still ends the goal: what the device did meanwhile is unknown.
  if (!sample.link_up || sample.link_losses != start_link_losses_)
  {
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = "link lost";
    verdict.link_lost = true;
    return verdict;
  }
  if (sample.fault_count != start_fault_count_)
  {
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = "device fault";
    verdict.device_fault = true;
    return verdict;
  }
  switch (kind_)
  {
    case Kind::POSITION:
      return updatePosition(sample, now, verdict);
    case Kind::TRACK:
      return verdict;  // goes on until cancelled or preempted
    case Kind::VIEW:
      return updateView(sample, now, verdict);
    default:
      return updateVelocity(sample, now, verdict);
  }
}

GoalVerdict GoalMonitor::updatePosition(const PtzSample& sample, TimePoint now, GoalVerdict verdict)
{
  std::array<bool, AXIS_COUNT> outside_tolerance{};
  bool all_inside = true;
  for (Axis axis : ALL_AXES)
  {
    outside_tolerance[axis] =
        capabilities_.axes[axis].present && std::abs(verdict.remaining[axis]) > config_.tolerance[axis];
    all_inside = all_inside && !outside_tolerance[axis];
  }
  if (all_inside && !sample.moving)
  {
    verdict.phase = GoalPhase::SUCCEEDED;
    verdict.reason = "reached " + describePosition(sample);
    return verdict;
  }
  const std::size_t stalled = findStalledAxis(sample, now, outside_tolerance);
  if (stalled != AXIS_COUNT)
  {
    const Axis axis = static_cast<Axis>(stalled);
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = formatText("stalled: %s made no progress for %.2f s (remaining %.4f %s)", axisName(axis),
                                config_.stall_timeout, verdict.remaining[axis], unitOf(axis));
    return verdict;
  }
  const double elapsed = secondsBetween(started_at_, now);
  if (elapsed > timeout_)
  {
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = formatText("timed out after %.2f s (expected %.2f s) at %s", elapsed, expected_duration_,
                                describePosition(sample).c_str());
  }
  return verdict;
}

GoalVerdict GoalMonitor::updateVelocity(const PtzSample& sample, TimePoint now, GoalVerdict verdict)
{
  std::array<bool, AXIS_COUNT> must_move{};
  bool any_commanded = false;
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities_.axes[axis];
    if (!capability.present || goal_[axis] == 0.0)
    {
      continue;
    }
    any_commanded = true;
    if (!capability.feedback)
    {
      continue;  // no position to see a limit or a stall in: the goal goes on until cancelled or replaced
    }
    const bool upward = goal_[axis] > 0.0;
    const double limit = upward ? capability.range.max : capability.range.min;
    if (std::abs(sample.position[axis] - limit) <= config_.tolerance[axis])
    {
      verdict.phase = GoalPhase::SUCCEEDED;
      verdict.stop_device = true;
      verdict.reason = formatText("%s reached its %s limit %.4f %s", axisName(axis), upward ? "upper" : "lower", limit,
                                  unitOf(axis));
      return verdict;
    }
    must_move[axis] = true;
  }
  if (!any_commanded)
  {
    if (!sample.moving)
    {
      verdict.phase = GoalPhase::SUCCEEDED;
      verdict.reason = "stopped at " + describePosition(sample);
    }
    return verdict;
  }
  const std::size_t stalled = findStalledAxis(sample, now, must_move);
  if (stalled != AXIS_COUNT)
  {
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = formatText("stalled: %s did not move for %.2f s at %.4f %s", axisName(static_cast<Axis>(stalled)),
                                config_.stall_timeout, sample.position[stalled], unitOf(static_cast<Axis>(stalled)));
  }
  return verdict;
}

GoalVerdict GoalMonitor::updateStop(const PtzSample& sample, TimePoint now, GoalVerdict verdict)
{
  if (!sample.link_up || sample.link_losses != start_link_losses_)
  {
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = "link lost while stopping";
    verdict.link_lost = true;
  }
  else if (!sample.moving)
  {
    verdict.phase = GoalPhase::SUCCEEDED;
    verdict.reason = "stopped at " + describePosition(sample);
  }
  else if (secondsBetween(started_at_, now) > timeout_)
  {
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = formatText("still moving %.2f s after the stop command", timeout_);
  }
  return verdict;
}

GoalVerdict GoalMonitor::updateView(const PtzSample& sample, TimePoint now, GoalVerdict verdict)
{
  bool observable = false;
  // Settled: at rest, and the same in a later report than the last (a report judged twice proves nothing).
  bool settled = !sample.moving && (sample.stamp != view_last_stamp_ || sample.stamp == TimePoint{});
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities_.axes[axis];
    if (capability.present && capability.feedback)
    {
      observable = true;
      // Any change of a reported position is the device's own move: it reports in its own steps.
      view_moved_ = view_moved_ || std::abs(sample.position[axis] - start_position_[axis]) > VIEW_MOVED;
      settled = settled && std::abs(sample.position[axis] - view_last_[axis]) <= VIEW_MOVED;
    }
  }
  view_last_ = sample.position;
  view_last_stamp_ = sample.stamp;
  view_moved_ = view_moved_ || sample.moving;
  const double elapsed = secondsBetween(started_at_, now);
  if (view_moved_ && settled)
  {
    verdict.phase = GoalPhase::SUCCEEDED;
    verdict.reason = "the device aimed itself: ended at " + describeViewEnd(sample);
  }
  else if (!view_moved_ && elapsed > config_.stall_timeout)
  {
    verdict.phase = must_move_ && observable ? GoalPhase::ABORTED : GoalPhase::SUCCEEDED;
    verdict.reason = !observable ? "sent to the device's own command; it reports no position, so where it ended is "
                                   "not known" :
                     must_move_  ? formatText("the device did not move within %.2f s of its own command, at %s",
                                              config_.stall_timeout, describePosition(sample).c_str()) :
                                   "already centred: the device did not move, at " + describePosition(sample);
  }
  else if (elapsed > timeout_)
  {
    verdict.phase = GoalPhase::ABORTED;
    verdict.reason = formatText("timed out after %.2f s (the device's own command) at %s", elapsed,
                                describePosition(sample).c_str());
  }
  return verdict;
}

std::string GoalMonitor::describeViewEnd(const PtzSample& sample) const
{
  std::string text = describePosition(sample);
  std::string still;
  std::string unseen;
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities_.axes[axis];
    if (!capability.present)
    {
      continue;
    }
    if (!capability.feedback)
    {
      unseen += std::string(unseen.empty() ? "" : " and ") + axisName(axis);
    }
    else if (std::abs(sample.position[axis] - start_position_[axis]) <= VIEW_MOVED)
    {
      still += std::string(still.empty() ? "" : " and ") + axisName(axis);
    }
  }
  if (!still.empty())
  {
    text += "; " + still + " did not move";
  }
  if (!unseen.empty())
  {
    text += "; the device does not report its " + unseen;
  }
  return text;
}

std::size_t GoalMonitor::findStalledAxis(const PtzSample& sample, TimePoint now,
                                         const std::array<bool, AXIS_COUNT>& must_move)
{
  std::size_t stalled = AXIS_COUNT;
  for (Axis axis : ALL_AXES)
  {
    const double step = MOVEMENT_SHARE_OF_TOLERANCE * config_.tolerance[axis];
    if (!must_move[axis] || std::abs(sample.position[axis] - last_moved_position_[axis]) > step)
    {
      last_moved_position_[axis] = sample.position[axis];
      last_moved_at_[axis] = std::max(last_moved_at_[axis], now);  // a late sample is judged at its own, earlier time
      last_moved_stamp_[axis] = std::max(last_moved_stamp_[axis], sample.stamp);
    }
    else if (stalled == AXIS_COUNT && secondsBetween(last_moved_at_[axis], now) > config_.stall_timeout &&
             secondsBetween(last_moved_stamp_[axis], sample.stamp) > config_.stall_timeout)
    {
      // The device's own reports must span the stall timeout: an axis that stood still in the last reports before a
      // silence has not been seen to stall (the silence is the link supervision's to report, at its own deadline).
      stalled = axis;
    }
  }
  return stalled;
}

std::string GoalMonitor::describePosition(const PtzSample& sample) const
{
  // Only the axes the goal is judged on and the device reports: a zoom it lacks or cannot see has no position to tell.
  std::string text;
  for (Axis axis : ALL_AXES)
  {
    if (capabilities_.axes[axis].present && capabilities_.axes[axis].feedback)
    {
      text += (text.empty() ? "" : ", ") +
              formatText(axis == ZOOM ? "%s %.2f X" : "%s %.4f rad", axisName(axis), sample.position[axis]);
    }
  }
  return text.empty() ? std::string("a position the device does not report") : text;
}

}  // namespace ptz_action_server

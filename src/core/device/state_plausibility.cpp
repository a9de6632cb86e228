#include "ptz_action_server/core/device/state_plausibility.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// \p to - \p from, the short way round on a range that covers a full turn.
double distance(double from, double to, const AxisRange& range)
{
  double difference = to - from;
  if (range.max - range.min >= 2.0 * M_PI - 1e-6)
  {
    difference = std::remainder(difference, 2.0 * M_PI);
  }
  return std::abs(difference);
}

}  // namespace

std::string StatePlausibility::findJump(const AxisValues& from, TimePoint from_at, const AxisValues& position,
                                        TimePoint at, const Capabilities& capabilities)
{
  const double elapsed = std::max(0.0, secondsBetween(from_at, at));
  for (Axis axis : { PAN, TILT })
  {
    const AxisCapability& capability = capabilities.axes[axis];
    if (!capability.present || !capability.feedback || !(capability.max_speed > 0.0))
    {
      continue;
    }
    const double moved = distance(from[axis], position[axis], capability.range);
    if (moved > JUMP_SPEED_FACTOR * capability.max_speed * (elapsed + JUMP_SLACK) + MIN_MARGIN)
    {
      return formatText("%s jumped %.2f rad in %.2f s: faster than its top speed of %.2f rad/s", axisName(axis), moved,
                        elapsed, capability.max_speed);
    }
  }
  return {};
}

std::string StatePlausibility::judge(const AxisValues& position, TimePoint at, const Capabilities& capabilities)
{
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities.axes[axis];
    if (!capability.present || !capability.feedback)
    {
      continue;
    }
    const double value = position[axis];
    if (!std::isfinite(value))
    {
      return formatText("%s is %s", axisName(axis), std::isnan(value) ? "NaN" : "infinite");
    }
    const AxisRange& range = capability.range;
    const double margin = std::max(MIN_MARGIN, RANGE_MARGIN_SHARE * (range.max - range.min));
    if (value < range.min - margin || value > range.max + margin)
    {
      return formatText("%s %.2f %s is outside the device's limits [%.2f, %.2f]", axisName(axis), value, unitOf(axis),
                        range.min, range.max);
    }
  }
  if (has_reference_)
  {
    const std::string jump = findJump(reference_, reference_at_, position, at, capabilities);
    // In doubt, only a report that jumps back from the dropped ones is believed.
    const bool came_back =
        !jump_reason_.empty() && jump.empty() && !findJump(previous_, previous_at_, position, at, capabilities).empty();
    if (!jump.empty() || (!jump_reason_.empty() && !came_back))
    {
      if (jump_reason_.empty())
      {
        jump_reason_ = jump;
      }
      previous_ = position;
      previous_at_ = at;
      return jump_reason_;
    }
  }
  has_reference_ = true;
  jump_reason_.clear();
  reference_ = position;
  reference_at_ = at;
  return {};
}

}  // namespace ptz_action_server

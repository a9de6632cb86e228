#include "ptz_action_server/core/pelco_d/set_position_check.h"

#include <cmath>

namespace ptz_action_server
{
namespace pelco
{
bool SetPositionCheck::begin(const AxisValues& from, const AxisValues& target, TimePoint at)
{
  phase_ = Phase::IDLE;
  if (honoured_)
  {
    return false;
  }
  bool any = false;
  for (Axis axis : ALL_AXES)
  {
    // Twice the movement threshold: an axis seen to move has not passed its target yet.
    const double remaining = target[axis] - from[axis];
    const bool far = !std::isnan(remaining) && std::abs(remaining) > 2.0 * config_.moved[axis];
    directions_[axis] = far ? (remaining > 0.0 ? 1 : -1) : 0;
    any = any || far;
  }
  if (any)
  {
    phase_ = Phase::WATCHING;
    from_ = from;
    since_ = at;
    rounds_ = 0;
  }
  return any;
}

bool SetPositionCheck::movedFrom(const AxisValues& from, const AxisValues& position) const
{
  for (Axis axis : ALL_AXES)
  {
    if (std::abs(position[axis] - from[axis]) > config_.moved[axis])
    {
      return true;
    }
  }
  return false;
}

SetPositionCheck::Step SetPositionCheck::update(const AxisValues& position, TimePoint now)
{
  if (phase_ == Phase::IDLE)
  {
    return Step::NONE;
  }
  const bool moved = movedFrom(from_, position);
  const bool waited = ++rounds_ >= config_.rounds && secondsBetween(since_, now) >= config_.wait;
  if (phase_ == Phase::WATCHING)
  {
    if (moved)
    {
      phase_ = Phase::IDLE;
      honoured_ = true;
      return Step::HONOURED;
    }
    if (!waited)
    {
      return Step::NONE;
    }
    phase_ = Phase::PROBING;
    from_ = position;
    since_ = now;
    rounds_ = 0;
    return Step::PROBE;
  }
  if (moved || waited)
  {
    phase_ = Phase::IDLE;
    return moved ? Step::IGNORED : Step::STUCK;
  }
  return Step::NONE;
}

}  // namespace pelco
}  // namespace ptz_action_server

#include "ptz_action_server/core/motion/motion_estimator.h"

#include <cmath>

namespace ptz_action_server
{
namespace
{
/// Positions closer than this are the same (rad, or X for zoom).
constexpr double STILL_EPSILON = 1e-6;

bool differs(const AxisValues& a, const AxisValues& b)
{
  for (Axis axis : ALL_AXES)
  {
    if (std::abs(a[axis] - b[axis]) > STILL_EPSILON)
    {
      return true;
    }
  }
  return false;
}
}  // namespace

MotionEstimator::MotionEstimator(double settle_window, std::size_t history)
  : settle_window_(settle_window), history_(history)
{
}

void MotionEstimator::add(TimePoint at, const AxisValues& position)
{
  reports_.push_back(Report{ at, position });
  if (reports_.size() > history_)
  {
    reports_.pop_front();
  }
}

void MotionEstimator::clear()
{
  reports_.clear();
}

void MotionEstimator::fill(PtzSample& sample) const
{
  if (reports_.empty())
  {
    return;
  }
  const Report& newest = reports_.back();
  sample.stamp = newest.at;
  sample.position = newest.position;
  sample.velocity = AxisValues{};
  const Report* reference = nullptr;
  for (auto report = reports_.rbegin(); report != reports_.rend(); ++report)
  {
    if (secondsBetween(report->at, newest.at) >= settle_window_)
    {
      reference = &*report;
      break;
    }
  }
  if (reference == nullptr)
  {
    // Not enough history yet: moving if anything changed at all.
    sample.moving = differs(newest.position, reports_.front().position);
    return;
  }
  const double span = secondsBetween(reference->at, newest.at);
  for (Axis axis : ALL_AXES)
  {
    sample.velocity[axis] = (newest.position[axis] - reference->position[axis]) / span;
  }
  sample.moving = differs(newest.position, reference->position);
}

}  // namespace ptz_action_server

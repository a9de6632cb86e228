#include "ptz_action_server/ros/pose_recorder.h"

#include <algorithm>
#include <limits>

#include <ros/duration.h>

namespace ptz_action_server
{
ros::Time rosStampOf(TimePoint stamp, const Clock& clock, const ros::Time& now)
{
  const double age = std::max(0.0, secondsBetween(stamp, clock.now()));
  return now - ros::Duration(age);
}

PoseRecorder::PoseRecorder(const Capabilities& limits, const PoseHistoryConfig& config)
  : limits_(limits), history_(config)
{
}

void PoseRecorder::record(const ros::Time& stamp, const PtzSample& sample, std::chrono::nanoseconds min_spacing)
{
  // Claims the sample: only a thread that moves latest_sample_ forward records it.
  const TimePoint::rep taken = sample.stamp.time_since_epoch().count();
  TimePoint::rep latest = latest_sample_.load();
  do
  {
    const bool first = latest == std::numeric_limits<TimePoint::rep>::min();
    if (taken <= latest || (!first && taken - latest < min_spacing.count()))
    {
      return;
    }
  } while (!latest_sample_.compare_exchange_weak(latest, taken));
  AxisValues pose = sample.position;
  for (const Axis axis : ALL_AXES)
  {
    // As ptz_state: a position the device does not report is unknown (a zoom it does not have is 1).
    const AxisCapability& capability = limits_.axes[axis];
    if (capability.present && !capability.feedback)
    {
      pose[axis] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  history_.add(headerStampOf(stamp), pose);
}

void PoseRecorder::recordExact(const ros::Time& stamp, const AxisValues& pose)
{
  history_.add(headerStampOf(stamp), pose);
}

void PoseRecorder::checkClock(const ros::Time& now)
{
  if (now < last_check_)
  {
    history_.clear();
  }
  last_check_ = now;
}

}  // namespace ptz_action_server

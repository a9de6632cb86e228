/**
 * \file
 * \brief The node's pose history, fed with ROS-stamped samples: the camera's pose when each image was taken.
 */
#pragma once

#include <atomic>
#include <chrono>
#include <limits>

#include <ros/time.h>

#include "ptz_action_server/core/motion/pose_history.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// The ROS time a backend sample stamped \p stamp was taken at, as joint_states and the simulated camera's images are
/// stamped: ROS time \p now less the sample's age on \p clock (a sample from the future counts as taken now).
ros::Time rosStampOf(TimePoint stamp, const Clock& clock, const ros::Time& now = ros::Time::now());

/// \p stamp as the pose history keys it (nanoseconds of ROS time).
inline HeaderStamp headerStampOf(const ros::Time& stamp)
{
  return HeaderStamp(static_cast<std::int64_t>(stamp.toNSec()));
}

/**
 * \brief Feeds one PoseHistory from every place that knows where the camera looked: the state tick and the backend's
 * own sample reports (record(const ros::Time&, const PtzSample&)), and the simulated camera, with the exact pose of
 * each image it renders (recordExact()).
 *
 * A sample's pose is what ptz_state reports of it: NaN for an axis whose position the device does not report (the
 * history then knows that axis is unknown). A device sample already recorded (the tick and a report of the same
 * sample) is recorded once. When ROS time goes back (a bag played again, a simulator restarted) the state tick calls
 * checkClock(), which forgets the history: its stamps would all lie in the future.
 *
 * Thread-safe: the record methods from any thread, checkClock() from one (the state tick). Nothing here allocates.
 */
class PoseRecorder
{
public:
  /// \p limits are the node's: which axes the device reports.
  explicit PoseRecorder(const Capabilities& limits, const PoseHistoryConfig& config = PoseHistoryConfig());

  PoseRecorder(const PoseRecorder&) = delete;
  PoseRecorder& operator=(const PoseRecorder&) = delete;

  /// Records \p sample's pose at \p stamp (rosStampOf() of its stamp), unless a sample the device took at the same
  /// time or later is recorded already, or one taken less than \p min_spacing before it (a device reporting at
  /// hundreds of Hz would crowd the history's window out).
  void record(const ros::Time& stamp, const PtzSample& sample,
              std::chrono::nanoseconds min_spacing = std::chrono::nanoseconds(0));
  /// Records \p pose (pan, tilt in rad, zoom in X; NaN: unknown) at \p stamp: the simulated camera's image.
  void recordExact(const ros::Time& stamp, const AxisValues& pose);

  /// On the state tick, with ROS time \p now: forgets every pose if ROS time went back since the last call.
  void checkClock(const ros::Time& now);

  /// The pose at \p stamp, or why there is none (PoseLookup::error, for a goal's rejection).
  PoseLookup at(const ros::Time& stamp) const
  {
    return history_.at(headerStampOf(stamp));
  }

  const PoseHistory& history() const
  {
    return history_;
  }

private:
  const Capabilities limits_;
  PoseHistory history_;
  /// The device stamp (steady clock, ns) of the latest sample recorded, so no sample is recorded twice.
  std::atomic<TimePoint::rep> latest_sample_{ std::numeric_limits<TimePoint::rep>::min() };
  ros::Time last_check_;  ///< checkClock()'s thread only
};

}  // namespace ptz_action_server

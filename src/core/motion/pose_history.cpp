#include "ptz_action_server/core/motion/pose_history.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/circular_buffer.hpp>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace pose_history
{
/// One pose at one stamp.
struct Sample
{
  HeaderStamp stamp;
  AxisValues pose;
};

using Samples = boost::circular_buffer<Sample>;

bool stampBefore(const Sample& sample, HeaderStamp stamp)
{
  return sample.stamp < stamp;
}

/// Linear between \p from and \p to at \p fraction; pan along the shorter way round, kept in [-pi, pi].
double interpolate(Axis axis, double from, double to, double fraction)
{
  double difference = to - from;
  if (axis != PAN || std::abs(difference) <= M_PI)
  {
    return from + fraction * difference;
  }
  difference = std::remainder(difference, 2.0 * M_PI);
  return std::remainder(from + fraction * difference, 2.0 * M_PI);
}

/**
 * \brief \p axis at \p stamp from the nearest samples that know it: those at or after \p at_or_after and before it.
 *
 * Between two: linear. At one's stamp: its value. Only before, within \p tolerance: the last known value. Else NaN.
 */
double axisAt(const Samples& samples, Samples::const_iterator at_or_after, Axis axis, HeaderStamp stamp,
              HeaderStamp tolerance)
{
  const auto knows = [axis](const Sample& sample) { return !std::isnan(sample.pose[axis]); };
  const auto after = std::find_if(at_or_after, samples.end(), knows);
  if (after != samples.end() && after->stamp == stamp)
  {
    return after->pose[axis];
  }
  const auto before_reversed = std::find_if(Samples::const_reverse_iterator(at_or_after), samples.rend(), knows);
  if (before_reversed == samples.rend())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const Sample& before = *before_reversed;
  if (after == samples.end())
  {
    return stamp - before.stamp <= tolerance ? before.pose[axis] : std::numeric_limits<double>::quiet_NaN();
  }
  const double fraction =
      static_cast<double>((stamp - before.stamp).count()) / static_cast<double>((after->stamp - before.stamp).count());
  return interpolate(axis, before.pose[axis], after->pose[axis], fraction);
}
}  // namespace pose_history

HeaderStamp headerStampFromSeconds(double seconds)
{
  return HeaderStamp(std::llround(seconds * 1e9));
}

double secondsOf(HeaderStamp stamp)
{
  return std::chrono::duration<double>(stamp).count();
}

struct PoseHistory::Ring
{
  explicit Ring(std::size_t capacity) : samples(capacity)
  {
  }
  pose_history::Samples samples;
};

PoseHistory::PoseHistory(const PoseHistoryConfig& config) : config_(config)
{
  if (config_.window.count() <= 0 || config_.newer_tolerance.count() < 0 || config_.capacity < 2)
  {
    throw ConfigError(formatText("pose history: the window (%g s) must be positive, the tolerance (%g s) not negative "
                                 "and the capacity (%zu) at least 2",
                                 secondsOf(config_.window), secondsOf(config_.newer_tolerance), config_.capacity));
  }
  ring_ = std::make_unique<Ring>(config_.capacity);
}

PoseHistory::~PoseHistory() = default;

PoseHistory::Added PoseHistory::add(HeaderStamp stamp, const AxisValues& pose)
{
  std::lock_guard<std::mutex> lock(mutex_);
  pose_history::Samples& samples = ring_->samples;
  if (!samples.empty() && stamp < samples.back().stamp - config_.window)
  {
    return Added::TOO_OLD;
  }
  const auto place = std::lower_bound(samples.begin(), samples.end(), stamp, pose_history::stampBefore);
  if (place != samples.end() && place->stamp == stamp)
  {
    for (const Axis axis : ALL_AXES)
    {
      if (!std::isnan(pose[axis]))
      {
        place->pose[axis] = pose[axis];
      }
    }
    return Added::MERGED;
  }
  if (samples.full() && place == samples.begin())
  {
    return Added::DROPPED;
  }
  samples.insert(place, pose_history::Sample{ stamp, pose });  // full: the oldest goes
  trim();
  return Added::KEPT;
}

void PoseHistory::trim()
{
  pose_history::Samples& samples = ring_->samples;
  const HeaderStamp oldest_kept = samples.back().stamp - config_.window;
  while (samples.front().stamp < oldest_kept)
  {
    samples.pop_front();
  }
}

PoseLookup PoseHistory::at(HeaderStamp stamp) const
{
  PoseLookup lookup;
  lookup.pose.fill(std::numeric_limits<double>::quiet_NaN());
  std::lock_guard<std::mutex> lock(mutex_);
  const pose_history::Samples& samples = ring_->samples;
  if (samples.empty())
  {
    lookup.status = PoseLookupStatus::EMPTY;
    lookup.error = formatText("no pose of the camera is known yet for the image at %.3f s", secondsOf(stamp));
    return lookup;
  }
  lookup.oldest = samples.front().stamp;
  lookup.newest = samples.back().stamp;
  if (stamp < lookup.oldest)
  {
    lookup.status = PoseLookupStatus::TOO_OLD;
    lookup.error = formatText("the image at %.3f s is older than the camera's pose history (%.3f to %.3f s, at most "
                              "%g s)%s",
                              secondsOf(stamp), secondsOf(lookup.oldest), secondsOf(lookup.newest),
                              secondsOf(config_.window), stamp.count() == 0 ? ": its header has no stamp" : "");
    return lookup;
  }
  if (stamp > lookup.newest + config_.newer_tolerance)
  {
    lookup.status = PoseLookupStatus::TOO_NEW;
    lookup.error = formatText("the image at %.3f s is %.3f s newer than the camera's latest known pose (%.3f s; "
                              "tolerance %g s)",
                              secondsOf(stamp), secondsOf(stamp - lookup.newest), secondsOf(lookup.newest),
                              secondsOf(config_.newer_tolerance));
    return lookup;
  }
  lookup.status = stamp > lookup.newest ? PoseLookupStatus::HELD : PoseLookupStatus::INTERPOLATED;
  const auto at_or_after = std::lower_bound(samples.begin(), samples.end(), stamp, pose_history::stampBefore);
  for (const Axis axis : ALL_AXES)
  {
    lookup.pose[axis] = pose_history::axisAt(samples, at_or_after, axis, stamp, config_.newer_tolerance);
  }
  return lookup;
}

std::size_t PoseHistory::size() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return ring_->samples.size();
}

void PoseHistory::clear()
{
  std::lock_guard<std::mutex> lock(mutex_);
  ring_->samples.clear();
}

}  // namespace ptz_action_server

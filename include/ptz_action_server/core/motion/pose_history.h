/**
 * \file
 * \brief The camera's recent poses keyed by image-header time, to know where it looked when an image was taken.
 */
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief A time on the clock that stamps image headers: nanoseconds since that clock's epoch.
 *
 * The ROS layer converts with `HeaderStamp(static_cast<std::int64_t>(stamp.toNSec()))`: wall time, or simulated time
 * under /use_sim_time, whatever ros::Time says. Not the core's SteadyClock: the two are never compared.
 */
using HeaderStamp = std::chrono::nanoseconds;

/// \p seconds since the header clock's epoch (as ros::Time::toSec() gives) as a HeaderStamp, to the nearest ns.
HeaderStamp headerStampFromSeconds(double seconds);
/// \p stamp in seconds, for messages.
double secondsOf(HeaderStamp stamp);

/// How PoseHistory::at() found a pose.
enum class PoseLookupStatus
{
  INTERPOLATED,  ///< between (or at) two samples: the pose is good
  HELD,          ///< newer than the newest sample within the tolerance: the newest sample's pose
  EMPTY,         ///< no sample yet
  TOO_OLD,       ///< older than the oldest sample held
  TOO_NEW,       ///< newer than the newest sample by more than the tolerance
};

/// The pose at a stamp, or why there is none.
struct PoseLookup
{
  PoseLookupStatus status = PoseLookupStatus::EMPTY;
  /// pan, tilt (rad), zoom (X) at the stamp; an axis is NaN where it is unknown (none of the samples around the stamp
  /// knows it), or everywhere when the lookup failed.
  AxisValues pose{};
  HeaderStamp oldest{};  ///< the history's span at the lookup (zero when empty)
  HeaderStamp newest{};
  std::string error;  ///< "" when found; else the reason, naming the stamp and the span, for a goal's rejection

  bool found() const
  {
    return status == PoseLookupStatus::INTERPOLATED || status == PoseLookupStatus::HELD;
  }
};

/// The limits of a PoseHistory.
struct PoseHistoryConfig
{
  /// Samples further than this behind the newest are forgotten.
  std::chrono::nanoseconds window = std::chrono::seconds(10);
  /// A stamp at most this much newer than the newest sample gets the newest pose (an image taken between two state
  /// samples); later ones are TOO_NEW.
  std::chrono::nanoseconds newer_tolerance = std::chrono::milliseconds(200);
  /// Samples held at most (allocated once, at construction): 10 s of 10 Hz ticks, a backend reporting at 100 Hz and a
  /// renderer at 30 Hz fit. A full ring forgets its oldest sample, narrowing the window.
  std::size_t capacity = 2048;
};

/**
 * \brief A bounded history of the camera's pose (pan, tilt, zoom; any axis may be NaN: unknown) keyed by HeaderStamp.
 *
 * Fed by every state sample the node takes (the 10 Hz ticks and the backend's own reports) and by the simulated
 * camera's renderer (the exact pose it drew), possibly from several threads and out of order: a sample goes to its
 * place by stamp; one with the stamp of a sample held is merged into it (its known axes replace the held ones). It
 * keeps the samples of the last window behind the newest, in a ring allocated once, so adding never allocates.
 *
 * at() interpolates each axis linearly between the nearest samples before and after the stamp that know the axis
 * (pan along the shorter way round, so a pose history across +-pi stays right).
 *
 * A sample more than a window older than the newest is not kept (a stale state sample of a device gone silent looks
 * like that), so when the header clock goes back (a bag played again, a simulator restarted) the ROS layer must call
 * clear(): until then every new sample is refused as TOO_OLD.
 *
 * Thread-safe: every method takes one mutex, briefly.
 */
class PoseHistory
{
public:
  /// Throws ConfigError unless the window is positive, the tolerance not negative and the capacity at least 2.
  explicit PoseHistory(const PoseHistoryConfig& config = PoseHistoryConfig());
  ~PoseHistory();
  PoseHistory(const PoseHistory&) = delete;
  PoseHistory& operator=(const PoseHistory&) = delete;

  /// What add() did with a sample.
  enum class Added
  {
    KEPT,     ///< held in its place
    MERGED,   ///< into the sample of the same stamp
    TOO_OLD,  ///< not held: more than a window older than the newest sample
    DROPPED,  ///< not held: the ring is full of newer samples
  };

  /// Records \p pose (pan, tilt in rad, zoom in X; NaN: unknown) at \p stamp. Never allocates.
  Added add(HeaderStamp stamp, const AxisValues& pose);

  /// The pose at \p stamp: see PoseLookupStatus.
  PoseLookup at(HeaderStamp stamp) const;

  /// Samples held.
  std::size_t size() const;
  /// Forgets every sample (the header clock jumped: the ROS layer may call it on a time reset).
  void clear();

  const PoseHistoryConfig& config() const
  {
    return config_;
  }

private:
  struct Ring;

  /// Drops the samples more than a window behind the newest. Called with the mutex held.
  void trim();

  const PoseHistoryConfig config_;
  mutable std::mutex mutex_;
  std::unique_ptr<Ring> ring_;  ///< oldest first
};

}  // namespace ptz_action_server

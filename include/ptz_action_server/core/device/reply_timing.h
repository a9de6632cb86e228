/**
 * \file
 * \brief The reply deadline of a device that answers requests, learnt from how long its answers take.
 */
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <vector>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/counter.h"

namespace ptz_action_server
{
/**
 * \brief How long a device may take to answer a request, learnt from the answers it gives.
 *
 * The deadline starts at its floor (the configured reply timeout, or the exchange's wire time plus 100 ms) and is
 * never shorter. Each answer's time (from when the device could start on the request to its answer) is kept for the
 * latest ANSWERS answers (some seconds of polling), and the deadline is half again the longest of them, at most the
 * ceiling (twice the floor): a PTZOptics G2 whose position answers take 88 to 123 ms gets 185 ms, a device that
 * answers in 5 ms keeps the floor. The deadline falls back once the slow answers have left the window. An answer later
 * than the ceiling is never taken (TransactionChannel drops it), so it teaches nothing: the ceiling is the most a
 * device may take.
 *
 * Learning runs on the I/O thread; deadline(), typical() and diagnostics() may be read from any thread.
 */
class ReplyTiming
{
public:
  static constexpr std::size_t ANSWERS = 256;  ///< answers the deadline is learnt from (the latest)
  static constexpr double MARGIN = 1.5;        ///< the deadline over the longest of them
  static constexpr double CEILING = 2.0;       ///< the ceiling over the floor

  /// \p floor s: where the deadline starts and the least it may be.
  explicit ReplyTiming(double floor);

  double floor() const
  {
    return floor_;
  }
  double ceiling() const
  {
    return ceiling_;
  }
  /// The deadline now (s). Any thread.
  double deadline() const
  {
    return deadline_.load(std::memory_order_relaxed);
  }
  /// The median of the latest answer times (s; 0 before the first). Any thread.
  double typical() const
  {
    return median_.load(std::memory_order_relaxed);
  }
  /// The longest of the latest answer times (s; 0 before the first). Any thread.
  double longest() const
  {
    return longest_.load(std::memory_order_relaxed);
  }
  std::uint64_t answers() const
  {
    return answers_;
  }

  /// An answer took \p seconds (I/O thread). True if the deadline changed.
  bool answered(double seconds);
  /// The deadline, its bounds and the latest answer times, for diagnostics. Any thread.
  void diagnostics(std::vector<DiagnosticValue>& values) const;

private:
  const double floor_;
  const double ceiling_;
  std::array<double, ANSWERS> latest_{};  ///< I/O thread: a ring of the latest answer times
  std::size_t next_ = 0;                  ///< where the next answer time goes in latest_
  Counter answers_;
  std::atomic<double> deadline_;
  std::atomic<double> median_{ 0.0 };
  std::atomic<double> longest_{ 0.0 };
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief What each part of the 10 Hz state tick costs: the instrumented mode ptz_bench reads (off in the node).
 */
#pragma once

#include <time.h>

#include <atomic>
#include <cstdint>

namespace ptz_action_server
{
/**
 * \brief CPU time of the state tick's parts on the tick's thread, summed over the ticks, and the messages each sent.
 *
 * Plain atomics, so it may live in memory shared with another process (ptz_bench's counters). Nothing is measured
 * until \c enabled is set; the tick then reads the thread's CPU clock between its parts, so what the bench reads is the
 * tick's own work (building, serialising, roscpp's lookup and hand-over to its poll thread), not roscpp's poll thread
 * writing the messages to the sockets, which the bench shows as the other threads' CPU.
 */
struct TickCosts
{
  enum Part
  {
    SAMPLE,         ///< the backend's sample and the supervisor's mode
    STATE,          ///< ptz_state
    JOINT_STATES,   ///< joint_states
    TF,             ///< the pan and tilt transforms on /tf
    FIELD_OF_VIEW,  ///< field_of_view
    DIAGNOSTICS,    ///< the diagnostics updater (its check every tick, its 1 Hz status)
    STATUS_LISTS,   ///< the action servers' goal status lists (actionlib_status_frequency)
    HAND_OVER,      ///< the sample to the main queue while a goal is active
    PARTS
  };

  std::atomic<bool> enabled{ false };
  std::atomic<std::int64_t> tick_thread{ 0 };  ///< the tick thread's id (gettid), once a tick was measured
  std::atomic<std::uint64_t> ticks{ 0 };       ///< measured ticks
  std::atomic<std::uint64_t> nanoseconds[PARTS] = {};
  std::atomic<std::uint64_t> messages[PARTS] = {};  ///< messages the part sent (to a listener; tf: one per /tf message)

  /// Clears the sums (not \c enabled).
  void clear()
  {
    ticks = 0;
    for (int part = 0; part < PARTS; ++part)
    {
      nanoseconds[part] = 0;
      messages[part] = 0;
    }
  }
};

/// Adds the CPU time of the calling thread since the last lap() to each part in turn; does nothing with \p costs null
/// or not enabled.
class TickCostMeter
{
public:
  explicit TickCostMeter(TickCosts* costs) : costs_(costs != nullptr && costs->enabled ? costs : nullptr)
  {
    if (costs_)
    {
      last_ = threadNanoseconds();
    }
  }

  bool active() const
  {
    return costs_ != nullptr;
  }

  /// Charges the time since the last lap to \p part.
  void lap(TickCosts::Part part)
  {
    if (costs_)
    {
      const std::int64_t now = threadNanoseconds();
      costs_->nanoseconds[part] += static_cast<std::uint64_t>(now - last_);
      last_ = now;
    }
  }

  /// Counts \p count messages sent by \p part.
  void sent(TickCosts::Part part, std::uint64_t count = 1)
  {
    if (costs_ && count > 0)
    {
      costs_->messages[part] += count;
    }
  }

private:
  static std::int64_t threadNanoseconds()
  {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<std::int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
  }

  TickCosts* const costs_;
  std::int64_t last_ = 0;
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief A diagnostics counter: bumped on a backend's I/O thread, read from any thread, copied as a snapshot.
 */
#pragma once

#include <atomic>
#include <cstdint>

namespace ptz_action_server
{
/**
 * \brief A monotonic event count that one thread increments and any thread reads without a lock.
 *
 * Copying reads the value, so a struct of Counters is a (per-field) snapshot for diagnostics and tests.
 */
class Counter
{
public:
  Counter() = default;
  Counter(const Counter& other) : value_(other.value())
  {
  }
  Counter& operator=(const Counter& other)
  {
    value_.store(other.value(), std::memory_order_relaxed);
    return *this;
  }

  Counter& operator++()
  {
    value_.fetch_add(1, std::memory_order_relaxed);
    return *this;
  }
  Counter& operator+=(std::uint64_t amount)
  {
    value_.fetch_add(amount, std::memory_order_relaxed);
    return *this;
  }

  /// Mirrors a count kept elsewhere (a parser's own tally).
  void set(std::uint64_t value)
  {
    value_.store(value, std::memory_order_relaxed);
  }

  std::uint64_t value() const
  {
    return value_.load(std::memory_order_relaxed);
  }
  operator std::uint64_t() const  // NOLINT: reads like the number it counts
  {
    return value();
  }

private:
  std::atomic<std::uint64_t> value_{ 0 };
};

}  // namespace ptz_action_server

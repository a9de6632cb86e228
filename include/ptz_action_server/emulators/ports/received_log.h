/**
 * \file
 * \brief What an emulator received, kept for tests and benchmarks to look at and wait on.
 */
#pragma once

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <vector>

namespace ptz_action_server
{
/// A bounded, thread-safe log of received items (commands, frames, datagrams, messages), oldest first.
template <class Item>
class ReceivedLog
{
public:
  explicit ReceivedLog(std::size_t capacity = 10000) : capacity_(capacity)
  {
  }

  /// Adds \p item; beyond the capacity the oldest go.
  void add(Item item)
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      items_.push_back(std::move(item));
      if (items_.size() > capacity_)
      {
        items_.pop_front();
      }
    }
    changed_.notify_all();
  }

  std::vector<Item> items() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::vector<Item>(items_.begin(), items_.end());
  }

  void clear()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    items_.clear();
  }

  /// Waits until an item satisfies \p predicate, or \p timeout s pass; true if one does.
  bool waitFor(const std::function<bool(const Item&)>& predicate, double timeout) const
  {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::duration<double>(timeout),
                             [&] { return std::any_of(items_.begin(), items_.end(), predicate); });
  }

  /// Waits until at least \p count items are logged, or \p timeout s pass.
  bool waitForCount(std::size_t count, double timeout) const
  {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::duration<double>(timeout), [&] { return items_.size() >= count; });
  }

private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::deque<Item> items_;
};

}  // namespace ptz_action_server

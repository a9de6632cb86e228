/**
 * \file
 * \brief What an emulator received, kept for tests and benchmarks to look at and wait on, and what it was to the
 * device (ClassifiedCommand: each emulator's classify()).
 */
#pragma once

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// What a received item was to the device, as its emulator classifies it (classify()): for the contract tests' checks
/// and the benchmarks' figures, which count a goal's commands and a cancel's stop.
struct ClassifiedCommand
{
  enum class Kind
  {
    MOVE,   ///< moves the device or says how it moves with a goal: a position, a velocity, the goal's speeds or mode
    STOP,   ///< a stop or halt
    QUERY,  ///< a state poll, a subscription, a state request, a question about the device
    OTHER,  ///< set-up, anything else
  };
  TimePoint at;  ///< when it arrived (its last byte)
  Kind kind = Kind::OTHER;
  std::string text;   ///< readable, for failure messages and the tests' expected frames
  bool aims = false;  ///< the command carries a pan it aims at (pan)
  double pan = 0.0;   ///< rad, the contract's sign (positive: clockwise seen from above)
  double wire = 0.0;  ///< s it took on the wire (a serial line's bytes at its baud rate; 0 on a network)
  /// rad/s a position move says the pan goes at (VISCA's VV, Pelco-D's, Axis' speed=, ...), as the device reads it;
  /// 0 where the command says none.
  double pan_speed = 0.0;
};

/// \p size bytes at \p data as upper-case hex pairs separated by spaces ("81 01 06 01 FF"), for
/// ClassifiedCommand::text.
inline std::string hexText(const std::uint8_t* data, std::size_t size)
{
  std::string text;
  for (std::size_t index = 0; index < size; ++index)
  {
    char digits[4];
    std::snprintf(digits, sizeof(digits), "%s%02X", text.empty() ? "" : " ", data[index]);
    text += digits;
  }
  return text;
}

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
        if (!classified_.empty())
        {
          classified_.pop_front();
        }
      }
    }
    changed_.notify_all();
  }

  std::vector<Item> items() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::vector<Item>(items_.begin(), items_.end());
  }

  /// Every item as \p classify (Item -> ClassifiedCommand, or std::nullopt to leave it out) sorts it, oldest first.
  /// Each item is classified once: the log keeps what \p classify gave (so it must give the same for the same item),
  /// and a benchmark that asks again and again while a device runs pays only for what came since.
  template <class Classify>
  std::vector<ClassifiedCommand> classified(Classify classify) const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    while (classified_.size() < items_.size())
    {
      classified_.push_back(classify(items_[classified_.size()]));
    }
    std::vector<ClassifiedCommand> commands;
    commands.reserve(classified_.size());
    for (const std::optional<ClassifiedCommand>& command : classified_)
    {
      if (command)
      {
        commands.push_back(*command);
      }
    }
    return commands;
  }

  void clear()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    items_.clear();
    classified_.clear();
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
  mutable std::deque<std::optional<ClassifiedCommand>> classified_;  ///< classified(): items_'s first ones
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief The ended goals of an action server's status list, each serialized once and kept until it expires.
 */
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <string_view>
#include <unordered_set>

namespace ptz_action_server
{
/**
 * \brief Ended goals, each as its serialized status entry, found by id, kept until an expiry time.
 *
 * actionlib's server keeps every goal in one list for status_list_timeout after its last handle went, scans that
 * list string by string for every goal that arrives, and the node copied it into every status list it published:
 * under a storm of 200 goals a second, 200 entries. An ended goal whose handles are gone cannot change any more, so
 * it moves here: its entry is serialized once, its id is found by hash, and its bytes go into every list as they are.
 *
 * A goal leaves at its expiry, or later: goals leave oldest first, so one waits for those added before it (their
 * expiry times differ by the moments their handles went). Not thread-safe: the caller's lock (the server's) guards it.
 */
class EndedGoalList
{
public:
  /// Adds the goal \p id, whose status entry serializes to \p bytes, until \p expires (s, on the caller's clock).
  void add(const std::string& id, std::string_view bytes, double expires);
  /// Drops, oldest first, the goals whose expiry is before \p now.
  void expire(double now);
  /// True if a goal of this id is in the list.
  bool contains(const std::string& id) const;
  /// Takes every goal of this id out of the list.
  void remove(const std::string& id);
  /// How many goals the list holds.
  std::size_t count() const
  {
    return goals_.size();
  }
  /// Every goal's serialized entry, oldest first, one after the other.
  std::string_view bytes() const
  {
    return std::string_view(buffer_).substr(front_);
  }

private:
  struct Goal
  {
    std::string id;
    double expires;
    std::size_t size;  ///< of its entry in buffer_
  };

  std::deque<Goal> goals_;  ///< oldest first
  std::string buffer_;      ///< the entries in goals_' order, from front_ on
  std::size_t front_ = 0;   ///< where the oldest goal's entry starts (the bytes before it have left)
  std::unordered_multiset<std::string> ids_;
};

}  // namespace ptz_action_server

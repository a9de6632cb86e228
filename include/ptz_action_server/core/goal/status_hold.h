/**
 * \file
 * \brief Holds goal status changes back for a moment after each new goal, so Python clients do not see a status of
 * a goal they have not finished sending (ros/actionlib#206).
 */
#pragma once

#include <deque>
#include <functional>
#include <utility>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Delays the status changes (accept, reject, result) that follow a new goal by a fixed hold, in order.
 *
 * rospy's SimpleActionClient stores the goal handle only when its send_goal() returns, after the goal is on the
 * wire; a status of that goal that arrives first is reported as "a goal handle that we're not tracking". Any status
 * message of the server, for any goal, lists the new goal (PENDING) and counts as such a status. So after each goal
 * arrives, every status change waits until the hold has passed; changes keep their order, and none is dropped. A
 * change made while nothing is held and no goal came within the hold runs at once.
 *
 * Not thread-safe: one thread (the node's main thread) calls everything.
 */
class StatusHold
{
public:
  using Change = std::function<void()>;

  /// \p hold in s; 0 turns holding off.
  explicit StatusHold(double hold) : hold_(hold)
  {
  }

  /// A goal arrived at \p now: changes made from now on wait until now + hold.
  void goalArrived(TimePoint now)
  {
    if (hold_ > 0.0)
    {
      hold_until_ = addSeconds(now, hold_);
    }
  }

  /// Runs \p change now, or queues it behind the held ones until the current hold has passed.
  void run(Change change, TimePoint now)
  {
    if (held_.empty() && now >= hold_until_)
    {
      change();
      return;
    }
    held_.emplace_back(hold_until_, std::move(change));
  }

  /// Runs the held changes whose time has come, in order; returns when the next one is due (TimePoint::max() if none).
  TimePoint release(TimePoint now)
  {
    while (!held_.empty() && held_.front().first <= now)
    {
      Change change = std::move(held_.front().second);
      held_.pop_front();
      change();
    }
    return held_.empty() ? TimePoint::max() : held_.front().first;
  }

  /// True while a change made at \p now would be held.
  bool holding(TimePoint now) const
  {
    return !held_.empty() || now < hold_until_;
  }

  std::size_t heldCount() const
  {
    return held_.size();
  }

private:
  const double hold_;
  TimePoint hold_until_{};
  std::deque<std::pair<TimePoint, Change>> held_;  ///< due times never decrease along the queue
};

}  // namespace ptz_action_server

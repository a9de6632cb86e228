#include "ptz_action_server/core/goal/ended_goal_list.h"

#include <utility>

namespace ptz_action_server
{
void EndedGoalList::add(const std::string& id, std::string_view bytes, double expires)
{
  goals_.push_back({ id, expires, bytes.size() });
  buffer_.append(bytes);
  ids_.insert(id);
}

void EndedGoalList::expire(double now)
{
  while (!goals_.empty() && goals_.front().expires < now)
  {
    front_ += goals_.front().size;
    ids_.erase(ids_.find(goals_.front().id));
    goals_.pop_front();
  }
  // The bytes that left are dropped once they are half the buffer: each byte moves at most once on average.
  if (goals_.empty())
  {
    buffer_.clear();
    front_ = 0;
  }
  else if (front_ > buffer_.size() / 2)
  {
    buffer_.erase(0, front_);
    front_ = 0;
  }
}

bool EndedGoalList::contains(const std::string& id) const
{
  return ids_.count(id) > 0;
}

void EndedGoalList::remove(const std::string& id)
{
  if (!contains(id))
  {
    return;
  }
  // Rare (a goal sent again with an id already used): the buffer is rebuilt without the goal's entries.
  std::string kept;
  kept.reserve(buffer_.size() - front_);
  std::size_t offset = front_;
  for (auto goal = goals_.begin(); goal != goals_.end();)
  {
    if (goal->id == id)
    {
      offset += goal->size;
      goal = goals_.erase(goal);
      continue;
    }
    kept.append(buffer_, offset, goal->size);
    offset += goal->size;
    ++goal;
  }
  buffer_ = std::move(kept);
  front_ = 0;
  ids_.erase(id);
}

}  // namespace ptz_action_server

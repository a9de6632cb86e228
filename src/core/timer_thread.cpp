#include "ptz_action_server/core/timer_thread.h"

#include <utility>

#include "ptz_action_server/core/process_shared.h"

namespace ptz_action_server
{
std::shared_ptr<TimerThread> TimerThread::shared()
{
  return processShared<TimerThread>();
}

TimerThread::TimerThread() : thread_([this] { run(); })
{
}

TimerThread::TimerThread(std::function<void()> wake) : wake_(std::move(wake))
{
}

TimerThread::~TimerThread()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (!thread_.joinable())
  {
    return;  // a schedule its owner runs
  }
  if (thread_.get_id() == std::this_thread::get_id())
  {
    thread_.detach();  // the last holder let go inside a work: the thread ends on its own once that returns
  }
  else
  {
    thread_.join();
  }
}

TimerThread::Id TimerThread::every(Clock::duration period, Clock::time_point first, std::function<void()> work)
{
  Id id = 0;
  bool earlier = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    id = next_id_++;
    Entry& entry = entries_[id];
    entry.work = std::move(work);
    entry.period = period;
    entry.due = first;
    entry.slot = due_.end();
    earlier = mustWake(arm(id, entry));
  }
  if (earlier)
  {
    wake_();
  }
  return id;
}

TimerThread::Id TimerThread::at(Clock::time_point when, std::function<void()> work)
{
  return every(Clock::duration::zero(), when, std::move(work));
}

void TimerThread::move(Id id, Clock::time_point when)
{
  bool earlier = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = entries_.find(id);
    if (found == entries_.end())
    {
      return;
    }
    disarm(found->second);
    found->second.due = when;
    if (running_ != id)  // a running one is armed again when its run ends
    {
      earlier = mustWake(arm(id, found->second));
    }
  }
  if (earlier)
  {
    wake_();
  }
}

void TimerThread::cancel(Id id)
{
  std::unique_lock<std::mutex> lock(mutex_);
  const auto found = entries_.find(id);
  if (found != entries_.end())
  {
    disarm(found->second);
    entries_.erase(found);  // run() holds its own copy of the work while it runs
  }
  if (std::this_thread::get_id() != runner_)
  {
    ran_.wait(lock, [this, id] { return running_ != id; });
  }
}

std::size_t TimerThread::size() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

bool TimerThread::arm(Id id, Entry& entry)
{
  if (entry.due == Clock::time_point::max())
  {
    return false;
  }
  const bool earliest = due_.empty() || entry.due < due_.begin()->first;
  entry.slot = due_.emplace(entry.due, id);
  if (earliest)
  {
    changed_.notify_one();
  }
  return earliest;
}

bool TimerThread::mustWake(bool earliest) const
{
  // The owner's thread looks at the schedule again after each thing it does: only another thread must wake it.
  return earliest && wake_ && std::this_thread::get_id() != runner_;
}

void TimerThread::disarm(Entry& entry)
{
  if (entry.slot != due_.end())
  {
    due_.erase(entry.slot);
    entry.slot = due_.end();
  }
}

void TimerThread::run()
{
  std::unique_lock<std::mutex> lock(mutex_);
  runner_ = std::this_thread::get_id();
  while (!stopping_)
  {
    if (due_.empty())
    {
      changed_.wait(lock);
      continue;
    }
    const Clock::time_point next = due_.begin()->first;
    if (Clock::now() < next)
    {
      changed_.wait_until(lock, next);
      continue;
    }
    runFirst(lock);
  }
}

TimerThread::Clock::time_point TimerThread::runDue()
{
  std::unique_lock<std::mutex> lock(mutex_);
  runner_ = std::this_thread::get_id();
  while (!stopping_ && !due_.empty() && due_.begin()->first <= Clock::now())
  {
    runFirst(lock);
  }
  return due_.empty() ? Clock::time_point::max() : due_.begin()->first;
}

void TimerThread::runFirst(std::unique_lock<std::mutex>& lock)
{
  const Id id = due_.begin()->second;
  due_.erase(due_.begin());
  Entry& entry = entries_.at(id);
  entry.slot = due_.end();
  const Clock::time_point was_due = entry.due;
  std::function<void()> work = entry.work;  // a cancel during the run erases the entry, not this copy
  running_ = id;
  lock.unlock();
  work();
  lock.lock();
  running_ = 0;
  ran_.notify_all();
  const auto found = entries_.find(id);
  if (found == entries_.end())
  {
    return;  // cancelled while it ran
  }
  Entry& after = found->second;
  if (after.period > Clock::duration::zero())
  {
    after.due = was_due + after.period;
    const Clock::time_point now = Clock::now();
    if (after.due <= now)  // fell a whole period behind: skip to the next due time of the same phase
    {
      after.due += ((now - after.due) / after.period + 1) * after.period;
    }
    arm(id, after);
  }
  else if (after.due != was_due)  // moved while it ran
  {
    arm(id, after);
  }
  else
  {
    after.due = Clock::time_point::max();
  }
}

}  // namespace ptz_action_server

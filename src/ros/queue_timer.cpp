#include "ptz_action_server/ros/queue_timer.h"

#include <map>
#include <utility>

#include <boost/make_shared.hpp>

namespace ptz_action_server
{
namespace
{
TimerThread::Clock::duration toDuration(double seconds)
{
  return std::chrono::duration_cast<TimerThread::Clock::duration>(std::chrono::duration<double>(seconds));
}

/// The queues whose spinning thread runs their timers (QueueTimer::scheduleOn()).
struct QueueSchedules
{
  std::mutex mutex;
  std::map<ros::CallbackQueueInterface*, std::shared_ptr<TimerThread>> schedules;
};

QueueSchedules& queueSchedules()
{
  static QueueSchedules schedules;
  return schedules;
}
}  // namespace

void QueueTimer::scheduleOn(ros::CallbackQueueInterface* queue, std::shared_ptr<TimerThread> schedule)
{
  QueueSchedules& schedules = queueSchedules();
  std::lock_guard<std::mutex> lock(schedules.mutex);
  if (schedule)
  {
    schedules.schedules[queue] = std::move(schedule);
  }
  else
  {
    schedules.schedules.erase(queue);
  }
}

std::shared_ptr<TimerThread> QueueTimer::scheduleFor(ros::CallbackQueueInterface* queue)
{
  {
    QueueSchedules& schedules = queueSchedules();
    std::lock_guard<std::mutex> lock(schedules.mutex);
    const auto found = schedules.schedules.find(queue);
    if (found != schedules.schedules.end())
    {
      return found->second;
    }
  }
  return TimerThread::shared();
}

class QueueTimer::QueuedCall : public ros::CallbackInterface
{
public:
  explicit QueuedCall(QueueTimer& timer) : timer_(timer)
  {
  }
  CallResult call() override
  {
    timer_.run();
    return Success;
  }

private:
  QueueTimer& timer_;
};

QueueTimer::QueueTimer(ros::CallbackQueueInterface* queue, std::function<void()> callback)
  : queue_(queue)
  , callback_(std::move(callback))
  , timer_(scheduleFor(queue))
  , queued_call_(boost::make_shared<QueuedCall>(*this))
  , id_(timer_->at(TimePoint::max(), [this] { fire(); }))
{
}

QueueTimer::~QueueTimer()
{
  timer_->cancel(id_);  // once it returns, nothing more is queued
  // What was queued goes; a call running on another thread is waited for.
  queue_->removeByID(reinterpret_cast<uint64_t>(this));
}

void QueueTimer::startOnce(double delay)
{
  start(TimerThread::Clock::now() + toDuration(delay), TimerThread::Clock::duration::zero());
}

void QueueTimer::startPeriodic(double period)
{
  const TimerThread::Clock::duration step = toDuration(period);
  start(TimerThread::Clock::now() + step, step);
}

void QueueTimer::startAt(TimePoint when)
{
  start(when, TimerThread::Clock::duration::zero());
}

void QueueTimer::stop()
{
  startAt(TimePoint::max());
}

void QueueTimer::start(TimePoint first, TimerThread::Clock::duration period)
{
  std::lock_guard<std::mutex> lock(mutex_);  // the timer thread's deadline changes with due_, never apart from it
  ++generation_;                             // a call already queued no longer runs
  due_ = first;
  period_ = period;
  timer_->move(id_, first);
}

void QueueTimer::fire()
{
  bool add_call = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const TimePoint now = TimerThread::Clock::now();
    if (due_ > now)
    {
      return;  // stopped or moved while the timer thread was taking it: the new deadline is armed
    }
    add_call = !queued_;  // one waiting call at most; a waiting one of an earlier start runs as this one
    queued_ = true;
    queued_generation_ = generation_;
    TimePoint next = TimePoint::max();
    if (period_ > TimerThread::Clock::duration::zero())
    {
      // The phase is kept: the next run is due a whole number of periods after the first.
      next = due_ + period_;
      if (next <= now)
      {
        next += ((now - next) / period_ + 1) * period_;
      }
    }
    due_ = next;
    timer_->move(id_, next);
  }
  if (add_call)
  {
    queue_->addCallback(queued_call_, reinterpret_cast<uint64_t>(this));
  }
}

void QueueTimer::run()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queued_ = false;
    if (queued_generation_ != generation_)
    {
      return;  // stopped or started again since it was queued
    }
  }
  callback_();  // may start or stop this timer (or destroy it): nothing of it is touched after
}

}  // namespace ptz_action_server

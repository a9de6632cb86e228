/**
 * \file
 * \brief A timer whose callback runs on a ROS callback queue, driven by the process's TimerThread.
 */
#pragma once

#include <functional>
#include <memory>
#include <mutex>

#include <boost/shared_ptr.hpp>
#include <ros/callback_queue_interface.h>

#include "ptz_action_server/core/timer_thread.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief What NodeHandle::createSteadyTimer() gives (the callback on the node handle's queue, one-shot or periodic),
 * without roscpp's steady timer thread: that thread, once the first steady timer exists, wakes ten times a second for
 * as long as the process lives, timers or not. The process's TimerThread sleeps until a timer is due.
 *
 * The callback is fixed at construction, so starting and stopping allocate nothing (the status release is armed on
 * every goal of a storm). As with roscpp's timers, at most one call waits in the queue: a periodic timer whose queue
 * falls behind skips runs, it does not bunch them. start*() and stop() from any thread; once stop() returns the
 * callback does not start any more. The destructor also waits for a call running on another thread.
 *
 * A queue whose spinning thread runs its timers itself (scheduleOn(), the executable's MainSpinner) gets its timers'
 * calls from that thread instead: no other thread wakes for them.
 */
class QueueTimer
{
public:
  /// \p callback runs on \p queue (the node handle's), which must outlive the timer.
  QueueTimer(ros::CallbackQueueInterface* queue, std::function<void()> callback);

  /// Timers made from now on for \p queue are run by \p schedule (a TimerThread without a thread of its own, run by
  /// the thread that spins the queue) instead of the process's TimerThread; nullptr ends it for timers made after.
  static void scheduleOn(ros::CallbackQueueInterface* queue, std::shared_ptr<TimerThread> schedule);
  ~QueueTimer();
  QueueTimer(const QueueTimer&) = delete;
  QueueTimer& operator=(const QueueTimer&) = delete;

  /// Runs the callback once, \p delay s from now, replacing whatever was set.
  void startOnce(double delay);
  /// Runs the callback every \p period s, the first time one period from now, replacing whatever was set.
  void startPeriodic(double period);
  /// Runs the callback once at \p when (TimePoint::max(): never, as stop()), replacing whatever was set.
  void startAt(TimePoint when);
  void stop();

private:
  class QueuedCall;

  /// The schedule of \p queue's timers: the one scheduleOn() gave it, else the process's TimerThread.
  static std::shared_ptr<TimerThread> scheduleFor(ros::CallbackQueueInterface* queue);

  void start(TimePoint first, TimerThread::Clock::duration period);
  /// On the timer thread: puts the call in the queue (unless one waits there) and arms the next period.
  void fire();
  /// On the queue's thread: the queued call, unless stopped or started again since it was queued.
  void run();

  ros::CallbackQueueInterface* const queue_;
  const std::function<void()> callback_;
  const std::shared_ptr<TimerThread> timer_;
  boost::shared_ptr<QueuedCall> queued_call_;  ///< the one queue entry, added again for each run

  std::mutex mutex_;
  TimePoint due_ = TimePoint::max();          ///< the next run, max() while stopped
  TimerThread::Clock::duration period_{ 0 };  ///< 0: one-shot
  unsigned generation_ = 0;                   ///< counts start*() and stop()
  unsigned queued_generation_ = 0;            ///< generation_ when the waiting call was queued
  bool queued_ = false;                       ///< a call waits in the queue
  TimerThread::Id id_ = 0;                    ///< last: set once everything above exists
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief One thread for the timed work of every camera in a process: the 10 Hz state ticks, each at its own phase,
 * and deadlines that move (the simulated device's next event).
 *
 * A process with 64 cameras in one nodelet manager would otherwise run 64 timers through roscpp's timer manager
 * (whose cost grows with the timers of the process) and wake 64 spinner threads ten times a second. Here one thread
 * sleeps until the earliest deadline of all and runs what is due in place.
 *
 * The same schedule may instead be run by a thread its owner already has (TimerThread(wake) and runDue()): the
 * ptz_action_server executable's main thread runs the timers of its own queue between callbacks, so a timer that
 * puts a call in that queue (the status release after every goal of a storm) wakes one thread, not two.
 */
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>

namespace ptz_action_server
{
class TimerThread
{
public:
  using Clock = std::chrono::steady_clock;
  using Id = std::uint64_t;

  /// The process's timer thread, started by the first caller; it stops once the last holder lets go.
  static std::shared_ptr<TimerThread> shared();

  TimerThread();
  /**
   * \brief A schedule without a thread of its own: the owner's thread calls runDue() and sleeps until the time it
   * returns. \p wake is called (without the schedule's lock) when another thread arms a deadline earlier than the
   * earliest one, so that the owner's thread stops sleeping and calls runDue() again.
   */
  explicit TimerThread(std::function<void()> wake);
  /// Stops and joins the thread. Work still scheduled is dropped without running.
  ~TimerThread();
  TimerThread(const TimerThread&) = delete;
  TimerThread& operator=(const TimerThread&) = delete;

  /**
   * \brief Runs \p work every \p period, the first time at \p first. The phase is kept: the n-th run is due at
   * first + n * period, and a run that falls a whole period behind (a stalled machine) is skipped, not bunched.
   */
  Id every(Clock::duration period, Clock::time_point first, std::function<void()> work);
  /// Runs \p work once at \p when; Clock::time_point::max() keeps it unarmed until moved.
  Id at(Clock::time_point when, std::function<void()> work);
  /// Moves the deadline of a one-shot (armed or not; one that has run is armed again).
  void move(Id id, Clock::time_point when);
  /**
   * \brief Removes \p id. Once it returns, its work does not run and is not running, unless cancel() is called
   * from that work itself (it then finishes the run it is in, and never runs again).
   */
  void cancel(Id id);
  /// How many works are scheduled (for tests and diagnostics).
  std::size_t size() const;

  /// A schedule without a thread (TimerThread(wake)): runs the works that are due, from the owner's thread, and
  /// returns when the next one is due (Clock::time_point::max() if none is armed).
  Clock::time_point runDue();

private:
  struct Entry
  {
    std::function<void()> work;
    Clock::duration period{ 0 };  ///< 0: a one-shot
    Clock::time_point due = Clock::time_point::max();
    std::multimap<Clock::time_point, Id>::iterator slot;  ///< in due_, or due_.end() while unarmed or running
  };

  void run();
  /// Runs the earliest work, due by now. Call with \p lock (of mutex_) held; it is released while the work runs.
  void runFirst(std::unique_lock<std::mutex>& lock);
  /// Puts \p entry in the schedule at its due time; returns true if it is now the earliest. Call with mutex_ held.
  bool arm(Id id, Entry& entry);
  /// True if wake_ must be called (once mutex_ is released) after an arm() that returned \p earliest. With mutex_.
  bool mustWake(bool earliest) const;
  /// Takes \p entry out of the schedule. Call with mutex_ held.
  void disarm(Entry& entry);

  mutable std::mutex mutex_;
  std::condition_variable changed_;  ///< an earlier deadline, a cancel or the stop (with mutex_)
  std::condition_variable ran_;      ///< a run ended (with mutex_), for cancel() waiting on it
  std::unordered_map<Id, Entry> entries_;
  std::multimap<Clock::time_point, Id> due_;
  Id next_id_ = 1;
  Id running_ = 0;  ///< the work running now, 0 if none
  bool stopping_ = false;
  const std::function<void()> wake_;  ///< set: no thread, the owner runs runDue()
  std::thread::id runner_;            ///< the thread that runs the works (with mutex_)
  std::thread thread_;                ///< last: starts once everything above exists (none with wake_)
};

}  // namespace ptz_action_server

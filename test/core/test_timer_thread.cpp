#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "ptz_action_server/core/timer_thread.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using std::chrono::milliseconds;
using Clock = TimerThread::Clock;

/// A gate a work blocks on until the test opens it.
class Gate
{
public:
  void open()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    open_ = true;
    changed_.notify_all();
  }
  void pass()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    entered_ = true;
    changed_.notify_all();
    changed_.wait(lock, [this] { return open_; });
  }
  bool entered() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return entered_;
  }

private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool open_ = false;
  bool entered_ = false;
};

TEST(TimerThread, ATickKeepsItsPhaseAndNeverRunsEarly)
{
  TimerThread timer;
  std::mutex mutex;
  std::vector<Clock::time_point> runs;
  const Clock::duration period = milliseconds(20);
  const Clock::time_point first = Clock::now() + milliseconds(30);
  const TimerThread::Id id = timer.every(period, first, [&] {
    std::lock_guard<std::mutex> lock(mutex);
    runs.push_back(Clock::now());
  });
  ASSERT_TRUE(waitUntil(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return runs.size() >= 10;
      },
      30.0));
  timer.cancel(id);
  std::lock_guard<std::mutex> lock(mutex);
  for (std::size_t index = 0; index < runs.size(); ++index)
  {
    // Each run at or after its own due time: the phase is first + n * period, whatever the lateness of the others.
    EXPECT_GE(runs[index], first + static_cast<int>(index) * period) << "run " << index;
  }
}

TEST(TimerThread, TicksOfManyOwnersEachRunAtTheirOwnRate)
{
  TimerThread timer;
  constexpr int OWNERS = 16;
  std::vector<std::atomic<int>> counts(OWNERS);
  std::vector<TimerThread::Id> ids;
  const Clock::time_point start = Clock::now();
  for (int owner = 0; owner < OWNERS; ++owner)
  {
    ids.push_back(timer.every(milliseconds(10), start + milliseconds(owner), [&counts, owner] { ++counts[owner]; }));
  }
  EXPECT_EQ(timer.size(), static_cast<std::size_t>(OWNERS));
  ASSERT_TRUE(waitUntil(
      [&] {
        for (const auto& count : counts)
        {
          if (count < 5)
          {
            return false;
          }
        }
        return true;
      },
      30.0));
  for (TimerThread::Id id : ids)
  {
    timer.cancel(id);
  }
  EXPECT_EQ(timer.size(), 0u);
}

TEST(TimerThread, ACancelledWorkNeverRunsAgain)
{
  TimerThread timer;
  std::atomic<int> cancelled_runs{ 0 };
  std::atomic<int> other_runs{ 0 };
  const TimerThread::Id cancelled = timer.every(milliseconds(5), Clock::now(), [&] { ++cancelled_runs; });
  ASSERT_TRUE(waitUntil([&] { return cancelled_runs >= 2; }, 30.0));
  timer.cancel(cancelled);
  const int after_cancel = cancelled_runs;
  timer.every(milliseconds(5), Clock::now(), [&] { ++other_runs; });
  ASSERT_TRUE(waitUntil([&] { return other_runs >= 10; }, 30.0));  // ten of its periods later
  EXPECT_EQ(cancelled_runs, after_cancel);
}

TEST(TimerThread, AOneShotWaitsUnarmedUntilMovedAndRunsOncePerMove)
{
  TimerThread timer;
  std::atomic<int> runs{ 0 };
  std::atomic<int> clock_runs{ 0 };
  const TimerThread::Id id = timer.at(Clock::time_point::max(), [&] { ++runs; });
  timer.every(milliseconds(5), Clock::now(), [&] { ++clock_runs; });
  ASSERT_TRUE(waitUntil([&] { return clock_runs >= 5; }, 30.0));
  EXPECT_EQ(runs, 0);
  timer.move(id, Clock::now() + milliseconds(5));
  ASSERT_TRUE(waitUntil([&] { return runs == 1; }, 30.0));
  const int clock_then = clock_runs;
  ASSERT_TRUE(waitUntil([&] { return clock_runs >= clock_then + 5; }, 30.0));
  EXPECT_EQ(runs, 1);
  timer.move(id, Clock::now());
  ASSERT_TRUE(waitUntil([&] { return runs == 2; }, 30.0));
  timer.move(id, Clock::now() + std::chrono::hours(1));  // moved later again: does not run now
  const int clock_later = clock_runs;
  ASSERT_TRUE(waitUntil([&] { return clock_runs >= clock_later + 5; }, 30.0));
  EXPECT_EQ(runs, 2);
}

TEST(TimerThread, CancelWaitsForTheRunInProgress)
{
  TimerThread timer;
  Gate gate;
  std::atomic<bool> finished{ false };
  const TimerThread::Id id = timer.at(Clock::now(), [&] {
    gate.pass();
    finished = true;
  });
  ASSERT_TRUE(waitUntil([&] { return gate.entered(); }, 30.0));
  std::atomic<bool> cancel_returned{ false };
  std::thread canceller([&] {
    timer.cancel(id);
    cancel_returned = true;
  });
  // cancel() is blocked while the work runs: its return would come before `finished`.
  EXPECT_FALSE(waitUntil([&] { return cancel_returned.load(); }, 0.2));
  gate.open();
  canceller.join();
  EXPECT_TRUE(finished);
  EXPECT_TRUE(cancel_returned);
}

TEST(TimerThread, AWorkMayCancelItselfAndTheTimerKeepsRunning)
{
  TimerThread timer;
  std::atomic<int> runs{ 0 };
  TimerThread::Id id = 0;
  std::mutex mutex;
  std::unique_lock<std::mutex> hold(mutex);  // the work waits until its id is known
  id = timer.every(milliseconds(5), Clock::now(), [&] {
    std::lock_guard<std::mutex> lock(mutex);
    ++runs;
    timer.cancel(id);
  });
  hold.unlock();
  std::atomic<int> other_runs{ 0 };
  timer.every(milliseconds(5), Clock::now(), [&] { ++other_runs; });
  ASSERT_TRUE(waitUntil([&] { return other_runs >= 10; }, 30.0));
  EXPECT_EQ(runs, 1);
}

TEST(TimerThread, ATickThatFellBehindSkipsToItsNextDueTimeInsteadOfBunching)
{
  TimerThread timer;
  Gate gate;
  std::mutex mutex;
  std::vector<Clock::time_point> runs;
  const Clock::duration period = milliseconds(10);
  const Clock::time_point first = Clock::now();
  const TimerThread::Id id = timer.every(period, first, [&] {
    bool block = false;
    {
      std::lock_guard<std::mutex> lock(mutex);
      runs.push_back(Clock::now());
      block = runs.size() == 1;
    }
    if (block)
    {
      gate.pass();  // the machine stalls for many periods in the first run
    }
  });
  ASSERT_TRUE(waitUntil([&] { return gate.entered(); }, 30.0));
  ASSERT_TRUE(waitUntil([&] { return Clock::now() > first + 10 * period; }, 30.0));
  const Clock::time_point released = Clock::now();
  gate.open();
  ASSERT_TRUE(waitUntil(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return runs.size() >= 4;
      },
      30.0));
  timer.cancel(id);
  std::lock_guard<std::mutex> lock(mutex);
  // After the stall the missed runs are skipped: the next one is due after the release, and the one after it a whole
  // period later (bunched, they would all come at the release).
  EXPECT_GT(runs[1], released);
  EXPECT_GT(runs[2], released + period);
  EXPECT_GT(runs[3], released + 2 * period);
}

TEST(TimerThread, AScheduleItsOwnerRunsRunsOnlyWhatIsDueOnTheOwnersThread)
{
  std::atomic<int> wakes{ 0 };
  TimerThread schedule([&] { ++wakes; });
  std::vector<std::thread::id> ran_on;
  EXPECT_EQ(schedule.runDue(), Clock::time_point::max());  // empty; this thread is now the one that runs it
  const Clock::time_point later = Clock::now() + std::chrono::hours(1);
  schedule.at(later, [&] { ran_on.push_back(std::this_thread::get_id()); });
  EXPECT_EQ(schedule.runDue(), later);  // nothing due: the next deadline
  EXPECT_TRUE(ran_on.empty());

  const TimerThread::Id soon = schedule.at(Clock::now(), [&] { ran_on.push_back(std::this_thread::get_id()); });
  EXPECT_EQ(wakes, 0);  // armed from the owner's own thread: it looks at the schedule again by itself
  EXPECT_EQ(schedule.runDue(), later);
  ASSERT_EQ(ran_on.size(), 1u);
  EXPECT_EQ(ran_on[0], std::this_thread::get_id());
  EXPECT_EQ(schedule.runDue(), later);  // a one-shot runs once per arming
  EXPECT_EQ(ran_on.size(), 1u);

  // Armed earlier than the earliest from another thread: the owner is woken, once.
  std::thread([&] { schedule.move(soon, Clock::now()); }).join();
  EXPECT_EQ(wakes, 1);
  std::thread([&] { schedule.move(soon, Clock::now() + std::chrono::hours(2)); }).join();
  EXPECT_EQ(wakes, 1);  // not the earliest: no wake
  EXPECT_EQ(schedule.runDue(), later);
  EXPECT_EQ(ran_on.size(), 1u);  // moved away before it ran
}

TEST(TimerThread, AScheduleItsOwnerRunsKeepsATicksPhaseAndCancelWaitsForItsRun)
{
  TimerThread schedule([] {});
  std::atomic<int> ticks{ 0 };
  Gate gate;
  const Clock::time_point first = Clock::now();
  const TimerThread::Id id = schedule.every(milliseconds(100), first, [&] {
    if (++ticks == 2)
    {
      gate.pass();
    }
  });
  EXPECT_EQ(schedule.runDue(), first + milliseconds(100));
  EXPECT_EQ(ticks, 1);

  // The owner's thread runs the second tick and blocks in it; a cancel from elsewhere waits for that run.
  std::thread owner([&] {
    while (ticks < 2)
    {
      const Clock::time_point next = schedule.runDue();
      if (ticks < 2)
      {
        std::this_thread::sleep_until(next);
      }
    }
  });
  ASSERT_TRUE(waitUntil([&] { return gate.entered(); }, 30.0));
  std::atomic<bool> cancel_returned{ false };
  std::thread canceller([&] {
    schedule.cancel(id);
    cancel_returned = true;
  });
  EXPECT_FALSE(waitUntil([&] { return cancel_returned.load(); }, 0.2));
  gate.open();
  canceller.join();
  owner.join();
  EXPECT_TRUE(cancel_returned);
  EXPECT_EQ(schedule.size(), 0u);
  EXPECT_EQ(schedule.runDue(), Clock::time_point::max());
  EXPECT_EQ(ticks, 2);
}

TEST(TimerThread, TheSharedThreadIsOneWhileHeldAndGoesWithTheLastHolder)
{
  std::shared_ptr<TimerThread> first = TimerThread::shared();
  std::shared_ptr<TimerThread> second = TimerThread::shared();
  EXPECT_EQ(first.get(), second.get());
  std::weak_ptr<TimerThread> watch = first;
  first.reset();
  second.reset();
  EXPECT_TRUE(watch.expired());
}

}  // namespace
}  // namespace ptz_action_server

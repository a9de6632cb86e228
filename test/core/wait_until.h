/**
 * \file
 * \brief Waiting on a condition with a deadline, for the tests that run real I/O threads.
 */
#pragma once

#include <chrono>
#include <functional>
#include <thread>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// Polls \p condition every \p step until it holds or \p timeout s pass; returns its last value. Not every 2 ms: four
/// test processes polling so often beside two busy `yes` starved the kernel's one tty worker (runnable, not run) for up
/// to 8 s, and with it every pseudo-terminal's bytes; at 10 ms it kept up (scripts/test's shards, doc/contributing.md).
inline bool waitUntil(const std::function<bool()>& condition, double timeout,
                      std::chrono::milliseconds step = std::chrono::milliseconds(10))
{
  const TimePoint deadline = addSeconds(SteadyClock::now(), timeout);
  while (SteadyClock::now() < deadline)
  {
    if (condition())
    {
      return true;
    }
    std::this_thread::sleep_for(step);
  }
  return condition();
}

}  // namespace ptz_action_server

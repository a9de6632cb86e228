/**
 * \file
 * \brief Unit conversions used across the codecs and backends: angles and durations.
 */
#pragma once

#include <chrono>
#include <cmath>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
constexpr double toDegrees(double radians)
{
  return radians * 180.0 / M_PI;
}

constexpr double toRadians(double degrees)
{
  return degrees * M_PI / 180.0;
}

/// Arc seconds (FLIR's resolution unit) to radians.
constexpr double arcSecondsToRadians(double arc_seconds)
{
  return toRadians(arc_seconds / 3600.0);
}

/// Fractional seconds as the steady clock's duration (for timers and deadlines).
inline SteadyClock::duration toDuration(double seconds)
{
  return std::chrono::duration_cast<SteadyClock::duration>(std::chrono::duration<double>(seconds));
}

}  // namespace ptz_action_server

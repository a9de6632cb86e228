/**
 * \file
 * \brief Checks a goal against the device's limits before anything moves.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// Goals this far outside a limit are taken as the limit itself: float32 goals cannot hold pi exactly.
constexpr double LIMIT_EPSILON = 1e-5;

/// The outcome of a validation: what to command, or why not.
struct ValidatedGoal
{
  bool accepted = false;
  AxisValues values{};  ///< the values to command (clamped where allowed); absent axes hold a neutral value
  bool clamped = false;
  std::string message;  ///< the rejection reason, or the clamping note when clamped; empty otherwise
};

/// Returns "" if every value is finite, else the reason naming the first axis that is NaN or Inf.
std::string findNonFinite(const AxisValues& values, const char* quantity);

/**
 * \brief Validates an absolute position goal (pan, tilt in rad, zoom as X) against \p limits.
 *
 * NaN or Inf anywhere rejects the goal. A value outside its range rejects it, or, with \p clamp, is clamped and
 * noted in the message. An absent axis (no zoom) is ignored and commanded at its range minimum.
 */
ValidatedGoal validatePositionGoal(const AxisValues& target, const Capabilities& limits, bool clamp);

/// Validates a velocity goal (rad/s, X/s) against each axis' max speed, with the same rules.
ValidatedGoal validateVelocityGoal(const AxisValues& velocity, const Capabilities& limits, bool clamp);

}  // namespace ptz_action_server

/**
 * \file
 * \brief The speed of a position goal: what the goal (or its preset) asks, the operator's default, and the device's
 * range, resolved into the speed each axis is moved at.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// What a position goal asks of its speed (move_ptz/position_abs_speed, a preset's speed); all 0: the default speed.
struct SpeedRequest
{
  double fraction = 0.0;  ///< of each axis' top speed, in (0, 1]; 0: the operator's default speed
  AxisValues rate{};      ///< rad/s, rad/s, X/s; > 0 overrides the fraction on that axis
};

/// A goal's speed resolved against the device: what PtzBackend::goToAtSpeed() is given.
struct ResolvedSpeed
{
  bool accepted = true;
  /// Per axis (rad/s, X/s); 0 where the axis moves at the device's own top speed, as a goal without a speed does.
  AxisValues speed{};
  /// Why the speed was refused; or what was changed to fit the device (clamped or raised), "; " between them.
  std::string message;
};

/// The operator's default speed when nobody set one: the device's top speed, as before speeds existed.
constexpr double FULL_SPEED = 1.0;

/// "" when \p fraction is a speed an operator may set as the default (in (0, 1]), else why not.
std::string checkDefaultSpeed(double fraction);

/**
 * \brief Resolves \p request against \p limits with the operator's \p default_fraction (in (0, 1]).
 *
 * A NaN, infinite or negative fraction or rate is refused. A fraction above 1 is taken as 1, noted. Each present
 * axis then moves at its rate if one is given, else at the fraction of its max_speed; a speed at or above max_speed
 * is the device's own (0: a rate above it is noted), one below the device's slowest (MoveSpeedCapability::min_speed)
 * is raised to it, noted.
 */
ResolvedSpeed resolveSpeed(const SpeedRequest& request, double default_fraction, const Capabilities& limits);

}  // namespace ptz_action_server

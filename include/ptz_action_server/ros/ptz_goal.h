/**
 * \file
 * \brief Building a Ptz goal in one expression, for clients, tests and benchmarks.
 */
#pragma once

#include "ptz_action_server/PtzAction.h"

namespace ptz_action_server
{
/// A Ptz goal: pan and tilt in rad (or rad/s), zoom as X-factor (or X/s).
inline PtzGoal makePtzGoal(double pan, double tilt, double zoom)
{
  PtzGoal goal;
  goal.pan = static_cast<float>(pan);
  goal.tilt = static_cast<float>(tilt);
  goal.zoom = static_cast<float>(zoom);
  return goal;
}

}  // namespace ptz_action_server

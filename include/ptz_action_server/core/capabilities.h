/**
 * \file
 * \brief Capabilities in words, for the node's start-up log, its diagnostics and ptz_move.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// What \p axis can do, in a few words: "position, velocity, feedback, [-3.1416, 3.1416] rad", or "none (the device
/// has no zoom)", or "velocity only (this camera reports no position: ...)".
std::string describeAxis(const Capabilities& capabilities, Axis axis);

/// The device's own extras: "relative moves, presets, home, centres and box-zooms in its own picture (VAPIX center,
/// areazoom)", or "none".
std::string describeExtras(const Capabilities& capabilities);

}  // namespace ptz_action_server

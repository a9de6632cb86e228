/**
 * \file
 * \brief The capabilities topic's message, from the core's Capabilities.
 */
#pragma once

#include <string>

#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// \p limits (the device's capabilities within the URDF's limits) of the backend \p backend, as a message. An axis'
/// limitation text carries its remedy after "; ".
PtzCapabilities toMessage(const std::string& backend, const Capabilities& limits);

}  // namespace ptz_action_server

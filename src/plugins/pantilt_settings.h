/**
 * \file
 * \brief The PanTilt settings both plugins read (pantilt_udp, and serial with protocol: pantilt).
 */
#pragma once

#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/ros/backend_plugin.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// format, state_request_period, pan_speed, tilt_speed and the pan / tilt axes under \p params.
void readPanTiltSettings(const ParamReader& params, const BackendContext& context, PanTiltSettings& pantilt);

}  // namespace ptz_action_server

/**
 * \file
 * \brief The VISCA parameters both VISCA plugins read (`serial` with `protocol: visca`, and `visca_ip`).
 */
#pragma once

#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// address, model (a preset) and its overrides (pan/..., tilt/..., zoom/...) under \p params (e.g. ~serial/visca/).
/// The framing is the caller's: it depends on the transport.
void readViscaSettings(const ParamReader& params, ViscaSettings& visca);

/// framing under \p params: sony_ip by default on UDP, raw otherwise; sony_ip on anything but UDP is an error.
ViscaFraming readViscaFraming(const ParamReader& params, LinkKind kind);

/// "0x0000:1, 0x4000:18" (zoom position, decimal or hex, then X) -> \p table; false if it does not read.
bool parseZoomTable(const std::string& text, std::vector<visca::ZoomPoint>& table);

}  // namespace ptz_action_server

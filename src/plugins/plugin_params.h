/**
 * \file
 * \brief Parameter reading the device backend plugins share: links, session timing, per-axis limits.
 */
#pragma once

#include "ptz_action_server/core/device/device_session.h"
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// reconnect_min, reconnect_max (s) into \p link.
void readReconnect(const ParamReader& params, LinkConfig& link);

/// An IP camera's HTTP link: host (an http:// or https:// prefix sets tls), port (0: 80, or 443 with tls), tls,
/// tls_verify (old name verify_peer), ca_file, tls_fingerprint, auth, username, password (never printed),
/// request_timeout, connect_timeout, reconnect timing.
void readHttpLink(const ParamReader& params, LinkConfig& link);

/// A serial port: the device path in \p path_name ("port"), baud (standard rates only), reconnect timing.
void readSerialLink(const ParamReader& params, const char* path_name, LinkConfig& link);

/// startup_timeout and settle_window (s) into \p session; the state timeout is each backend's own parameter.
void readSessionTiming(const ParamReader& params, DeviceSessionConfig& session);

/// One axis' min, max (rad, within the URDF's range and +-\p bound by default), max_speed (rad/s) and acceleration
/// (rad/s^2) under \p params (e.g. ~serial/pelco_d/pan/).
void readAxis(const ParamReader& params, const AxisRange& urdf, double bound, AxisCapability& axis);

}  // namespace ptz_action_server

/**
 * \file
 * \brief Parameter reading every device backend plugin shares: the link, the session timing, per-axis limits. Old
 * names never reach it: the readers it gets map them to today's (deprecated_names.h).
 *
 * One vocabulary for every link (doc/backends/link-parameters.md): `transport` (serial, tcp, udp, http or
 * https, among those the protocol supports), `host`, `port` (the device path on a serial transport, the port number
 * otherwise, as rosserial names it), `baud`, `local_host`, `local_port`, `connect_timeout`, `reconnect_min`,
 * `reconnect_max`, the HTTP set (`tls`, `tls_verify`, `ca_file`, `tls_fingerprint`, `auth`, `username`,
 * `password`, `credentials_file`, `request_timeout`), and the session's `state_timeout`, `poll_period`,
 * `startup_timeout`, `settle_window`.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ptz_action_server/core/device/device_session.h"
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// One transport a protocol can run over, and its default port number (0: none, e.g. serial, or http's 80/443).
struct TransportChoice
{
  LinkKind kind;
  std::uint16_t default_port = 0;
};

/// What a protocol's link may be: its transports (the first is the default) and the bounds of its timing.
struct LinkChoices
{
  std::vector<TransportChoice> transports;
  double state_timeout_min = 0.02;  ///< s: the shortest state deadline that makes sense for the protocol
  double poll_period_min = 0.005;   ///< s
};

/// "serial", "tcp", "udp", "http", "https" (the https transport is http with tls on).
std::string transportName(LinkKind kind);

/// `transport` (one of \p choices') and the link's parameters for it under \p params into \p link (whose values are
/// the protocol's defaults).
void readLink(const ParamReader& params, const LinkChoices& choices, LinkConfig& link);

/// state_timeout, poll_period, startup_timeout and settle_window under \p params into \p session.
void readSession(const ParamReader& params, const LinkChoices& choices, DeviceSessionConfig& session);

/// One axis' min, max (rad, within the URDF's range and +-\p bound by default), max_speed (rad/s) and acceleration
/// (rad/s^2) under \p params (e.g. ~pelco_d/pan/).
void readAxis(const ParamReader& params, const AxisRange& urdf, double bound, AxisCapability& axis);

}  // namespace ptz_action_server

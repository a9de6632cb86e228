/**
 * \file
 * \brief Parameter reading every device backend plugin shares: the link, the session timing, per-axis limits, and
 * the old spellings (with one deprecation line each).
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
#include <utility>
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

/**
 * \brief Where a device plugin reads its parameters, and the old spellings it still accepts.
 *
 * A plugin of today reads everything under ~NAME/ (e.g. ~flir/). A deprecated plugin name (pantilt_udp, visca_ip,
 * serial with protocol:) reads its old namespaces: \ref params the link, session and common settings (~serial/),
 * \ref own the protocol's own settings (~serial/flir/). Old parameter names are read when the new one is not set,
 * each with one ROS_WARN naming the new spelling under ~NAME/.
 */
struct DeviceParams
{
  DeviceParams(const ParamReader& params, std::string name);

  ParamReader params;  ///< link, session and common settings: ~flir/ (old: ~serial/)
  ParamReader own;     ///< the protocol's own settings: ~flir/ (old: ~serial/flir/)
  std::string name;    ///< the plugin of today ("flir"): deprecation lines name ~NAME/...
  /// (new name, old name) pairs read when the new name is not set. Every plugin accepts the common old names
  /// (device_host, device_port, tcp_port, udp_port, serial_port, transaction_deadline, verify_peer); a deprecated
  /// plugin adds its own.
  std::vector<std::pair<std::string, std::string>> old_names;
  /// The default transport when it is not the protocol's first (visca_ip's udp); empty: the protocol's.
  std::string default_transport;
  /// The transports allowed when fewer than the protocol's (visca_ip: udp, tcp); empty: the protocol's.
  std::vector<std::string> transports;
  /// The deprecated plugin name these parameters came through ("serial", "pantilt_udp", "visca_ip"); empty: none.
  std::string old_plugin;

  /**
   * \brief The name to read \p name under in \ref params: \p name if set (and \p usable says its value fits,
   * e.g. a number for a port number), else the first of its old names (\ref old_names, then \p more_old_names)
   * that is set (one ROS_WARN), else \p name.
   */
  std::string pick(const std::string& name, const std::vector<std::string>& more_old_names = {},
                   bool (*usable)(const ParamReader&, const std::string&) = nullptr) const;

  /// One ROS_WARN: \p old_text (a parameter or a plugin name) is deprecated, use \p new_text.
  static void warnDeprecated(const std::string& old_text, const std::string& new_text);
};

/// "serial", "tcp", "udp", "http", "https" (the https transport is http with tls on).
std::string transportName(LinkKind kind);

/// `transport` and the link's parameters for it into \p link (whose values are the protocol's defaults).
void readLink(const DeviceParams& device, const LinkChoices& choices, LinkConfig& link);

/// state_timeout (old name transaction_deadline), poll_period, startup_timeout and settle_window into \p session.
void readSession(const DeviceParams& device, const LinkChoices& choices, DeviceSessionConfig& session);

/// One axis' min, max (rad, within the URDF's range and +-\p bound by default), max_speed (rad/s) and acceleration
/// (rad/s^2) under \p params (e.g. ~pelco_d/pan/).
void readAxis(const ParamReader& params, const AxisRange& urdf, double bound, AxisCapability& axis);

}  // namespace ptz_action_server

/**
 * \file
 * \brief Axis PTZ cameras over VAPIX (HTTP): absolute moves in fractional degrees, continuous moves for velocity
 * goals, `move=stop` for a cancel, `query=position` polled at 10 Hz, limits and the zoom table read at start.
 */
#pragma once

#include <memory>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/device/device_backend.h"

namespace ptz_action_server
{
/// What only the Axis protocol needs to know.
struct AxisSettings
{
  int camera = 1;               ///< the `camera=` of every request (video channel of multi-sensor units)
  int speed = 100;              ///< `speed=` of absolute moves, 1..100
  double pan_max_speed = 1.5;   ///< rad/s of `continuouspantiltmove=100,..` (and of speed=100)
  double tilt_max_speed = 1.0;  ///< rad/s
  double zoom_max_rate = 8.0;   ///< X/s of `continuouszoommove=100`
  double acceleration = 3.0;    ///< rad/s^2, for goal timeouts
  /// `VALUE:X,...`; "" = ask the camera (`query=attributes&group=zoom`), falling back to no zoom if it has no table
  std::string zoom_table;
};

/// Everything an Axis backend is built from.
struct AxisConfig
{
  /// kind HTTP, port 80 (443 with TLS), Digest.
  LinkConfig link = defaultLink();
  /// State is `query=position` every 100 ms; no answer for 0.5 s drops the link.
  DeviceSessionConfig session{ 0.5, 0.1, 10.0, 0.15, 0.5 };
  AxisSettings axis;

  static LinkConfig defaultLink();
};

/// Counters for diagnostics.
struct AxisCounters
{
  Counter positions;      ///< position replies read
  Counter refusals;       ///< `Error:` answers to commands
  Counter error_answers;  ///< HTTP statuses >= 400 to commands or polls
  Counter malformed;      ///< bodies that were neither `key=value` lines nor `Error:`
};

/**
 * \brief VAPIX PTZ over a DeviceSession's HTTP link.
 *
 * At every (re)connection: `query=limits` (limits in degrees, the node intersects them with the URDF's) and, unless a
 * table is configured, `query=attributes&group=zoom` (the zoom table). 401, 403, 404, `Error:` bodies and malformed
 * replies during the set-up fail the start with the reason (later: the connection is dropped and set up again after
 * the backoff). A command answered with `Error:` or an HTTP error is a device fault with the camera's words.
 */
class AxisProtocol : public DeviceProtocol
{
public:
  AxisProtocol(const AxisSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "axis";
  }
  std::string deviceName() const override
  {
    return "an Axis camera";
  }
  /// Pan, tilt within +-180 / +-90 deg until the camera's limits are read; zoom as the configured table says.
  Capabilities capabilities() const override;
  void onConnected() override;
  void onReceived(const std::uint8_t*, std::size_t) override
  {
  }
  /// `query=position`.
  void poll() override;
  /// `pan tilt zoom speed`, fractional degrees, the zoom through the table.
  void goTo(const AxisValues& position) override;
  /// `continuouspantiltmove` and `continuouszoommove`, scaled by the max speeds.
  void moveAtVelocity(const AxisValues& velocity) override;
  /// `move=stop` (the camera decelerates).
  void stop() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const AxisCounters& counters() const
  {
    return counters_;
  }

private:
  /// Sends `ptz.cgi?camera=N&` + \p arguments; true and \p reply filled when the camera answered usably, otherwise
  /// \p problem says why ("" when the link was lost: the session has its reason).
  bool request(const std::string& arguments, vapix::Reply& reply, std::string& problem);
  /// A command: a refusal or error answer is a fault of the current command.
  void command(const std::string& arguments);
  /// The set-up failed: the start fails with \p problem; after a start, the connection is set up again later.
  void setupFailed(const std::string& problem);
  Capabilities cameraCapabilities(const vapix::Limits& limits) const;

  const AxisSettings settings_;
  DeviceSession& session_;
  HttpLink& http_;
  AxisCounters counters_;

  // I/O thread only.
  vapix::ZoomTable zoom_table_;  ///< empty: no zoom
  HttpRequest request_;          ///< reused: the 10 Hz poll allocates nothing once warm
  vapix::Reply reply_;
  std::string arguments_;
};

/// An Axis backend: AxisProtocol on a DeviceSession over HTTP.
std::unique_ptr<DeviceBackend> makeAxisBackend(const AxisConfig& config,
                                               std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());

}  // namespace ptz_action_server

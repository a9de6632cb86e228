/**
 * \file
 * \brief The pantilt backend: the node is the control system, a PanTilt device controller sits across UDP (or a
 * serial line or TCP, SLIP-framed).
 */
#pragma once

#include <array>
#include <cmath>
#include <memory>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/framing/slip.h"
#include "ptz_action_server/core/pantilt/pantilt_codec.h"

namespace ptz_action_server
{
/// What only the PanTilt protocol needs to know.
struct PanTiltSettings
{
  cr::pantilt::WireFormat format = cr::pantilt::WireFormat::SEED;
  double state_request_period = 0.2;  ///< s between state requests while no frames arrive
  double pan_speed = 100.0;           ///< % of the max speed for position goals
  double tilt_speed = 100.0;          ///< %
  /// Pan and tilt ranges (rad), max speeds at 100 % (rad/s) and accelerations (rad/s^2). Zoom: none.
  std::array<AxisCapability, 2> axes{ { fullAxis({ -M_PI, M_PI }, 1.5, 3.0),
                                        fullAxis({ -M_PI / 2.0, M_PI / 2.0 }, 1.0, 3.0) } };
};

/// Why frames from the device were dropped; each is counted under exactly one reason. (Datagrams from anyone
/// else are the link's `foreign_datagrams`.)
struct PanTiltCounters
{
  Counter frames_ok;
  Counter bad_size;
  Counter bad_header;
  Counter bad_version;
  Counter bad_mask;
  Counter bad_value;              ///< a field no device of the format could report (NaN angles, subnormals, ...)
  Counter foreign_format_frames;  ///< a valid frame of another PanTilt format: never taken as state
  Counter bad_framing;            ///< serial: SLIP frames with a bad escape or too long, dropped before decoding

  std::uint64_t dropped() const
  {
    return bad_size + bad_header + bad_version + bad_mask + bad_value + foreign_format_frames + bad_framing;
  }
};

/**
 * \brief PanTilt over a DeviceSession: UDP (a frame per datagram) or a serial line (SLIP frames, RFC 1055).
 *
 * Goals become SET_PARAM (speeds, angles in degrees) + COMMAND GO_TO_PAN_TILT_ANGLE frames (v1.0 and v1.1: one
 * COMMAND with the angles as arguments); a goal's speed becomes its PAN_MOTOR_SPEED / TILT_MOTOR_SPEED (in % of each
 * axis' max_speed); velocity goals become MOVE_PAN_TILT in v1.x and, in the seed's format, which
 * has no velocity command, a speed setting plus a move towards the limit; cancel becomes STOP. State comes from the
 * device's params frames of the configured format (see PanTiltEmulator for the reporting rules), asked for while the
 * device is quiet; frames of another format are counted and never taken as state. After a loss the device is held
 * with STOP and the speeds are set again.
 */
class PanTiltProtocol : public DeviceProtocol
{
public:
  /// DeviceConfig<PanTiltProtocol> (device_backend.h): these settings, and the defaults of the link and the session.
  using Settings = PanTiltSettings;
  /// udp: the device controller's address; local_host/local_port where its frames arrive
  static LinkConfig defaultLink()
  {
    LinkConfig link;
    link.kind = LinkKind::UDP;
    link.port = 5000;
    return link;
  }
  /// No valid params frame for 0.5 s drops the link; positions 50 ms apart that agree mean "settled".
  static DeviceSessionConfig defaultSession()
  {
    return { 0.5, 0.05, 10.0, 0.05, 0.5 };
  }

  PanTiltProtocol(const PanTiltSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "pantilt";
  }
  std::string deviceName() const override
  {
    return "a PanTilt device controller";
  }
  /// From the settings: the PanTilt protocol cannot tell limits or speeds. No zoom. Pan and tilt take a position
  /// goal's speed (SpeedControl::DEVICE), down to MIN_SPEED_PERCENT of their max_speed.
  Capabilities capabilities() const override;
  /// The speeds and a state request (a params frame with an empty mask).
  void onConnected() override;
  /// One params frame per datagram, or per SLIP frame on a byte stream (a serial line); anything else is counted
  /// under its reason and dropped. A frame of another PanTilt format before the first valid one fails the start-up:
  /// the device speaks another format.
  void onReceived(const std::uint8_t* data, std::size_t size) override;
  /// A state request while the device is quiet (it reports on its own otherwise).
  void poll() override;
  /// The configured speeds, the angles in degrees and GO_TO_PAN_TILT_ANGLE (v1.x: one COMMAND with the angles).
  void goTo(const AxisValues& position) override;
  /// goTo() with each axis' motor speed at \p speed's share of its max_speed (0: the configured speed), up to the
  /// configured speed and down to MIN_SPEED_PERCENT.
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  /// v1.x: MOVE_PAN_TILT in % of the max speed; seed: a speed and a move towards the limit.
  void moveAtVelocity(const AxisValues& velocity) override;
  /// COMMAND STOP.
  void stop() override;
  /// STOP, then the speeds again.
  void hold() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const PanTiltCounters& counters() const
  {
    return counters_;
  }

  /// The slowest motor speed a goal asks (% of max_speed): the PanTilt library sets no floor, 1 % is the slowest
  /// the node's own shaping streams.
  static constexpr double MIN_SPEED_PERCENT = 1.0;

private:
  void handleFrame(const std::uint8_t* data, std::size_t size);
  /// One frame to the device: a datagram, or a SLIP frame on a byte stream.
  void send(const std::uint8_t* frame, std::size_t size);
  void sendSetParam(cr::pantilt::PanTiltParam id, double value);
  void sendCommand(cr::pantilt::PanTiltCommand id, double arg1 = 0.0, double arg2 = 0.0);
  void sendSpeeds();
  void sendSpeeds(double pan_percent, double tilt_percent);
  void sendStateRequest();

  const PanTiltSettings settings_;
  DeviceSession& session_;
  PanTiltCounters counters_;

  // I/O thread only.
  slip::Decoder slip_{ 256 };           ///< serial: frames past 256 bytes are dropped up to the next END
  std::uint64_t dropped_reported_ = 0;  ///< of slip_'s dropped bytes, those reported to the session
  std::vector<std::uint8_t> framed_;
  bool heard_ = false;  ///< a valid frame arrived since the socket opened
  TimePoint last_frame_at_{};
  TimePoint last_request_at_{};
};

}  // namespace ptz_action_server

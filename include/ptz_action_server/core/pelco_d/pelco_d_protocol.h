/**
 * \file
 * \brief PTZ cameras that speak Pelco-D, on RS-485 or behind a serial-to-Ethernet server (TCP).
 */
#pragma once

#include <array>
#include <cmath>
#include <memory>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/device/poll_round.h"
#include "ptz_action_server/core/device/transaction_channel.h"
#include "ptz_action_server/core/pelco_d/pelco_d_codec.h"
#include "ptz_action_server/core/pelco_d/set_position_check.h"

namespace ptz_action_server
{
/// Whether a Pelco-D device moves on set-position (0x4B, 0x4D, 0x4F): `pelco_d/set_position`.
enum class PelcoSetPosition
{
  AUTO,  ///< it should; a goal on which it stays put while a speed command moves it shows it does not (the default)
  YES,   ///< it does: never checked
  NO,    ///< it does not (it only answers the position queries): position goals are steered on speed commands
};

/// What only the Pelco-D protocol needs to know.
struct PelcoSettings
{
  std::uint8_t address = 1;
  pelco::TiltEncoding tilt_encoding = pelco::TiltEncoding::DOWN_POSITIVE;
  bool general_reply = false;  ///< the device acknowledges commands with 4-byte general replies
  /// Ranges (rad, X), speed at 0x3F (rad/s; zoom: X/s) and acceleration (for timeouts) of each axis.
  /// The zoom has no speed byte: it zooms at its own rate, stated here with how fast the lens reaches it.
  std::array<AxisCapability, AXIS_COUNT> axes{ { fullAxis({ -M_PI, M_PI }, 1.5, 3.0),
                                                 fullAxis({ -M_PI / 2.0, M_PI / 2.0 }, 1.0, 3.0),
                                                 fullAxis({ 1.0, 24.0 }, 8.0, 40.0) } };
  std::uint16_t zoom_position_max = 0xFFFF;  ///< the zoom position value at the longest focal length
  std::uint8_t turbo_byte = 0;               ///< the device's pan turbo speed byte (0x40, 0xFF, ...); 0: no turbo
  double turbo_speed = 0.0;                  ///< rad/s the pan turns at with turbo (above axes[PAN].max_speed)
  double reply_timeout =
      0.0;  ///< s: the reply deadline's floor (0: the exchange's wire time plus 100 ms); it learns up to twice that
  PelcoSetPosition set_position = PelcoSetPosition::AUTO;
  /// s a set-position has to move the device before a speed command checks it (AUTO), and that check after it
  double set_position_wait = 0.5;
  bool focus = true;  ///< the camera has a focus the standard command's near/far bits drive (pelco_d/focus)
  bool iris = true;   ///< the camera has an iris the open/close bits drive (pelco_d/iris)

  /// Zoom X-factor <-> the device's zoom position value.
  std::uint16_t zoomToPosition(double zoom) const;
  double positionToZoom(std::uint16_t position) const;
};

/// The lens \p settings declare: focus near/far and iris open/close drives at the device's speed, nothing more.
LensCapabilities pelcoLens(const PelcoSettings& settings);

/// Counters for diagnostics (reply timeouts and late replies are the channel's).
struct PelcoCounters
{
  Counter frames;             ///< valid frames and general replies for our address
  Counter bad_checksum;       ///< dropped: a 0xFF whose frame did not check
  Counter skipped_bytes;      ///< dropped: bytes outside frames
  Counter wrong_address;      ///< dropped: frames for another address
  Counter unexpected_frames;  ///< valid frames that answer nothing asked
};

/**
 * \brief Pelco-D over a DeviceSession.
 *
 * Goals become the extended absolute commands (0x4B pan, 0x4D tilt, 0x4F zoom), velocity goals the standard
 * movement command with speeds 0..0x3F, cancel the all-zero stop frame. The position is polled (0x51, 0x53, 0x55,
 * answered by 0x59, 0x5B, 0x5D). Frames with a bad checksum and partial frames are dropped with a counter; the
 * reader resynchronises on 0xFF. Pan is clockwise from home, as the contract's. Pelco-D has no error replies.
 *
 * A device without set-position (many conference cameras: they answer the queries and ignore 0x4B..0x4F) declares
 * no `absolute` axis, so that the node's ClosedLoopBackend steers position goals on speed commands: from the settings
 * (PelcoSetPosition::NO), or once a goal showed it (AUTO: see pelco::SetPositionCheck), which that goal's fault names.
 */
class PelcoProtocol : public DeviceProtocol
{
public:
  /// DeviceConfig<PelcoProtocol> (device_backend.h): these settings, and the defaults of the link and the session.
  using Settings = PelcoSettings;
  /// serial, or tcp to a serial-to-Ethernet server
  static LinkConfig defaultLink()
  {
    return LinkConfig();
  }
  static DeviceSessionConfig defaultSession()
  {
    return { 0.25, 0.05, 10.0, 0.1, 0.5 };
  }

  PelcoProtocol(const PelcoSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "pelco_d";
  }
  std::string deviceName() const override;
  /// From the settings: Pelco-D cannot ask a camera for its limits or speeds.
  Capabilities capabilities() const override;
  /// Nothing to say first: the position queries are the handshake.
  void onConnected() override;
  /// Frames of our address (and general replies), each matched to the one request on the wire.
  void onReceived(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected() override;
  void onClosing() override
  {
    channel_.close();
  }
  /// 0x51, 0x53 (and 0x55 with zoom) whenever the line is free.
  void poll() override;
  /// The extended absolute commands 0x4B, 0x4D, 0x4F (of the axes not NaN); refused as a fault where the device
  /// takes none.
  void goTo(const AxisValues& position) override;
  /// The standard movement command, speeds scaled to 1..0x3F; a pan nearer the turbo speed than the 0x3F speed: the
  /// turbo byte, if configured. The zoom has no speed byte: its direction only.
  void moveAtVelocity(const AxisValues& velocity) override;
  /// The all-zero frame at once, ahead of anything queued.
  void stop() override;
  /// Focus near/far and iris open/close: the bits of the standard movement command, sent with the drive running
  /// (Pelco-D's movement command says everything that moves). A stop ends them too.
  void lens(const LensCommand& command) override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const PelcoCounters& counters() const
  {
    return counters_;
  }

private:
  enum Tag
  {
    QUERY_PAN,
    QUERY_TILT,
    QUERY_ZOOM,
    COMMAND,  ///< acknowledged by a general reply (when the device sends them)
  };

  /// The device takes set-position: from the settings, and not found otherwise.
  bool takesSetPosition() const
  {
    return settings_.set_position != PelcoSetPosition::NO && !set_position_ignored_;
  }
  /// After each whole poll round: what the set-position check found (AUTO).
  void checkSetPosition();
  /// The check found a device that ignores set-position: its axes lose `absolute`, the goal a fault naming it.
  void setPositionIgnored();
  void stopNow();
  void handle(const pelco::FrameParser::Event& event);
  void queueFrame(const pelco::Frame& frame, Tag tag);
  void updateParserCounters();

  const PelcoSettings settings_;
  DeviceSession& session_;
  TransactionChannel channel_;
  pelco::FrameParser parser_;
  std::uint64_t dropped_reported_ = 0;  ///< of parser_'s dropped bytes, those reported to the session
  PelcoCounters counters_;

  // I/O thread only.
  AxisValues polled_{ { 0.0, 0.0, 1.0 } };
  AxisValues reported_{ { 0.0, 0.0, 1.0 } };  ///< the last state reported (a whole round)
  PollRound round_;                           ///< pan, then tilt, then zoom (where the device has zoom)
  pelco::SetPositionCheck set_position_check_;
  std::uint64_t checked_command_ = 0;              ///< the command whose goal the check watches
  bool set_position_ignored_ = false;              ///< found out: the device ignores set-position
  std::vector<pelco::FrameParser::Event> events_;  ///< reused for every read
  pelco::Frame motion_;  ///< the last standard movement command, without its lens bits (a stop at first)
  int focus_drive_ = 0;  ///< the lens bits sent with it: 1 far (open), -1 near (close), 0 none
  int iris_drive_ = 0;
};

}  // namespace ptz_action_server

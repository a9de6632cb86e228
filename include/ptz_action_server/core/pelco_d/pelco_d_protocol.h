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

namespace ptz_action_server
{
/// What only the Pelco-D protocol needs to know.
struct PelcoSettings
{
  std::uint8_t address = 1;
  pelco::TiltEncoding tilt_encoding = pelco::TiltEncoding::DOWN_POSITIVE;
  bool general_reply = false;  ///< the device acknowledges commands with 4-byte general replies
  /// Ranges (rad, X), speed at 0x3F (rad/s; zoom: X/s) and acceleration (for timeouts) of each axis.
  std::array<AxisCapability, AXIS_COUNT> axes{ { fullAxis({ -M_PI, M_PI }, 1.5, 3.0),
                                                 fullAxis({ -M_PI / 2.0, M_PI / 2.0 }, 1.0, 3.0),
                                                 fullAxis({ 1.0, 24.0 }, 8.0, 0.0) } };
  std::uint16_t zoom_position_max = 0xFFFF;  ///< the zoom position value at the longest focal length
  std::uint8_t turbo_byte = 0;               ///< the device's pan turbo speed byte (0x40, 0xFF, ...); 0: no turbo
  double turbo_speed = 0.0;                  ///< rad/s the pan turns at with turbo (above axes[PAN].max_speed)
  double reply_timeout = 0.0;                ///< s for one reply; 0: the exchange's wire time plus 100 ms

  /// Zoom X-factor <-> the device's zoom position value.
  std::uint16_t zoomToPosition(double zoom) const;
  double positionToZoom(std::uint16_t position) const;
};

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
    return "serial/pelco_d";
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
  /// The extended absolute commands 0x4B, 0x4D, 0x4F.
  void goTo(const AxisValues& position) override;
  /// The standard movement command, speeds scaled to 1..0x3F (pan faster than that: the turbo byte, if configured).
  void moveAtVelocity(const AxisValues& velocity) override;
  /// The all-zero frame at once, ahead of anything queued.
  void stop() override;
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
  PollRound round_;                                ///< pan, then tilt, then zoom (where the device has zoom)
  std::vector<pelco::FrameParser::Event> events_;  ///< reused for every read
};

}  // namespace ptz_action_server

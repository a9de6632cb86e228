/**
 * \file
 * \brief The serial backend with `protocol: pelco_d`: PTZ cameras on RS-485 that speak Pelco-D.
 */
#pragma once

#include <array>
#include <condition_variable>
#include <memory>
#include <mutex>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/motion_estimator.h"
#include "ptz_action_server/core/serial/pelco_d.h"
#include "ptz_action_server/core/serial/serial_backend_config.h"
#include "ptz_action_server/core/serial/transaction_channel.h"

namespace ptz_action_server
{
struct PelcoConfig
{
  SerialBackendConfig serial;
  std::uint8_t address = 1;
  pelco::TiltEncoding tilt_encoding = pelco::TiltEncoding::WRAP;
  bool general_reply = false;  ///< the device acknowledges commands with 4-byte general replies
  /// Ranges (rad, X), speed at 0x3F (rad/s; zoom: X/s) and acceleration (for timeouts) of each axis.
  std::array<AxisCapability, AXIS_COUNT> axes{ { { true, { -M_PI, M_PI }, 1.5, 3.0 },
                                                 { true, { -M_PI / 2.0, M_PI / 2.0 }, 1.0, 3.0 },
                                                 { true, { 1.0, 24.0 }, 8.0, 0.0 } } };
  std::uint16_t zoom_position_max = 0xFFFF;  ///< the zoom position value at the longest focal length
};

struct PelcoCounters
{
  pelco::ParserCounters parser;
  std::uint64_t unexpected_frames = 0;  ///< valid frames that answer nothing asked
  std::uint64_t timeouts = 0;
  std::uint64_t late_replies = 0;
  std::uint64_t link_losses = 0;
};

/**
 * \brief Drives a Pelco-D camera over a serial port.
 *
 * Goals become the extended absolute commands (0x4B pan, 0x4D tilt, 0x4F zoom), velocity goals the standard
 * movement command with speeds 0..0x3F, cancel the all-zero stop frame. The position is polled (0x51, 0x53, 0x55,
 * answered by 0x59, 0x5B, 0x5D) on the I/O thread. Frames with a bad checksum and partial frames are dropped with a
 * counter; the reader resynchronises on 0xFF. Pan is clockwise from home, as the contract's.
 */
class PelcoBackend : public PtzBackend, private SerialLink::Listener
{
public:
  explicit PelcoBackend(const PelcoConfig& config,
                        std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~PelcoBackend() override;

  std::string name() const override
  {
    return "serial";
  }
  Capabilities capabilities() const override;
  /// Opens the port and waits (up to startup_timeout) for the first answer to a position query.
  void start() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  PtzSample sample() const override;
  std::string lastFault() const override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  PelcoCounters counters() const;

  /// Zoom X-factor <-> the device's zoom position value.
  std::uint16_t zoomToPosition(double zoom) const;
  double positionToZoom(std::uint16_t position) const;

private:
  enum Tag
  {
    QUERY_PAN,
    QUERY_TILT,
    QUERY_ZOOM,
    COMMAND,  ///< acknowledged by a general reply (when the device sends them)
  };

  void onConnected() override;
  void onBytes(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected(const std::string& reason) override;
  void schedulePoll();
  void queueFrame(const pelco::Frame& frame, Tag tag);
  void sendUrgent(const pelco::Frame& frame);
  bool linkUpLocked(TimePoint now) const;

  const PelcoConfig config_;
  const std::shared_ptr<const Clock> clock_;
  SerialLink link_;
  TransactionChannel channel_;
  pelco::FrameParser parser_;
  boost::asio::steady_timer poll_timer_;

  // I/O thread only.
  int polls_pending_ = 0;
  AxisValues polled_{ { 0.0, 0.0, 1.0 } };

  mutable std::mutex mutex_;
  mutable std::condition_variable answered_;
  bool connected_ = false;
  bool ever_answered_ = false;
  bool was_connected_ = false;
  TimePoint last_reply_at_{};
  bool link_was_up_ = false;
  MotionEstimator motion_;
  PelcoCounters counters_;
};

}  // namespace ptz_action_server

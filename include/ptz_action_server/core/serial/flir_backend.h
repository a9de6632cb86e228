/**
 * \file
 * \brief The serial backend with `protocol: flir`: FLIR (Directed Perception) D46 / E46 pan-tilt units.
 */
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/motion_estimator.h"
#include "ptz_action_server/core/serial/flir_codec.h"
#include "ptz_action_server/core/serial/serial_backend_config.h"
#include "ptz_action_server/core/serial/transaction_channel.h"

namespace ptz_action_server
{
struct FlirConfig
{
  SerialBackendConfig serial;
  double pan_speed = 1.5;     ///< rad/s of position goals (PS); capped by the unit's upper speed (PU)
  double tilt_speed = 1.0;    ///< rad/s (TS)
  double acceleration = 3.0;  ///< rad/s^2, for goal timeouts
};

/// Counters for diagnostics.
struct FlirCounters
{
  std::uint64_t replies = 0;
  std::uint64_t errors = 0;           ///< `!` replies to commands
  std::uint64_t limit_hits = 0;       ///< `!P` / `!T`
  std::uint64_t unexpected_text = 0;  ///< banners, echoes, noise
  std::uint64_t timeouts = 0;         ///< requests without a reply in time
  std::uint64_t late_replies = 0;     ///< replies ignored after a timeout
  std::uint64_t link_losses = 0;
};

/**
 * \brief Drives a FLIR PTU over a serial port.
 *
 * At every (re)connection: terse mode, echo off, position mode (`FT ED CI`), then the resolutions (`PR`/`TR`), the
 * position limits (`PN`/`PX`/`TN`/`TX`) and upper speeds (`PU`/`TU`) are read from the unit; after a reconnection a
 * halt follows, so an aborted goal is not resumed. Position goals are `PS TS PP TP`, velocity goals switch to
 * velocity mode (`CV`) and set signed `PS TS`, cancel is `H`. The position is polled (`PP`, `TP`) back to back on
 * the I/O thread, so PtzState reads a cache and never waits on the wire. The unit's counter-clockwise pan is
 * inverted to the contract's clockwise pan. A `!` reply to a command is a device fault (the goal aborts with the
 * unit's message); `!P` / `!T` limit reports and unexpected text are counted.
 */
class FlirBackend : public PtzBackend, private SerialLink::Listener
{
public:
  explicit FlirBackend(const FlirConfig& config, std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~FlirBackend() override;

  std::string name() const override
  {
    return "serial";
  }
  Capabilities capabilities() const override;
  /// Opens the port and waits (up to startup_timeout) until the unit has told its resolution and limits.
  void start() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  PtzSample sample() const override;
  std::string lastFault() const override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  FlirCounters counters() const;

private:
  /// What a request asked, to interpret its reply.
  enum Tag
  {
    SETUP,           ///< FT, ED, CI: acknowledged
    PAN_RESOLUTION,  ///< PR
    TILT_RESOLUTION,
    PAN_MIN,  ///< PN
    PAN_MAX,
    TILT_MIN,
    TILT_MAX,
    PAN_SPEED_MAX,  ///< PU
    TILT_SPEED_MAX,
    PAN_POSITION,  ///< PP query
    TILT_POSITION,
    COMMAND,  ///< anything acknowledged with *
  };

  void onConnected() override;
  void onBytes(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected(const std::string& reason) override;
  void handleReply(const flir::Reply& reply);
  void handleAnswer(const TransactionChannel::Request& request, const flir::Reply& reply);
  void queueSetup();
  void schedulePoll();
  void request(const std::string& text, Tag tag);
  void sendMode(bool velocity);
  bool linkUpLocked(TimePoint now) const;
  double panResolution() const;
  double tiltResolution() const;

  const FlirConfig config_;
  const std::shared_ptr<const Clock> clock_;
  SerialLink link_;
  TransactionChannel channel_;
  flir::ReplyParser parser_;
  boost::asio::steady_timer poll_timer_;

  // I/O thread only.
  bool poll_pending_ = false;
  bool was_ready_ = false;   ///< the unit answered its setup once: a later setup is a reconnection
  double polled_pan_ = 0.0;  ///< rad, from the last PP

  // Shared with the node's threads.
  mutable std::mutex mutex_;
  mutable std::condition_variable ready_changed_;
  bool connected_ = false;
  bool ready_ = false;           ///< setup complete: resolutions and limits known
  double pan_resolution_ = 0.0;  ///< rad per position
  double tilt_resolution_ = 0.0;
  long limits_[4] = { 0, 0, 0, 0 };  ///< PN, PX, TN, TX (positions)
  long speed_max_[2] = { 0, 0 };     ///< PU, TU (positions/s)
  TimePoint last_reply_at_{};
  bool link_was_up_ = false;
  MotionEstimator motion_;
  std::uint64_t fault_count_ = 0;
  std::string last_fault_;
  FlirCounters counters_;
};

}  // namespace ptz_action_server

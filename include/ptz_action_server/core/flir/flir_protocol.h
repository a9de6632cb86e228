/**
 * \file
 * \brief FLIR (Directed Perception) D46 / E46 pan-tilt units, on a serial port or (E-series) TCP port 4000.
 */
#pragma once

#include <memory>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/device/poll_round.h"
#include "ptz_action_server/core/device/transaction_channel.h"
#include "ptz_action_server/core/flir/flir_codec.h"

namespace ptz_action_server
{
/// What only the FLIR protocol needs to know.
struct FlirSettings
{
  double pan_speed = 1.5;     ///< rad/s of position goals (PS); capped by the unit's upper speed (PU)
  double tilt_speed = 1.0;    ///< rad/s (TS)
  double acceleration = 3.0;  ///< rad/s^2, for goal timeouts
  double reply_timeout =
      0.0;  ///< s: the reply deadline's floor (0: the exchange's wire time plus 100 ms); it learns up to twice that
  /// s the set-up waits at most for a banner to end (tcp: the per-connection banner) or for the line to fall quiet
  double banner_timeout = 3.0;
};

/// Counters for diagnostics (reply timeouts and late replies are the channel's).
struct FlirCounters
{
  Counter replies;
  Counter errors;            ///< `!` replies to commands
  Counter limit_hits;        ///< `!P` / `!T`
  Counter banner_lines;      ///< lines of a start-up banner
  Counter restarts;          ///< banners after the set-up: the unit restarted under us
  Counter resets;            ///< reset answers (`!T!T!P!P*`): someone reset the unit, which calibrated meanwhile
  Counter unusable_replies;  ///< a query answered without a usable number, or a set-up that made no sense
  Counter unexpected_text;   ///< echoes without a reply, noise
};

/**
 * \brief The FLIR PTU ASCII protocol over a DeviceSession.
 *
 * At every (re)connection, once the line is quiet (on TCP, once the banner has ended): terse mode, echo off, position
 * mode (`FT ED CI`), then the resolutions (`PR`/`TR`), the position limits (`PN`/`PX`/`TN`/`TX`) and upper speeds
 * (`PU`/`TU`) are read from the unit; answers that make no sense start the set-up again. Position goals are
 * `PS TS PP TP`, velocity goals switch to velocity mode (`CV`) and set signed `PS TS`, cancel is `H`. The position is
 * polled (`PP`, `TP`) whenever the line is free, so PtzState reads a cache and never waits on the wire. The unit's
 * counter-clockwise pan is inverted to the contract's clockwise pan.
 *
 * Whatever a unit says besides its replies is never taken for one: echoes and verbose replies are read through,
 * `!P` / `!T` are counted wherever they come, and a banner during the set-up starts it again once the banner has
 * ended. A banner after the set-up means the unit restarted (a power cycle, or a reset on a unit that resets as it
 * powers up): it has forgotten the goal, its modes and speeds, so the connection is dropped as lost ("the FLIR PTU
 * restarted") and set up afresh. A reset's answer (`!T!T!P!P*`, after someone else sent `R`) is no reply either, nor
 * an error: the unit read nothing while it calibrated and may be back in its power-up modes, so the set-up starts
 * again (after the set-up, the connection is dropped as lost: "the FLIR PTU was reset"). A `!` reply to a command is
 * a device fault (the goal aborts with the unit's message).
 */
class FlirProtocol : public DeviceProtocol
{
public:
  /// DeviceConfig<FlirProtocol> (device_backend.h): these settings, and the defaults of the link and the session.
  using Settings = FlirSettings;
  /// serial (D46, E46) or tcp (E-series, port 4000)
  static LinkConfig defaultLink()
  {
    return LinkConfig();
  }
  /// A missing reply for 0.25 s drops the link; the position is polled every 50 ms.
  static DeviceSessionConfig defaultSession()
  {
    return { 0.25, 0.05, 10.0, 0.1, 0.5 };
  }

  FlirProtocol(const FlirSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "flir";
  }
  std::string deviceName() const override
  {
    return "a FLIR PTU";
  }
  /// Pan and tilt go to positions, move at a speed and report where they are (their ranges and speeds are unknown
  /// until the unit has told them, see onConnected()); no zoom ("a FLIR PTU has no zoom").
  Capabilities capabilities() const override;
  /// Waits for the line to fall quiet (on TCP, for the E-series banner); then `FT ED CI` and the queries of the unit's
  /// resolution, limits and upper speeds. The link is ready when the last answer is in and makes sense.
  void onConnected() override;
  /// Reply lines, each matched to the one request on the wire.
  void onReceived(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected() override;
  void onClosing() override;
  /// `PP` and `TP` whenever the line is free.
  void poll() override;
  /// `CI PS TS PP TP`, the pan inverted (the unit's positive pan is counter-clockwise).
  void goTo(const AxisValues& position) override;
  /// `PS` / `TS` before `PP` / `TP` at the goal's speed (the unit's top speed where it asks none).
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  /// `CV` and signed `PS TS`.
  void moveAtVelocity(const AxisValues& velocity) override;
  /// `H` at once, ahead of anything queued.
  void stop() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const FlirCounters& counters() const
  {
    return counters_;
  }

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

  /// What the set-up waits for before it goes out.
  enum class Wait
  {
    NOTHING,     ///< it went out
    BANNER_END,  ///< the banner's last line (`Initializing...`), then a quiet line
    QUIET,       ///< no byte from the unit for a reply time: nothing it still says can be taken for an answer
  };

  void handleReply(const flir::Reply& reply);
  void handleBanner(const flir::Reply& reply);
  void handleReset(const flir::Reply& reply);
  void handleAnswer(const TransactionChannel::Request& request, const flir::Reply& reply);
  /// A query answered without its number, or a set-up that made no sense: counted; the set-up starts again.
  void unusable();
  void onTimeout(const TransactionChannel::Request& lost);
  /// Forgets what is on the wire and sends the set-up once \p wait is over (at most banner_timeout from now).
  void setUpAfter(Wait wait);
  void armWaitTimer();
  void queueSetup();
  void request(const std::string& text, Tag tag);
  bool plausible() const;
  Capabilities unitCapabilities() const;

  const FlirSettings settings_;
  DeviceSession& session_;
  const double reply_timeout_;  ///< s: how long the unit may take to answer, and how long a quiet line must last
  TransactionChannel channel_;
  flir::ReplyParser parser_;
  boost::asio::steady_timer wait_timer_;
  FlirCounters counters_;

  // I/O thread only.
  Wait waiting_ = Wait::NOTHING;
  TimePoint wait_deadline_{};    ///< the set-up goes out then, whatever the line does
  TimePoint last_bytes_at_{};    ///< when the unit last said anything
  bool ready_ = false;           ///< the set-up of this connection is complete
  PollRound round_{ 2 };         ///< PP, then TP: polled_pan_ goes with the TP answered right after it
  double polled_pan_ = 0.0;      ///< rad, from the last PP
  double pan_resolution_ = 0.0;  ///< rad per position
  double tilt_resolution_ = 0.0;
  long limits_[4] = { 0, 0, 0, 0 };  ///< PN, PX, TN, TX (positions)
  long speed_max_[2] = { 0, 0 };     ///< PU, TU (positions/s)
};

}  // namespace ptz_action_server

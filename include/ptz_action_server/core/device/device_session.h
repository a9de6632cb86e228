/**
 * \file
 * \brief The device session every device backend shares: I/O (on the process's DeviceIoPool), link, state snapshot,
 * link supervision, start-up wait and recovery. Protocols only add a codec and a small policy (DeviceProtocol).
 */
#pragma once

#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/counter.h"
#include "ptz_action_server/core/device/device_io_pool.h"
#include "ptz_action_server/core/device/link_supervisor.h"
#include "ptz_action_server/core/device/state_plausibility.h"
#include "ptz_action_server/core/lens.h"
#include "ptz_action_server/core/motion/motion_estimator.h"
#include "ptz_action_server/core/transport/http_channel.h"
#include "ptz_action_server/core/transport/link.h"

namespace ptz_action_server
{
class DeviceProtocol;

/// How a session supervises its device. Every backend fills one from its parameters.
struct DeviceSessionConfig
{
  /// s without a valid state report before the link counts as lost: the least state deadline (a device that answers
  /// requests slowly gets longer, see DeviceSession::replyDeadlineChanged())
  double state_timeout = 0.5;
  double poll_period = 0.05;      ///< s between the protocol's poll() calls and the link checks
  double startup_timeout = 10.0;  ///< s start() waits for the device
  double settle_window = 0.1;     ///< s a still position must last to count as settled
  double shutdown_grace = 0.5;    ///< s the destructor waits for the protocol's last words to go out
};

/// What a session counts beyond its link.
struct DeviceSessionCounters
{
  Counter state_reports;      ///< valid states the protocol reported
  Counter recoveries;         ///< the device answered again after a loss and was held where it was
  Counter stale_faults;       ///< refusals of a command the node had already replaced: counted, not reported
  Counter impossible_states;  ///< reports dropped as impossible (NaN, outside the limits, a jump): never believed
  /// Received bytes the protocol's framing threw away: a reply past its protocol's limit (a line without end), noise
  /// between frames, a frame that never completed. Every receive buffer is bounded (doc/device-layer.md,
  /// "Hostile devices: replies that never end"): memory stays flat whatever the device sends.
  Counter dropped_bytes;
};

/**
 * \brief Owns the link and the state of one device; runs a DeviceProtocol over them on an I/O thread.
 *
 * The I/O thread is one of the process's DeviceIoPool: a few threads serve every session, each session's handlers
 * on one thread, one at a time, in order (a session over HTTP, whose calls block, gets a thread of its own). "The
 * I/O thread" below is that thread.
 *
 * Two audiences, two sets of calls:
 * - DeviceBackend (any thread): start(), stop(), command(), sample(), capabilities(), lastFault(), lastLinkLoss(),
 *   diagnostics(). None of them waits on I/O (start() waits, with a deadline, for the device to be ready; stop() for
 *   the last words and the teardown). stop() and the destructor: never on an I/O thread of the pool.
 * - The protocol (I/O thread only): write(), reportState(), reportAlive(), reportFault(), ready(), ...
 *
 * The link is up while the link is open, the protocol has said ready() since it opened, and a valid state came
 * within state_timeout. Every transition from up to down counts a loss (PtzSample::link_losses) with its reason.
 * When the device answers again after a loss, the protocol's hold() runs once, in the same I/O-thread handler that
 * brings the link up: any command the node sends once it sees the link up runs after it, so the recovery never
 * overrides a fresh goal.
 */
class DeviceSession : private Link::Listener
{
public:
  /// Takes its I/O thread from \p pool (tests give their own; a dedicated one for HTTP).
  DeviceSession(const LinkConfig& link, const DeviceSessionConfig& config, std::shared_ptr<const Clock> clock,
                DeviceIoPool& pool = DeviceIoPool::instance());
  ~DeviceSession() override;
  DeviceSession(const DeviceSession&) = delete;
  DeviceSession& operator=(const DeviceSession&) = delete;

  /// Binds the protocol (once, before start()); takes its initial capabilities.
  void attach(DeviceProtocol& protocol);
  /// Calls \p listener on the I/O thread after each valid state report and each loss of the link (before start()).
  void setStateListener(std::function<void()> listener)
  {
    state_listener_ = std::move(listener);
  }

  // ---------------------------------------------------------------- for the backend: any thread

  /// Opens the link on the I/O thread, then waits until the device is ready and its link up. Throws BackendError
  /// naming the device, the link and the reason when it is not within startup_timeout.
  void start();
  /**
   * \brief Lets the protocol say goodbye (shutdown()), closes the link, then waits until nothing of this session is
   * left on the I/O thread. Idempotent; the destructor calls it.
   *
   * On the I/O thread, once the last words are out (or after shutdown_grace): the timers are cancelled, the link
   * closed and the protocol's onClosing() runs; from then on no handler of the session, its link or its protocol
   * starts anything new. The aborted handlers are then queued on the single-threaded context ahead of a fence that
   * stop() waits for, so none of them runs after stop() returns.
   *
   * Any thread but an I/O thread of the pool (a handler that stopped a session would wait for its own thread, or
   * stall another's): throws std::logic_error there.
   */
  void stop();
  /// Runs \p work (one of the protocol's commands) on the I/O thread, after every earlier command. From then on,
  /// faults reported for earlier commands no longer count. Dropped once stop() has begun.
  void command(std::function<void()> work);
  /// Runs \p work on the I/O thread after every earlier command, without making it a command of its own: faults of
  /// the command running still count (a lens command beside a goal). Dropped once stop() has begun.
  void post(std::function<void()> work);

  PtzSample sample() const;
  Capabilities capabilities() const;
  std::string lastFault() const;
  std::string lastLinkLoss() const;
  /// The warnings given since the last call (see warn()), oldest first.
  std::vector<std::string> takeWarnings();
  /// The link's and the session's figures (the protocol adds its own).
  void diagnostics(std::vector<DiagnosticValue>& values) const;
  const DeviceSessionCounters& counters() const
  {
    return counters_;
  }
  const DeviceSessionConfig& config() const
  {
    return config_;
  }
  /// The state deadline in force (s): config().state_timeout, or longer where the device's replies take long.
  double stateDeadline() const;
  const LinkCounters& linkCounters() const
  {
    return link_->counters();
  }
  const LinkConfig& linkConfig() const
  {
    return link_->config();
  }
  /// The HTTP channel's counters, or nullptr on another link.
  const HttpCounters* httpCounters() const;

  // ---------------------------------------------------------------- for the protocol: I/O thread only

  /// The session's io_context (shared with other sessions): for the protocol's timers. Their handlers must start
  /// nothing once closing() (see DeviceProtocol::onClosing()).
  boost::asio::io_context& context()
  {
    return io_.context();
  }
  /// The session is closing for good: the link is closed and no handler may start a new operation.
  bool closing() const
  {
    return closing_;
  }
  TimePoint now() const
  {
    return clock_->now();
  }
  const Clock& clock() const
  {
    return *clock_;
  }
  bool connected() const
  {
    return link_->isOpen();
  }
  bool carriesDatagrams() const
  {
    return link_->carriesDatagrams();
  }
  /// Bytes for the device (a link that carries bytes: serial, TCP, UDP). Throws std::logic_error over HTTP.
  void write(const std::uint8_t* data, std::size_t size)
  {
    bytes().write(data, size);
  }
  void write(const std::string& bytes)
  {
    this->bytes().write(bytes);
  }
  /// The link's requests and answers, for protocols over HTTP (LinkKind::HTTP). Throws std::logic_error on another
  /// link.
  HttpChannel& http();
  /// Gives up on this connection (it reopens after the link's backoff).
  void disconnect(const std::string& reason)
  {
    link_->disconnect(reason);
  }

  /// A state from the device (pan, tilt rad; zoom X). A possible one keeps the link alive and feeds the motion
  /// estimate; an impossible one (StatePlausibility) is dropped and counted, and if nothing but impossible states
  /// comes for state_timeout the link counts as lost, with the reason.
  void reportState(const AxisValues& position);
  /// A valid answer that carries no state: keeps the link alive.
  void reportAlive();
  /**
   * \brief The protocol's reply deadline is now \p reply_deadline s (TransactionChannel learns it from the device's
   * answers): the state deadline becomes max(state_timeout, 3 * reply_deadline + poll_period).
   *
   * One answer lost outright (a dropped datagram, a frame lost on the line, an answer past the ceiling under load)
   * costs its reply deadline, the drain after it (as long again, nothing goes out meanwhile), up to a poll period
   * before the next request, and that request's answer (within a third reply deadline): such a loss never loses the
   * link; a device silent for longer does. With two reply deadlines a single lost answer from a device answering in
   * 120 ms lost the link (and the goal under way). Any thread (the channel's constructor, then the I/O thread).
   */
  void replyDeadlineChanged(double reply_deadline);
  /// The protocol's framing threw \p bytes received bytes away (too long, unframed, incomplete): counted.
  void reportDropped(std::uint64_t bytes)
  {
    counters_.dropped_bytes += bytes;
  }
  /// The device refused or failed a request sent for command \p command (see currentCommand()). Counts as a fault
  /// only if no newer command has been given since.
  void reportFault(const std::string& text, std::uint64_t command);
  /// The serial number of the command being run; tag requests with it to report their faults.
  std::uint64_t currentCommand() const
  {
    return command_serial_;
  }
  /// The latest state estimate (position, velocity, moving), whatever the link.
  PtzSample estimate() const;
  /// What the protocol learnt of the device (limits, speeds).
  void setCapabilities(const Capabilities& capabilities);
  /// The lens' modes, positions and refusals, as the protocol learns them (any thread; the node reads them).
  LensReport& lens()
  {
    return lens_;
  }
  const LensReport& lens() const
  {
    return lens_;
  }
  /// The protocol knows the device on this connection (its set-up is done): the link may count as up.
  void ready();
  /// The device cannot be used as configured (e.g. a camera it does not have): start() fails with \p reason.
  void failStartup(const std::string& reason);
  /// Something the user must know that does not stop the backend (a guess, a contradiction): reaches the node once
  /// per text, however often it is given (PtzBackend::takeWarnings()). Any thread.
  void warn(const std::string& text);

private:
  ByteLink& bytes();
  void onLinkUp() override;
  void onLinkBytes(const std::uint8_t* data, std::size_t size) override;
  void onLinkDown(const std::string& reason) override;

  void tick();
  /// Counts a loss if the link was up and is not any more (call with mutex_ held).
  void checkLinkLocked() const;
  /// Brings the link up if it now is, and runs the recovery once after a loss (I/O thread, mutex_ not held).
  void refreshLink();
  /// Begins the goodbye (I/O thread): the protocol's shutdown(), then finishStop() when written or at the grace time.
  void beginStop(std::shared_ptr<std::promise<void>> stopped);
  /// Closes for good (I/O thread, once): timers, link, protocol; then fulfils the promise from a fence behind them.
  void finishStop();

  const DeviceSessionConfig config_;
  const std::shared_ptr<const Clock> clock_;
  DeviceIoPool::Lease io_;      ///< first: the link and the timers below live on its context, and go before it
  std::unique_ptr<Link> link_;  ///< after io_: its handlers live on it
  boost::asio::steady_timer tick_timer_;
  boost::asio::steady_timer grace_timer_;
  DeviceProtocol* protocol_ = nullptr;

  // Guarded by post_mutex_: whether handlers may still be queued for the session (any thread).
  std::mutex post_mutex_;
  bool started_ = false;
  bool stop_begun_ = false;

  // I/O thread only.
  bool stopping_ = false;                        ///< beginStop() has run: no more polls
  bool closing_ = false;                         ///< finishStop() has run: nothing new may start
  std::shared_ptr<std::promise<void>> stopped_;  ///< fulfilled by the fence behind the last handlers
  std::uint64_t command_serial_ = 0;
  std::function<void()> state_listener_;  ///< set before start()

  // Shared; guarded by mutex_. Mutable: sample() notices a silent link and counts the loss itself.
  mutable std::mutex mutex_;
  Capabilities capabilities_;
  mutable LinkSupervisor supervisor_;        ///< up or down, losses, start-up; mutable: sample() counts a silence
  mutable StatePlausibility plausibility_;   ///< mutable: a loss noticed in sample() makes it forget its reference
  std::vector<std::string> warnings_given_;  ///< every text warn() was given, once
  std::size_t warnings_taken_ = 0;           ///< how many of them takeWarnings() has handed out
  MotionEstimator motion_;
  AxisValues last_position_{ { 0.0, 0.0, 1.0 } };
  std::uint64_t fault_count_ = 0;
  std::string last_fault_;
  mutable DeviceSessionCounters counters_;
  LensReport lens_;  ///< thread-safe on its own
};

}  // namespace ptz_action_server

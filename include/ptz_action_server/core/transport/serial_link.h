/**
 * \file
 * \brief A serial port (8N1) on Boost.Asio, with its own I/O thread, reconnection with backoff, and detection of a
 * port that vanished or was replaced under the same path (a udev symlink pointing to a new device).
 */
#pragma once

#include <sys/types.h>

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/serial_port.hpp>
#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/core/backend.h"

namespace ptz_action_server
{
struct SerialLinkConfig
{
  std::string path;              ///< e.g. /dev/ttyUSB0, or a udev / emulator symlink
  unsigned baud = 9600;          ///< standard rates only (a pseudo-terminal accepts no others)
  double reconnect_min = 0.05;   ///< s before the first reopen attempt
  double reconnect_max = 2.0;    ///< s between attempts, at most (the wait doubles up to it)
  double identity_check = 0.25;  ///< s between checks that the path still names the open device
};

struct SerialLinkCounters
{
  std::uint64_t opens = 0;
  std::uint64_t open_failures = 0;
  std::uint64_t disconnects = 0;
  std::uint64_t bytes_in = 0;
  std::uint64_t bytes_out = 0;
};

/**
 * \brief Owns a serial port and the thread that runs its Boost.Asio event loop.
 *
 * Everything the protocol does runs on that thread: the Listener's callbacks, write(), disconnect() and the
 * protocol's own timers on context(). Other threads hand work over with post().
 */
class SerialLink
{
public:
  /// Called on the I/O thread.
  class Listener
  {
  public:
    virtual ~Listener() = default;
    /// The port is open (again): whatever the device knew may be gone.
    virtual void onConnected() = 0;
    virtual void onBytes(const std::uint8_t* data, std::size_t size) = 0;
    /// The port is closed; reopening is under way.
    virtual void onDisconnected(const std::string& reason) = 0;
  };

  SerialLink(const SerialLinkConfig& config, Listener& listener);
  ~SerialLink();
  SerialLink(const SerialLink&) = delete;
  SerialLink& operator=(const SerialLink&) = delete;

  /// Starts the I/O thread, which opens the port (and keeps reopening it).
  void start();
  /// Stops and joins the I/O thread; the port is closed. Safe to call twice.
  void stop();

  /// Runs \p work on the I/O thread. Any thread.
  void post(std::function<void()> work);
  boost::asio::io_context& context()
  {
    return context_;
  }

  /// Queues bytes for the port. I/O thread only; dropped while disconnected.
  void write(const std::string& bytes);
  void write(const std::uint8_t* data, std::size_t size);
  /// Closes the port (a protocol-level failure) and schedules a reopen. I/O thread only.
  void disconnect(const std::string& reason);
  /// I/O thread only.
  bool connected() const
  {
    return connected_;
  }

  SerialLinkCounters counters() const;
  /// Last reason the port closed or failed to open ("" if none). Any thread.
  std::string lastError() const;
  /// The port, its rate, opens, failures and losses, for a backend's diagnostics. Any thread.
  void diagnostics(std::vector<DiagnosticValue>& values) const;

private:
  void open();
  void scheduleReopen();
  void startRead();
  void startWrite();
  void checkIdentity();

  const SerialLinkConfig config_;
  Listener& listener_;
  boost::asio::io_context context_;
  boost::asio::serial_port port_;
  boost::asio::steady_timer reopen_timer_;
  boost::asio::steady_timer identity_timer_;
  std::array<std::uint8_t, 512> read_buffer_{};
  std::deque<std::vector<std::uint8_t>> write_queue_;
  bool connected_ = false;
  double backoff_ = 0.0;
  dev_t device_ = 0;  ///< st_rdev of the open device
  ino_t inode_ = 0;   ///< st_ino of the open device node

  mutable std::mutex counters_mutex_;
  SerialLinkCounters counters_;
  std::string last_error_;

  std::thread thread_;
};

}  // namespace ptz_action_server

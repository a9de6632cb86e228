/**
 * \file
 * \brief The serial end of a device emulator: a pseudo-terminal paced at a baud rate, with faults on demand.
 */
#pragma once

#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
struct PtyDeviceConfig
{
  /// Keep this symlink pointing at the current pseudo-terminal (so an unplug/replug keeps one path, like udev).
  /// Empty: no link; use path().
  std::string link;
  /// Open this existing tty instead of creating a pseudo-terminal (no unplug/replug then).
  std::string tty;
  unsigned baud = 9600;       ///< bytes are paced at 10 bits each (8N1): a pseudo-terminal does not pace by itself
  double tick_period = 0.05;  ///< s between onTick() calls, for devices that report on their own
};

/**
 * \brief A pseudo-terminal whose other end behaves like a serial line at \p baud. Owns its I/O thread.
 *
 * Received bytes reach the handler when the last of them would have arrived over the wire; sent bytes leave at
 * the line's pace. Faults: silent (input ignored, nothing sent), garbled output bytes, unplug (the port closes and
 * the link disappears) and replug (a new pseudo-terminal under the same link).
 */
class PtyDevice
{
public:
  /// Called on the I/O thread with bytes and the time the last of them arrived.
  using BytesHandler = std::function<void(const std::uint8_t* data, std::size_t size, TimePoint arrived_at)>;
  using TickHandler = std::function<void()>;

  PtyDevice(const PtyDeviceConfig& config, BytesHandler on_bytes, TickHandler on_tick = TickHandler());
  ~PtyDevice();
  PtyDevice(const PtyDevice&) = delete;
  PtyDevice& operator=(const PtyDevice&) = delete;

  /// Starts the I/O thread (call once the handlers can run).
  void start();

  /// The path clients open: the link if configured, else the pseudo-terminal's own path.
  std::string path() const;
  /// Seconds one byte takes on the wire.
  double byteTime() const
  {
    return 10.0 / config_.baud;
  }

  /// Queues bytes to send, paced. Any thread.
  void send(const std::uint8_t* data, std::size_t size);
  void send(const std::string& text);

  void setSilent(bool silent);
  void setGarbleRatio(double ratio);
  /// Closes the port and removes the link: the client sees its device vanish.
  void unplug();
  /// A new pseudo-terminal under the same link.
  void replug();
  bool plugged() const;

  std::uint64_t bytesGarbled() const
  {
    return bytes_garbled_;
  }

private:
  struct Pending
  {
    TimePoint at;
    std::vector<std::uint8_t> bytes;
  };
  struct OutputByte
  {
    TimePoint at;  ///< when the byte has crossed the line
    std::uint8_t byte;
  };

  void openPort();
  void closePort();
  void run();
  void wake();

  const PtyDeviceConfig config_;
  BytesHandler on_bytes_;
  TickHandler on_tick_;

  mutable std::mutex mutex_;  ///< guards the port, the queues and the path
  int master_ = -1;
  int slave_ = -1;  ///< kept open so the master never sees a hang-up while the client reconnects
  std::string pty_path_;
  std::deque<OutputByte> output_;  ///< bytes waiting to be sent, in order
  TimePoint output_free_at_{};     ///< when the last queued output byte has crossed the line
  std::deque<Pending> input_;      ///< bytes received, waiting for their wire arrival time
  TimePoint input_free_at_{};

  std::atomic<bool> silent_{ false };
  std::atomic<double> garble_ratio_{ 0.0 };
  std::atomic<std::uint64_t> bytes_garbled_{ 0 };
  std::mt19937 random_{ 4242 };
  int wake_fd_ = -1;
  std::atomic<bool> running_{ false };
  std::thread thread_;
};

}  // namespace ptz_action_server

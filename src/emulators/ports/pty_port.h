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
#include <string>
#include <thread>
#include <vector>

#include "ptz_action_server/emulators/ports/device_port.h"

namespace ptz_action_server
{
/**
 * \brief A pseudo-terminal whose other end behaves like a serial line at \p baud. Owns its I/O thread.
 *
 * Received bytes reach the handler when the last of them would have arrived over the wire; sent bytes leave at
 * the line's pace, in packets of up to 64 bytes as a USB serial adapter delivers them, each written to the terminal
 * once its last byte has crossed the line (a frame reaches the client when it would have ended on the wire). As on a
 * real line, bytes sent or leaving while no client has the port open are lost (a
 * pseudo-terminal would keep them for the next opener), and so is what a client had not read when it closed the port.
 * Faults: silent (input ignored, nothing sent), garbled output bytes, unplug (the port closes and the link disappears)
 * and replug (a new pseudo-terminal under the same link).
 */
class PtyPort : public DevicePort
{
public:
  PtyPort(const DevicePortConfig& config, Handlers handlers);
  ~PtyPort() override;
  PtyPort(const PtyPort&) = delete;
  PtyPort& operator=(const PtyPort&) = delete;

  void start() override;
  /// The link if configured, else the pseudo-terminal's own path.
  std::string path() const override;
  double byteTime() const override
  {
    return 10.0 / config_.baud;
  }
  /// Queues bytes to send, paced; drops them if no client has the port open. Any thread.
  void send(const std::uint8_t* data, std::size_t size) override;
  /// Closes the port and removes the link.
  void unplug() override;
  /// A new pseudo-terminal under the same link.
  void replug() override;
  std::uint64_t bytesLost() const override
  {
    return bytes_lost_;
  }

private:
  struct Pending
  {
    TimePoint at;
    std::vector<std::uint8_t> bytes;
  };
  void openPort();
  void closePort();
  void run();
  void wake();
  /// True while a client has the terminal open (always for an existing tty). mutex_ held.
  bool clientPresentLocked() const;
  /// Discards what the last client left unread, as closing a serial port does. mutex_ held.
  void discardUnreadLocked();

  const DevicePortConfig config_;
  const Handlers handlers_;

  mutable std::mutex mutex_;  ///< guards the port, the queues and the path
  int master_ = -1;
  std::string pty_path_;
  std::deque<Pending> output_;  ///< packets waiting to be sent, in order, each due when its last byte has crossed
  TimePoint output_free_at_{};  ///< when the last queued output byte has crossed the line
  std::deque<Pending> input_;   ///< bytes received, waiting for their wire arrival time
  TimePoint input_free_at_{};

  std::atomic<std::uint64_t> bytes_lost_{ 0 };

  int wake_fd_ = -1;
  std::atomic<bool> running_{ false };
  std::thread thread_;
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief The device end of an emulator's line: a pseudo-terminal paced at a baud rate, or a TCP server (a unit on
 * Ethernet, or a serial device behind a serial-to-Ethernet server). Faults on demand.
 */
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <random>
#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
struct DevicePortConfig
{
  enum class Kind
  {
    PTY,  ///< a pseudo-terminal (a serial line)
    TCP,  ///< a TCP server; one client at a time, a new one replaces the old (unless many_clients)
    UDP,  ///< a UDP socket; answers go to whoever wrote last
  };
  Kind kind = Kind::PTY;
  /// pty: keep this symlink pointing at the current pseudo-terminal (so an unplug/replug keeps one path, like udev).
  /// Empty: no link; use path().
  std::string link;
  /// pty: open this existing tty instead of creating a pseudo-terminal (no unplug/replug then).
  std::string tty;
  unsigned baud = 9600;            ///< pty: bytes are paced at 10 bits each (8N1), as a real line does
  std::string host = "127.0.0.1";  ///< tcp, udp: where to listen
  std::uint16_t port = 0;          ///< tcp, udp: 0 = any free port (see tcpPort(), udpPort())
  bool many_clients = false;       ///< tcp: every client served at once (sender(), sendTo(), disconnect())
  double tick_period = 0.05;       ///< s between tick handler calls, for devices that report on their own
};

/**
 * \brief One end of a line to a client. Owns its I/O thread; the handlers run on it.
 *
 * Faults (any thread): silent (input ignored, nothing sent), garbled output bytes, unplug (the port closes; a
 * pseudo-terminal's link disappears, a TCP server stops listening) and replug.
 */
class DevicePort
{
public:
  /// Bytes from the client, and the time the last of them arrived.
  using BytesHandler = std::function<void(const std::uint8_t* data, std::size_t size, TimePoint arrived_at)>;
  struct Handlers
  {
    BytesHandler on_bytes;
    std::function<void()> on_tick;        ///< every tick_period (optional)
    std::function<void()> on_connect;     ///< tcp: a client connected (optional; sender() names it)
    std::function<void()> on_disconnect;  ///< tcp: a client's connection closed (optional; sender() names it)
  };

  static std::unique_ptr<DevicePort> create(const DevicePortConfig& config, Handlers handlers);
  virtual ~DevicePort() = default;

  /// Starts the I/O thread (call once the handlers can run).
  virtual void start() = 0;
  /// What a client opens: the pseudo-terminal's path (or link), or "host:port".
  virtual std::string path() const = 0;
  /// tcp: the port clients connect to; 0 for a pseudo-terminal.
  virtual std::uint16_t tcpPort() const
  {
    return 0;
  }
  /// udp: the port datagrams go to; 0 otherwise.
  virtual std::uint16_t udpPort() const
  {
    return 0;
  }
  /// Seconds one byte takes on the wire (0 on TCP).
  virtual double byteTime() const = 0;
  /// Queues bytes for the client (paced on a pseudo-terminal; lost if no client has the port open when they are sent
  /// or leave, as on a real line). Any thread.
  virtual void send(const std::uint8_t* data, std::size_t size) = 0;
  void send(const std::string& text)
  {
    send(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  }
  /// udp, tcp: the client a handler runs for (the datagram's sender; the connection's other end), as "host:port"
  /// (I/O thread, inside a handler); "" elsewhere.
  virtual std::string sender() const
  {
    return std::string();
  }
  /// udp, tcp: to \p peer ("host:port", as sender() gives it) rather than to the last sender or the newest client
  /// (lost if there is no such connection); elsewhere the same as send(). Any thread.
  virtual void sendTo(const std::string& /*peer*/, const std::uint8_t* data, std::size_t size)
  {
    send(data, size);
  }
  /// tcp: closes \p peer's connection (on_disconnect follows); nothing elsewhere. Any thread.
  virtual void disconnect(const std::string& /*peer*/)
  {
  }
  /// The client sees its device vanish.
  virtual void unplug() = 0;
  /// The device is back (a new pseudo-terminal under the same link, or listening again on the same port).
  virtual void replug() = 0;

  void setSilent(bool silent)
  {
    silent_ = silent;
  }
  bool silent() const
  {
    return silent_;
  }
  /// The next \p count arrivals of bytes (a request each, as clients write them) are ignored: requests lost on the way.
  void ignoreNextInputs(std::uint64_t count)
  {
    inputs_to_ignore_ = count;
  }
  void setGarbleRatio(double ratio);
  std::uint64_t bytesGarbled() const
  {
    return bytes_garbled_;
  }
  /// While \p on, every byte sent is replaced by \p filler (a byte that neither ends nor starts anything in the
  /// protocol): the device's replies become one reply that never ends, at the rate and size of the real ones.
  void setEndless(bool on, std::uint8_t filler = 'A')
  {
    endless_filler_ = filler;
    endless_ = on;
  }
  /// pty: bytes sent while no client had the port open (or leaving after it closed it).
  virtual std::uint64_t bytesLost() const
  {
    return 0;
  }

protected:
  /// Whether the bytes that just arrived reach the device: not while silent, nor while inputs are to be ignored.
  bool takesInput()
  {
    if (silent_)
    {
      return false;
    }
    std::uint64_t ignored = inputs_to_ignore_.load();
    while (ignored > 0)
    {
      if (inputs_to_ignore_.compare_exchange_weak(ignored, ignored - 1))
      {
        return false;
      }
    }
    return true;
  }
  /// Replaces the configured share of \p bytes with random ones. One thread at a time.
  void garble(std::uint8_t* bytes, std::size_t size);

private:
  std::atomic<bool> silent_{ false };
  std::atomic<std::uint64_t> inputs_to_ignore_{ 0 };
  std::atomic<double> garble_ratio_{ 0.0 };
  std::atomic<bool> endless_{ false };
  std::atomic<std::uint8_t> endless_filler_{ 'A' };
  std::atomic<std::uint64_t> bytes_garbled_{ 0 };
  std::mt19937 random_{ 4242 };
};

/**
 * \brief Destroys \p port, which keeps pointing at it until its I/O thread has stopped: the handlers that still run
 * meanwhile (a close already queued, a datagram being answered) may answer through it. What an owner's destructor
 * does first (unique_ptr::reset() would let go of the pointer before the thread stops).
 */
inline void destroyPort(std::unique_ptr<DevicePort>& port)
{
  delete port.get();
  static_cast<void>(port.release());
}

}  // namespace ptz_action_server

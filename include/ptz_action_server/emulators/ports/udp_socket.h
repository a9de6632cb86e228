/**
 * \file
 * \brief A UDP socket for the backends and device emulators: non-blocking sends, receives with a deadline, and a
 * wake-up so an I/O thread blocked in receive() can be told to stop.
 */
#pragma once

#include <netinet/in.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace ptz_action_server
{
/// An IPv4 address and port.
struct UdpEndpoint
{
  sockaddr_in address{};

  /// Resolves \p host (a dotted quad or a name) and \p port. Throws BackendError when it cannot.
  static UdpEndpoint resolve(const std::string& host, std::uint16_t port);
  std::string toString() const;
  std::uint16_t port() const;
  bool operator==(const UdpEndpoint& other) const;
  bool operator!=(const UdpEndpoint& other) const
  {
    return !(*this == other);
  }
};

/// Outcome of UdpSocket::receive().
enum class ReceiveStatus
{
  DATAGRAM,     ///< a datagram arrived
  TIMEOUT,      ///< nothing before the deadline
  INTERRUPTED,  ///< interrupt() was called
};

/// Thread-safe for one receiving thread and any number of sending threads.
class UdpSocket
{
public:
  UdpSocket();
  ~UdpSocket();
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  /// Binds to \p host:\p port (port 0: an ephemeral port). Throws BackendError.
  void bind(const std::string& host, std::uint16_t port);
  /// The bound endpoint (with the ephemeral port filled in).
  UdpEndpoint localEndpoint() const;

  /// Sends one datagram without blocking. False if the kernel refused it (full buffer, unreachable).
  bool sendTo(const UdpEndpoint& to, const std::uint8_t* data, std::size_t size);

  /**
   * \brief Waits up to \p timeout_ms for one datagram (-1: no deadline).
   *
   * On DATAGRAM, \p size is its length (datagrams longer than \p capacity are truncated to it, and \p truncated is
   * set) and \p from its sender.
   */
  ReceiveStatus receive(std::uint8_t* buffer, std::size_t capacity, std::size_t& size, UdpEndpoint& from,
                        int timeout_ms, bool* truncated = nullptr);

  /// Makes a receive() in progress (or the next one) return INTERRUPTED. Any thread.
  void interrupt();

private:
  int socket_ = -1;
  int wake_fd_ = -1;  ///< eventfd: written by interrupt(), polled by receive()
};

}  // namespace ptz_action_server

#include "ptz_action_server/emulators/ports/udp_socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
UdpEndpoint UdpEndpoint::resolve(const std::string& host, std::uint16_t port)
{
  UdpEndpoint endpoint;
  endpoint.address.sin_family = AF_INET;
  endpoint.address.sin_port = htons(port);
  if (inet_pton(AF_INET, host.c_str(), &endpoint.address.sin_addr) == 1)
  {
    return endpoint;
  }
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* found = nullptr;
  const int status = getaddrinfo(host.c_str(), nullptr, &hints, &found);
  if (status != 0 || found == nullptr)
  {
    throw BackendError("cannot resolve host '" + host + "': " + gai_strerror(status));
  }
  endpoint.address.sin_addr = reinterpret_cast<sockaddr_in*>(found->ai_addr)->sin_addr;
  freeaddrinfo(found);
  return endpoint;
}

std::string UdpEndpoint::toString() const
{
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &address.sin_addr, text, sizeof(text));
  return std::string(text) + ":" + std::to_string(port());
}

std::uint16_t UdpEndpoint::port() const
{
  return ntohs(address.sin_port);
}

bool UdpEndpoint::operator==(const UdpEndpoint& other) const
{
  return address.sin_addr.s_addr == other.address.sin_addr.s_addr && address.sin_port == other.address.sin_port;
}

UdpSocket::UdpSocket()
{
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  wake_fd_ = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (socket_ < 0 || wake_fd_ < 0)
  {
    const std::string reason = std::strerror(errno);
    if (socket_ >= 0)
    {
      ::close(socket_);
    }
    if (wake_fd_ >= 0)
    {
      ::close(wake_fd_);
    }
    throw BackendError("cannot create a UDP socket: " + reason);
  }
}

UdpSocket::~UdpSocket()
{
  ::close(socket_);
  ::close(wake_fd_);
}

void UdpSocket::bind(const std::string& host, std::uint16_t port)
{
  const UdpEndpoint endpoint = UdpEndpoint::resolve(host, port);
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&endpoint.address), sizeof(endpoint.address)) != 0)
  {
    throw BackendError("cannot bind UDP " + endpoint.toString() + ": " + std::strerror(errno));
  }
}

UdpEndpoint UdpSocket::localEndpoint() const
{
  UdpEndpoint endpoint;
  socklen_t length = sizeof(endpoint.address);
  ::getsockname(socket_, reinterpret_cast<sockaddr*>(&endpoint.address), &length);
  return endpoint;
}

bool UdpSocket::sendTo(const UdpEndpoint& to, const std::uint8_t* data, std::size_t size)
{
  const ssize_t sent =
      ::sendto(socket_, data, size, MSG_NOSIGNAL, reinterpret_cast<const sockaddr*>(&to.address), sizeof(to.address));
  return sent == static_cast<ssize_t>(size);
}

ReceiveStatus UdpSocket::receive(std::uint8_t* buffer, std::size_t capacity, std::size_t& size, UdpEndpoint& from,
                                 int timeout_ms, bool* truncated)
{
  size = 0;
  const TimePoint deadline = addSeconds(SteadyClock::now(), timeout_ms / 1000.0);
  while (true)
  {
    int remaining_ms = timeout_ms;
    if (timeout_ms > 0)
    {
      remaining_ms = std::max(0, static_cast<int>(std::ceil(secondsBetween(SteadyClock::now(), deadline) * 1000.0)));
    }
    pollfd descriptors[2] = { { socket_, POLLIN, 0 }, { wake_fd_, POLLIN, 0 } };
    const int ready = ::poll(descriptors, 2, remaining_ms);
    if (ready < 0 && errno == EINTR)
    {
      continue;
    }
    if (ready <= 0)
    {
      return ReceiveStatus::TIMEOUT;
    }
    if (descriptors[1].revents & POLLIN)
    {
      std::uint64_t count = 0;
      (void)!::read(wake_fd_, &count, sizeof(count));
      return ReceiveStatus::INTERRUPTED;
    }
    socklen_t length = sizeof(from.address);
    const ssize_t received =
        ::recvfrom(socket_, buffer, capacity, MSG_TRUNC, reinterpret_cast<sockaddr*>(&from.address), &length);
    if (received < 0)
    {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR || errno == ECONNREFUSED)
      {
        continue;  // spurious wake-up, or an ICMP error from an earlier send: not a datagram
      }
      return ReceiveStatus::TIMEOUT;
    }
    if (truncated)
    {
      *truncated = static_cast<std::size_t>(received) > capacity;
    }
    size = std::min(static_cast<std::size_t>(received), capacity);
    return ReceiveStatus::DATAGRAM;
  }
}

void UdpSocket::interrupt()
{
  const std::uint64_t one = 1;
  (void)!::write(wake_fd_, &one, sizeof(one));
}

}  // namespace ptz_action_server

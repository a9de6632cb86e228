/**
 * \file
 * \brief What the tests of the units on a line (FLIR PTU, Pelco-D) share: unique pseudo-terminal links, the link
 * config to reach them, a rest check, and clients that open a pseudo-terminal as a serial port or connect over TCP,
 * the way a third-party driver does.
 */
#pragma once

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// s to wait for anything that should happen: generous, a busy test machine may starve the I/O threads.
constexpr double LINE_TEST_WAIT = 20.0;
/// s without a reply before a backend's link is down: generous for the same reason (1 s was lost once beside two busy
/// processes).
constexpr double LINE_TEST_STATE_TIMEOUT = 1.5;

/// A path for a pseudo-terminal's link no other test (or test process) uses.
inline std::string uniqueLink(const char* name)
{
  static int counter = 0;
  return ::testing::TempDir() + "ptz_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
}

inline LinkConfig serialLink(const std::string& path, unsigned baud)
{
  LinkConfig link;
  link.path = path;
  link.baud = baud;
  return link;
}

/// The backend reports the device settled at \p pan, \p tilt (rad).
inline bool atRest(const PtzBackend& backend, double pan, double tilt)
{
  const PtzSample sample = backend.sample();
  return !sample.moving && std::abs(sample.position[PAN] - pan) < 2e-3 && std::abs(sample.position[TILT] - tilt) < 2e-3;
}

/// A driver's end of a line to a unit: what it writes, and reads as a serial library does. See PtyClient, TcpClient.
class LineClient
{
public:
  ~LineClient()
  {
    if (fd_ >= 0)
    {
      ::close(fd_);
    }
  }
  LineClient(const LineClient&) = delete;
  LineClient& operator=(const LineClient&) = delete;

  bool isOpen() const
  {
    return fd_ >= 0;
  }
  int fd() const
  {
    return fd_;
  }
  void write(const std::string& text)
  {
    ASSERT_EQ(::write(fd_, text.data(), text.size()), static_cast<ssize_t>(text.size()));
  }
  /// What arrives until \p count bytes have or \p timeout s pass (a serial library's read(count)).
  std::string read(std::size_t count, double timeout = LINE_TEST_WAIT)
  {
    return readUntil([count](const std::string& text) { return text.size() >= count; }, timeout);
  }
  /// What arrives up to and including the next LF, or until \p timeout s pass (a serial library's readline()).
  std::string readLine(double timeout = LINE_TEST_WAIT)
  {
    return readUntil([](const std::string& text) { return !text.empty() && text.back() == '\n'; }, timeout);
  }
  /// What arrives until the text ends with \p end, or \p timeout s pass.
  std::string readThrough(const std::string& end, double timeout = LINE_TEST_WAIT)
  {
    return readUntil(
        [&end](const std::string& text) {
          return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
        },
        timeout);
  }
  /// How many bytes arrived and wait to be read (a serial library's available()).
  std::size_t available() const
  {
    int count = 0;
    return ::ioctl(fd_, FIONREAD, &count) == 0 && count > 0 ? static_cast<std::size_t>(count) : 0;
  }
  /// Drops what arrived and was not read yet (a serial library's flush of its input).
  void flushInput()
  {
    ::tcflush(fd_, TCIFLUSH);
  }

protected:
  explicit LineClient(int fd) : fd_(fd)
  {
  }

private:
  /// Reads one byte at a time, so nothing beyond what \p done asks for is taken from the line.
  template <class Done>
  std::string readUntil(Done done, double timeout)
  {
    const TimePoint deadline = addSeconds(SteadyClock::now(), timeout);
    std::string text;
    while (!done(text))
    {
      const double left = secondsBetween(SteadyClock::now(), deadline);
      if (left <= 0.0)
      {
        break;
      }
      pollfd descriptor{ fd_, POLLIN, 0 };
      if (::poll(&descriptor, 1, static_cast<int>(std::ceil(left * 1000.0))) <= 0)
      {
        continue;
      }
      char byte = 0;
      if (::read(fd_, &byte, 1) == 1)
      {
        text.push_back(byte);
      }
    }
    return text;
  }

  int fd_ = -1;
};

/// A serial port opened on a pseudo-terminal, raw, as a driver opens its device.
class PtyClient : public LineClient
{
public:
  explicit PtyClient(const std::string& path)
    : LineClient(::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC))
  {
    termios settings{};
    if (isOpen() && ::tcgetattr(fd(), &settings) == 0)
    {
      ::cfmakeraw(&settings);
      ::tcsetattr(fd(), TCSANOW, &settings);
    }
  }
};

/// A TCP connection to \p port on 127.0.0.1 (an E-series unit's port 4000, a serial server's).
class TcpClient : public LineClient
{
public:
  explicit TcpClient(std::uint16_t port) : LineClient(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0))
  {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = isOpen() && ::connect(fd(), reinterpret_cast<const sockaddr*>(&address), sizeof(address)) == 0;
  }
  bool isConnected() const
  {
    return connected_;
  }

private:
  bool connected_ = false;
};

}  // namespace ptz_action_server

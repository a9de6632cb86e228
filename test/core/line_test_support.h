/**
 * \file
 * \brief What the tests of the units on a line (FLIR PTU, Pelco-D) share: unique pseudo-terminal links, the link
 * config to reach them, a rest check, and a client that opens a pseudo-terminal as a serial port, the way a
 * third-party driver does.
 */
#pragma once

#include <fcntl.h>
#include <poll.h>
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
/// s without a reply before a backend's link is down: generous for the same reason.
constexpr double LINE_TEST_STATE_TIMEOUT = 1.0;

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

/// A serial port opened on a pseudo-terminal, raw, as a driver opens its device.
class PtyClient
{
public:
  explicit PtyClient(const std::string& path) : fd_(::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC))
  {
    termios settings{};
    if (fd_ >= 0 && ::tcgetattr(fd_, &settings) == 0)
    {
      ::cfmakeraw(&settings);
      ::tcsetattr(fd_, TCSANOW, &settings);
    }
  }
  ~PtyClient()
  {
    if (fd_ >= 0)
    {
      ::close(fd_);
    }
  }
  PtyClient(const PtyClient&) = delete;
  PtyClient& operator=(const PtyClient&) = delete;

  bool isOpen() const
  {
    return fd_ >= 0;
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
  /// Drops what arrived and was not read yet (a serial library's flush of its input).
  void flushInput()
  {
    ::tcflush(fd_, TCIFLUSH);
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

}  // namespace ptz_action_server

#include "pty_port.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/eventfd.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace ptz_action_server
{
namespace
{
/// s between looks for a client while none has the port open.
constexpr double PRESENCE_CHECK = 0.01;
/// Bytes written to the terminal at once at most: a USB serial adapter's packet. A write per byte (11,000 a second at
/// 115200 baud) queues as many flushes on the kernel's one tty worker, which CPU-bound processes on every core then
/// starve: a 1-byte pseudo-terminal round trip took up to 8 s beside four such emulators and two busy `yes`.
constexpr std::size_t OUTPUT_PACKET = 64;

void makeRaw(int fd)
{
  termios settings{};
  if (tcgetattr(fd, &settings) == 0)
  {
    cfmakeraw(&settings);
    tcsetattr(fd, TCSANOW, &settings);
  }
}
}  // namespace

PtyPort::PtyPort(const DevicePortConfig& config, Handlers handlers) : config_(config), handlers_(std::move(handlers))
{
  wake_fd_ = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (wake_fd_ < 0)
  {
    throw BackendError(std::string("eventfd: ") + std::strerror(errno));
  }
  std::lock_guard<std::mutex> lock(mutex_);
  openPort();
}

PtyPort::~PtyPort()
{
  running_ = false;
  wake();
  if (thread_.joinable())
  {
    thread_.join();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  closePort();
  ::close(wake_fd_);
}

void PtyPort::start()
{
  running_ = true;
  thread_ = std::thread(&PtyPort::run, this);
}

std::string PtyPort::path() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return config_.link.empty() ? pty_path_ : config_.link;
}

void PtyPort::openPort()
{
  if (!config_.tty.empty())
  {
    master_ = ::open(config_.tty.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (master_ < 0)
    {
      throw BackendError("cannot open " + config_.tty + ": " + std::strerror(errno));
    }
    makeRaw(master_);
    pty_path_ = config_.tty;
    return;
  }
  char name[256] = {};
  int slave = -1;
  if (::openpty(&master_, &slave, name, nullptr, nullptr) != 0)
  {
    throw BackendError(std::string("openpty: ") + std::strerror(errno));
  }
  // The settings stay with the terminal while the master is open; the slave end is the client's alone, so the
  // master sees when nobody has it open (a hang-up) and output can be lost as on a real line.
  makeRaw(slave);
  ::close(slave);
  ::fcntl(master_, F_SETFL, ::fcntl(master_, F_GETFL) | O_NONBLOCK);
  ::fcntl(master_, F_SETFD, FD_CLOEXEC);
  pty_path_ = name;
  if (!config_.link.empty())
  {
    // Replace the link atomically, as udev does: a client never sees a half-made path.
    const std::string temporary = config_.link + ".new";
    ::unlink(temporary.c_str());
    if (::symlink(name, temporary.c_str()) != 0 || ::rename(temporary.c_str(), config_.link.c_str()) != 0)
    {
      throw BackendError("cannot link " + config_.link + " to " + name + ": " + std::strerror(errno));
    }
  }
}

bool PtyPort::clientPresentLocked() const
{
  if (master_ < 0)
  {
    return false;
  }
  if (!config_.tty.empty())
  {
    return true;
  }
  pollfd descriptor{ master_, POLLIN, 0 };
  return ::poll(&descriptor, 1, 0) >= 0 && !(descriptor.revents & POLLHUP);
}

void PtyPort::discardUnreadLocked()
{
  if (!config_.tty.empty() || pty_path_.empty())
  {
    return;
  }
  const int slave = ::open(pty_path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (slave >= 0)
  {
    ::tcflush(slave, TCIFLUSH);
    ::close(slave);
  }
}

void PtyPort::closePort()
{
  if (master_ >= 0)
  {
    ::close(master_);
    master_ = -1;
  }
  if (!config_.link.empty())
  {
    ::unlink(config_.link.c_str());
  }
  output_.clear();
  input_.clear();
}

void PtyPort::send(const std::uint8_t* data, std::size_t size)
{
  if (silent())
  {
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (master_ < 0)
    {
      return;
    }
    if (!clientPresentLocked())
    {
      // Nobody listens: a line drops them, whereas the terminal would keep them for the next opener.
      bytes_lost_ += size;
      return;
    }
    // Each packet reaches the client once the ten bits of its last byte have crossed the line.
    const double byte_time = byteTime();
    for (std::size_t offset = 0; offset < size; offset += OUTPUT_PACKET)
    {
      const std::size_t count = std::min(OUTPUT_PACKET, size - offset);
      output_free_at_ = addSeconds(std::max(SteadyClock::now(), output_free_at_), count * byte_time);
      output_.push_back(Pending{ output_free_at_, std::vector<std::uint8_t>(data + offset, data + offset + count) });
    }
  }
  wake();
}

void PtyPort::unplug()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (config_.tty.empty())
    {
      closePort();
    }
  }
  wake();
}

void PtyPort::replug()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (master_ < 0)
    {
      openPort();
    }
  }
  wake();
}

void PtyPort::wake()
{
  const std::uint64_t one = 1;
  (void)!::write(wake_fd_, &one, sizeof(one));
}

void PtyPort::run()
{
  const double byte_time = byteTime();
  TimePoint next_tick = SteadyClock::now();  // the first tick runs at once
  std::uint8_t buffer[1024];
  bool present = false;
  while (running_)
  {
    // 1. Work out how long to sleep: the next paced packet out, the next input delivery, the next tick; while no client
    // has the port open, the next look for one (nothing tells the master when its slave is opened).
    TimePoint now = SteadyClock::now();
    TimePoint wake_at = handlers_.on_tick ? next_tick : addSeconds(now, 3600.0);
    int master = -1;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const bool was_present = present;
      present = clientPresentLocked();
      if (was_present && !present && master_ >= 0)
      {
        discardUnreadLocked();
      }
      // A master without a client polls as hung up at once: wait for a client instead of spinning on it.
      master = present ? master_ : -1;
      if (!present)
      {
        wake_at = std::min(wake_at, addSeconds(now, PRESENCE_CHECK));
      }
      if (!output_.empty())
      {
        wake_at = std::min(wake_at, output_.front().at);
      }
      if (!input_.empty())
      {
        wake_at = std::min(wake_at, input_.front().at);
      }
    }
    const double wait = std::max(0.0, secondsBetween(now, wake_at));
    timespec timeout{ static_cast<time_t>(wait), static_cast<long>((wait - std::floor(wait)) * 1e9) };
    pollfd descriptors[2] = { { wake_fd_, POLLIN, 0 }, { master, POLLIN, 0 } };
    const int ready = ::ppoll(descriptors, master >= 0 ? 2 : 1, &timeout, nullptr);
    if (ready > 0 && (descriptors[0].revents & POLLIN))
    {
      std::uint64_t count = 0;
      (void)!::read(wake_fd_, &count, sizeof(count));
    }
    if (!running_)
    {
      break;
    }
    now = SteadyClock::now();

    // 2. Bytes from the client: they "arrive" at the line's pace. (A hang-up is noticed at the next look.)
    if (ready > 0 && master >= 0 && (descriptors[1].revents & POLLIN))
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const ssize_t size = master_ >= 0 ? ::read(master_, buffer, sizeof(buffer)) : -1;
      if (size > 0)
      {
        input_free_at_ = addSeconds(std::max(now, input_free_at_), size * byte_time);
        input_.push_back(Pending{ input_free_at_, std::vector<std::uint8_t>(buffer, buffer + size) });
      }
    }

    // 3. Hand over the input whose time has come.
    while (true)
    {
      Pending arrived;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (input_.empty() || input_.front().at > now)
        {
          break;
        }
        arrived = std::move(input_.front());
        input_.pop_front();
      }
      if (takesInput())
      {
        handlers_.on_bytes(arrived.bytes.data(), arrived.bytes.size(), arrived.at);
      }
    }

    // 4. Send the output packets whose time has come, in one write; with nobody at the other end, they are lost.
    {
      std::lock_guard<std::mutex> lock(mutex_);
      std::vector<std::uint8_t> chunk;
      while (!output_.empty() && output_.front().at <= now)
      {
        chunk.insert(chunk.end(), output_.front().bytes.begin(), output_.front().bytes.end());
        output_.pop_front();
      }
      if (!chunk.empty() && clientPresentLocked())
      {
        garble(chunk.data(), chunk.size());
        (void)!::write(master_, chunk.data(), chunk.size());
      }
      else
      {
        bytes_lost_ += chunk.size();
      }
    }

    // 5. The device's own periodic work.
    if (handlers_.on_tick && now >= next_tick)
    {
      next_tick = addSeconds(now, config_.tick_period);
      handlers_.on_tick();
    }
  }
}

}  // namespace ptz_action_server

/**
 * \file
 * \brief The shared pool of device I/O threads: sizing, least-loaded placement, a bounded thread count with many
 * sessions, and teardown that leaves no handler behind on a thread other sessions keep running.
 */
#include <gtest/gtest.h>

#include <dirent.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "ptz_action_server/core/device/device_io_pool.h"
#include "ptz_action_server/core/device/device_protocol.h"
#include "ptz_action_server/core/device/device_session.h"
#include "ptz_action_server/core/device/transaction_channel.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"
#include "wait_until.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = 10.0;

/// Threads of this process now.
std::size_t countThreads()
{
  std::size_t count = 0;
  DIR* tasks = ::opendir("/proc/self/task");
  if (tasks == nullptr)
  {
    return 0;
  }
  while (const dirent* entry = ::readdir(tasks))
  {
    count += entry->d_name[0] != '.' ? 1 : 0;
  }
  ::closedir(tasks);
  return count;
}

/// A UDP device that answers every datagram with one of its own, whoever sent it: one for many sessions.
class Responder
{
public:
  Responder()
  {
    socket_.bind("127.0.0.1", 0);
    thread_ = std::thread([this] {
      std::uint8_t buffer[256];
      std::size_t size = 0;
      UdpEndpoint from;
      while (socket_.receive(buffer, sizeof(buffer), size, from, -1) == ReceiveStatus::DATAGRAM)
      {
        const std::uint8_t answer[] = { 'S', '\n' };
        socket_.sendTo(from, answer, sizeof(answer));
      }
    });
  }
  ~Responder()
  {
    socket_.interrupt();
    thread_.join();
  }
  std::uint16_t port() const
  {
    return socket_.localEndpoint().port();
  }

private:
  UdpSocket socket_;
  std::thread thread_;
};

/// A TCP device that accepts and then never reads nor writes. Its small receive window keeps a large write in flight.
class SilentAcceptor
{
public:
  SilentAcceptor()
  {
    listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
    const int small = 4096;
    ::setsockopt(listener_, SOL_SOCKET, SO_RCVBUF, &small, sizeof(small));  // inherited by accepted sockets
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof(address);
    if (::bind(listener_, reinterpret_cast<sockaddr*>(&address), length) != 0 || ::listen(listener_, 64) != 0 ||
        ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length) != 0)
    {
      throw std::runtime_error("cannot listen on 127.0.0.1");
    }
    port_ = ntohs(address.sin_port);
    thread_ = std::thread([this] {
      while (!done_)
      {
        pollfd ready{ listener_, POLLIN, 0 };
        if (::poll(&ready, 1, 20) == 1)
        {
          const int accepted = ::accept(listener_, nullptr, nullptr);
          std::lock_guard<std::mutex> lock(mutex_);
          accepted_.push_back(accepted);
        }
      }
    });
  }
  ~SilentAcceptor()
  {
    done_ = true;
    thread_.join();
    dropConnections();
    ::close(listener_);
  }
  std::uint16_t port() const
  {
    return port_;
  }
  /// Closes what was accepted so far (the session's end is gone by now).
  void dropConnections()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (int accepted : accepted_)
    {
      ::close(accepted);
    }
    accepted_.clear();
  }

private:
  int listener_ = -1;
  std::uint16_t port_ = 0;
  std::atomic<bool> done_{ false };
  std::mutex mutex_;
  std::vector<int> accepted_;
  std::thread thread_;
};

/**
 * \brief A protocol that keeps every kind of operation busy: a large write on a stream link (in flight against a
 * device that does not read), a request with a reply timer (TransactionChannel) on every poll, commands that write.
 * Any datagram back is a state.
 */
class BusyProtocol : public DeviceProtocol
{
public:
  explicit BusyProtocol(DeviceSession& session)
    : session_(session)
    , channel_(
          session.context(), session.clock(), [&session](const std::string& bytes) { session.write(bytes); }, 0.05,
          [](const TransactionChannel::Request&) {})
  {
  }
  std::string name() const override
  {
    return "busy";
  }
  std::string deviceName() const override
  {
    return "the busy device";
  }
  Capabilities capabilities() const override
  {
    Capabilities capabilities;
    capabilities.axes[ZOOM].present = false;
    return capabilities;
  }
  void onConnected() override
  {
    channel_.reset();
    if (!session_.carriesDatagrams())
    {
      session_.write(std::string(8 * 1024 * 1024, 'x'));  // stays in flight: the device reads nothing
    }
  }
  void onReceived(const std::uint8_t*, std::size_t) override
  {
    channel_.complete();
    session_.ready();
    session_.reportState(AxisValues{ { 0.0, 0.0, 1.0 } });
  }
  void poll() override
  {
    if (!channel_.polling())
    {
      channel_.queue(TransactionChannel::Request{ "POLL\n", 0, true, session_.currentCommand(), true });
    }
  }
  void goTo(const AxisValues&) override
  {
    session_.write("GOTO\n");
  }
  void moveAtVelocity(const AxisValues&) override
  {
  }
  void stop() override
  {
  }
  void shutdown() override
  {
    session_.write("BYE\n");
  }
  void onClosing() override
  {
    channel_.close();
  }

private:
  DeviceSession& session_;
  TransactionChannel channel_;
};

/// A session and its protocol, stopped before the protocol goes (as DeviceBackend does).
struct Device
{
  Device(const LinkConfig& link, const DeviceSessionConfig& config, DeviceIoPool& pool)
    : session(std::make_unique<DeviceSession>(link, config, std::make_shared<SystemClock>(), pool))
    , protocol(std::make_unique<BusyProtocol>(*session))
  {
    session->attach(*protocol);
  }
  ~Device()
  {
    session->stop();
    protocol.reset();
    session.reset();
  }

  std::unique_ptr<DeviceSession> session;
  std::unique_ptr<BusyProtocol> protocol;
};

LinkConfig udpLink(std::uint16_t port)
{
  LinkConfig link;
  link.kind = LinkKind::UDP;
  link.port = port;
  return link;
}

LinkConfig tcpLink(std::uint16_t port)
{
  LinkConfig link;
  link.kind = LinkKind::TCP;
  link.port = port;
  return link;
}

/// Fast polls and timers, a short start-up wait and grace: many sessions come and go in a few seconds.
DeviceSessionConfig quickConfig()
{
  DeviceSessionConfig config;
  config.state_timeout = 0.5;
  config.poll_period = 0.005;
  config.startup_timeout = 0.03;
  config.shutdown_grace = 0.02;
  return config;
}
}  // namespace

TEST(DeviceIoPool, TakesItsSizeFromPtzIoThreadsWhenItIsACount)
{
  const char* saved = std::getenv("PTZ_IO_THREADS");
  const std::string before = saved != nullptr ? saved : "";
  ::setenv("PTZ_IO_THREADS", "3", 1);
  EXPECT_EQ(DeviceIoPool::sizeFromEnvironment(), 3u);
  for (const char* wrong : { "0", "-2", "three", "65", "" })
  {
    ::setenv("PTZ_IO_THREADS", wrong, 1);
    EXPECT_EQ(DeviceIoPool::sizeFromEnvironment(), 0u) << wrong;
  }
  if (saved != nullptr)
  {
    ::setenv("PTZ_IO_THREADS", before.c_str(), 1);
  }
  else
  {
    ::unsetenv("PTZ_IO_THREADS");
  }
  EXPECT_GE(DeviceIoPool::defaultSize(), 2u);
  EXPECT_LE(DeviceIoPool::defaultSize(), 4u);
}

TEST(DeviceIoPool, PlacesSessionsOnTheLeastLoadedThreadAndGivesBlockingLinksTheirOwn)
{
  DeviceIoPool pool(2);
  EXPECT_EQ(pool.runningThreads(), 0u);  // threads start with their first session
  DeviceIoPool::Lease first = pool.acquire();
  DeviceIoPool::Lease second = pool.acquire();
  EXPECT_NE(&first.context(), &second.context());
  EXPECT_EQ(pool.runningThreads(), 2u);
  {
    DeviceIoPool::Lease third = pool.acquire();
    EXPECT_EQ(&third.context(), &first.context());
  }
  DeviceIoPool::Lease fourth = pool.acquire();  // the third's place is free again
  EXPECT_EQ(&fourth.context(), &first.context());
  {
    DeviceIoPool::Lease own = pool.acquire(true);
    EXPECT_NE(&own.context(), &first.context());
    EXPECT_NE(&own.context(), &second.context());
    EXPECT_EQ(pool.dedicatedThreads(), 1u);
    EXPECT_EQ(pool.runningThreads(), 2u);
  }
  EXPECT_EQ(pool.dedicatedThreads(), 0u);  // its thread is joined with its lease
}

TEST(DeviceIoPool, RefusesToStopASessionFromAnIoThread)
{
  DeviceIoPool pool(1);
  Responder responder;
  Device device(udpLink(responder.port()), quickConfig(), pool);
  std::atomic<bool> refused{ false };
  device.session->command([&] {
    try
    {
      device.session->stop();
    }
    catch (const std::logic_error&)
    {
      refused = true;
    }
  });
  EXPECT_TRUE(waitUntil([&] { return refused.load(); }, WAIT));
}

// Sessions come and go on one shared thread, with writes, timers, reply timeouts and commands in flight: none of
// their handlers may outlive them (run it under AddressSanitizer to see a use after free). The thread keeps serving.
TEST(DeviceIoPool, ManySessionsComeAndGoOnOneThreadWithOperationsInFlight)
{
  DeviceIoPool pool(1);
  Responder responder;
  SilentAcceptor acceptor;
  const std::uint16_t nobody = [] {
    UdpSocket unused;  // bound, then closed: nothing listens there
    unused.bind("127.0.0.1", 0);
    return unused.localEndpoint().port();
  }();
  std::size_t started = 0;
  std::size_t refused = 0;
  for (int i = 0; i < 200; ++i)
  {
    const int kind = i % 4;
    const LinkConfig link = kind == 0 || kind == 3 ? tcpLink(acceptor.port()) :
                            kind == 1              ? udpLink(responder.port()) :
                                                     udpLink(nobody);
    {
      Device device(link, quickConfig(), pool);
      for (int command = 0; command < 5; ++command)
      {
        // Queued before start() (kind 3 is never started: destroyed with them queued).
        device.session->command([protocol = device.protocol.get()] { protocol->goTo(AxisValues{}); });
      }
      if (kind != 3)
      {
        try
        {
          device.session->start();
          ++started;
          device.session->command([protocol = device.protocol.get()] { protocol->goTo(AxisValues{}); });
        }
        catch (const BackendError&)
        {
          ++refused;  // the silent ones: stopped by start() itself, with the large write or the poll timers in flight
        }
      }
    }
    acceptor.dropConnections();
  }
  EXPECT_EQ(started, 50u);
  EXPECT_EQ(refused, 100u);
  EXPECT_EQ(pool.runningThreads(), 1u);
  // The thread still serves a new session.
  Device last(udpLink(responder.port()), quickConfig(), pool);
  EXPECT_NO_THROW(last.session->start());
  EXPECT_TRUE(last.session->sample().link_up);
}

// The figure for issue 25: threads with 32 sessions on the pool, and with one thread per session (as before the
// pool: a pool with as many threads as sessions places each on its own).
TEST(DeviceIoPool, ThirtyTwoSessionsRunOnABoundedNumberOfThreads)
{
  Responder responder;
  DeviceSessionConfig config = quickConfig();
  config.poll_period = 0.05;
  config.startup_timeout = WAIT;
  const auto threadsWith = [&](std::size_t pool_size) {
    DeviceIoPool pool(pool_size);
    const std::size_t before = countThreads();
    std::vector<std::unique_ptr<Device>> devices;
    for (int i = 0; i < 32; ++i)
    {
      devices.push_back(std::make_unique<Device>(udpLink(responder.port()), config, pool));
      devices.back()->session->start();
    }
    for (const auto& device : devices)
    {
      EXPECT_TRUE(device->session->sample().link_up);
    }
    return countThreads() - before;
  };
  const std::size_t pooled = threadsWith(4);
  const std::size_t one_each = threadsWith(32);
  std::printf("[ figures  ] threads added by 32 UDP device sessions: %zu on a pool of 4, %zu with one I/O thread per "
              "session (before the pool)\n",
              pooled, one_each);
  EXPECT_LE(pooled, 4u);
  EXPECT_GE(one_each, 32u);
}

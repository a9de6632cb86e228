/**
 * \file
 * \brief The device session on its own: a scripted protocol over a real UDP link to a device the test plays by hand,
 * so every ordering question (stale faults, the recovery and a fresh command, start-up) has one answer (the
 * request/reply channel is test_transaction_channel.cpp's).
 */
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>

#include "wait_until.h"

#include <sstream>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read_until.hpp>
#include <boost/asio/streambuf.hpp>
#include <boost/asio/write.hpp>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = 10.0;

/**
 * \brief A protocol of text datagrams: the device sends "STATE pan", "READY", "REFUSED serial", "NOPE reason"; the
 * backend sends "HELLO", "GOTO pan serial", "STOP serial", "HOLD".
 */
class TextProtocol : public DeviceProtocol
{
public:
  explicit TextProtocol(DeviceSession& session) : session_(session)
  {
  }
  std::string name() const override
  {
    return "text";
  }
  std::string deviceName() const override
  {
    return "the text device";
  }
  Capabilities capabilities() const override
  {
    Capabilities capabilities;
    capabilities.axes[PAN].range = AxisRange{ -3.0, 3.0 };
    capabilities.axes[ZOOM].present = false;
    return capabilities;
  }
  void onConnected() override
  {
    session_.write("HELLO\n");
  }
  void onReceived(const std::uint8_t* data, std::size_t size) override
  {
    // Lines, so a byte stream (TCP) works as well as datagrams.
    pending_.append(reinterpret_cast<const char*>(data), size);
    for (std::size_t end = pending_.find('\n'); end != std::string::npos; end = pending_.find('\n'))
    {
      handleLine(pending_.substr(0, end));
      pending_.erase(0, end + 1);
    }
  }
  void handleLine(const std::string& line)
  {
    std::istringstream text(line);
    std::string word;
    text >> word;
    if (word == "STATE")
    {
      std::string pan;  // strtod: "nan" and "inf" too
      text >> pan;
      session_.reportState(AxisValues{ { std::strtod(pan.c_str(), nullptr), 0.0, 1.0 } });
    }
    else if (word == "READY")
    {
      session_.ready();
    }
    else if (word == "REFUSED")
    {
      std::uint64_t serial = 0;
      text >> serial;
      session_.reportFault("the text device refused command " + std::to_string(serial), serial);
    }
    else if (word == "NOPE")
    {
      std::string reason;
      std::getline(text, reason);
      session_.failStartup(reason.substr(1));
    }
  }
  void goTo(const AxisValues& position) override
  {
    session_.write("GOTO " + std::to_string(position[PAN]) + " " + std::to_string(session_.currentCommand()) + "\n");
  }
  void moveAtVelocity(const AxisValues&) override
  {
  }
  void stop() override
  {
    session_.write("STOP " + std::to_string(session_.currentCommand()) + "\n");
  }
  void hold() override
  {
    session_.write("HOLD\n");
  }

private:
  DeviceSession& session_;
  std::string pending_;
};

/// The device end, played by the test.
class TextDevice
{
public:
  TextDevice()
  {
    socket_.bind("127.0.0.1", 0);
  }
  std::uint16_t port() const
  {
    return socket_.localEndpoint().port();
  }
  /// The next datagram from the backend ("" after \p timeout s).
  std::string receive(double timeout = WAIT)
  {
    std::uint8_t buffer[256];
    std::size_t size = 0;
    if (socket_.receive(buffer, sizeof(buffer), size, backend_, static_cast<int>(timeout * 1000)) !=
        ReceiveStatus::DATAGRAM)
    {
      return {};
    }
    std::string text(reinterpret_cast<const char*>(buffer), size);
    if (!text.empty() && text.back() == '\n')
    {
      text.pop_back();
    }
    return text;
  }
  /// Receives until a datagram starts with \p prefix; returns it ("" if none came).
  std::string receiveUntil(const std::string& prefix)
  {
    for (std::string text = receive(); !text.empty(); text = receive())
    {
      if (text.rfind(prefix, 0) == 0)
      {
        return text;
      }
    }
    return {};
  }
  void send(std::string text)
  {
    text += '\n';
    socket_.sendTo(backend_, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  }

private:
  UdpSocket socket_;
  UdpEndpoint backend_;
};

class DeviceSessionTest : public ::testing::Test
{
protected:
  std::unique_ptr<DeviceBackend> makeBackend(double startup_timeout = WAIT)
  {
    LinkConfig link;
    link.kind = LinkKind::UDP;
    link.port = device_.port();
    DeviceSessionConfig config{ 0.2, 0.02, startup_timeout, 0.05, 0.5 };
    return std::make_unique<DeviceBackend>(
        link, config, [](DeviceSession& session) { return std::make_unique<TextProtocol>(session); });
  }

  /// Starts \p backend against the device: it says hello, the device answers ready with a state.
  void startUp(DeviceBackend& backend)
  {
    std::thread starter([&] { backend.start(); });
    EXPECT_EQ(device_.receive(), "HELLO");
    device_.send("READY");
    device_.send("STATE 0.1");
    starter.join();
    ASSERT_TRUE(backend.sample().link_up);
  }

  TextDevice device_;
};

TEST_F(DeviceSessionTest, StartFailsWithTheSilenceNamed)
{
  auto silent = makeBackend(0.3);
  try
  {
    silent->start();
    FAIL() << "start() returned without a device";
  }
  catch (const BackendError& error)
  {
    EXPECT_EQ(std::string(error.what()),
              "no answer from the text device on udp 127.0.0.1:" + std::to_string(device_.port()) + " within 0.3 s");
  }
}

TEST_F(DeviceSessionTest, StartFailsWithTheReasonTheProtocolGives)
{
  auto refusing = makeBackend();
  std::thread device([&] {
    device_.receiveUntil("HELLO");
    device_.send("NOPE camera 3 does not exist");
  });
  try
  {
    refusing->start();
    FAIL() << "start() accepted a device that cannot be used";
  }
  catch (const BackendError& error)
  {
    EXPECT_EQ(std::string(error.what()),
              "the text device on udp 127.0.0.1:" + std::to_string(device_.port()) + ": camera 3 does not exist");
  }
  device.join();
}

TEST_F(DeviceSessionTest, AFaultOfAReplacedCommandDoesNotCountAgainstTheNewOne)
{
  auto backend = makeBackend();
  startUp(*backend);
  backend->goTo({ 1.0, 0.0, 1.0 });
  const std::string first = device_.receiveUntil("GOTO");
  backend->goTo({ 2.0, 0.0, 1.0 });
  const std::string second = device_.receiveUntil("GOTO");
  ASSERT_FALSE(first.empty());
  ASSERT_FALSE(second.empty());
  const std::string first_serial = first.substr(first.rfind(' ') + 1);
  const std::string second_serial = second.substr(second.rfind(' ') + 1);
  ASSERT_NE(first_serial, second_serial);

  device_.send("REFUSED " + first_serial);  // late: the first goal was already replaced
  ASSERT_TRUE(waitUntil([&] { return backend->session().counters().stale_faults == 1u; }, WAIT));
  EXPECT_EQ(backend->sample().fault_count, 0u);
  EXPECT_EQ(backend->lastFault(), "");

  device_.send("REFUSED " + second_serial);
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count == 1u; }, WAIT));
  EXPECT_EQ(backend->lastFault(), "the text device refused command " + second_serial);
}

TEST_F(DeviceSessionTest, SilencePastTheDeadlineIsALossWithItsReasonAndTheRecoveryComesBeforeAnyNewCommand)
{
  auto backend = makeBackend();
  startUp(*backend);
  // Keep the link up for a while, then fall silent.
  for (int state = 0; state < 5; ++state)
  {
    device_.send("STATE 0.1");
    ASSERT_TRUE(
        waitUntil([&] { return backend->session().counters().state_reports >= std::uint64_t(state + 2); }, WAIT));
  }
  ASSERT_TRUE(waitUntil([&] { return !backend->sample().link_up; }, WAIT));
  EXPECT_EQ(backend->sample().link_losses, 1u);
  EXPECT_EQ(backend->lastLinkLoss(), "no state from the text device for 0.20 s");

  // The device answers again; a command sent the moment the link shows up must come after the hold.
  device_.send("STATE 0.3");
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  backend->goTo({ -1.0, 0.0, 1.0 });
  std::vector<std::string> received;
  for (std::string text = device_.receive(); !text.empty(); text = device_.receive())
  {
    received.push_back(text.substr(0, 4));
    if (received.back() == "GOTO")
    {
      break;
    }
  }
  EXPECT_EQ(received, (std::vector<std::string>{ "HOLD", "GOTO" }));
  EXPECT_EQ(backend->session().counters().recoveries, 1u);
  EXPECT_EQ(backend->sample().link_losses, 1u);  // counted once, however often it was looked at
}

TEST_F(DeviceSessionTest, ImpossibleStatesAreDroppedAndOnlyThemForTheDeadlineIsALossNamingThem)
{
  auto backend = makeBackend();
  startUp(*backend);
  for (const char* impossible : { "nan", "inf", "3.5", "-40" })
  {
    const std::uint64_t dropped = backend->session().counters().impossible_states.value();
    device_.send(std::string("STATE ") + impossible);
    ASSERT_TRUE(waitUntil([&] { return backend->session().counters().impossible_states.value() > dropped; }, WAIT))
        << impossible;
    EXPECT_DOUBLE_EQ(backend->sample().position[PAN], 0.1) << impossible << " was taken as the device's pan";
  }
  // Nothing but NaN for the state timeout: a loss, named for what came.
  ASSERT_TRUE(waitUntil(
      [&] {
        device_.send("STATE nan");
        return !backend->sample().link_up;
      },
      WAIT));
  EXPECT_EQ(backend->lastLinkLoss(), "only impossible states from the text device for 0.20 s (pan is NaN)");
  EXPECT_DOUBLE_EQ(backend->sample().position[PAN], 0.1);
  // A possible state brings the link back.
  device_.send("STATE 0.12");
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  EXPECT_DOUBLE_EQ(backend->sample().position[PAN], 0.12);
}

TEST_F(DeviceSessionTest, ADeviceThatReportsOnlyImpossibleStatesFailsToStartNamingThem)
{
  auto backend = makeBackend(0.5);
  std::atomic<bool> done{ false };
  std::thread device([&] {
    device_.receiveUntil("HELLO");
    device_.send("READY");
    while (!done)
    {
      device_.send("STATE 7.0");
      device_.receive(0.02);
    }
  });
  try
  {
    backend->start();
    FAIL() << "start() believed a pan of 7 rad on a device that turns 3";
  }
  catch (const BackendError& error)
  {
    EXPECT_EQ(std::string(error.what()),
              "only impossible states from the text device on udp 127.0.0.1:" + std::to_string(device_.port()) +
                  " within 0.5 s: pan 7.00 rad is outside the device's limits [-3.00, 3.00]");
  }
  done = true;
  device.join();
}

TEST_F(DeviceSessionTest, AHostThatDoesNotResolveIsAnOpenFailureNamedAtStart)
{
  LinkConfig link;
  link.kind = LinkKind::UDP;
  link.host = "not a host name!";
  DeviceBackend backend(link, DeviceSessionConfig{ 0.2, 0.02, 0.2, 0.05, 0.5 },
                        [](DeviceSession& session) { return std::make_unique<TextProtocol>(session); });
  try
  {
    backend.start();
    FAIL() << "start() succeeded without a host";
  }
  catch (const BackendError& error)
  {
    EXPECT_NE(std::string(error.what()).find("cannot resolve not a host name!"), std::string::npos) << error.what();
  }
  EXPECT_GT(backend.session().linkCounters().open_failures, 0u);
  EXPECT_EQ(backend.session().linkCounters().opens, 0u);
}

TEST(DeviceSessionReconnection, AfterAReconnectionTheLinkIsUpOnlyOnceTheDeviceReportsAndItsHoldComesFirst)
{
  // The device end of a TCP connection, played by hand: it decides when the backend hears its first state.
  using boost::asio::ip::tcp;
  boost::asio::io_context context;
  tcp::acceptor acceptor(context, tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
  tcp::socket device(context);
  boost::asio::streambuf input;
  auto readLine = [&] {
    boost::asio::read_until(device, input, '\n');
    std::istream stream(&input);
    std::string line;
    std::getline(stream, line);
    return line;
  };
  auto say = [&](const std::string& text) { boost::asio::write(device, boost::asio::buffer(text)); };

  LinkConfig link;
  link.kind = LinkKind::TCP;
  link.port = acceptor.local_endpoint().port();
  // A long state timeout: the last state before the break is still fresh when the connection is back.
  DeviceBackend backend(link, DeviceSessionConfig{ 5.0, 0.02, WAIT, 0.05, 0.5 },
                        [](DeviceSession& session) { return std::make_unique<TextProtocol>(session); });
  std::thread starter([&] { backend.start(); });
  acceptor.accept(device);
  EXPECT_EQ(readLine(), "HELLO");
  say("READY\nSTATE 0.1\n");
  starter.join();
  ASSERT_TRUE(backend.sample().link_up);

  device.close();           // the connection breaks...
  acceptor.accept(device);  // ...and is back at once
  EXPECT_EQ(readLine(), "HELLO");
  // Connected again, the last state not old: still, nothing is known of this connection's device yet.
  EXPECT_FALSE(backend.sample().link_up);
  EXPECT_EQ(backend.sample().link_losses, 1u);
  EXPECT_EQ(backend.lastLinkLoss(), "connection to 127.0.0.1:" + std::to_string(link.port) + " closed");

  say("READY\nSTATE 0.2\n");
  ASSERT_TRUE(waitUntil([&] { return backend.sample().link_up; }, WAIT));
  backend.goTo({ -1.0, 0.0, 1.0 });  // the moment the link shows up
  EXPECT_EQ(readLine(), "HOLD");
  EXPECT_EQ(readLine().substr(0, 4), "GOTO");
}

// ---------------------------------------------------------------- the state deadline

TEST(DeviceSessionStateDeadline, FollowsTheReplyDeadlineAboveTheConfiguredStateTimeout)
{
  // The shipped VISCA, FLIR and Pelco-D timing: a state deadline of 0.25 s, polls every 0.05 s.
  LinkConfig link;
  link.kind = LinkKind::UDP;
  link.port = 9;
  DeviceSessionConfig config;
  config.state_timeout = 0.25;
  config.poll_period = 0.05;
  DeviceSession session(link, config, std::make_shared<SystemClock>());
  EXPECT_DOUBLE_EQ(session.stateDeadline(), 0.25);
  // The reply deadline's floor: one lost answer (its deadline, the drain, a poll, the next answer) is 0.35 s.
  session.replyDeadlineChanged(0.1);
  EXPECT_NEAR(session.stateDeadline(), 0.35, 1e-9);
  session.replyDeadlineChanged(0.185);  // learnt from a PTZOptics G2 (answers up to 123 ms)
  EXPECT_NEAR(session.stateDeadline(), 0.605, 1e-9);
  std::vector<DiagnosticValue> values;
  session.diagnostics(values);
  EXPECT_NE(std::find(values.begin(), values.end(), DiagnosticValue("state deadline (s)", "0.605")), values.end());
  session.replyDeadlineChanged(0.01);  // never below the configured value
  EXPECT_DOUBLE_EQ(session.stateDeadline(), 0.25);
  EXPECT_DOUBLE_EQ(session.config().state_timeout, 0.25);
}

}  // namespace

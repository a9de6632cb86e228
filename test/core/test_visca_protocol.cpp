/**
 * \file
 * \brief What only the VISCA protocol does, against its emulator over a real pseudo-terminal and UDP on 127.0.0.1
 * (the backend contract suite covers what every device does): the start-up of each transport, one request on the
 * wire at a time, velocity goals as drive commands, a sequence error answered by a reset, a chain without the
 * camera's address, garbled replies; and, against a camera the test plays by hand, that no state mixes a pan from
 * before a lost answer with a zoom from after it.
 */
#include <gtest/gtest.h>

#include "diagnostic_value.h"
#include "line_test_support.h"
#include "wait_until.h"

#include <thread>

#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"
#include "ptz_action_server/emulators/visca_emulator.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = LINE_TEST_WAIT;

/// A camera and its backend, on a pseudo-terminal at 9600 baud or over UDP.
class ViscaTest : public ::testing::Test
{
protected:
  void start(DevicePortConfig::Kind kind, ViscaFraming framing, std::uint8_t backend_address = 1)
  {
    ViscaEmulatorConfig emulator_config;
    emulator_config.port.kind = kind;
    emulator_config.port.link = uniqueLink("visca");
    emulator_config.framing = framing;
    emulator_ = std::make_unique<ViscaEmulator>(emulator_config);
    DeviceConfig<ViscaProtocol> config;
    if (kind == DevicePortConfig::Kind::PTY)
    {
      config.link = serialLink(emulator_config.port.link, 9600);
    }
    else
    {
      config.link.kind = LinkKind::UDP;
      config.link.port = emulator_->port().udpPort();
      config.link.local_host = "127.0.0.1";
    }
    config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
    config.session.startup_timeout = 5.0;
    config.settings.framing = framing;
    config.settings.address = backend_address;
    model_ = config.settings.model;
    backend_ = makeDeviceBackend<ViscaProtocol>(config);
  }
  void startAndWaitUp(DevicePortConfig::Kind kind, ViscaFraming framing)
  {
    start(kind, framing);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  }
  const ViscaCounters& counters() const
  {
    return backend_->protocol<ViscaProtocol>().counters();
  }

  visca::ViscaModel model_;
  std::unique_ptr<ViscaEmulator> emulator_;
  std::unique_ptr<DeviceBackend> backend_;
};

TEST_F(ViscaTest, OnASerialLineTheAddressIsSetAndTheInterfaceClearedBeforeAnyInquiry)
{
  startAndWaitUp(DevicePortConfig::Kind::PTY, ViscaFraming::RAW);
  const std::vector<ReceivedPacket> received = emulator_->received().items();
  ASSERT_GE(received.size(), 4u);
  EXPECT_EQ(visca::toHex(received[0].packet), "88 30 01 FF");
  EXPECT_EQ(visca::toHex(received[1].packet), "88 01 00 01 FF");
  EXPECT_EQ(visca::toHex(received[2].packet), "81 09 06 12 FF");
  EXPECT_EQ(visca::toHex(received[3].packet), "81 09 04 47 FF");
}

TEST_F(ViscaTest, OneRequestIsOnTheWireAtATimeAndEveryOneIsAnswered)
{
  startAndWaitUp(DevicePortConfig::Kind::PTY, ViscaFraming::RAW);
  // Goals and polls interleave on a 9600 baud line; a reply matched to the wrong request would show as an unexpected
  // reply, or a late one dropped. A reply later than its deadline on a loaded machine is a timeout whose answer the
  // drain still takes: every request is answered, in order.
  for (double pan : { 0.3, -0.2, 0.4, 0.1 })
  {
    backend_->goTo({ pan, 0.1, 3.0 });
    ASSERT_TRUE(waitUntil([&] { return atRest(*backend_, pan, 0.1); }, WAIT)) << pan;
  }
  EXPECT_EQ(diagnosticValue(*backend_, "late replies dropped"), "0");
  EXPECT_EQ(diagnosticValue(*backend_, "late replies taken"), diagnosticValue(*backend_, "reply timeouts"));
  EXPECT_EQ(counters().unexpected_replies, 0u);
  EXPECT_GT(counters().completions, 0u);  // the positions completed in their sockets
  EXPECT_EQ(emulator_->counters().buffer_full, 0u);
  EXPECT_NEAR(emulator_->sample().position[ZOOM], 3.0, 0.01);
}

TEST_F(ViscaTest, VelocityGoalsAreDriveCommandsWithTheModelsSpeedBytes)
{
  startAndWaitUp(DevicePortConfig::Kind::UDP, ViscaFraming::RAW);
  emulator_->received().clear();
  backend_->moveAtVelocity({ -0.5, 0.2, 4.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().velocity[PAN] < -0.4; }, WAIT));
  const visca::Packet drive = visca::panTiltDrive(1, model_.speedByte(PAN, 0.5), model_.speedByte(TILT, 0.2), -1, 1);
  const visca::Packet zoom = visca::zoomDrive(1, model_.zoomSpeed(4.0));
  EXPECT_TRUE(emulator_->received().waitFor([&](const ReceivedPacket& item) { return item.packet == drive; }, WAIT));
  EXPECT_TRUE(emulator_->received().waitFor([&](const ReceivedPacket& item) { return item.packet == zoom; }, WAIT));
  EXPECT_NEAR(emulator_->sample().velocity[TILT], model_.speedOfByte(TILT, model_.speedByte(TILT, 0.2)), 1e-6);
  backend_->stop();
  const visca::Packet halt = visca::panTiltDrive(1, 0x18, 0x14, 0, 0);
  EXPECT_TRUE(emulator_->received().waitFor([&](const ReceivedPacket& item) { return item.packet == halt; }, WAIT));
  EXPECT_TRUE(waitUntil([&] { return !emulator_->sample().moving && !backend_->sample().moving; }, WAIT));
}

TEST_F(ViscaTest, OverIpTheSequenceIsResetFirstAndASequenceErrorIsAnsweredByAReset)
{
  startAndWaitUp(DevicePortConfig::Kind::UDP, ViscaFraming::SONY_IP);
  const std::vector<ReceivedPacket> received = emulator_->received().items();
  ASSERT_GE(received.size(), 3u);
  EXPECT_TRUE(received[0].control);
  EXPECT_EQ(received[0].sequence, 0u);
  EXPECT_EQ(received[1].sequence, 1u);
  EXPECT_EQ(received[2].sequence, 2u);

  emulator_->skipSequence(1000000);  // another controller used the camera
  ASSERT_TRUE(waitUntil([&] { return counters().sequence_resets > 0; }, WAIT));
  backend_->goTo({ -0.3, 0.2, 2.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, -0.3, 0.2); }, WAIT));
  EXPECT_GT(emulator_->counters().sequence_errors, 0u);
  EXPECT_EQ(backend_->sample().fault_count, 0u);
}

TEST_F(ViscaTest, AChainWithoutTheConfiguredAddressFailsTheStartWithTheReason)
{
  start(DevicePortConfig::Kind::PTY, ViscaFraming::RAW, 3);
  try
  {
    backend_->start();
    FAIL() << "started without a camera at address 3";
  }
  catch (const std::exception& error)
  {
    EXPECT_NE(std::string(error.what()).find("the VISCA chain has 1 camera(s), none at address 3"), std::string::npos)
        << error.what();
  }
}

TEST_F(ViscaTest, GarbledRepliesAreDroppedAndCountedAndGoalsStillSucceed)
{
  startAndWaitUp(DevicePortConfig::Kind::PTY, ViscaFraming::RAW);
  emulator_->port().setGarbleRatio(0.02);
  ASSERT_TRUE(waitUntil([&] { return counters().skipped_bytes + counters().broken_packets > 3; }, WAIT));
  emulator_->port().setGarbleRatio(0.0);
  backend_->goTo({ 0.2, -0.1, 1.0 });
  EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, 0.2, -0.1); }, WAIT));
}

/// Raw VISCA over UDP from a camera at address 1 the test plays by hand, one inquiry at a time.
class HandPlayedCamera
{
public:
  HandPlayedCamera()
  {
    socket_.bind("127.0.0.1", 0);
  }
  std::uint16_t port() const
  {
    return socket_.localEndpoint().port();
  }
  /// The next inquiry, in hex ("" if none came within WAIT).
  std::string receive()
  {
    std::uint8_t buffer[64];
    std::size_t size = 0;
    if (socket_.receive(buffer, sizeof(buffer), size, backend_, static_cast<int>(WAIT * 1000)) !=
        ReceiveStatus::DATAGRAM)
    {
      return {};
    }
    return visca::toHex(visca::Packet(buffer, buffer + size));
  }
  /// Answers `81 09 06 12 FF` with \p pan and \p tilt in steps.
  void answerPanTilt(std::int32_t pan, std::int32_t tilt)
  {
    visca::Packet answer{ 0x90, 0x50 };
    visca::putNibbles(answer, static_cast<std::uint16_t>(pan), 4);
    visca::putNibbles(answer, static_cast<std::uint16_t>(tilt), 4);
    send(answer);
  }
  /// Answers `81 09 04 47 FF` with zoom position \p position.
  void answerZoom(std::uint16_t position)
  {
    visca::Packet answer{ 0x90, 0x50 };
    visca::putNibbles(answer, position, 4);
    send(answer);
  }

private:
  void send(visca::Packet packet)
  {
    packet.push_back(visca::TERMINATOR);
    socket_.sendTo(backend_, packet.data(), packet.size());
  }

  UdpSocket socket_;
  UdpEndpoint backend_;
};

constexpr const char* PAN_TILT_INQUIRY = "81 09 06 12 FF";
constexpr const char* ZOOM_INQUIRY = "81 09 04 47 FF";

/// The backend against a camera played by hand: raw VISCA over UDP, a state timeout the lost answers never reach.
class ViscaHandPlayed : public ::testing::Test
{
protected:
  ViscaHandPlayed()
  {
    config_.link.kind = LinkKind::UDP;
    config_.link.port = camera_.port();
    config_.link.local_host = "127.0.0.1";
    config_.session.state_timeout = 60.0;  // the lost answers below are the test's, not a silence of the link
    config_.session.startup_timeout = WAIT;
    config_.settings.lens.poll_period = 0.0;  // rounds of the pose alone (test_visca_lens.cpp polls the lens)
    model_ = config_.settings.model;
  }
  /// Starts the backend: the camera answers the first round at pan 0.
  void startUp()
  {
    backend_ = makeDeviceBackend<ViscaProtocol>(config_);
    std::thread starter([&] { backend_->start(); });
    EXPECT_EQ(camera_.receive(), PAN_TILT_INQUIRY);
    camera_.answerPanTilt(0, 0);
    EXPECT_EQ(camera_.receive(), ZOOM_INQUIRY);
    camera_.answerZoom(0);
    starter.join();
    ASSERT_TRUE(backend_->sample().link_up);
    // The link is up once the round's answers came and the protocol said ready(); its state is reported right
    // after, on the I/O thread: the count starts from it.
    ASSERT_TRUE(waitUntil([&] { return stateReports() > 0; }, WAIT));
    reports_ = stateReports();
  }
  std::uint64_t stateReports() const
  {
    return backend_->session().counters().state_reports.value();
  }
  /// Answers one whole round in time, at \p pan rad, and waits for its state.
  void answerRound(double pan)
  {
    ASSERT_EQ(camera_.receive(), PAN_TILT_INQUIRY);
    camera_.answerPanTilt(model_.toSteps(PAN, pan), 0);
    ASSERT_EQ(camera_.receive(), ZOOM_INQUIRY);
    camera_.answerZoom(0);
    ASSERT_TRUE(waitUntil([&] { return stateReports() > reports_; }, WAIT));
  }

  HandPlayedCamera camera_;
  DeviceConfig<ViscaProtocol> config_;
  visca::ViscaModel model_;
  std::unique_ptr<DeviceBackend> backend_;
  std::uint64_t reports_ = 0;  ///< state reports once started
};

TEST_F(ViscaHandPlayed, AZoomAnswerAfterALostAnswerNeverCompletesAStateWithThePanFromBeforeIt)
{
  startUp();
  // A round cut in two by a silence: its pan answered before, its zoom question lost; the next pan question lost,
  // its zoom question answered after.
  ASSERT_EQ(camera_.receive(), PAN_TILT_INQUIRY);
  camera_.answerPanTilt(model_.toSteps(PAN, 0.5), 0);
  ASSERT_EQ(camera_.receive(), ZOOM_INQUIRY);
  ASSERT_EQ(camera_.receive(), PAN_TILT_INQUIRY);  // after the zoom answer's reply timeout
  ASSERT_EQ(camera_.receive(), ZOOM_INQUIRY);
  camera_.answerZoom(0);
  // A whole round: the camera is at 1.2 rad, and that is the one state since the start.
  answerRound(1.2);
  EXPECT_NEAR(backend_->sample().position[PAN], 1.2, 0.01);
  EXPECT_EQ(stateReports(), reports_ + 1);
  EXPECT_EQ(backend_->session().counters().impossible_states.value(), 0u);
}

TEST_F(ViscaHandPlayed, AnAnswerLaterThanTheDrainIsDroppedAndTheNextIsMatchedToItsOwnInquiry)
{
  startUp();
  // The pan-tilt answer comes only once its reply timeout and the drain after it are over, when the zoom inquiry is
  // on the wire, just ahead of the zoom answer (a camera on a busy line).
  ASSERT_EQ(camera_.receive(), PAN_TILT_INQUIRY);
  ASSERT_EQ(camera_.receive(), ZOOM_INQUIRY);
  camera_.answerPanTilt(model_.toSteps(PAN, 0.5), 0);
  camera_.answerZoom(0);
  answerRound(0.6);
  EXPECT_EQ(backend_->protocol<ViscaProtocol>().counters().unexpected_replies, 0u) << "the late pan-tilt answer was "
                                                                                      "taken for the zoom inquiry's";
  EXPECT_NEAR(backend_->sample().position[PAN], 0.6, 0.01);
}

}  // namespace

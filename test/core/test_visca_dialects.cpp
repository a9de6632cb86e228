/**
 * \file
 * \brief The VISCA dialects of the cameras in the field, each against the emulator mode that speaks it: Sony's
 * current models (positions in 5 nibbles, one speed byte), PTZOptics G3 firmware answering from `A0`, NewTek's NDI
 * PTZ1 reading sequence numbers 1..3 only, a camera that takes only the standard zoom drive, one that answers no
 * inquiry, Sony's replies to port 52381; and what the emulator answers libvisca.
 */
#include <gtest/gtest.h>

#include "diagnostic_value.h"
#include "line_test_support.h"
#include "wait_until.h"

#include <cmath>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"
#include "ptz_action_server/emulators/visca_emulator.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = LINE_TEST_WAIT;

/// A camera of some dialect over UDP on 127.0.0.1 (or a pseudo-terminal), and a backend configured for it.
class ViscaDialect : public ::testing::Test
{
protected:
  ViscaDialect()
  {
    emulator_config_.port.kind = DevicePortConfig::Kind::UDP;
    config_.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
    config_.session.startup_timeout = WAIT;
  }
  /// Starts the emulator, and makes (not starts) the backend for it.
  void make(ViscaFraming framing)
  {
    emulator_config_.framing = framing;
    emulator_config_.port.link = uniqueLink("visca_dialect");
    emulator_ = std::make_unique<ViscaEmulator>(emulator_config_);
    if (emulator_config_.port.kind == DevicePortConfig::Kind::PTY)
    {
      config_.link = serialLink(emulator_config_.port.link, 38400);
    }
    else
    {
      config_.link.kind = LinkKind::UDP;
      config_.link.port = emulator_->port().udpPort();
      config_.link.local_host = "127.0.0.1";
    }
    config_.settings.framing = framing;
    config_.settings.model = emulator_config_.model;
    backend_ = makeDeviceBackend<ViscaProtocol>(config_);
  }
  void startUp(ViscaFraming framing)
  {
    make(framing);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
  }
  /// Both the emulator and the backend on the preset \p name.
  void useModel(const char* name)
  {
    ASSERT_TRUE(visca::ViscaModel::preset(name, emulator_config_.model)) << name;
  }
  const ViscaCounters& counters() const
  {
    return backend_->protocol<ViscaProtocol>().counters();
  }
  std::string diagnostic(const std::string& name) const
  {
    return diagnosticValue(*backend_, name);
  }
  /// The backend's warnings so far, one text.
  std::string warnings()
  {
    for (const std::string& warning : backend_->takeWarnings())
    {
      warnings_ += warning + "\n";
    }
    return warnings_;
  }
  bool received(const std::string& hex) const
  {
    for (const ReceivedPacket& item : emulator_->received().items())
    {
      if (visca::toHex(item.packet) == hex)
      {
        return true;
      }
    }
    return false;
  }
  /// A goal reached, as the backend reports it and as the camera is.
  void expectGoalReached(double pan, double tilt)
  {
    const double zoom = config_.settings.model.zoom_table_known ? 3.0 : NAN;
    backend_->goTo({ pan, tilt, zoom });
    EXPECT_TRUE(waitUntil([&] { return atRest(*backend_, pan, tilt); }, WAIT)) << config_.settings.model.name;
    EXPECT_NEAR(emulator_->sample().position[PAN], pan, 0.01);
    EXPECT_NEAR(emulator_->sample().position[TILT], tilt, 0.01);
    if (!std::isnan(zoom))
    {
      EXPECT_TRUE(waitUntil([&] { return std::abs(emulator_->sample().position[ZOOM] - zoom) < 0.01; }, WAIT));
    }
    EXPECT_EQ(backend_->sample().fault_count, 0u) << backend_->lastFault();
  }

  ViscaEmulatorConfig emulator_config_;
  DeviceConfig<ViscaProtocol> config_;
  std::unique_ptr<ViscaEmulator> emulator_;
  std::unique_ptr<DeviceBackend> backend_;
  std::string warnings_;
};

// ---------------------------------------------------------------- Sony's current models

TEST_F(ViscaDialect, EverySonyModelIsDrivenInItsOwnNibblesAndSpeedForm)
{
  for (const char* name : { "brc_x1000", "brc_h800", "brc_x400", "srg_360she", "ilme_fr7", "brc_am7" })
  {
    SCOPED_TRACE(name);
    useModel(name);
    startUp(ViscaFraming::SONY_IP);
    expectGoalReached(0.3, 0.2);
    expectGoalReached(-0.5, -0.1);
    EXPECT_EQ(emulator_->counters().syntax_errors, 0u);
    backend_.reset();
    emulator_.reset();
  }
}

// ---------------------------------------------------------------- replies from another address

TEST_F(ViscaDialect, APtzOpticsG3AnsweringFromA0IsHeardOnANetworkLink)
{
  ASSERT_TRUE(emulator_config_.applyMode("g3-address"));
  useModel("ptzoptics_g3");
  startUp(ViscaFraming::RAW);
  expectGoalReached(0.4, 0.1);
  EXPECT_GT(counters().foreign_address, 0u);
  EXPECT_EQ(counters().other_address, 0u);
  EXPECT_EQ(diagnostic("replies from address"), "2");
  EXPECT_NE(warnings().find("answers from address 2 (A0)"), std::string::npos) << warnings();
}

TEST_F(ViscaDialect, OnASerialChainARepliesFromAnotherAddressAreAnotherCamerasAndDropped)
{
  ASSERT_TRUE(emulator_config_.applyMode("g3-address"));
  emulator_config_.port.kind = DevicePortConfig::Kind::PTY;
  config_.session.startup_timeout = 2.0;
  make(ViscaFraming::RAW);
  EXPECT_THROW(backend_->start(), BackendError);
  EXPECT_GT(counters().other_address, 0u);
}

// ---------------------------------------------------------------- sequence numbers

TEST_F(ViscaDialect, AnNdiPtz1ReadingSequenceNumbers1To3IsLearntAndDrivenWithThem)
{
  ASSERT_TRUE(emulator_config_.applyMode("ndi-sequence"));
  startUp(ViscaFraming::SONY_IP);
  // It never answers the reset (numbered 0): the set-up goes on without it. It answers 1..3, then nothing.
  ASSERT_TRUE(waitUntil([&] { return diagnostic("sequence numbers") == "1..3"; }, WAIT)) << diagnostic("sequence "
                                                                                                       "numbers");
  const std::uint64_t losses = backend_->sample().link_losses;
  expectGoalReached(0.3, 0.1);
  expectGoalReached(-0.2, 0.2);
  EXPECT_EQ(backend_->sample().link_losses, losses) << backend_->lastLinkLoss();
  EXPECT_NE(warnings().find("does not answer the VISCA over IP sequence reset"), std::string::npos) << warnings();
  EXPECT_NE(warnings().find("sequence numbers 1..3 only"), std::string::npos) << warnings();
}

TEST_F(ViscaDialect, WithASequenceCycleSetNoRequestIsNumberedBeyondIt)
{
  ASSERT_TRUE(emulator_config_.applyMode("ndi-sequence"));
  config_.settings.sequence_cycle = 3;
  startUp(ViscaFraming::SONY_IP);
  expectGoalReached(0.3, 0.1);
  // What the camera did not read: the two resets (numbered 0) and nothing else.
  EXPECT_EQ(emulator_->counters().unread_sequences, 2u);
  for (const ReceivedPacket& item : emulator_->received().items())
  {
    EXPECT_GE(item.sequence, 1u);
    EXPECT_LE(item.sequence, 3u);
  }
}

// ---------------------------------------------------------------- the standard zoom drive

TEST_F(ViscaDialect, ACameraTakingOnlyTheStandardZoomDriveZoomsAtItsOneSpeed)
{
  ASSERT_TRUE(emulator_config_.applyMode("standard-zoom"));
  startUp(ViscaFraming::RAW);
  backend_->moveAtVelocity({ 0.0, 0.0, 4.0 });
  // Until the lens is well away from its widest view: zooming out from just beside it ends at once, sooner than a
  // busy machine lets the test see the zoom move.
  ASSERT_TRUE(waitUntil([&] { return emulator_->sample().position[ZOOM] > 1.5; }, WAIT));
  EXPECT_TRUE(received("81 01 04 07 02 FF"));
  EXPECT_EQ(backend_->sample().fault_count, 0u) << backend_->lastFault();
  EXPECT_EQ(diagnostic("zoom drive"), "standard");
  EXPECT_NE(warnings().find("refuses the variable zoom drive"), std::string::npos) << warnings();
  // From now on the standard drive at once: wide is `03`.
  emulator_->received().clear();
  const double zoomed = emulator_->sample().position[ZOOM];
  backend_->moveAtVelocity({ 0.0, 0.0, -2.0 });
  // The lens goes wider (a position that stays, where its velocity may be over before the test looks).
  ASSERT_TRUE(waitUntil([&] { return received("81 01 04 07 03 FF"); }, WAIT));
  EXPECT_TRUE(waitUntil([&] { return emulator_->sample().position[ZOOM] < zoomed; }, WAIT));
  EXPECT_FALSE(received(visca::toHex(visca::zoomDrive(1, -2))));
  backend_->stop();
  EXPECT_TRUE(waitUntil([&] { return emulator_->sample().velocity[ZOOM] == 0.0; }, WAIT));
  EXPECT_EQ(backend_->sample().fault_count, 0u) << backend_->lastFault();
}

TEST_F(ViscaDialect, WithTheVariableZoomDriveKeptItsRefusalIsAFaultOfTheGoal)
{
  ASSERT_TRUE(emulator_config_.applyMode("standard-zoom"));
  config_.settings.zoom_drive = ViscaZoomDrive::VARIABLE;
  startUp(ViscaFraming::RAW);
  backend_->moveAtVelocity({ 0.0, 0.0, 4.0 });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().fault_count > 0; }, WAIT));
  EXPECT_NE(backend_->lastFault().find("syntax error"), std::string::npos) << backend_->lastFault();
}

// ---------------------------------------------------------------- a camera that answers no inquiry

TEST_F(ViscaDialect, ACameraThatAnswersCommandsButNoInquiryRunsWithoutFeedback)
{
  ASSERT_TRUE(emulator_config_.applyMode("no-inquiries"));
  startUp(ViscaFraming::RAW);
  const Capabilities capabilities = backend_->capabilities();
  for (Axis axis : ALL_AXES)
  {
    EXPECT_FALSE(capabilities.axes[axis].feedback) << axisName(axis);
  }
  EXPECT_NE(warnings().find("answers commands but no inquiry"), std::string::npos) << warnings();
  backend_->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return emulator_->sample().velocity[PAN] > 0.2; }, WAIT));
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !emulator_->sample().moving; }, WAIT));
  // The link stays up on the answers to the repeated halt.
  const std::uint64_t losses = backend_->sample().link_losses;
  emulator_->received().clear();
  ASSERT_TRUE(waitUntil([&] { return emulator_->received().items().size() >= 5; }, WAIT));
  EXPECT_TRUE(backend_->sample().link_up);
  EXPECT_EQ(backend_->sample().link_losses, losses) << backend_->lastLinkLoss();
  EXPECT_EQ(backend_->sample().fault_count, 0u) << backend_->lastFault();
}

TEST_F(ViscaDialect, WithInquiriesOffTheCameraIsNeverAsked)
{
  ASSERT_TRUE(emulator_config_.applyMode("no-inquiries"));
  config_.settings.inquiries = false;
  startUp(ViscaFraming::RAW);
  EXPECT_FALSE(backend_->capabilities().axes[PAN].feedback);
  EXPECT_EQ(emulator_->counters().inquiries_ignored, 0u);
  EXPECT_TRUE(warnings().empty()) << warnings();
}

// ---------------------------------------------------------------- Sony's reply port

/// A UDP port on 127.0.0.1 free a moment ago.
std::uint16_t freeUdpPort()
{
  UdpSocket socket;
  socket.bind("127.0.0.1", 0);
  return socket.localEndpoint().port();
}

TEST_F(ViscaDialect, ACameraAnsweringToAFixedPortIsHeardWhereTheBackendListensThere)
{
  emulator_config_.modes.reply_port = freeUdpPort();
  config_.link.local_port = emulator_config_.modes.reply_port;
  startUp(ViscaFraming::SONY_IP);
  expectGoalReached(0.3, 0.1);
}

TEST_F(ViscaDialect, ACameraAnsweringToAFixedPortIsNeverHeardOnAnyOtherPort)
{
  emulator_config_.modes.reply_port = freeUdpPort();
  config_.session.startup_timeout = 2.0;
  make(ViscaFraming::SONY_IP);
  EXPECT_THROW(backend_->start(), BackendError);
}

// ---------------------------------------------------------------- what the emulator answers a libvisca client

/// libvisca's end of a UDP link to the emulator: one datagram out, one back.
class ViscaClient
{
public:
  explicit ViscaClient(std::uint16_t port) : camera_(UdpEndpoint::resolve("127.0.0.1", port))
  {
    socket_.bind("127.0.0.1", 0);
  }
  /// Sends \p bytes; the answer in hex ("" if none came).
  std::string ask(const visca::Packet& bytes)
  {
    socket_.sendTo(camera_, bytes.data(), bytes.size());
    std::uint8_t buffer[64];
    std::size_t size = 0;
    UdpEndpoint from;
    if (socket_.receive(buffer, sizeof(buffer), size, from, static_cast<int>(WAIT * 1000)) != ReceiveStatus::DATAGRAM)
    {
      return {};
    }
    return visca::toHex(visca::Packet(buffer, buffer + size));
  }

private:
  UdpSocket socket_;
  UdpEndpoint camera_;
};

ViscaEmulatorConfig udpCamera(ViscaFraming framing, const char* model)
{
  ViscaEmulatorConfig config;
  config.port.kind = DevicePortConfig::Kind::UDP;
  config.framing = framing;
  visca::ViscaModel::preset(model, config.model);
  return config;
}

TEST(ViscaEmulatorAnswers, TheVersionPowerAndAddressedIfClearALibviscaClientAsksAreAnswered)
{
  ViscaEmulator camera(udpCamera(ViscaFraming::RAW, "brc_x1000"));
  ViscaClient client(camera.port().udpPort());
  // Vendor 0001 (Sony), model 0519 (BRC-X1000), ROM 0100, two sockets.
  EXPECT_EQ(client.ask(visca::versionInquiry(1)), "90 50 00 01 05 19 01 00 02 FF");
  EXPECT_EQ(client.ask(visca::powerInquiry(1)), "90 50 02 FF");
  EXPECT_EQ(client.ask(visca::ifClearAddressed(1)), "90 50 FF");
}

TEST(ViscaEmulatorAnswers, OverIpTheResetAndTheDeviceSettingCommandCarryTheNumbersTheyAnswer)
{
  ViscaEmulator camera(udpCamera(ViscaFraming::SONY_IP, "ptzoptics"));
  ViscaClient client(camera.port().udpPort());
  // The reset's own number is ignored, and echoed.
  EXPECT_EQ(client.ask({ 0x02, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x05, 0x01 }), "02 01 00 01 00 00 00 05 01");
  // IF_Clear as a device setting command (payload type 0120h), as libvisca sends it: a VISCA reply, numbered.
  EXPECT_EQ(client.ask({ 0x01, 0x20, 0x00, 0x05, 0x00, 0x00, 0x00, 0x06, 0x88, 0x01, 0x00, 0x01, 0xFF }), "01 11 00 05 "
                                                                                                          "00 00 00 06 "
                                                                                                          "88 01 00 01 "
                                                                                                          "FF");
  // After the reset the count starts again: 1 is in order.
  EXPECT_EQ(client.ask({ 0x01, 0x10, 0x00, 0x05, 0x00, 0x00, 0x00, 0x01, 0x81, 0x09, 0x04, 0x00, 0xFF }), "01 11 00 04 "
                                                                                                          "00 00 00 01 "
                                                                                                          "90 50 02 "
                                                                                                          "FF");
  // A message of an unknown type is refused with its own number, not 0.
  EXPECT_EQ(client.ask({ 0x01, 0x30, 0x00, 0x03, 0x00, 0x00, 0x00, 0x08, 0x81, 0x41, 0xFF }), "02 01 00 02 00 00 00 08 "
                                                                                              "0F 02");
}

TEST(ViscaEmulatorLatency, TheG2ModeDrawsTheLatenciesMeasuredOnFiveCameras)
{
  std::mt19937 random(7);
  std::size_t above_100_ms = 0;
  constexpr std::size_t DRAWS = 3000;
  for (std::size_t draw = 0; draw < DRAWS; ++draw)
  {
    const double pan_tilt = ViscaEmulator::g2Latency(visca::panTiltInquiry(1), random);
    EXPECT_GE(pan_tilt, 0.088);
    EXPECT_LE(pan_tilt, 0.123);
    above_100_ms += pan_tilt > 0.1 ? 1 : 0;
    const double zoom = ViscaEmulator::g2Latency(visca::zoomInquiry(1), random);
    EXPECT_GE(zoom, 0.026);
    EXPECT_LE(zoom, 0.058);
    const double ack = ViscaEmulator::g2Latency(visca::panTiltHome(1), random);
    EXPECT_GE(ack, 0.028);
    EXPECT_LE(ack, 0.089);
  }
  // 10 of the 15 measured answers took more than 100 ms.
  EXPECT_NEAR(double(above_100_ms) / DRAWS, 10.0 / 15.0, 0.05);
  EXPECT_EQ(ViscaEmulator::g2Latency({ visca::CONTROL_RESET }, random), 0.0);
}

}  // namespace

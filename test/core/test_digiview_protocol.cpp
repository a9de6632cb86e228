/**
 * \file
 * \brief What only the digiview backend does, against the DigiView emulator on 127.0.0.1 (the backend contract
 * suite covers what every device does), and the emulator's own answers.
 */
#include <gtest/gtest.h>
#include <poll.h>

#include "wait_until.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include "ptz_action_server/core/digiview/digiview_protocol.h"
#include "ptz_action_server/emulators/digiview_emulator.h"

using namespace ptz_action_server;
using namespace ptz_action_server::digiview;

namespace
{
constexpr double WAIT = 10.0;

DigiViewConfig backendConfig(const DigiViewEmulator& emulator, LinkKind transport = LinkKind::TCP)
{
  DigiViewConfig config;
  config.link.port = emulator.port();
  config.link.kind = transport;
  config.digiview.acceleration = 4.0;  // as the emulator turns
  config.session.startup_timeout = WAIT;
  config.session.state_timeout = 1.0;  // generous: a busy test machine may starve the I/O threads
  return config;
}

bool received(const DigiViewEmulator& emulator, MessageType type, digiview::ParamType param)
{
  for (const ReceivedMessage& item : emulator.received().items())
  {
    if (item.error == UnpackError::NONE && item.message.message_type == type && item.message.param_type == param)
    {
      return true;
    }
  }
  return false;
}
}  // namespace

TEST(DigiViewBackend, StartupSubscribesToTheViewAndLearnsTheStream)
{
  DigiViewEmulator emulator(DigiViewEmulatorConfig{});
  auto backend = makeDigiViewBackend(backendConfig(emulator));
  backend->start();
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  EXPECT_TRUE(received(emulator, MessageType::GET_PARAMETERS, digiview::ParamType::VIDEO_OUTPUT));
  EXPECT_TRUE(received(emulator, MessageType::GET_INTERVAL, digiview::ParamType::CAM_TARGETING));
  EXPECT_TRUE(received(emulator, MessageType::GET_INTERVAL, digiview::ParamType::CAM_OPTICS_AND_CONTROL));
  EXPECT_NEAR(backend->sample().position[ZOOM], 1.0, 1e-3);  // the emulator starts at fov 1.2 = fov_wide: zoom 1x
  // States keep coming, every 100 ms.
  const std::uint64_t states = backend->protocol<DigiViewProtocol>().counters().states;
  EXPECT_TRUE(waitUntil([&] { return backend->protocol<DigiViewProtocol>().counters().states >= states + 6; }, WAIT));
  EXPECT_DOUBLE_EQ(backend->capabilities().axes[ZOOM].range.max, 12.0);  // fov_wide / 0.1
}

TEST(DigiViewBackend, QuitIsSentAtShutdownAndClosesTheConnection)
{
  DigiViewEmulator emulator(DigiViewEmulatorConfig{});
  {
    auto backend = makeDigiViewBackend(backendConfig(emulator));
    backend->start();
    ASSERT_TRUE(waitUntil([&] { return emulator.connections() == 1; }, WAIT));
    emulator.received().clear();
  }
  // The backend is gone; what it wrote last may still be on its way to the emulator.
  auto is = [](MessageType type, digiview::ParamType param) {
    return [type, param](const ReceivedMessage& item) {
      return item.message.message_type == type && item.message.param_type == param;
    };
  };
  EXPECT_TRUE(emulator.received().waitFor(is(MessageType::GET_INTERVAL, digiview::ParamType::CAM_TARGETING), WAIT));
  EXPECT_TRUE(emulator.received().waitFor(is(MessageType::QUIT, digiview::ParamType::SYSTEM_STATUS), WAIT));
  EXPECT_TRUE(waitUntil([&] { return emulator.connections() == 0; }, WAIT)) << "QUIT closes the connection";
}

TEST(DigiViewBackend, ACameraTheStreamDoesNotHaveFailsAtStart)
{
  DigiViewEmulatorConfig emulator_config;
  emulator_config.layout_mode = 0;  // one user view
  DigiViewEmulator emulator(emulator_config);
  DigiViewConfig config = backendConfig(emulator);
  config.digiview.cam_id = 1;
  auto backend = makeDigiViewBackend(config);
  try
  {
    backend->start();
    FAIL() << "start() accepted a camera that does not exist";
  }
  catch (const BackendError& error)
  {
    const std::string text = error.what();
    EXPECT_NE(text.find("DigiView view 'main' camera 1 on tcp 127.0.0.1:"), std::string::npos) << text;
    EXPECT_NE(text.find("stream 'main' has 1 user view(s), so cam_id 1 does not exist"), std::string::npos) << text;
  }
}

TEST(DigiViewEmulator, AnswersLikeDigiView)
{
  DigiViewEmulator emulator(DigiViewEmulatorConfig{});
  boost::asio::io_context context;
  boost::asio::ip::tcp::socket socket(context);
  socket.connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), emulator.port()));
  auto read = [&]() {
    Bytes answer{};
    boost::asio::read(socket, boost::asio::buffer(answer));
    Message message;
    EXPECT_EQ(Message::unpack(answer.data(), answer.size(), message), UnpackError::NONE);
    return message;
  };
  auto exchange = [&](Bytes bytes) {
    boost::asio::write(socket, boost::asio::buffer(bytes));
    return read();
  };
  const CameraId camera{ "main", 0 };
  CamTargeting targeting;
  targeting.camera = camera;
  targeting.yaw = 0.1;
  EXPECT_EQ(exchange(packTargeting(MessageType::SET_PARAMETERS, targeting).pack()).message_type,
            MessageType::ACKNOWLEDGEMENT);
  Bytes broken = packTargeting(MessageType::SET_PARAMETERS, targeting).pack();
  broken[30] ^= 0x10;
  EXPECT_EQ(exchange(broken).message_type, MessageType::CHECKSUM_ERROR);
  Bytes unknown = packBare(MessageType::ACKNOWLEDGEMENT, digiview::ParamType::CAM_TARGETING).pack();
  unknown[9] = 42;
  unknown[75] = crc8(unknown.data(), 75);
  EXPECT_EQ(exchange(unknown).message_type, MessageType::UNKNOWN);
  Bytes out_of_range = packTargeting(MessageType::SET_PARAMETERS, targeting).pack();
  out_of_range[11 + 8] = 9;  // cam_id 9
  out_of_range[75] = crc8(out_of_range.data(), 75);
  EXPECT_EQ(exchange(out_of_range).message_type, MessageType::DATA_ERROR);
  EXPECT_EQ(exchange(packGet(digiview::ParamType::AI, camera).pack()).message_type, MessageType::UNKNOWN);
  const Message state = exchange(packGet(digiview::ParamType::CAM_TARGETING, camera).pack());
  EXPECT_EQ(state.message_type, MessageType::CURRENT_PARAMETERS);

  // GET_INTERVAL: under 100 ms is ignored; 100 ms comes periodically; 0 cancels. The emulator stamps what it sends
  // in microseconds: its own stamps tell the period, whatever this thread's timing.
  boost::asio::write(
      socket,
      boost::asio::buffer(packInterval(IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 50 }).pack()));
  boost::asio::write(
      socket,
      boost::asio::buffer(packInterval(IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 100 }).pack()));
  std::vector<std::uint64_t> stamps;
  for (int count = 0; count < 6; ++count)
  {
    stamps.push_back(read().timestamp);
  }
  // On average: a late timer shortens the next interval (the schedule does not drift), never the mean.
  EXPECT_GE((stamps.back() - stamps.front()) / (stamps.size() - 1), 75000u) << "reports every 50 ms: 50 was taken";
  boost::asio::write(
      socket,
      boost::asio::buffer(packInterval(IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 0 }).pack()));
  // Reports sent before the cancel was read come first; the answer to this GET marks the end of them.
  boost::asio::write(socket, boost::asio::buffer(packGet(digiview::ParamType::SYSTEM_STATUS, camera).pack()));
  while (read().param_type != digiview::ParamType::SYSTEM_STATUS)
  {
  }
  pollfd readable{ socket.native_handle(), POLLIN, 0 };
  EXPECT_EQ(::poll(&readable, 1, 350), 0) << "the subscription went on after an interval of 0";

  // QUIT closes the connection.
  boost::asio::write(socket,
                     boost::asio::buffer(packBare(MessageType::QUIT, digiview::ParamType::SYSTEM_STATUS).pack()));
  Bytes after{};
  boost::system::error_code error;
  boost::asio::read(socket, boost::asio::buffer(after), error);
  EXPECT_EQ(error, boost::asio::error::eof);
}

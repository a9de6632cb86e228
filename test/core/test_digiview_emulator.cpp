/**
 * \file
 * \brief The DigiView emulator's own answers, in every format, to a client on a TCP socket.
 */
#include <gtest/gtest.h>
#include <poll.h>

#include <cmath>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include "digiview_golden_frames.h"
#include "digiview_test_formats.h"
#include "ptz_action_server/emulators/digiview_emulator.h"
#include "wait_until.h"

using namespace ptz_action_server;
using namespace ptz_action_server::digiview;

namespace
{
constexpr double WAIT = 10.0;

/// A client of the emulator on a blocking TCP socket, speaking the format under test.
class DigiViewEmulatorAnswers : public ::testing::TestWithParam<Format>
{
protected:
  void SetUp() override
  {
    start(DigiViewEmulatorConfig{});
  }

  /// An emulator of \p config in the format under test (its documented angle unit unless \p config names the format).
  void start(DigiViewEmulatorConfig config)
  {
    if (config.wire.format != GetParam())
    {
      config.wire = Wire(GetParam(), config.wire.checksum);
    }
    socket_.reset();
    emulator_ = std::make_unique<DigiViewEmulator>(config);
    socket_ = std::make_unique<boost::asio::ip::tcp::socket>(context_);
    socket_->connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), emulator_->port()));
  }

  Layout layout() const
  {
    return layoutOf(GetParam());
  }

  void write(const Bytes& bytes)
  {
    boost::asio::write(*socket_, boost::asio::buffer(bytes));
  }
  void write(const Message& message)
  {
    write(message.pack());
  }

  /// The next message; its raw bytes in last_.
  Message read(const Wire& wire)
  {
    last_.assign(layout().size, 0);
    boost::asio::read(*socket_, boost::asio::buffer(last_));
    Message message;
    EXPECT_EQ(Message::unpack(last_.data(), last_.size(), wire, message), UnpackError::NONE);
    return message;
  }
  Message read()
  {
    return read(Wire{ GetParam() });
  }
  Message exchange(const Bytes& bytes)
  {
    write(bytes);
    return read();
  }
  Message exchange(const Message& message)
  {
    return exchange(message.pack());
  }

  boost::asio::io_context context_;
  std::unique_ptr<DigiViewEmulator> emulator_;
  std::unique_ptr<boost::asio::ip::tcp::socket> socket_;
  Bytes last_;
};
}  // namespace

TEST_P(DigiViewEmulatorAnswers, AnswersLikeDigiView)
{
  const Format format = GetParam();
  const std::size_t checksum = layout().checksum_offset;
  const CameraId camera{ "main", 0 };
  CamTargeting targeting;
  targeting.camera = camera;
  targeting.yaw = 0.1;
  EXPECT_EQ(exchange(packTargeting(format, MessageType::SET_PARAMETERS, targeting)).message_type,
            MessageType::ACKNOWLEDGEMENT);
  EXPECT_EQ(last_[9], format == Format::V0_5 ? 5 : 4);  // renumbered from 1.0 on
  Bytes broken = packTargeting(format, MessageType::SET_PARAMETERS, targeting).pack();
  broken[30] ^= 0x10;
  EXPECT_EQ(exchange(broken).message_type, MessageType::CHECKSUM_ERROR);
  Bytes unknown = packBare(format, MessageType::ACKNOWLEDGEMENT, digiview::ParamType::CAM_TARGETING).pack();
  unknown[9] = 42;
  unknown[checksum] = crc8(unknown.data(), checksum);
  EXPECT_EQ(exchange(unknown).message_type, MessageType::UNKNOWN);
  Bytes out_of_range = packTargeting(format, MessageType::SET_PARAMETERS, targeting).pack();
  out_of_range[layout().data_offset + nameSizeOf(format)] = 9;  // cam_id 9
  out_of_range[checksum] = crc8(out_of_range.data(), checksum);
  EXPECT_EQ(exchange(out_of_range).message_type, MessageType::DATA_ERROR);
  EXPECT_EQ(exchange(packGet(format, digiview::ParamType::AI, camera)).message_type, MessageType::UNKNOWN);
  const Message state = exchange(packGet(format, digiview::ParamType::CAM_TARGETING, camera));
  EXPECT_EQ(state.message_type, MessageType::CURRENT_PARAMETERS);
  EXPECT_EQ(state.interval_ms, 0u);

  // Subscriptions: under the minimum (100 ms, 1.2: 50 ms) is ignored, or in 1.2 answered once; 100 ms comes
  // periodically; 0 cancels. The emulator stamps what it sends in microseconds: its own stamps tell the period,
  // whatever this thread's timing.
  const std::uint32_t too_short = minIntervalOf(format) / 2;
  write(packInterval(format, IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, too_short }));
  if (shortIntervalIsOneShot(format))
  {
    EXPECT_EQ(read().message_type, MessageType::CURRENT_PARAMETERS);  // the one answer
  }
  write(packInterval(format, IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 100 }));
  std::vector<std::uint64_t> stamps;
  for (int count = 0; count < 6; ++count)
  {
    stamps.push_back(read().timestamp);
  }
  // On average: a late timer shortens the next interval (the schedule does not drift), never the mean.
  EXPECT_GE((stamps.back() - stamps.front()) / (stamps.size() - 1), 75000u)
      << "reports more often than every 100 ms: " << too_short << " was taken";
  write(packInterval(format, IntervalRequest{ digiview::ParamType::CAM_TARGETING, camera, 0 }));
  // Reports sent before the cancel was read come first; the answer to this GET marks the end of them.
  write(packGet(format, digiview::ParamType::SYSTEM_STATUS, camera));
  while (read().param_type != digiview::ParamType::SYSTEM_STATUS)
  {
  }
  pollfd readable{ socket_->native_handle(), POLLIN, 0 };
  EXPECT_EQ(::poll(&readable, 1, 350), 0) << "the subscription went on after an interval of 0";

  // QUIT closes the connection.
  write(packBare(format, MessageType::QUIT, digiview::ParamType::SYSTEM_STATUS));
  Bytes after(layout().size);
  boost::system::error_code error;
  boost::asio::read(*socket_, boost::asio::buffer(after), error);
  EXPECT_EQ(error, boost::asio::error::eof);
}

TEST_P(DigiViewEmulatorAnswers, DescribesTheStreamAsThePublishedPackerDoes)
{
  const Format format = GetParam();
  VideoOutput output;
  ASSERT_EQ(
      unpackVideoOutput(exchange(packGet(format, digiview::ParamType::VIDEO_OUTPUT, CameraId{ "main", 0 })), output),
      UnpackError::NONE);
  EXPECT_EQ(output.layout_mode, 4);
  EXPECT_EQ(output.num_user_views, 4);
  EXPECT_EQ(last_[layout().data_offset + nameSizeOf(format) + 7], 4);  // its own byte
  EXPECT_EQ(output.views[3].x, 960);
  EXPECT_EQ(output.views[3].y, 540);

  DigiViewEmulatorConfig config;
  config.layout_mode = 3;  // two on top, one below
  start(config);
  ASSERT_EQ(
      unpackVideoOutput(exchange(packGet(format, digiview::ParamType::VIDEO_OUTPUT, CameraId{ "main", 0 })), output),
      UnpackError::NONE);
  EXPECT_EQ(output.num_user_views, 3);
  EXPECT_EQ(output.views[2].w, 1920);
  SystemStatus status;
  ASSERT_EQ(unpackSystemStatus(exchange(packGet(format, digiview::ParamType::SYSTEM_STATUS, CameraId{})), status),
            UnpackError::NONE);
  EXPECT_DOUBLE_EQ(status.jetson_temp, 45.5);
  EXPECT_EQ(status.status, runningStatus(format));  // the seed's "running" 1, app_status RUNNING 2 from 1.1 on
}

TEST_P(DigiViewEmulatorAnswers, HaltsAndRunsAgainAsItsDocumentationSays)
{
  // From 1.1 on a SET SYSTEM_STATUS switches between RUNNING and HALT (nothing else); halted, the views stay where
  // they are. Before 1.1 SYSTEM_STATUS is GET only.
  const Format format = GetParam();
  const CameraId camera{ "main", 0 };
  const Message halt = packSystemStatus(format, MessageType::SET_PARAMETERS, SystemStatus{ APP_STATUS_HALT, 0, 0 });
  if (!hasAppStatus(format))
  {
    EXPECT_EQ(exchange(halt).message_type, MessageType::UNKNOWN);
    EXPECT_FALSE(emulator_->halted());
    return;
  }
  EXPECT_EQ(exchange(packSystemStatus(format, MessageType::SET_PARAMETERS, SystemStatus{ 3, 0, 0 })).message_type,
            MessageType::DATA_ERROR);  // ERROR is no state to set
  EXPECT_EQ(exchange(halt).message_type, MessageType::ACKNOWLEDGEMENT);
  EXPECT_TRUE(emulator_->halted());
  SystemStatus status;
  ASSERT_EQ(unpackSystemStatus(exchange(packGet(format, digiview::ParamType::SYSTEM_STATUS, camera)), status),
            UnpackError::NONE);
  EXPECT_EQ(status.status, APP_STATUS_HALT);
  CamTargeting targeting;
  targeting.camera = camera;
  targeting.yaw = 0.4;
  EXPECT_EQ(exchange(packTargeting(format, MessageType::SET_PARAMETERS, targeting)).message_type,
            MessageType::ACKNOWLEDGEMENT);
  EXPECT_EQ(emulator_->view("main", 0).position[PAN], 0.0) << "a halted DigiView turned a view";
  EXPECT_EQ(exchange(packSystemStatus(format, MessageType::SET_PARAMETERS, SystemStatus{ APP_STATUS_RUNNING, 0, 0 }))
                .message_type,
            MessageType::ACKNOWLEDGEMENT);
  EXPECT_FALSE(emulator_->halted());
  EXPECT_EQ(exchange(packTargeting(format, MessageType::SET_PARAMETERS, targeting)).message_type,
            MessageType::ACKNOWLEDGEMENT);
  EXPECT_TRUE(waitUntil([&] { return std::abs(emulator_->view("main", 0).position[PAN] - 0.4) < 1e-3; }, WAIT));
}

TEST_P(DigiViewEmulatorAnswers, SpeaksEitherAngleUnit)
{
  // The format's documented unit unless told otherwise: the same view reads 0.4 rad in either, and its bytes differ.
  const Format format = GetParam();
  for (AngleUnit unit : { AngleUnit::RADIANS, AngleUnit::DEGREES })
  {
    DigiViewEmulatorConfig config;
    config.wire = Wire(format, ChecksumRule::REQUIRED, unit);
    start(config);
    CamTargeting targeting;
    targeting.camera = CameraId{ "main", 0 };
    targeting.yaw = 0.4;
    write(packTargeting(config.wire, MessageType::SET_PARAMETERS, targeting));
    EXPECT_EQ(read(config.wire).message_type, MessageType::ACKNOWLEDGEMENT);
    ASSERT_TRUE(waitUntil([&] { return std::abs(emulator_->view("main", 0).position[PAN] - 0.4) < 1e-3; }, WAIT))
        << toString(unit);
    write(packGet(config.wire, digiview::ParamType::CAM_TARGETING, targeting.camera));
    CamTargeting state;
    ASSERT_EQ(unpackTargeting(read(config.wire), state), UnpackError::NONE);
    EXPECT_NEAR(state.yaw, 0.4, 2e-3) << toString(unit);  // truncated on the way: 399 mrad is 0.4 too
  }
}

TEST_P(DigiViewEmulatorAnswers, AZeroChecksumIsTakenOnlyWhenConfiguredAndItsOwnCanBeLeftUnfilled)
{
  // A published client leaves the checksum byte as its struct held it: 0.
  Bytes unfilled = digiview_golden::fromHex(digiview_golden::GET_CAM_TARGETING.in(GetParam()));
  unfilled[layout().checksum_offset] = 0;
  EXPECT_EQ(exchange(unfilled).message_type, MessageType::CHECKSUM_ERROR);

  DigiViewEmulatorConfig config;
  config.wire.checksum = ChecksumRule::ZERO_ACCEPTED;
  config.fill_checksum = false;
  start(config);
  write(unfilled);
  const Message state = read(Wire{ GetParam(), ChecksumRule::ZERO_ACCEPTED });
  EXPECT_EQ(state.message_type, MessageType::CURRENT_PARAMETERS);
  EXPECT_EQ(last_[layout().checksum_offset], 0) << "the emulator was told not to fill it";
  Message strict;
  // Unless the answer's own CRC-8 happens to be 0 (1 in 256: it carries the moving state), a strict peer refuses it.
  const bool crc_is_zero = digiview::crc8(last_.data(), layout().checksum_offset) == 0;
  EXPECT_EQ(Message::unpack(last_.data(), last_.size(), Wire{ GetParam() }, strict),
            crc_is_zero ? UnpackError::NONE : UnpackError::BAD_CHECKSUM);
  ASSERT_TRUE(emulator_->received().waitForCount(1, WAIT));
  const ReceivedMessage received = emulator_->received().items().front();
  EXPECT_EQ(received.error, UnpackError::NONE);
  EXPECT_TRUE(received.unverified);
}

INSTANTIATE_TEST_SUITE_P(Formats, DigiViewEmulatorAnswers, ::testing::ValuesIn(digiview_test::FORMATS),
                         digiview_test::formatName);

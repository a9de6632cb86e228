/**
 * \file
 * \brief Frames of one PanTilt wire format sent to a receiver configured for another, over UDP on 127.0.0.1: the
 * emulated device and the pantilt backend count every frame they can recognise as another format under
 * "foreign format", and never execute it: the device does not move and nothing it holds changes; the backend takes
 * no state from it, and does not start against a device of another format.
 */
#include <gtest/gtest.h>

#include "wait_until.h"

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"
#include "ptz_action_server/emulators/ports/udp_socket.h"

using namespace ptz_action_server;
using namespace cr::pantilt;
using Bytes = std::vector<std::uint8_t>;

namespace
{
/// (sender, receiver): every ordered pair of different formats.
using FormatPair = std::tuple<WireFormat, WireFormat>;

std::vector<FormatPair> differentFormatPairs()
{
  std::vector<FormatPair> pairs;
  for (WireFormat sender : ALL_WIRE_FORMATS)
  {
    for (WireFormat receiver : ALL_WIRE_FORMATS)
    {
      if (sender != receiver)
      {
        pairs.emplace_back(sender, receiver);
      }
    }
  }
  return pairs;
}

std::string pairName(const ::testing::TestParamInfo<FormatPair>& info)
{
  auto name = [](WireFormat format) {
    return format == WireFormat::SEED ? std::string("Seed") : format == WireFormat::V1_0 ? "V1_0" : "V1_1";
  };
  return name(std::get<0>(info.param)) + "To" + name(std::get<1>(info.param));
}

Bytes paramsFrame(const PanTiltParams& params, WireFormat format, const PanTiltParamsMask* mask = nullptr)
{
  Bytes frame(MAX_PARAMS_FRAME_SIZE);
  int size = 0;
  EXPECT_TRUE(params.encode(frame.data(), static_cast<int>(frame.size()), size, mask, format));
  frame.resize(static_cast<std::size_t>(size));
  return frame;
}

Bytes stateRequest(WireFormat format)
{
  const PanTiltParamsMask none = PanTiltParamsMask::none();
  return paramsFrame(PanTiltParams(), format, &none);
}

/// A state a device far from home would report: pan 90, tilt 45 degrees.
PanTiltParams farAwayState()
{
  PanTiltParams params;
  params.panAngle = params.panTiltAngle = 90.0f;
  params.tiltAngle = 45.0f;
  params.panMotorPosition = params.panTiltMotorPosition = SimPanTilt::angleToMotorPosition(PAN, 90.0);
  params.tiltMotorPosition = SimPanTilt::angleToMotorPosition(TILT, 45.0);
  params.panMotorSpeed = params.tiltMotorSpeed = params.panTiltMotorSpeed = 10.0f;
  params.isConnected = params.isOpen = true;
  return params;
}

/// Params frames of \p sender that a decoder of \p receiver recognises as another format: full frames, and single
/// fields that only plausibility tells (mask0 bit 7, bit 3) or only their length.
std::vector<Bytes> foreignParamsFrames(WireFormat sender, WireFormat receiver)
{
  std::vector<Bytes> frames = { paramsFrame(farAwayState(), sender) };
  for (bool PanTiltParamsMask::*field :
       { &PanTiltParamsMask::panAngle, &PanTiltParamsMask::panMotorPosition, &PanTiltParamsMask::panMotorSpeed,
         &PanTiltParamsMask::panTiltMotorPosition, &PanTiltParamsMask::tiltAngle, &PanTiltParamsMask::isConnected })
  {
    PanTiltParamsMask mask = PanTiltParamsMask::none();
    mask.*field = true;
    frames.push_back(paramsFrame(farAwayState(), sender, &mask));
  }
  frames.push_back(stateRequest(sender));
  std::vector<Bytes> foreign;
  for (const Bytes& frame : frames)
  {
    PanTiltParams ignored;
    DecodeError error = DecodeError::NONE;
    if (!ignored.decode(frame.data(), static_cast<int>(frame.size()), receiver, &error) &&
        error == DecodeError::FOREIGN_FORMAT)
    {
      foreign.push_back(frame);
    }
  }
  return foreign;
}

/// Every COMMAND of \p sender (a move far away, speeds, a restart), and its SET_PARAMs that a decoder of \p receiver
/// recognises as another format (ids 1..9 of the seed and v1.0 look alike: those are left out).
std::vector<Bytes> foreignCommandFrames(WireFormat sender, WireFormat receiver)
{
  std::vector<Bytes> frames;
  for (int id = 1; id <= (hasCommandArguments(sender) ? 12 : 9); ++id)
  {
    Bytes frame(MAX_COMMAND_SIZE);
    int size = 0;
    EXPECT_TRUE(PanTilt::encodeCommand(frame.data(), size, static_cast<PanTiltCommand>(id), sender, 50.0f, 25.0f));
    frame.resize(static_cast<std::size_t>(size));
    frames.push_back(frame);
  }
  for (int param : { 1, 2, 3, 4, 5, 6, 7, 8, 9, 101, 102, 103, 104, 105 })
  {
    Bytes frame(SET_PARAM_SIZE);
    int size = 0;
    if (PanTilt::encodeSetParamCommand(frame.data(), size, static_cast<PanTiltParam>(param), 50.0f, sender))
    {
      PanTiltParam decoded_param{};
      PanTiltCommand command{};
      float value = 0.0f;
      DecodeError error = DecodeError::NONE;
      PanTilt::decodeCommand(frame.data(), size, decoded_param, command, value, receiver, nullptr, &error);
      if (error == DecodeError::FOREIGN_FORMAT)
      {
        frames.push_back(frame);
      }
    }
  }
  return frames;
}

/// A free UDP port on 127.0.0.1 (the kernel's choice).
std::uint16_t freeLocalPort()
{
  UdpSocket probe;
  probe.bind("127.0.0.1", 0);
  return probe.localEndpoint().port();
}

class PanTiltForeignFramesTest : public ::testing::TestWithParam<FormatPair>
{
protected:
  WireFormat sender() const
  {
    return std::get<0>(GetParam());
  }
  WireFormat receiver() const
  {
    return std::get<1>(GetParam());
  }
};
}  // namespace

TEST_P(PanTiltForeignFramesTest, TheDeviceCountsThemAndExecutesNothing)
{
  PanTiltEmulatorConfig config;
  config.format = receiver();
  config.state_period = 0.0;  // replies only: every reply answers one valid datagram
  PanTiltEmulator device(config);
  UdpSocket client;
  client.bind("127.0.0.1", 0);
  auto send = [&](const Bytes& frame) {
    ASSERT_TRUE(client.sendTo(UdpEndpoint::resolve("127.0.0.1", device.udpPort()), frame.data(), frame.size()));
  };
  // Every valid datagram has had its reply (the count of a reply follows the count of its datagram); a foreign frame
  // answered would keep this false.
  auto all_answered = [&] {
    const PanTiltEmulatorCounters counted = device.counters();
    return counted.replies_sent == counted.commands_executed + counted.commands_refused + counted.state_requests;
  };

  // Speeds at 50 % in the device's own format, so that a foreign RESTART or speed would show.
  for (PanTiltParam speed : { PanTiltParam::PAN_MOTOR_SPEED, PanTiltParam::TILT_MOTOR_SPEED })
  {
    Bytes frame(SET_PARAM_SIZE);
    int size = 0;
    ASSERT_TRUE(PanTilt::encodeSetParamCommand(frame.data(), size, speed, 50.0f, receiver()));
    send(frame);
  }
  ASSERT_TRUE(waitUntil([&] { return device.counters().commands_executed == 2 && all_answered(); }, 10.0));
  PanTiltParams before;
  device.panTilt().getParams(before);
  const PanTiltEmulatorCounters counted_before = device.counters();

  std::vector<Bytes> foreign = foreignCommandFrames(sender(), receiver());
  ASSERT_GE(foreign.size(), 9u) << "every COMMAND tells its format";
  const std::vector<Bytes> params = foreignParamsFrames(sender(), receiver());
  ASSERT_GE(params.size(), 1u);
  foreign.insert(foreign.end(), params.begin(), params.end());
  for (const Bytes& frame : foreign)
  {
    send(frame);
  }
  // Then a state request of its own: once it is answered, every frame before it has been handled (one socket to
  // another on the loopback keeps their order).
  send(stateRequest(receiver()));
  ASSERT_TRUE(waitUntil(
      [&] { return device.counters().state_requests == counted_before.state_requests + 1 && all_answered(); }, 10.0))
      << "dropped as another format: " << device.counters().dropped(DecodeError::FOREIGN_FORMAT)
      << ", replies sent: " << device.counters().replies_sent - counted_before.replies_sent;

  const PanTiltEmulatorCounters counted = device.counters();
  EXPECT_EQ(counted.dropped(DecodeError::FOREIGN_FORMAT), foreign.size());
  for (std::size_t reason = 0; reason < DECODE_ERROR_COUNT; ++reason)
  {
    if (reason != static_cast<std::size_t>(DecodeError::FOREIGN_FORMAT))
    {
      EXPECT_EQ(counted.invalid[reason], 0u) << toString(static_cast<DecodeError>(reason));
    }
  }
  EXPECT_EQ(counted.commands_executed, counted_before.commands_executed);
  EXPECT_EQ(counted.commands_refused, counted_before.commands_refused);
  EXPECT_EQ(counted.replies_sent, counted_before.replies_sent + 1) << "a foreign frame was answered";
  EXPECT_FALSE(device.panTilt().sample().moving);
  PanTiltParams after;
  device.panTilt().getParams(after);
  EXPECT_EQ(after, before);
}

TEST_P(PanTiltForeignFramesTest, TheBackendCountsThemAndTakesNoStateFromThem)
{
  PanTiltEmulatorConfig emulator_config;
  emulator_config.format = receiver();
  emulator_config.state_period = 0.05;
  auto emulator = std::make_unique<PanTiltEmulator>(emulator_config);
  const std::uint16_t device_port = emulator->udpPort();
  DeviceConfig<PanTiltProtocol> config;
  config.settings.format = receiver();
  config.link.port = device_port;
  config.link.local_host = "127.0.0.1";
  config.link.local_port = freeLocalPort();  // known, so that the test can send to the backend
  config.session.state_timeout = 1.0;
  std::unique_ptr<DeviceBackend> backend = makeDeviceBackend<PanTiltProtocol>(config);
  backend->start();
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, 10.0)) << "the link never came up";

  // The device's place is taken by a socket the test speaks through: nothing else reaches the backend from there.
  emulator.reset();
  UdpSocket device;
  device.bind("127.0.0.1", device_port);
  const UdpEndpoint backend_endpoint = UdpEndpoint::resolve("127.0.0.1", config.link.local_port);
  auto send = [&](const Bytes& frame) { ASSERT_TRUE(device.sendTo(backend_endpoint, frame.data(), frame.size())); };
  auto counters = [&] { return backend->protocol<PanTiltProtocol>().counters(); };
  auto pan_at = [&](double degrees) {
    return std::abs(backend->sample().position[PAN] - degrees * M_PI / 180.0) < 1e-4;
  };

  // A state of its own format first: once it shows, whatever the emulator sent before has been handled.
  PanTiltParams own;
  own.panAngle = 7.0f;
  own.tiltAngle = -3.0f;
  send(paramsFrame(own, receiver()));
  ASSERT_TRUE(waitUntil([&] { return pan_at(7.0); }, 10.0));
  const PanTiltCounters before = counters();

  const std::vector<Bytes> foreign = foreignParamsFrames(sender(), receiver());
  ASSERT_GE(foreign.size(), 2u);
  for (const Bytes& frame : foreign)
  {
    send(frame);
  }
  ASSERT_TRUE(waitUntil(
      [&] { return counters().foreign_format_frames == before.foreign_format_frames + foreign.size(); }, 10.0))
      << "another format: " << counters().foreign_format_frames - before.foreign_format_frames << " of "
      << foreign.size() << ", frames ok " << counters().frames_ok - before.frames_ok;
  // Nothing came after them: the state is still the one of the backend's own format.
  const PanTiltCounters after = counters();
  EXPECT_EQ(after.frames_ok, before.frames_ok);
  EXPECT_EQ(after.dropped() - before.dropped(), foreign.size());
  EXPECT_TRUE(pan_at(7.0)) << backend->sample().position[PAN];
  EXPECT_NEAR(backend->sample().position[TILT], -3.0 * M_PI / 180.0, 1e-4);
}

TEST_P(PanTiltForeignFramesTest, ABackendAndADeviceOfDifferentFormatsNeverWorkTogether)
{
  // The device speaks the sender's format, the backend the receiver's.
  PanTiltEmulatorConfig emulator_config;
  emulator_config.format = sender();
  PanTiltEmulator device(emulator_config);
  DeviceConfig<PanTiltProtocol> config;
  config.settings.format = receiver();
  config.link.port = device.udpPort();
  config.link.local_host = "127.0.0.1";
  // The seed and v1.0 share their version bytes, so each answers the other's state request, and the backend gives
  // up at the first answer it recognises as another format. Between v1.1 and the others every frame is foreign:
  // the device drops them all and answers nothing, so the backend waits its whole start-up time.
  const bool device_answers = receiver() != WireFormat::V1_1 && sender() != WireFormat::V1_1;
  config.session.startup_timeout = device_answers ? 30.0 : 1.0;
  std::unique_ptr<DeviceBackend> backend = makeDeviceBackend<PanTiltProtocol>(config);
  try
  {
    backend->start();
    FAIL() << "the backend started against a device of another format";
  }
  catch (const BackendError& error)
  {
    const std::string expected =
        device_answers ? "in another PanTilt wire format than the configured " : "no answer from ";
    EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
  }
  const PanTiltCounters counted = backend->protocol<PanTiltProtocol>().counters();
  EXPECT_EQ(counted.frames_ok, 0u);
  EXPECT_EQ(counted.foreign_format_frames > 0, device_answers);
  EXPECT_EQ(counted.dropped(), counted.foreign_format_frames);
  const PanTiltEmulatorCounters device_counted = device.counters();
  EXPECT_EQ(device_counted.dropped(DecodeError::FOREIGN_FORMAT) > 0, !device_answers);
  if (!device_answers)
  {
    EXPECT_EQ(device_counted.commands_executed + device_counted.commands_refused + device_counted.state_requests, 0u);
  }
  EXPECT_FALSE(device.panTilt().sample().moving);
}

INSTANTIATE_TEST_SUITE_P(EveryPairOfFormats, PanTiltForeignFramesTest, ::testing::ValuesIn(differentFormatPairs()),
                         pairName);

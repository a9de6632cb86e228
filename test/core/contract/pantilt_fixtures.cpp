#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "device_fixtures_internal.h"
#include "ptz_action_server/core/pantilt/pantilt_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;

// ---------------------------------------------------------------- PanTilt over UDP

class PanTiltFixture : public DeviceFixture
{
public:
  /// Over UDP, or (\p serial) in SLIP frames on a pseudo-terminal.
  explicit PanTiltFixture(cr::pantilt::WireFormat format, bool serial = false)
  {
    emulator_config_.format = format;
    emulator_config_.state_period = 0.05;
    emulator_config_.serial = serial;
    if (serial)
    {
      emulator_config_.line.link = uniqueLink("pantilt");
      emulator_config_.line.baud = 115200;
      config_.link.kind = LinkKind::SERIAL;
      config_.link.path = emulator_config_.line.link;
      config_.link.baud = 115200;
    }
    emulator_ = std::make_unique<PanTiltEmulator>(emulator_config_);
    if (!serial)
    {
      emulator_config_.port = emulator_->udpPort();  // a restart takes the same port
      config_.link.port = emulator_config_.port;
      config_.link.local_host = "127.0.0.1";
    }
    config_.settings.format = format;
    config_.session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    return makeDeviceBackend<PanTiltProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    using namespace cr::pantilt;
    std::vector<DeviceCommand> commands;
    for (const ReceivedDatagram& datagram : emulator_->received().items())
    {
      PanTiltParam param{};
      PanTiltCommand command{};
      float value = 0.0f;
      Kind kind = Kind::OTHER;
      const int decoded = datagram.bytes.empty() || datagram.bytes[0] == PARAMS_HEADER ?
                              -1 :
                              PanTilt::decodeCommand(datagram.bytes.data(), static_cast<int>(datagram.bytes.size()),
                                                     param, command, value, emulator_config_.format);
      if (decoded < 0)
      {
        kind = Kind::QUERY;  // a state request (or garbage)
      }
      else if (decoded == 0 && command == PanTiltCommand::STOP)
      {
        kind = Kind::STOP;
      }
      else if (decoded == 0 && command == PanTiltCommand::GO_TO_PAN_TILT_ANGLE)
      {
        kind = Kind::MOVE;
      }
      commands.push_back(DeviceCommand{ datagram.at, kind, hex(datagram.bytes) });
    }
    return commands;
  }
  void clearCommands() override
  {
    emulator_->received().clear();
  }
  PtzSample deviceState() const override
  {
    return emulator_->panTilt().sample();
  }
  /// The controller reports as soon as it knows its peer, so the link can come up on the first speed frame, before
  /// the emulator reads the rest; the state request that ends the start-up has arrived once the rest has.
  bool startupReceived() const override
  {
    const auto datagrams = emulator_->received().items();
    return std::any_of(datagrams.begin(), datagrams.end(), [](const ReceivedDatagram& datagram) {
      return !datagram.bytes.empty() && datagram.bytes[0] == cr::pantilt::PARAMS_HEADER;
    });
  }
  void setSilent(bool silent) override
  {
    emulator_->setSilent(silent);
  }
  bool setFlood(unsigned copies) override
  {
    if (emulator_config_.serial)
    {
      return false;  // a serial line carries what its baud rate allows: no flood
    }
    emulator_->setFlood(copies);
    return true;
  }
  bool setEndlessReplies(bool endless) override
  {
    emulator_->setEndless(endless);
    return true;
  }
  bool setFaults(const SimFaults& faults) override
  {
    emulator_->panTilt().setFaults(faults);
    return true;
  }
  void breakLink() override
  {
    if (emulator_config_.serial)
    {
      emulator_->unplug();
      return;
    }
    emulator_.reset();  // the device controller is gone
  }
  void restoreLink() override
  {
    if (emulator_config_.serial)
    {
      emulator_->replug();
    }
    else if (!emulator_)
    {
      emulator_ = std::make_unique<PanTiltEmulator>(emulator_config_);
    }
  }
  bool breaksAtOnce() const override
  {
    return emulator_config_.serial;
  }
  std::string linkLossWords() const override
  {
    return emulator_config_.serial ? config_.link.path : "no state from a PanTilt device controller";
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    using namespace cr::pantilt;
    const WireFormat format = emulator_config_.format;
    auto set = [format](PanTiltParam id, double value) {
      std::vector<std::uint8_t> frame(SET_PARAM_SIZE);
      int size = 0;
      PanTilt::encodeSetParamCommand(frame.data(), size, id, static_cast<float>(value), format);
      return hex(frame);
    };
    auto command = [format](PanTiltCommand id, double arg1 = 0.0, double arg2 = 0.0) {
      std::vector<std::uint8_t> frame(MAX_COMMAND_SIZE);
      int size = 0;
      PanTilt::encodeCommand(frame.data(), size, id, format, static_cast<float>(arg1), static_cast<float>(arg2));
      frame.resize(static_cast<std::size_t>(size));
      return hex(frame);
    };
    std::vector<std::string> expected = { set(PanTiltParam::PAN_MOTOR_SPEED, 100.0),
                                          set(PanTiltParam::TILT_MOTOR_SPEED, 100.0) };
    if (format == WireFormat::SEED)
    {
      expected.push_back(set(PanTiltParam::PAN_ANGLE, toDegrees(target[PAN])));
      expected.push_back(set(PanTiltParam::TILT_ANGLE, toDegrees(target[TILT])));
      expected.push_back(command(PanTiltCommand::GO_TO_PAN_TILT_ANGLE));
    }
    else
    {
      expected.push_back(
          command(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, toDegrees(target[PAN]), toDegrees(target[TILT])));
    }
    std::vector<std::string> texts;
    for (const DeviceCommand& sent : withoutQueries(commands))
    {
      texts.push_back(sent.text);
    }
    EXPECT_EQ(texts, expected);
  }

private:
  PanTiltEmulatorConfig emulator_config_;
  std::unique_ptr<PanTiltEmulator> emulator_;
  DeviceConfig<PanTiltProtocol> config_;
};

const DeviceFixtureRegistration PANTILT_FIXTURES({
    { "PanTiltUdpSeed", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::SEED); } },
    { "PanTiltUdpV1_0", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::V1_0); } },
    { "PanTiltUdpV1_1", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::V1_1); } },
    { "PanTiltSerialSeed", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::SEED, true); } },
    { "PanTiltSerialV1_1", [] { return std::make_unique<PanTiltFixture>(cr::pantilt::WireFormat::V1_1, true); } },
});
}  // namespace

}  // namespace ptz_action_server

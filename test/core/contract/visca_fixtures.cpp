#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include "../line_test_support.h"
#include "device_fixtures_internal.h"
#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/emulators/visca_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;
using PortKind = DevicePortConfig::Kind;

/// The backend's configuration as config/visca.yaml ships it (visca: ...): the session's timing, the reply timeout,
/// the camera's address and model, the framing (sony_ip by default over UDP). The link is the test's: the emulator's
/// port on 127.0.0.1, any free local port (the tests run side by side; the emulator answers the sender).
DeviceConfig<ViscaProtocol> shippedConfig()
{
  const YAML::Node visca = YAML::LoadFile(std::string(PTZ_SOURCE_DIR) + "/config/visca.yaml")["visca"];
  DeviceConfig<ViscaProtocol> config;
  const auto number = [&visca](const char* name, double fallback) {
    return visca[name] ? visca[name].as<double>() : fallback;
  };
  config.session.state_timeout = number("state_timeout", config.session.state_timeout);
  config.session.poll_period = number("poll_period", config.session.poll_period);
  config.session.startup_timeout = number("startup_timeout", config.session.startup_timeout);
  config.session.settle_window = number("settle_window", config.session.settle_window);
  config.settings.reply_timeout = number("reply_timeout", config.settings.reply_timeout);
  config.settings.address = static_cast<std::uint8_t>(number("address", config.settings.address));
  EXPECT_TRUE(visca::ViscaModel::preset(visca["model"].as<std::string>("ptzoptics"), config.settings.model));
  EXPECT_EQ(visca["transport"].as<std::string>("udp"), "udp") << "the shipped file drives a camera over UDP";
  EXPECT_TRUE(parseViscaFraming(visca["framing"].as<std::string>("sony_ip"), config.settings.framing));
  return config;
}

/// A VISCA camera (EVI-D70 units) on a pseudo-terminal at 38400 baud, raw over TCP, or over UDP raw or with Sony's
/// header; or (\p shipped) a camera of the field dialect \p mode driven with config/visca.yaml as shipped.
class ViscaFixture : public DeviceFixture
{
public:
  ViscaFixture(PortKind kind, ViscaFraming framing, const char* mode = nullptr)
  {
    visca::ViscaModel::preset("evi_d70", emulator_config_.model);
    emulator_config_.address = 2;
    config_.session.state_timeout = TEST_STATE_TIMEOUT;
    if (mode != nullptr)
    {
      config_ = shippedConfig();
      framing = config_.settings.framing;
      emulator_config_.model = config_.settings.model;
      emulator_config_.address = config_.settings.address;
      EXPECT_TRUE(emulator_config_.applyMode(mode)) << mode;
    }
    emulator_config_.port.kind = kind;
    emulator_config_.port.link = uniqueLink("visca");
    emulator_config_.port.baud = 38400;
    emulator_config_.framing = framing;
    emulator_ = std::make_unique<ViscaEmulator>(emulator_config_);
    LinkConfig& link = config_.link;
    if (kind == PortKind::PTY)
    {
      link = serialLink(emulator_config_.port.link, emulator_config_.port.baud);
    }
    else
    {
      link.kind = kind == PortKind::TCP ? LinkKind::TCP : LinkKind::UDP;
      link.port = kind == PortKind::TCP ? emulator_->port().tcpPort() : emulator_->port().udpPort();
      link.local_host = "127.0.0.1";
      emulator_config_.port.port = link.port;  // a restart takes the same port
    }
    config_.settings.address = emulator_config_.address;
    config_.settings.framing = framing;
    config_.settings.model = emulator_config_.model;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    return makeDeviceBackend<ViscaProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    std::vector<DeviceCommand> commands;
    for (const ReceivedPacket& item : emulator_->received().items())
    {
      const visca::Packet& packet = item.packet;
      Kind kind = Kind::OTHER;
      if (!item.control && packet.size() > 3 && packet[1] == 0x09)
      {
        kind = Kind::QUERY;
      }
      else if (!item.control && packet.size() == 9 && packet[2] == 0x06 && packet[3] == 0x01 && packet[6] == 0x03 &&
               packet[7] == 0x03)
      {
        kind = Kind::STOP;
      }
      else if (!item.control && packet.size() > 3 && (packet[3] == 0x02 || packet[3] == 0x47))
      {
        kind = Kind::MOVE;
      }
      commands.push_back(DeviceCommand{ item.at, kind, hex(packet) });
    }
    return commands;
  }
  void clearCommands() override
  {
    emulator_->received().clear();
  }
  PtzSample deviceState() const override
  {
    return emulator_->sample();
  }
  void setSilent(bool silent) override
  {
    emulator_->port().setSilent(silent);
  }
  double replyDeadline() const override
  {
    if (emulator_config_.modes.g2_latency)
    {
      return 0.0;  // its answers already take up to 123 ms of the 200 the deadline learns: a delay on top means nothing
    }
    // The most the reply deadline learns beyond the exchange's wire time: twice its floor, reply_timeout or 100 ms.
    return 2.0 * (config_.settings.reply_timeout > 0.0 ? config_.settings.reply_timeout : 0.1);
  }
  bool setEndlessReplies(bool endless) override
  {
    emulator_->port().setEndless(endless);
    return true;
  }
  bool setFaults(const SimFaults& faults) override
  {
    emulator_->setFaults(faults);
    return true;
  }
  void breakLink() override
  {
    if (emulator_config_.port.kind == PortKind::UDP)
    {
      emulator_.reset();  // the camera is gone
      return;
    }
    emulator_->unplug();
  }
  void restoreLink() override
  {
    if (!emulator_)
    {
      emulator_ = std::make_unique<ViscaEmulator>(emulator_config_);
      return;
    }
    emulator_->replug();
  }
  bool breaksAtOnce() const override
  {
    return emulator_config_.port.kind != PortKind::UDP;
  }
  std::string linkLossWords() const override
  {
    switch (emulator_config_.port.kind)
    {
      case PortKind::PTY:
        return emulator_config_.port.link;
      case PortKind::TCP:
        return "connection to 127.0.0.1";
      default:
        return "no state from a VISCA camera";
    }
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    goal = AxisValues{ { 3.0, 0.0, 2.0 } };  // beyond the model's 170 degrees: illegal parameters
    return "the VISCA camera refused '" + visca::toHex(positionCommand(goal)) + "': syntax error";
  }
  AxisValues goal(double pan, double tilt) const override
  {
    return AxisValues{ { pan, tilt, 2.0 } };
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    const visca::ViscaModel& model = config_.settings.model;
    std::vector<std::string> texts;
    for (const DeviceCommand& command : withoutQueries(commands))
    {
      texts.push_back(command.text);
    }
    const std::vector<std::string> expected = {
      hex(positionCommand(target)), hex(visca::zoomDirect(config_.settings.address, model.zoomToPosition(target[ZOOM])))
    };
    EXPECT_EQ(texts, expected);
  }

private:
  /// The absolute pan-tilt command of a goal to \p target, at the model's top speeds.
  visca::Packet positionCommand(const AxisValues& target) const
  {
    const visca::ViscaModel& model = config_.settings.model;
    return visca::panTiltPosition(config_.settings.address, model.axes[PAN].max_speed_byte,
                                  model.axes[TILT].max_speed_byte, model.toSteps(PAN, target[PAN]),
                                  model.toSteps(TILT, target[TILT]), model.layout);
  }

  ViscaEmulatorConfig emulator_config_;
  DeviceConfig<ViscaProtocol> config_;
  std::unique_ptr<ViscaEmulator> emulator_;
};

const DeviceFixtureRegistration VISCA_FIXTURES({
    { "ViscaSerial", [] { return std::make_unique<ViscaFixture>(PortKind::PTY, ViscaFraming::RAW); } },
    { "ViscaTcp", [] { return std::make_unique<ViscaFixture>(PortKind::TCP, ViscaFraming::RAW); } },
    { "ViscaUdpSonyIp", [] { return std::make_unique<ViscaFixture>(PortKind::UDP, ViscaFraming::SONY_IP); } },
    { "ViscaUdpRaw", [] { return std::make_unique<ViscaFixture>(PortKind::UDP, ViscaFraming::RAW); } },
    // A camera answering with the latencies measured on five PTZOptics G2 (pan-tilt inquiries in 88-123 ms, zoom
    // inquiries in 26-58 ms, ACKs in 28-89 ms), driven with config/visca.yaml as shipped.
    { "ViscaUdpG2LatencyShippedConfig",
      [] { return std::make_unique<ViscaFixture>(PortKind::UDP, ViscaFraming::SONY_IP, "g2-latency"); } },
});
}  // namespace

}  // namespace ptz_action_server

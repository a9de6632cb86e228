#include <gtest/gtest.h>

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

/// A VISCA camera (EVI-D70 units) on a pseudo-terminal at 38400 baud, raw over TCP, or over UDP raw or with Sony's
/// header.
class ViscaFixture : public DeviceFixture
{
public:
  ViscaFixture(PortKind kind, ViscaFraming framing)
  {
    visca::ViscaModel::preset("evi_d70", emulator_config_.model);
    emulator_config_.port.kind = kind;
    emulator_config_.port.link = uniqueLink("visca");
    emulator_config_.port.baud = 38400;
    emulator_config_.framing = framing;
    emulator_config_.address = 2;
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
    config_.settings.address = 2;
    config_.settings.framing = framing;
    config_.settings.model = emulator_config_.model;
    config_.session.state_timeout = TEST_STATE_TIMEOUT;
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
    // The most the reply deadline learns beyond the exchange's wire time: twice its floor of 100 ms (reply_timeout 0).
    return 0.2;
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
    goal = AxisValues{ { 3.0, 0.0, 2.0 } };  // beyond the EVI-D70's 170 degrees: illegal parameters
    const visca::ViscaModel& model = config_.settings.model;
    return "the VISCA camera refused '" +
           visca::toHex(visca::panTiltPosition(2, 0x18, 0x17, model.toSteps(PAN, 3.0), model.toSteps(TILT, 0.0))) +
           "': syntax error";
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
      hex(visca::panTiltPosition(2, 0x18, 0x17, model.toSteps(PAN, target[PAN]), model.toSteps(TILT, target[TILT]))),
      hex(visca::zoomDirect(2, model.zoomToPosition(target[ZOOM])))
    };
    EXPECT_EQ(texts, expected);
  }

private:
  ViscaEmulatorConfig emulator_config_;
  DeviceConfig<ViscaProtocol> config_;
  std::unique_ptr<ViscaEmulator> emulator_;
};

const DeviceFixtureRegistration VISCA_FIXTURES({
    { "ViscaSerial", [] { return std::make_unique<ViscaFixture>(PortKind::PTY, ViscaFraming::RAW); } },
    { "ViscaTcp", [] { return std::make_unique<ViscaFixture>(PortKind::TCP, ViscaFraming::RAW); } },
    { "ViscaUdpSonyIp", [] { return std::make_unique<ViscaFixture>(PortKind::UDP, ViscaFraming::SONY_IP); } },
    { "ViscaUdpRaw", [] { return std::make_unique<ViscaFixture>(PortKind::UDP, ViscaFraming::RAW); } },
});
}  // namespace

}  // namespace ptz_action_server

#include <gtest/gtest.h>

#include "../line_test_support.h"
#include "device_fixtures_internal.h"
#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;

// ---------------------------------------------------------------- units on a line: a pseudo-terminal or TCP

/// What the FLIR and Pelco-D fixtures share: an emulator on a pseudo-terminal (38400 baud) or a TCP port.
template <class Emulator>
class LineFixture : public DeviceFixture
{
protected:
  /// Starts the emulator on a \p kind port and fills \p link to reach it.
  template <class EmulatorConfig>
  void startEmulator(EmulatorConfig config, DevicePortConfig::Kind kind, const char* name, LinkConfig& link)
  {
    config.port.kind = kind;
    config.port.link = uniqueLink(name);
    config.port.baud = 38400;
    emulator_ = std::make_unique<Emulator>(config);
    if (kind == DevicePortConfig::Kind::TCP)
    {
      link.kind = LinkKind::TCP;
      link.port = emulator_->port().tcpPort();
    }
    else
    {
      link.path = config.port.link;
      link.baud = config.port.baud;
    }
    link_ = link;
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
    return 0.1;  // the reply timeout's allowance beyond the exchange's wire time (reply_timeout 0)
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
    emulator_->unplug();
  }
  void restoreLink() override
  {
    emulator_->replug();
  }
  std::string linkLossWords() const override
  {
    return link_.kind == LinkKind::TCP ? "connection to 127.0.0.1" : link_.path;
  }

  std::unique_ptr<Emulator> emulator_;
  LinkConfig link_;
};

// ---------------------------------------------------------------- FLIR PTU: serial and TCP (E-series)

class FlirFixture : public LineFixture<FlirPtuEmulator>
{
public:
  explicit FlirFixture(DevicePortConfig::Kind kind)
  {
    startEmulator(FlirPtuEmulatorConfig{}, kind, "flir", config_.link);
    config_.session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    return makeDeviceBackend<FlirProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    std::vector<DeviceCommand> commands;
    for (const ReceivedCommand& item : emulator_->received().items())
    {
      const std::string& text = item.text;
      Kind kind = Kind::OTHER;
      if (text == "PP" || text == "TP")
      {
        kind = Kind::QUERY;
      }
      else if (text == "H" || text == "HP" || text == "HT")
      {
        kind = Kind::STOP;
      }
      else if (text.rfind("PP", 0) == 0 || text.rfind("TP", 0) == 0)
      {
        kind = Kind::MOVE;
      }
      commands.push_back(DeviceCommand{ item.at, kind, text });
    }
    return commands;
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    goal = AxisValues{ { 3.0, 0.0, 1.0 } };  // beyond the unit's pan limit (3090 positions, 2.77 rad)
    return "the FLIR PTU refused 'PP-3342': Minimum allowable Pan position is -3090";
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    // Position mode, the speeds (1.5 and 1.0 rad/s in positions/s), then the positions, the unit's pan inverted.
    const double resolution = arcSecondsToRadians(185.1428);
    std::vector<std::string> texts;
    for (const DeviceCommand& command : withoutQueries(commands))
    {
      texts.push_back(command.text);
    }
    const std::vector<std::string> expected = { "CI", "PS1671", "TS1114",
                                                "PP" + std::to_string(std::lround(-target[PAN] / resolution)),
                                                "TP" + std::to_string(std::lround(target[TILT] / resolution)) };
    EXPECT_EQ(texts, expected);
  }

private:
  DeviceConfig<FlirProtocol> config_;
};

// ---------------------------------------------------------------- Pelco-D: serial and TCP

class PelcoFixture : public LineFixture<PelcoDEmulator>
{
public:
  PelcoFixture(DevicePortConfig::Kind kind, pelco::TiltEncoding encoding)
  {
    PelcoDEmulatorConfig config;
    config.address = 7;
    config.tilt_encoding = encoding;
    startEmulator(config, kind, "pelco", config_.link);
    config_.settings.address = 7;
    config_.settings.tilt_encoding = encoding;
    config_.session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    return makeDeviceBackend<PelcoProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    std::vector<DeviceCommand> commands;
    for (const ReceivedFrame& item : emulator_->received().items())
    {
      const std::uint8_t command = item.frame.command2;
      Kind kind = Kind::OTHER;
      if (command == pelco::QUERY_PAN || command == pelco::QUERY_TILT || command == pelco::QUERY_ZOOM)
      {
        kind = Kind::QUERY;
      }
      else if (item.frame == pelco::stop(item.frame.address))
      {
        kind = Kind::STOP;
      }
      else if (command == pelco::SET_PAN || command == pelco::SET_TILT || command == pelco::SET_ZOOM)
      {
        kind = Kind::MOVE;
      }
      const pelco::Bytes bytes = pelco::encode(item.frame);
      commands.push_back(DeviceCommand{ item.at, kind, hex(std::vector<std::uint8_t>(bytes.begin(), bytes.end())) });
    }
    return commands;
  }
  AxisValues goal(double pan, double tilt) const override
  {
    return AxisValues{ { pan, tilt, 2.0 } };
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    const std::vector<DeviceCommand> sent = withoutQueries(commands);
    ASSERT_EQ(sent.size(), 3u) << describe(sent);
    auto text = [](const pelco::Frame& frame) {
      const pelco::Bytes bytes = pelco::encode(frame);
      return hex(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    };
    EXPECT_EQ(sent[0].text, text(pelco::withValue(7, pelco::SET_PAN, pelco::encodePan(toDegrees(target[PAN])))));
    EXPECT_EQ(sent[1].text,
              text(pelco::withValue(7, pelco::SET_TILT,
                                    pelco::encodeTilt(toDegrees(target[TILT]), config_.settings.tilt_encoding))));
    EXPECT_EQ(sent[2].text, text(pelco::withValue(7, pelco::SET_ZOOM, config_.settings.zoomToPosition(target[ZOOM]))));
  }

private:
  DeviceConfig<PelcoProtocol> config_;
};
}  // namespace

std::vector<FixtureMaker> lineDeviceFixtures()
{
  using PortKind = DevicePortConfig::Kind;
  return {
    { "FlirSerial", [] { return std::make_unique<FlirFixture>(PortKind::PTY); } },
    { "FlirTcp", [] { return std::make_unique<FlirFixture>(PortKind::TCP); } },
    { "PelcoSerialUpPositive",
      [] { return std::make_unique<PelcoFixture>(PortKind::PTY, pelco::TiltEncoding::UP_POSITIVE); } },
    { "PelcoSerialDownPositive",
      [] { return std::make_unique<PelcoFixture>(PortKind::PTY, pelco::TiltEncoding::DOWN_POSITIVE); } },
    { "PelcoTcp", [] { return std::make_unique<PelcoFixture>(PortKind::TCP, pelco::TiltEncoding::DOWN_POSITIVE); } },
  };
}

}  // namespace ptz_action_server

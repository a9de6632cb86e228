#include <gtest/gtest.h>

#include "line_fixture.h"
#include "ptz_action_server/core/flir/flir_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;

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

using PortKind = DevicePortConfig::Kind;
const DeviceFixtureRegistration FLIR_FIXTURES({
    { "FlirSerial", [] { return std::make_unique<FlirFixture>(PortKind::PTY); } },
    { "FlirTcp", [] { return std::make_unique<FlirFixture>(PortKind::TCP); } },
});
}  // namespace

}  // namespace ptz_action_server

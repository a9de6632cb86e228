#include <gtest/gtest.h>

#include "device_fixtures_internal.h"
#include "harness/flir_harness.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using PortKind = DevicePortConfig::Kind;

// ---------------------------------------------------------------- FLIR PTU: serial and TCP (E-series)

/// The unit on a pseudo-terminal at 38400 baud or a TCP port.
FlirPtuEmulatorConfig flirUnit(PortKind kind)
{
  FlirPtuEmulatorConfig config;
  config.port.kind = kind;
  config.port.baud = 38400;
  return config;
}

class FlirFixture : public HarnessFixture<FlirHarness>
{
public:
  explicit FlirFixture(PortKind kind) : HarnessFixture(flirUnit(kind))
  {
    harness_.config().session.state_timeout = TEST_STATE_TIMEOUT;
  }

  std::string linkLossWords() const override
  {
    return transportLossWords(harness_);
  }
  double replyDeadline() const override
  {
    return LINE_REPLY_DEADLINE;
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    goal = AxisValues{ { 3.0, 0.0, 1.0 } };  // beyond the unit's pan limit (3090 positions, 2.77 rad)
    return "the FLIR PTU refused 'PP-3342': Minimum allowable Pan position is -3090";
  }
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    // Position mode, the speeds (1.5 and 1.0 rad/s in positions/s), then the positions, the unit's pan inverted.
    const double resolution = arcSecondsToRadians(185.1428);
    const std::vector<std::string> expected = { "CI", "PS1671", "TS1114",
                                                "PP" + std::to_string(std::lround(-target[PAN] / resolution)),
                                                "TP" + std::to_string(std::lround(target[TILT] / resolution)) };
    EXPECT_EQ(texts(withoutQueries(commands)), expected);
  }
};

const DeviceFixtureRegistration FLIR_FIXTURES({
    { "FlirSerial", [] { return std::make_unique<FlirFixture>(PortKind::PTY); } },
    { "FlirTcp", [] { return std::make_unique<FlirFixture>(PortKind::TCP); } },
});
}  // namespace

}  // namespace ptz_action_server

#include <gtest/gtest.h>

#include "device_fixtures_internal.h"
#include "harness/pelco_d_harness.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using PortKind = DevicePortConfig::Kind;

// ---------------------------------------------------------------- Pelco-D: serial and TCP

/// The device at address 7 on a pseudo-terminal at 38400 baud or a TCP port, its tilt written as \p encoding says.
PelcoDEmulatorConfig pelcoDevice(PortKind kind, pelco::TiltEncoding encoding)
{
  PelcoDEmulatorConfig config;
  config.port.kind = kind;
  config.port.baud = 38400;
  config.address = 7;
  config.tilt_encoding = encoding;
  return config;
}

class PelcoFixture : public HarnessFixture<PelcoDHarness>
{
public:
  PelcoFixture(PortKind kind, pelco::TiltEncoding encoding) : HarnessFixture(pelcoDevice(kind, encoding))
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
  AxisValues goal(double pan, double tilt) const override
  {
    return AxisValues{ { pan, tilt, 2.0 } };
  }
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    const std::vector<ClassifiedCommand> sent = withoutQueries(commands);
    ASSERT_EQ(sent.size(), 3u) << describe(sent);
    auto text = [](const pelco::Frame& frame) {
      const pelco::Bytes bytes = pelco::encode(frame);
      return hexText(bytes.data(), bytes.size());
    };
    const PelcoSettings& settings = harness_.config().settings;
    EXPECT_EQ(sent[0].text, text(pelco::withValue(7, pelco::SET_PAN, pelco::encodePan(toDegrees(target[PAN])))));
    EXPECT_EQ(sent[1].text, text(pelco::withValue(7, pelco::SET_TILT,
                                                  pelco::encodeTilt(toDegrees(target[TILT]), settings.tilt_encoding))));
    EXPECT_EQ(sent[2].text, text(pelco::withValue(7, pelco::SET_ZOOM, settings.zoomToPosition(target[ZOOM]))));
  }
};

const DeviceFixtureRegistration PELCO_D_FIXTURES({
    { "PelcoSerialUpPositive",
      [] { return std::make_unique<PelcoFixture>(PortKind::PTY, pelco::TiltEncoding::UP_POSITIVE); } },
    { "PelcoSerialDownPositive",
      [] { return std::make_unique<PelcoFixture>(PortKind::PTY, pelco::TiltEncoding::DOWN_POSITIVE); } },
    { "PelcoTcp", [] { return std::make_unique<PelcoFixture>(PortKind::TCP, pelco::TiltEncoding::DOWN_POSITIVE); } },
});
}  // namespace

}  // namespace ptz_action_server

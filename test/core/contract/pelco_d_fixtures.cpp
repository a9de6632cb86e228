#include <gtest/gtest.h>

#include "line_fixture.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;

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

using PortKind = DevicePortConfig::Kind;
const DeviceFixtureRegistration PELCO_D_FIXTURES({
    { "PelcoSerialUpPositive",
      [] { return std::make_unique<PelcoFixture>(PortKind::PTY, pelco::TiltEncoding::UP_POSITIVE); } },
    { "PelcoSerialDownPositive",
      [] { return std::make_unique<PelcoFixture>(PortKind::PTY, pelco::TiltEncoding::DOWN_POSITIVE); } },
    { "PelcoTcp", [] { return std::make_unique<PelcoFixture>(PortKind::TCP, pelco::TiltEncoding::DOWN_POSITIVE); } },
});
}  // namespace

}  // namespace ptz_action_server

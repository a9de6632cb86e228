#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include "device_fixtures_internal.h"
#include "harness/visca_harness.h"

namespace ptz_action_server
{
namespace
{
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

/// An EVI-D70 (address 2) on a pseudo-terminal at 38400 baud, raw over TCP, or over UDP raw or with Sony's header;
/// or (\p shipped) a camera of the field dialect \p mode as \p shipped drives it.
ViscaEmulatorConfig viscaCamera(PortKind kind, ViscaFraming framing,
                                const DeviceConfig<ViscaProtocol>* shipped = nullptr, const char* mode = nullptr)
{
  ViscaEmulatorConfig camera;
  visca::ViscaModel::preset("evi_d70", camera.model);
  camera.address = 2;
  camera.framing = framing;
  if (shipped != nullptr)
  {
    camera.model = shipped->settings.model;
    camera.address = shipped->settings.address;
    camera.framing = shipped->settings.framing;
    EXPECT_TRUE(camera.applyMode(mode)) << mode;
  }
  camera.port.kind = kind;
  camera.port.baud = 38400;
  return camera;
}

/// A VISCA camera driven by a backend with the test's state timeout, or (\p mode) one of the field dialect \p mode
/// driven with config/visca.yaml as shipped.
class ViscaFixture : public HarnessFixture<ViscaHarness>
{
public:
  ViscaFixture(PortKind kind, ViscaFraming framing) : HarnessFixture(viscaCamera(kind, framing))
  {
    harness_.config().session.state_timeout = TEST_STATE_TIMEOUT;
  }
  ViscaFixture(PortKind kind, const char* mode, const DeviceConfig<ViscaProtocol>& shipped = shippedConfig())
    : HarnessFixture(viscaCamera(kind, shipped.settings.framing, &shipped, mode), shipped)
  {
  }

  std::string linkLossWords() const override
  {
    return transportLossWords(harness_, "no state from a VISCA camera");
  }
  double replyDeadline() const override
  {
    if (harness_.emulatorConfig().modes.g2_latency)
    {
      return 0.0;  // its answers already take up to 123 ms of the 200 the deadline learns: a delay on top means nothing
    }
    // The most the reply deadline learns beyond the exchange's wire time: twice its floor, reply_timeout or 100 ms.
    const double reply_timeout = harness_.config().settings.reply_timeout;
    return 2.0 * (reply_timeout > 0.0 ? reply_timeout : 0.1);
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
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    const ViscaSettings& settings = harness_.config().settings;
    const visca::Packet zoom = visca::zoomDirect(settings.address, settings.model.zoomToPosition(target[ZOOM]));
    const visca::Packet position = positionCommand(target);
    const std::vector<std::string> expected = { hexText(position.data(), position.size()),
                                                hexText(zoom.data(), zoom.size()) };
    EXPECT_EQ(texts(withoutQueries(commands)), expected);
  }

private:
  /// The absolute pan-tilt command of a goal to \p target, at the model's top speeds.
  visca::Packet positionCommand(const AxisValues& target) const
  {
    const ViscaSettings& settings = harness_.config().settings;
    const visca::ViscaModel& model = settings.model;
    return visca::panTiltPosition(settings.address, model.axes[PAN].max_speed_byte, model.axes[TILT].max_speed_byte,
                                  model.toSteps(PAN, target[PAN]), model.toSteps(TILT, target[TILT]), model.layout);
  }
};

const DeviceFixtureRegistration VISCA_FIXTURES({
    { "ViscaSerial", [] { return std::make_unique<ViscaFixture>(PortKind::PTY, ViscaFraming::RAW); } },
    { "ViscaTcp", [] { return std::make_unique<ViscaFixture>(PortKind::TCP, ViscaFraming::RAW); } },
    { "ViscaUdpSonyIp", [] { return std::make_unique<ViscaFixture>(PortKind::UDP, ViscaFraming::SONY_IP); } },
    { "ViscaUdpRaw", [] { return std::make_unique<ViscaFixture>(PortKind::UDP, ViscaFraming::RAW); } },
    // A camera answering with the latencies measured on five PTZOptics G2 (pan-tilt inquiries in 88-123 ms, zoom
    // inquiries in 26-58 ms, ACKs in 28-89 ms), driven with config/visca.yaml as shipped.
    { "ViscaUdpG2LatencyShippedConfig", [] { return std::make_unique<ViscaFixture>(PortKind::UDP, "g2-latency"); } },
});
}  // namespace

}  // namespace ptz_action_server

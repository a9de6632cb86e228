#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "http_camera_fixture.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;

// ---------------------------------------------------------------- Axis (VAPIX)

/// An Axis camera: by default the emulator's own (zoom attributes, an 18X table); \p camera for a field case.
class AxisFixture : public HttpCameraFixture
{
public:
  explicit AxisFixture(const AxisCameraEmulatorConfig& camera = AxisCameraEmulatorConfig(),
                       const vapix::ZoomTable& backend_table = zoomTable(AxisCameraEmulatorConfig::DEFAULT_ZOOM_TABLE))
    : backend_table_(backend_table)
  {
    emulator_ = std::make_unique<AxisCameraEmulator>(camera);
    config_.link.host = "127.0.0.1";
    config_.link.port = emulator_->port();
    config_.link.http.username = "root";
    config_.link.http.password = "pass";
    config_.link.http.request_timeout = 2.0;  // longer than the state timeout: silence is seen as silence
    pinIfTls(emulator_->server(), config_.link);
    config_.session.state_timeout = HTTP_TEST_STATE_TIMEOUT;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    return makeDeviceBackend<AxisProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    std::vector<DeviceCommand> commands;
    for (const HttpExchange& exchange : emulator_->server().received().items())
    {
      const std::string& target = exchange.target;
      Kind kind = Kind::OTHER;
      bool aims = false;
      double pan = 0.0;
      if (target.find("query=") != std::string::npos)
      {
        kind = Kind::QUERY;
      }
      else if (target.find("move=stop") != std::string::npos)
      {
        kind = Kind::STOP;
      }
      else if (target.find("&pan=") != std::string::npos)
      {
        kind = Kind::MOVE;
        aims = true;
        pan = toRadians(std::stod(target.substr(target.find("&pan=") + 5)));
      }
      commands.push_back(DeviceCommand{ exchange.at, kind, exchange.method + " " + target, aims, pan });
    }
    return commands;
  }
  PtzSample deviceState() const override
  {
    return emulator_->sample();
  }
  bool setFaults(const SimFaults& faults) override
  {
    emulator_->setFaults(faults);
    return true;
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    emulator_->setRefuse(true);
    goal = AxisValues{ { 0.3, 0.0, 1.0 } };
    return std::string("the Axis camera refused 'pan=17.1887&tilt=0.0000&zoom=1&speed=100': ") +
           AxisCameraEmulator::REFUSAL;
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    // The zoom value goes out through the table the backend found (the camera's, or its guess).
    std::string expected = "GET /axis-cgi/com/ptz.cgi?camera=1&";
    vapix::appendAbsoluteMove(expected, toDegrees(target[PAN]), toDegrees(target[TILT]),
                              backend_table_.toValue(target[ZOOM]), 100);
    std::vector<std::string> texts;
    for (const DeviceCommand& sent : withoutQueries(commands))
    {
      texts.push_back(sent.text);
    }
    EXPECT_EQ(texts, std::vector<std::string>{ expected });
  }

private:
  HttpCameraServer& server() const override
  {
    return emulator_->server();
  }
  static vapix::ZoomTable zoomTable(const std::string& text)
  {
    vapix::ZoomTable table;
    vapix::ZoomTable::parse(text, table);
    return table;
  }

  const vapix::ZoomTable backend_table_;
  std::unique_ptr<AxisCameraEmulator> emulator_;
  DeviceConfig<AxisProtocol> config_;
};

/// The camera of issue 21, as it answered in the field: no `query=attributes` (info=1 does not list it, asking answers
/// `Error:` / `query: unknown value: attributes`), MinZoom=1 and MaxZoom=9999 in the limits, zoom, iris, focus,
/// brightness, autofocus and autoiris in the position; a Q6155-E with a 30X lens, whose family the backend guesses
/// 30X for: the guess and the lens agree, so zoom goals reach their X.
/// The emulator's own Axis camera over https (its certificate pinned).
AxisCameraEmulatorConfig axisTlsCamera()
{
  AxisCameraEmulatorConfig camera;
  camera.http.tls = true;
  return camera;
}

AxisCameraEmulatorConfig axisFieldCamera()
{
  AxisCameraEmulatorConfig camera;
  camera.attributes = false;
  camera.zoom_table = AxisCameraEmulatorConfig::linearZoomTable(30.0);
  camera.model = "Q6155-E";
  return camera;
}

const DeviceFixtureRegistration AXIS_FIXTURES({
    { "AxisHttpDigest", [] { return std::make_unique<AxisFixture>(); } },
    { "AxisHttpsPinned", [] { return std::make_unique<AxisFixture>(axisTlsCamera()); } },
    { "AxisFieldNoZoomAttributes",
      [] { return std::make_unique<AxisFixture>(axisFieldCamera(), vapix::ZoomTable::linear(30.0)); } },
});
}  // namespace

}  // namespace ptz_action_server

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "http_camera_fixture.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = DeviceCommand::Kind;

// ---------------------------------------------------------------- ONVIF

/// The contract cases a camera mode cannot run, each with the reason and the dedicated test that covers it instead.
struct Unsupported
{
  std::vector<std::string> cases;  ///< test names (without the fixture), or {"*"} for all but `except`
  std::vector<std::string> except;
  std::string reason;
};

/// Skips the running contract case if \p unsupported names it (called during SetUp: gtest then skips the body).
void skipIfUnsupported(const Unsupported& unsupported)
{
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (info == nullptr || unsupported.reason.empty())
  {
    return;
  }
  std::string name = info->name();  // "ACase/OnvifNoPosition"
  name = name.substr(0, name.find('/'));
  const auto has = [&name](const std::vector<std::string>& list) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  const bool every = unsupported.cases == std::vector<std::string>{ "*" };
  if ((every || has(unsupported.cases)) && !has(unsupported.except))
  {
    GTEST_SKIP() << unsupported.reason;
  }
}

/// An ONVIF camera in one of the emulator's modes (standard, or a field camera's), behind a clock two hours behind
/// and HTTP Digest as well as WS-Security.
class OnvifFixture : public HttpCameraFixture
{
public:
  explicit OnvifFixture(const std::vector<std::string>& modes, Unsupported unsupported = {}, bool tls = false)
    : unsupported_(std::move(unsupported))
  {
    OnvifCameraEmulatorConfig camera;
    camera.http.tls = tls;
    for (const std::string& mode : modes)
    {
      EXPECT_TRUE(camera.applyMode(mode)) << mode;
    }
    camera.clock_offset = -7200.0;        // the camera's clock is two hours behind: tokens must be stamped in its time
    camera.http.auth = HttpAuth::DIGEST;  // and it demands HTTP Digest as well
    camera.http.username = camera.username;
    camera.http.password = camera.password;
    emulator_ = std::make_unique<OnvifCameraEmulator>(camera);
    config_.link.host = "127.0.0.1";
    config_.link.port = emulator_->port();
    config_.link.http.username = camera.username;
    config_.link.http.password = camera.password;
    config_.link.http.request_timeout = 2.0;
    pinIfTls(emulator_->server(), config_.link);
    config_.settings.username = camera.username;
    config_.settings.password = camera.password;
    config_.session.state_timeout = HTTP_TEST_STATE_TIMEOUT;
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    skipIfUnsupported(unsupported_);
    return makeDeviceBackend<OnvifProtocol>(config_);
  }
  std::vector<DeviceCommand> commands() const override
  {
    std::vector<DeviceCommand> commands;
    for (const HttpExchange& exchange : emulator_->server().received().items())
    {
      if (exchange.status == 401)
      {
        continue;  // the HTTP Digest challenge of a request that follows
      }
      onvif::SoapMessage message;
      if (!onvif::parseSoap(exchange.body, message).empty())
      {
        continue;
      }
      const std::string operation = onvif::localName(*message.content);
      Kind kind = operation == "GetStatus" ? Kind::QUERY : operation == "Stop" ? Kind::STOP : Kind::OTHER;
      bool aims = false;
      double pan = 0.0;
      if (operation == "AbsoluteMove")
      {
        kind = Kind::MOVE;
        const onvif::Element* pan_tilt =
            onvif::child(onvif::child(message.content, onvif::ns::PTZ, "Position"), onvif::ns::SCHEMA, "PanTilt");
        const char* space = onvif::attribute(pan_tilt, "space");
        aims = pan_tilt != nullptr;
        pan = aims ? std::stod(onvif::attribute(pan_tilt, "x")) : 0.0;
        pan = space != nullptr && std::string(space) == onvif::DEGREE_SPACE ? toRadians(pan) : pan * M_PI;
      }
      else if (operation == "ContinuousMove")
      {
        kind = Kind::MOVE;  // a velocity goal's command
      }
      commands.push_back(DeviceCommand{ exchange.at, kind, operation + " " + std::to_string(pan), aims, pan });
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
    return std::string("the ONVIF camera refused AbsoluteMove: ter:InvalidArgVal: ") + OnvifCameraEmulator::REFUSAL;
  }
  void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const override
  {
    const std::vector<DeviceCommand> sent = withoutQueries(commands);
    ASSERT_EQ(sent.size(), 1u) << describe(commands);
    EXPECT_EQ(sent[0].kind, Kind::MOVE);
    EXPECT_NEAR(sent[0].pan, target[PAN], 1e-5);
  }

private:
  HttpCameraServer& server() const override
  {
    return emulator_->server();
  }

  Unsupported unsupported_;
  std::unique_ptr<OnvifCameraEmulator> emulator_;
  DeviceConfig<OnvifProtocol> config_;
};

/// The contract cases the continuous-only and the no-position cameras cannot run, and why.
const Unsupported CONTINUOUS_ONLY_CANNOT = { { "*" },
                                             { "AVelocityGoalMovesAtTheRateUntilStopped" },
                                             "a continuous-only camera cannot go to a position: position goals run "
                                             "closed-loop above this DeviceBackend (the "
                                             "node's ClosedLoopBackend); OnvifFieldCameras.ContinuousOnly* and "
                                             "ClosedLoopOnvif.* cover it" };
const Unsupported NO_POSITION_CANNOT = {
  { "AGoalArrivesAsTheProtocolsCommandsAndIsReached", "ANewGoalRetargetsTheMovingDeviceWithoutAStop",
    "AVelocityGoalMovesAtTheRateUntilStopped", "RecoveryHoldsTheDeviceOnceAndAGoalSentRightAfterSucceeds",
    "ABrokenLinkEndsTheGoalAsLinkLostAndTheNextGoalWorks", "ADeviceThatIgnoresAnAxisNeverGetsASucceededForIt",
    "ASlowDeviceWorksWithinItsDeadlineAndPastItEndsTheGoalAsLinkLost" },
  {},
  "a camera without a position in GetStatus cannot show a goal reached or a speed (cancel, refusals and silence run "
  "here): OnvifFieldCameras.NoPosition* cover the rest (the link kept by its answers, velocity goals, position goals "
  "refused)"
};

using Modes = std::vector<std::string>;
const DeviceFixtureRegistration ONVIF_FIXTURES({
    { "OnvifDegreeSpace", [] { return std::make_unique<OnvifFixture>(Modes{ "standard" }); } },
    { "OnvifHttpsPinned", [] { return std::make_unique<OnvifFixture>(Modes{ "standard" }, Unsupported{}, true); } },
    { "OnvifGenericSpace", [] { return std::make_unique<OnvifFixture>(Modes{ "generic-only" }); } },
    // The field's cameras (doc/backends/onvif.md): each mode as the emulator plays it.
    { "OnvifDegreesListedGenericStatus", [] { return std::make_unique<OnvifFixture>(Modes{ "generic-status" }); } },
    { "OnvifWrongGenericRange", [] { return std::make_unique<OnvifFixture>(Modes{ "wrong-generic-range" }); } },
    { "OnvifNoPresets", [] { return std::make_unique<OnvifFixture>(Modes{ "no-presets" }); } },
    { "OnvifNoRelativeMove", [] { return std::make_unique<OnvifFixture>(Modes{ "no-relative" }); } },
    { "OnvifContinuousOnly",
      [] { return std::make_unique<OnvifFixture>(Modes{ "continuous-only" }, CONTINUOUS_ONLY_CANNOT); } },
    { "OnvifNoPosition", [] { return std::make_unique<OnvifFixture>(Modes{ "no-position" }, NO_POSITION_CANNOT); } },
});
}  // namespace

}  // namespace ptz_action_server

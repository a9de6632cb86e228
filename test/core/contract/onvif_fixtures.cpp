#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "device_fixtures_internal.h"
#include "harness/onvif_harness.h"

namespace ptz_action_server
{
namespace
{
using Kind = ClassifiedCommand::Kind;

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

/// An ONVIF camera in \p modes (standard, or a field camera's), its clock two hours behind (tokens must be stamped in
/// its time), demanding HTTP Digest as well as WS-Security.
OnvifCameraEmulatorConfig onvifCamera(const std::vector<std::string>& modes, bool tls)
{
  OnvifCameraEmulatorConfig camera;
  camera.http.tls = tls;
  for (const std::string& mode : modes)
  {
    EXPECT_TRUE(camera.applyMode(mode)) << mode;
  }
  camera.clock_offset = -7200.0;
  camera.http.auth = HttpAuth::DIGEST;
  camera.http.username = camera.username;
  camera.http.password = camera.password;
  return camera;
}

/// An ONVIF camera in one of the emulator's modes, and the contract cases it cannot run.
class OnvifFixture : public HttpCameraFixture<OnvifHarness>
{
public:
  explicit OnvifFixture(const std::vector<std::string>& modes, Unsupported unsupported = {}, bool tls = false)
    : HttpCameraFixture(onvifCamera(modes, tls)), unsupported_(std::move(unsupported))
  {
  }

  std::unique_ptr<DeviceBackend> makeBackend() override
  {
    skipIfUnsupported(unsupported_);
    return harness_.makeBackend();
  }
  std::string prepareRefusal(AxisValues& goal) override
  {
    harness_.emulator().setRefuse(true);
    goal = AxisValues{ { 0.3, 0.0, 1.0 } };
    return std::string("the ONVIF camera refused AbsoluteMove: ter:InvalidArgVal: ") + OnvifCameraEmulator::REFUSAL;
  }
  void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const override
  {
    const std::vector<ClassifiedCommand> sent = withoutQueries(commands);
    ASSERT_EQ(sent.size(), 1u) << describe(commands);
    EXPECT_EQ(sent[0].kind, Kind::MOVE);
    EXPECT_NEAR(sent[0].pan, target[PAN], 1e-5);
  }

private:
  Unsupported unsupported_;
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

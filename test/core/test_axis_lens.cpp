/**
 * \file
 * \brief Axis focus and iris against axis_camera_emulator's camera on 127.0.0.1: the VAPIX words of each lens command,
 * the lens declared from query=limits, query=position and info=1, its modes and positions read back, a camera
 * without iris refusing, and a refusal counted as a lens fault, not the goal's.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "axis_backend_test_support.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/lens_commander.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace axis_backend_test;

constexpr LensFunction FOCUS = LensFunction::FOCUS;
constexpr LensFunction IRIS = LensFunction::IRIS;

TEST(VapixLens, ArgumentsAreVapixWords)
{
  vapix::LensLimits limits;
  limits.focus = vapix::LensRange{ true, 1.0, 9999.0 };
  limits.iris = vapix::LensRange{ true, 1.0, 9999.0 };
  EXPECT_EQ(vapix::lensArguments(LensCommand::mode(FOCUS, true), limits), "autofocus=on");
  EXPECT_EQ(vapix::lensArguments(LensCommand::mode(IRIS, false), limits), "autoiris=off");
  EXPECT_EQ(vapix::lensArguments(LensCommand::velocity(FOCUS, -0.5), limits), "continuousfocusmove=-50");
  EXPECT_EQ(vapix::lensArguments(LensCommand::velocity(IRIS, 1.0), limits), "continuousirismove=100");
  EXPECT_EQ(vapix::lensArguments(LensCommand::position(FOCUS, 0.5), limits), "focus=5000");
  EXPECT_EQ(vapix::lensArguments(LensCommand::position(IRIS, 0.0), limits), "iris=1");
  EXPECT_EQ(vapix::lensArguments(LensCommand::onePush(), limits), "");
}

class AxisLensTest : public ::testing::Test
{
protected:
  void start(const AxisCameraEmulatorConfig& camera_config)
  {
    camera_ = std::make_unique<AxisCameraEmulator>(camera_config);
    backend_ = makeDeviceBackend<AxisProtocol>(configFor(camera_->port()));
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
    commander_ = std::make_unique<LensCommander>(*backend_, backend_->capabilities().lens, "axis", 0.5);
  }

  bool requested(const std::string& arguments) const
  {
    const std::string target = "/axis-cgi/com/ptz.cgi?camera=1&" + arguments;
    return camera_->server().received().waitFor([&](const HttpExchange& item) { return item.target == target; }, WAIT);
  }

  std::unique_ptr<AxisCameraEmulator> camera_;
  std::unique_ptr<DeviceBackend> backend_;
  std::unique_ptr<LensCommander> commander_;
};

TEST_F(AxisLensTest, TheLensIsDeclaredFromWhatTheCameraReports)
{
  start(AxisCameraEmulatorConfig());
  const LensCapabilities lens = backend_->capabilities().lens;
  for (const LensControl* control : { &lens.focus, &lens.iris })
  {
    EXPECT_TRUE(control->present && control->auto_mode && control->velocity && control->absolute);
    EXPECT_TRUE(control->feedback);
    EXPECT_FALSE(control->one_push);
  }
  ASSERT_TRUE(waitUntil([&] { return backend_->lensState().modeOf(FOCUS) == LensMode::AUTO; }, WAIT));
  EXPECT_EQ(backend_->lensState().modeOf(IRIS), LensMode::AUTO);
}

TEST_F(AxisLensTest, FocusAndIrisCommandsReachTheCameraInVapixWords)
{
  start(AxisCameraEmulatorConfig());
  ASSERT_EQ(commander_->command(LensCommand::position(FOCUS, 0.25), SteadyClock::now()), "");
  ASSERT_TRUE(requested("focus=2501"));  // 1 + 0.25 x 9998, rounded
  ASSERT_TRUE(waitUntil([&] { return camera_->lensState().modeOf(FOCUS) == LensMode::MANUAL; }, WAIT));
  // Read back: the backend's lens state follows the camera's position answers.
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend_->lensState().positionOf(FOCUS) - 0.25) < 1e-3; }, WAIT));
  EXPECT_EQ(backend_->lensState().modeOf(FOCUS), LensMode::MANUAL);
  ASSERT_EQ(commander_->command(LensCommand::velocity(IRIS, 0.4), SteadyClock::now()), "");
  ASSERT_TRUE(requested("continuousirismove=40"));
  ASSERT_TRUE(waitUntil([&] { return camera_->lensState().positionOf(IRIS) == 1.0; }, WAIT));
  ASSERT_EQ(commander_->command(LensCommand::mode(FOCUS, true), SteadyClock::now()), "");
  ASSERT_TRUE(requested("autofocus=on"));
  EXPECT_TRUE(waitUntil([&] { return backend_->lensState().modeOf(FOCUS) == LensMode::AUTO; }, WAIT));
  EXPECT_EQ(backend_->lensState().fault_count, 0u);
}

TEST_F(AxisLensTest, ACameraWithoutIrisSaysSoAndGetsNothing)
{
  AxisCameraEmulatorConfig camera_config;
  camera_config.lens.iris.present = false;
  start(camera_config);
  const std::string refusal = commander_->command(LensCommand::mode(IRIS, true), SteadyClock::now());
  EXPECT_EQ(refusal, "this Axis camera reports no iris (query=position has no iris=)");
  EXPECT_TRUE(targets(camera_->server(), "iris").empty());
}

TEST_F(AxisLensTest, ARefusalIsALensFaultNotTheGoals)
{
  start(AxisCameraEmulatorConfig());
  const std::uint64_t device_faults = backend_->sample().fault_count;
  camera_->setRefuse(true);
  ASSERT_EQ(commander_->command(LensCommand::position(FOCUS, 1.0), SteadyClock::now()), "");
  ASSERT_TRUE(requested("focus=9999"));
  ASSERT_TRUE(waitUntil([&] { return backend_->lensState().fault_count == 1; }, WAIT));
  EXPECT_NE(backend_->lastLensFault().find(AxisCameraEmulator::REFUSAL), std::string::npos)
      << backend_->lastLensFault();
  EXPECT_EQ(backend_->sample().fault_count, device_faults);
}
}  // namespace
}  // namespace ptz_action_server

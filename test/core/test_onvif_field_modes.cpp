/**
 * \file
 * \brief The ONVIF backend against onvif_camera_emulator's field modes on 127.0.0.1 (OnvifFieldCameras): continuous
 * only, AbsoluteMove refused, no position in the status, presets, home and relative moves as the camera answers them,
 * the wrong generic range, an axis given as NaN, degrees listed but a generic status. The scripted field cameras are
 * test_onvif_protocol.cpp's, the cheap cameras' modes test_onvif_cheap_cameras.cpp's.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "onvif_backend_test_support.h"
#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif_backend_test;

TEST(OnvifFieldCameras, ContinuousOnlyDeclaresSpeedAndPositionButNoGoToAndSendsNoAbsoluteMove)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("continuous-only", camera));
  backend->start();
  const Capabilities capabilities = backend->capabilities();
  for (Axis axis : { PAN, TILT })
  {
    EXPECT_FALSE(capabilities.axes[axis].absolute);
    EXPECT_TRUE(capabilities.axes[axis].velocity);
    EXPECT_TRUE(capabilities.axes[axis].feedback);  // its status has a position: goals can run closed-loop on it
  }
  EXPECT_FALSE(capabilities.axes[ZOOM].present);  // no zoom position space
  EXPECT_EQ(capabilities.axes[ZOOM].limitation, "this camera lists no zoom position space (it only zooms at a speed)");
  EXPECT_FALSE(capabilities.relative_moves);
  EXPECT_FALSE(capabilities.device_presets);
  EXPECT_EQ(findUnsupported(capabilities, PAN, AxisRequest::POSITION), "this camera lists no absolute pan-tilt space "
                                                                       "(no AbsoluteMove): pan goals are not "
                                                                       "supported");
  EXPECT_EQ(findUnsupported(capabilities, PAN, AxisRequest::OFFSET), "");

  // A goTo that reaches it anyway is a fault in words, and nothing goes to the camera.
  backend->goTo({ 0.5, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count == 1u; }, WAIT));
  EXPECT_EQ(backend->lastFault(), "not sent: the ONVIF camera cannot go to a pan-tilt position (this camera lists no "
                                  "absolute pan-tilt space (no AbsoluteMove))");
  EXPECT_EQ(countOf(camera->server(), "AbsoluteMove"), 0u);

  // What it does: speeds, seen in its status; cancel.
  backend->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera->sample().velocity[PAN] - 0.3) < 0.02; }, WAIT));
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend->sample().velocity[PAN] - 0.3) < 0.08; }, WAIT));
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !camera->sample().moving && !backend->sample().moving; }, WAIT));
  // Its silence is a lost link, as anyone's.
  camera->server().setSilent(true);
  ASSERT_TRUE(waitUntil([&] { return !backend->sample().link_up; }, WAIT));
  EXPECT_NE(backend->lastLinkLoss().find("no state from"), std::string::npos) << backend->lastLinkLoss();
}

TEST(OnvifFieldCameras, ACameraThatRefusesAbsoluteMoveFaultsTheGoalWithItsWordsAndIsContinuousOnlyFromThen)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("refuse-absolute-move", camera));
  backend->start();
  backend->goTo({ 0.5, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count == 1u; }, WAIT));
  EXPECT_EQ(backend->lastFault(), "the ONVIF camera refused AbsoluteMove: ter:ActionNotSupported: The operation "
                                  "AbsoluteMove is not supported");
  // Its answer is the truth about it: from now on it is a camera that moves at a speed, and says so.
  const Capabilities capabilities = backend->capabilities();
  EXPECT_FALSE(capabilities.axes[PAN].absolute);
  EXPECT_FALSE(capabilities.axes[ZOOM].absolute);
  EXPECT_TRUE(capabilities.axes[PAN].velocity && capabilities.axes[PAN].feedback);
  EXPECT_EQ(findUnsupported(capabilities, PAN, AxisRequest::POSITION), "this camera answers AbsoluteMove with "
                                                                       "ter:ActionNotSupported: pan goals are not "
                                                                       "supported");
  ASSERT_EQ(backend->protocol<OnvifProtocol>().warnings().size(), 1u);
  EXPECT_EQ(backend->protocol<OnvifProtocol>().warnings()[0], "the camera lists position spaces but answered "
                                                              "AbsoluteMove with ter:ActionNotSupported: The operation "
                                                              "AbsoluteMove is not supported: it is taken as a camera "
                                                              "that only moves at a speed (ContinuousMove) from "
                                                              "now on");
  camera->server().received().clear();
  backend->goTo({ -0.5, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count == 2u; }, WAIT));
  EXPECT_EQ(countOf(camera->server(), "AbsoluteMove"), 0u);  // not sent again
  backend->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera->sample().velocity[PAN] - 0.3) < 0.02; }, WAIT));
}

TEST(OnvifFieldCameras, NoPositionKeepsTheLinkOnItsAnswersAndDoesSpeedsAndCancel)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("no-position", camera));
  backend->start();
  const Capabilities capabilities = backend->capabilities();
  for (Axis axis : { PAN, TILT, ZOOM })
  {
    EXPECT_FALSE(capabilities.axes[axis].feedback) << axisName(axis);
    EXPECT_TRUE(capabilities.axes[axis].absolute) << axisName(axis);
    EXPECT_TRUE(capabilities.axes[axis].velocity) << axisName(axis);
  }
  const ValidatedGoal refused = validatePositionGoal({ 0.5, 0.0, 0.0 }, capabilities, false);
  EXPECT_FALSE(refused.accepted);
  EXPECT_EQ(refused.message, "this camera's GetStatus answers no pan-tilt position: pan goals are not supported");
  EXPECT_TRUE(validateVelocityGoal({ 0.3, 0.0, 0.0 }, capabilities, false).accepted);

  // Its answers alone keep the link: well past the state timeout, it is still up and never lost.
  const auto& protocol = backend->protocol<OnvifProtocol>();
  const std::uint64_t statuses = protocol.counters().statuses;
  const double polls_past_timeout = 3.0 * 1.0 / 0.1;  // three state timeouts of 1 s at the 0.1 s poll period
  ASSERT_TRUE(waitUntil([&] { return protocol.counters().statuses >= statuses + polls_past_timeout; }, WAIT));
  EXPECT_TRUE(backend->sample().link_up);
  EXPECT_EQ(backend->sample().link_losses, 0u);

  backend->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera->sample().velocity[PAN] - 0.3) < 0.02; }, WAIT));
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !camera->sample().moving; }, WAIT));
  EXPECT_EQ(backend->sample().fault_count, 0u);

  camera->server().setSilent(true);
  ASSERT_TRUE(waitUntil([&] { return !backend->sample().link_up; }, WAIT));
  EXPECT_EQ(backend->sample().link_losses, 1u);
}

TEST(OnvifFieldCameras, PresetsHomeAndRelativeMovesAreDeclaredAsTheCameraAnswers)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  {
    auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("standard", camera));
    backend->start();
    EXPECT_TRUE(backend->capabilities().device_presets);
    EXPECT_TRUE(backend->capabilities().device_home);
    EXPECT_TRUE(backend->capabilities().relative_moves);
  }
  {
    auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("no-presets", camera));
    backend->start();  // GetPresets refused: never a start-up failure
    EXPECT_FALSE(backend->capabilities().device_presets);
    std::vector<DiagnosticValue> values;
    backend->diagnostics(values);
    EXPECT_NE(std::find(values.begin(), values.end(),
                        DiagnosticValue("presets on the camera", "none: the ONVIF camera refused GetPresets: "
                                                                 "ter:ActionNotSupported: The operation GetPresets is "
                                                                 "not supported")),
              values.end());
  }
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("no-relative", camera));
  backend->start();
  EXPECT_FALSE(backend->capabilities().relative_moves);
}

TEST(OnvifFieldCameras, TheWrongGenericRangeIsToldOnceAndTheCameraGoesWhereItsStatusShowsItCan)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  DeviceConfig<OnvifProtocol> config = configForMode("wrong-generic-range", camera);
  auto backend = makeDeviceBackend<OnvifProtocol>(config);
  backend->start();
  EXPECT_NEAR(backend->capabilities().axes[PAN].range.min, -M_PI, 1e-9);
  const AxisValues target{ { -0.5, 0.1, 2.0 } };
  backend->goTo(target);
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[PAN] - target[PAN]) < 1e-3 && !backend->sample().moving; },
      WAIT));
  EXPECT_NEAR(camera->sample().position[PAN], target[PAN], 1e-3);
  EXPECT_EQ(backend->takeWarnings().size(), 1u);
  EXPECT_TRUE(backend->takeWarnings().empty());
}

TEST(OnvifFieldCameras, AGoalLeavesAnAxisGivenAsNaNWhereItIs)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("standard", camera));
  backend->start();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  camera->server().received().clear();
  backend->goTo({ nan, nan, 3.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(camera->sample().position[ZOOM] - 3.0) < 1e-3; }, WAIT));
  const std::string sent = lastBodyOf(camera->server(), "AbsoluteMove");
  EXPECT_EQ(sent.find("PanTilt"), std::string::npos) << sent;  // zoom only: the pan-tilt is not touched
  EXPECT_NEAR(camera->sample().position[PAN], 0.0, 1e-9);
}

TEST(OnvifFieldCameras, DegreesListedButAGenericStatusMovesInTheGenericSpaceAndIsReached)
{
  std::unique_ptr<OnvifCameraEmulator> camera;
  auto backend = makeDeviceBackend<OnvifProtocol>(configForMode("generic-status", camera));
  backend->start();
  backend->goTo({ 0.4, -0.1, 3.0 });
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[PAN] - 0.4) < 1e-3 && !backend->sample().moving; }, WAIT));
  EXPECT_NEAR(camera->sample().position[PAN], 0.4, 1e-3);
  EXPECT_NE(lastBodyOf(camera->server(), "AbsoluteMove").find(onvif::GENERIC_PAN_TILT_SPACE), std::string::npos);
}

}  // namespace
}  // namespace ptz_action_server

/**
 * \file
 * \brief onvif_camera_emulator's modes for the cheap cameras of the field, each answering as those cameras do: Axis's
 * 401 to GetSystemDateAndTime, Stop answered and not obeyed, AbsoluteMove answered and never moved, a speed that
 * ignores the magnitude, a PanTilt that moves pan and tilt even where they stand, a PTZTimeout range, a zoom range not
 * honoured; and a blocked axis, reported MOVING. Motion runs on a manual clock.
 */
#include <gtest/gtest.h>

#include <cmath>

#include "onvif_test_client.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif;
using namespace onvif_test;

/// A pan-tilt-zoom of \p x, \p y in the default space, \p z: what AbsoluteMove sends.
Vector panTiltZoom(double x, double y, double z)
{
  Vector vector;
  vector.pan_tilt = true;
  vector.x = x;
  vector.y = y;
  vector.zoom = true;
  vector.z = z;
  return vector;
}

TEST(OnvifEmulatorFieldModes, AxisAsksForCredentialsOfAnUnauthenticatedGetSystemDateAndTime)
{
  Camera camera("axis-401");
  OnvifClient client(camera.emulator->port(), "admin", isoTime, false);
  const HttpReply refused = client.post("/onvif/device_service", getSystemDateAndTime(), false);
  EXPECT_EQ(refused.status, 401);
  EXPECT_NE(refused.body.find("401 Unauthorized"), std::string::npos);
  // With a UsernameToken it answers; so does the rest, as on any camera.
  EXPECT_TRUE(client.call("/onvif/device_service", getSystemDateAndTime(), true)) << client.message().fault_text;
  EXPECT_TRUE(client.ptz(getNodes())) << client.message().fault_text;
}

TEST(OnvifEmulatorFieldModes, StopKeepsMovingUntilAZeroVelocity)
{
  Camera camera("stop-keeps-moving");
  OnvifClient client(camera.emulator->port());
  ASSERT_TRUE(client.ptz(continuousMove("profile_1", 0.2, 0.0, false, 0.0, 1)));
  camera.clock->advance(0.5);
  ASSERT_TRUE(client.ptz(stop("profile_1"))) << client.message().fault_text;
  camera.clock->advance(2.0);                                   // past its Timeout of 1 s too
  EXPECT_EQ(client.status("profile_1").move_status, "MOVING");  // answered, and still on its way
  EXPECT_NEAR(camera.emulator->sample().velocity[PAN], 0.2 * 1.5, 1e-9);
  ASSERT_TRUE(client.ptz(continuousMove("profile_1", 0.0, 0.0, false, 0.0, 60)));
  camera.clock->advance(2.0);
  EXPECT_EQ(client.status("profile_1").move_status, "IDLE");
  // A position move stops on Stop.
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", panTiltZoom(90.0, 0.0, 0.0))));
  camera.clock->advance(0.3);
  ASSERT_TRUE(client.ptz(stop("profile_1")));
  camera.clock->advance(2.0);
  EXPECT_EQ(client.status("profile_1").move_status, "IDLE");
}

TEST(OnvifEmulatorFieldModes, AbsoluteMoveIsAnsweredAndNothingMovesButContinuousMoveWorks)
{
  Camera camera("absolute-never-moves");
  OnvifClient client(camera.emulator->port());
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", panTiltZoom(45.0, 10.0, 0.5)))) << client.message().fault_text;
  camera.clock->advance(5.0);
  const Status status = client.status("profile_1");
  EXPECT_EQ(status.x, 0.0);
  EXPECT_EQ(status.zoom, 0.0);
  EXPECT_EQ(status.move_status, "IDLE");
  ASSERT_TRUE(client.ptz(continuousMove("profile_1", 0.2, 0.0, false, 0.0, 60)));
  camera.clock->advance(1.0);
  EXPECT_GT(client.status("profile_1").x, 1.0);  // degrees
}

TEST(OnvifEmulatorFieldModes, AnyVelocityButZeroMovesAtOneSpeed)
{
  Camera camera("speed-ignores-magnitude");
  OnvifClient client(camera.emulator->port());
  for (const double x : { 0.05, 1.0, -0.3 })
  {
    ASSERT_TRUE(client.ptz(continuousMove("profile_1", x, 0.0, true, x, 60)));
    camera.clock->advance(1.0);
    EXPECT_NEAR(camera.emulator->sample().velocity[PAN], std::copysign(0.5 * 1.5, x), 1e-9) << x;
    EXPECT_NEAR(camera.emulator->sample().velocity[ZOOM], std::copysign(0.5 * 8.0, x), 1e-9) << x;
  }
  ASSERT_TRUE(client.ptz(continuousMove("profile_1", 0.0, 0.0, true, 0.0, 60)));
  camera.clock->advance(1.0);
  EXPECT_FALSE(camera.emulator->sample().moving);
}

TEST(OnvifEmulatorFieldModes, APanTiltWhereItStandsStillMovesPanAndTiltAndAZoomAloneDoesNot)
{
  Camera camera("zoom-only-moves-pantilt");
  OnvifClient client(camera.emulator->port());
  // The PanTilt it stands at, with a new zoom: pan and tilt move all the same (the backlash approach), and end there.
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", panTiltZoom(0.0, 0.0, 0.3))));
  camera.clock->advance(0.2);
  Status status = client.status("profile_1");
  EXPECT_EQ(status.move_status, "MOVING");
  EXPECT_LT(status.x, -0.1);  // degrees: on its way 2 degrees below
  camera.clock->advance(5.0);
  client.status("profile_1");
  camera.clock->advance(5.0);
  status = client.status("profile_1");
  EXPECT_NEAR(status.x, 0.0, 1e-6);
  EXPECT_EQ(status.move_status, "IDLE");
  // The zoom alone leaves them still.
  Vector zoom;
  zoom.zoom = true;
  zoom.z = 0.6;
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", zoom)));
  camera.clock->advance(0.2);
  status = client.status("profile_1");
  EXPECT_EQ(status.move_status, "IDLE");
  EXPECT_EQ(status.zoom_move_status, "MOVING");
}

TEST(OnvifEmulatorFieldModes, ATimeoutOutsideItsRangeIsRefused)
{
  Camera camera("timeout-range");
  OnvifClient client(camera.emulator->port());
  ASSERT_TRUE(client.ptz(getConfigurationOptions("ptz0")));
  double min = 0.0, max = 0.0;
  ASSERT_EQ(readTimeoutRange(client.content(), min, max), "");
  EXPECT_EQ(min, 1.0);
  EXPECT_EQ(max, 10.0);
  EXPECT_FALSE(client.ptz(continuousMove("profile_1", 0.2, 0.0, false, 0.0, 30)));
  EXPECT_TRUE(faultHas(client.message(), "TimeoutNotSupported"));
  EXPECT_TRUE(client.ptz(continuousMove("profile_1", 0.2, 0.0, false, 0.0, 10)));
}

TEST(OnvifEmulatorFieldModes, AZoomBeyondWhatItsLensReachesIsAnsweredAndStopsShort)
{
  Camera camera("zoom-range-not-honoured");
  OnvifClient client(camera.emulator->port());
  ASSERT_TRUE(client.ptz(getNodes()));
  Node node;
  ASSERT_EQ(readNode(client.content(), "", node), "");
  EXPECT_EQ(findSpace(node.absolute_zoom, GENERIC_ZOOM_SPACE)->x.max, 1.0);  // listed
  Vector zoom;
  zoom.zoom = true;
  zoom.z = 0.8;
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", zoom))) << client.message().fault_text;
  camera.clock->advance(10.0);
  EXPECT_NEAR(client.status("profile_1").zoom, 0.5, 1e-6);  // where its lens ends
  zoom.z = 0.3;
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", zoom)));
  camera.clock->advance(10.0);
  EXPECT_NEAR(client.status("profile_1").zoom, 0.3, 1e-6);
}

TEST(OnvifEmulatorFieldModes, ABlockedAxisIsReportedMovingWhileItsCommandLasts)
{
  Camera camera;
  OnvifClient client(camera.emulator->port());
  SimFaults blocked;
  blocked.stalled[PAN] = true;
  camera.emulator->setFaults(blocked);
  ASSERT_TRUE(client.ptz(absoluteMove("profile_1", panTiltZoom(45.0, 0.0, 0.0))));
  camera.clock->advance(5.0);
  Status status = client.status("profile_1");
  EXPECT_EQ(status.x, 0.0);
  EXPECT_EQ(status.move_status, "MOVING");  // its controller drives a motor that does not turn
  ASSERT_TRUE(client.ptz(stop("profile_1")));
  EXPECT_EQ(client.status("profile_1").move_status, "IDLE");
}

}  // namespace
}  // namespace ptz_action_server

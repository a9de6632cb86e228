#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "ptz_action_server/core/limits.h"

using namespace ptz_action_server;

namespace
{
/// A pan joint of the given type and limits, and a tilt joint limited to [tilt_min, tilt_max] at 2 rad/s.
PtzKinematics kinematicsWith(const char* pan_type, const char* pan_limit, double tilt_min, double tilt_max)
{
  char urdf[1024];
  std::snprintf(urdf, sizeof(urdf), R"(<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/><link name="cam"/>
  <joint name="pan" type="%s"><parent link="base"/><child link="a"/><axis xyz="0 0 -1"/>%s</joint>
  <joint name="tilt" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 -1 0"/>
    <limit lower="%f" upper="%f" velocity="2" effort="1"/></joint>
  <joint name="cam_joint" type="fixed"><parent link="b"/><child link="cam"/></joint>
</robot>)",
                pan_type, pan_limit, tilt_min, tilt_max);
  KinematicsNames names;
  names.pan_joint = "pan";
  names.tilt_joint = "tilt";
  names.camera_link = "cam";
  return PtzKinematics::fromUrdf(urdf, names);
}

Capabilities deviceWith(AxisRange pan, AxisRange tilt, double max_speed)
{
  Capabilities device;
  device.axes[PAN].range = pan;
  device.axes[PAN].max_speed = max_speed;
  device.axes[TILT].range = tilt;
  device.axes[TILT].max_speed = max_speed;
  device.axes[ZOOM].range = AxisRange{ 1.0, 24.0 };
  device.axes[ZOOM].max_speed = 8.0;
  return device;
}

std::string configError(const std::function<void()>& action)
{
  try
  {
    action();
  }
  catch (const ConfigError& error)
  {
    return error.what();
  }
  return "no error";
}
}  // namespace

TEST(UrdfLimits, JointLimitsInsideTheContractBounds)
{
  const Capabilities limits =
      urdfLimits(kinematicsWith("revolute", R"(<limit lower="-4" upper="0.8" velocity="1.5" effort="1"/>)", -2.0, 0.5));
  EXPECT_DOUBLE_EQ(limits.axes[PAN].range.min, -M_PI);  // -4 is beyond the contract's -pi
  EXPECT_DOUBLE_EQ(limits.axes[PAN].range.max, 0.8);
  EXPECT_DOUBLE_EQ(limits.axes[PAN].max_speed, 1.5);
  EXPECT_DOUBLE_EQ(limits.axes[TILT].range.min, -M_PI / 2);  // -2 is beyond the contract's -pi/2
  EXPECT_DOUBLE_EQ(limits.axes[TILT].range.max, 0.5);
  EXPECT_DOUBLE_EQ(limits.axes[TILT].max_speed, 2.0);
  EXPECT_DOUBLE_EQ(limits.axes[ZOOM].range.min, 1.0);
  EXPECT_DOUBLE_EQ(limits.axes[ZOOM].range.max, 1.0);
}

TEST(UrdfLimits, ContinuousPanSpansTheContractAndHasNoSpeed)
{
  const Capabilities limits = urdfLimits(kinematicsWith("continuous", "", -1.0, 1.0));
  EXPECT_DOUBLE_EQ(limits.axes[PAN].range.min, -M_PI);
  EXPECT_DOUBLE_EQ(limits.axes[PAN].range.max, M_PI);
  EXPECT_DOUBLE_EQ(limits.axes[PAN].max_speed, 0.0);
}

TEST(UrdfLimits, EmptyRangeInsideTheContractIsAConfigError)
{
  const PtzKinematics kinematics = kinematicsWith("continuous", "", 1.6, 2.0);
  EXPECT_EQ(configError([&] { urdfLimits(kinematics); }), "URDF joint 'tilt' has an empty range inside the contract's "
                                                          "limits");
}

TEST(IntersectLimits, TheTighterRangeAndTheLowerSpeedWin)
{
  Capabilities urdf = urdfLimits(kinematicsWith("continuous", "", -1.0, 1.0));
  urdf.axes[PAN].max_speed = 1.0;
  const Capabilities device = deviceWith({ -M_PI, M_PI }, { -1.5, 1.5 }, 3.0);
  const LimitIntersection result = intersectLimits(device, urdf);
  EXPECT_TRUE(result.warnings.empty());  // the device covers the URDF's ranges: nothing to warn about
  EXPECT_DOUBLE_EQ(result.limits.axes[PAN].range.min, -M_PI);
  EXPECT_DOUBLE_EQ(result.limits.axes[PAN].range.max, M_PI);
  EXPECT_DOUBLE_EQ(result.limits.axes[PAN].max_speed, 1.0);
  EXPECT_DOUBLE_EQ(result.limits.axes[TILT].range.min, -1.0);
  EXPECT_DOUBLE_EQ(result.limits.axes[TILT].range.max, 1.0);
  EXPECT_DOUBLE_EQ(result.limits.axes[TILT].max_speed, 2.0);
  // Zoom is the device's alone.
  EXPECT_DOUBLE_EQ(result.limits.axes[ZOOM].range.max, 24.0);
  EXPECT_DOUBLE_EQ(result.limits.axes[ZOOM].max_speed, 8.0);
}

TEST(IntersectLimits, ANarrowerDeviceRangeIsUsedWithAWarning)
{
  const Capabilities urdf = urdfLimits(kinematicsWith("continuous", "", -1.0, 1.0));
  const Capabilities device = deviceWith({ -M_PI, M_PI }, { -0.5, 1.5 }, 0.5);
  const LimitIntersection result = intersectLimits(device, urdf);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0], "the device's tilt range [-0.5000, 1.5000] is narrower than the URDF's [-1.0000, "
                                "1.0000]; using the "
                                "device's");
  EXPECT_DOUBLE_EQ(result.limits.axes[TILT].range.min, -0.5);
  EXPECT_DOUBLE_EQ(result.limits.axes[TILT].range.max, 1.0);
  EXPECT_DOUBLE_EQ(result.limits.axes[PAN].max_speed, 0.5);  // a URDF without a speed limit leaves the device's
  EXPECT_DOUBLE_EQ(result.limits.axes[TILT].max_speed, 0.5);
}

TEST(IntersectLimits, RangesThatDoNotOverlapAreAConfigError)
{
  const Capabilities urdf = urdfLimits(kinematicsWith("continuous", "", -1.0, 1.0));
  const Capabilities device = deviceWith({ 0.5, 3.0 }, { 1.2, 1.5 }, 1.0);
  EXPECT_EQ(configError([&] { intersectLimits(device, urdf); }), "the device's and the URDF's tilt ranges do not "
                                                                 "overlap");
}

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ptz_action_server/core/goal_validation.h"
#include "ptz_action_server/core/sim_device_model.h"

using namespace ptz_action_server;

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double INF = std::numeric_limits<double>::infinity();

Capabilities cameraLimits()
{
  return SimDeviceConfig::defaults().capabilities();  // pan +-pi, tilt +-pi/2, zoom 1..24, 1.5 / 1.0 / 8 per s
}
}  // namespace

TEST(GoalValidation, AcceptsAGoalInsideTheLimitsUnchanged)
{
  const ValidatedGoal goal = validatePositionGoal({ 0.5, -0.2, 3.0 }, cameraLimits(), false);
  EXPECT_TRUE(goal.accepted);
  EXPECT_FALSE(goal.clamped);
  EXPECT_TRUE(goal.message.empty());
  EXPECT_EQ(goal.values, (AxisValues{ 0.5, -0.2, 3.0 }));
}

TEST(GoalValidation, RejectsNaNAndInfOnEveryAxisEvenWhenClamping)
{
  for (bool clamp : { false, true })
  {
    for (Axis axis : ALL_AXES)
    {
      for (double bad : { NaN, INF, -INF })
      {
        AxisValues values{ 0.0, 0.0, 1.0 };
        values[axis] = bad;
        const ValidatedGoal position = validatePositionGoal(values, cameraLimits(), clamp);
        EXPECT_FALSE(position.accepted);
        EXPECT_NE(position.message.find(axisName(axis)), std::string::npos) << position.message;
        EXPECT_NE(position.message.find(std::isnan(bad) ? "NaN" : "Inf"), std::string::npos) << position.message;
        EXPECT_FALSE(validateVelocityGoal(values, cameraLimits(), clamp).accepted);
      }
    }
  }
}

TEST(GoalValidation, RejectsOutOfRangeWithTheLimitsInTheReason)
{
  const ValidatedGoal goal = validatePositionGoal({ 0.0, 2.0, 1.0 }, cameraLimits(), false);
  EXPECT_FALSE(goal.accepted);
  EXPECT_EQ(goal.message, "tilt 2.0000 rad is outside the limits [-1.5708, 1.5708] rad");
  const ValidatedGoal zoom = validatePositionGoal({ 0.0, 0.0, 30.0 }, cameraLimits(), false);
  EXPECT_FALSE(zoom.accepted);
  EXPECT_EQ(zoom.message, "zoom 30.0000 X is outside the limits [1.0000, 24.0000] X");
}

TEST(GoalValidation, ClampsWhenAskedAndSaysSo)
{
  const ValidatedGoal goal = validatePositionGoal({ 4.0, -2.0, 0.0 }, cameraLimits(), true);
  ASSERT_TRUE(goal.accepted);
  EXPECT_TRUE(goal.clamped);
  EXPECT_DOUBLE_EQ(goal.values[PAN], M_PI);
  EXPECT_DOUBLE_EQ(goal.values[TILT], -M_PI / 2);
  EXPECT_DOUBLE_EQ(goal.values[ZOOM], 1.0);
  EXPECT_EQ(goal.message, "clamped pan 4.0000 -> 3.1416 rad, tilt -2.0000 -> -1.5708 rad, zoom 0.0000 -> 1.0000 X");
}

TEST(GoalValidation, Float32PiIsTheLimitNotBeyondIt)
{
  const double float_pi = static_cast<float>(M_PI);  // 3.14159274 > M_PI
  ASSERT_GT(float_pi, M_PI);
  const ValidatedGoal goal = validatePositionGoal({ float_pi, 0.0, 1.0 }, cameraLimits(), false);
  EXPECT_TRUE(goal.accepted);
  EXPECT_FALSE(goal.clamped);
  EXPECT_DOUBLE_EQ(goal.values[PAN], M_PI);
}

TEST(GoalValidation, IgnoresZoomOfADeviceWithoutZoom)
{
  Capabilities limits = cameraLimits();
  limits.axes[ZOOM].present = false;
  const ValidatedGoal goal = validatePositionGoal({ 0.1, 0.1, 0.0 }, limits, false);
  EXPECT_TRUE(goal.accepted);
  EXPECT_DOUBLE_EQ(goal.values[ZOOM], 1.0);
  EXPECT_FALSE(validatePositionGoal({ 0.1, 0.1, NaN }, limits, false).accepted);  // NaN anywhere
}

TEST(GoalValidation, VelocityAboveMaxSpeedIsRejectedOrClamped)
{
  const ValidatedGoal rejected = validateVelocityGoal({ -2.0, 0.0, 0.0 }, cameraLimits(), false);
  EXPECT_FALSE(rejected.accepted);
  EXPECT_EQ(rejected.message, "pan velocity -2.0000 rad/s exceeds the maximum speed 1.5000 rad/s");
  const ValidatedGoal clamped = validateVelocityGoal({ -2.0, 0.5, 0.0 }, cameraLimits(), true);
  ASSERT_TRUE(clamped.accepted);
  EXPECT_DOUBLE_EQ(clamped.values[PAN], -1.5);
  EXPECT_DOUBLE_EQ(clamped.values[TILT], 0.5);
  EXPECT_NE(clamped.message.find("pan -2.0000 -> -1.5000 rad/s"), std::string::npos) << clamped.message;
}

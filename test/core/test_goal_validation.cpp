#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

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

TEST(GoalValidation, AZoomGoalOnADeviceWithoutZoomIsIgnoredAsTheSeedSays)
{
  Capabilities limits = cameraLimits();
  limits.axes[ZOOM] = absentAxis();
  // Zoom 1 (what it reports) and 0 (unset) ask nothing of it: accepted without a word.
  for (double zoom : { 0.0, 1.0 })
  {
    const ValidatedGoal quiet = validatePositionGoal({ 0.1, 0.1, zoom }, limits, false);
    ASSERT_TRUE(quiet.accepted) << quiet.message;
    EXPECT_EQ(quiet.message, "");
    EXPECT_DOUBLE_EQ(quiet.values[ZOOM], 1.0);
  }
  // Any other zoom is ignored, and the goal says so; it is judged on pan and tilt only.
  for (bool clamp : { false, true })
  {
    const ValidatedGoal ignored = validatePositionGoal({ 0.1, 0.1, 4.0 }, limits, clamp);
    ASSERT_TRUE(ignored.accepted) << ignored.message;
    EXPECT_EQ(ignored.message, "zoom 4.0000 X ignored: the device has no zoom");
    EXPECT_DOUBLE_EQ(ignored.values[ZOOM], 1.0);
    EXPECT_TRUE(ignored.judged[PAN]);
    EXPECT_TRUE(ignored.judged[TILT]);
    EXPECT_FALSE(ignored.judged[ZOOM]);
  }
  // In the device's own words, after a clamping note.
  limits.axes[ZOOM] = absentAxis("a FLIR PTU has no zoom");
  EXPECT_EQ(validatePositionGoal({ 4.0, 0.1, -3.0 }, limits, true).message, "clamped pan 4.0000 -> 3.1416 rad; zoom "
                                                                            "-3.0000 X ignored: a FLIR PTU has no "
                                                                            "zoom");
  // A zoom velocity too: the goal moves pan and tilt only.
  const ValidatedGoal velocity = validateVelocityGoal({ 0.2, 0.0, 0.5 }, limits, false);
  ASSERT_TRUE(velocity.accepted) << velocity.message;
  EXPECT_EQ(velocity.message, "zoom velocity 0.5000 X/s ignored: a FLIR PTU has no zoom");
  EXPECT_EQ(velocity.values, (AxisValues{ 0.2, 0.0, 0.0 }));
  EXPECT_FALSE(velocity.judged[ZOOM]);
  // NaN is still refused there: it is not a zoom, it is a broken goal.
  EXPECT_FALSE(validatePositionGoal({ 0.1, 0.1, NaN }, limits, false).accepted);
  EXPECT_FALSE(validateVelocityGoal({ 0.1, 0.1, INF }, limits, false).accepted);
}

TEST(GoalValidation, ZoomOneTheWidestViewIsAcceptedOnAZoomThatCannotBePositioned)
{
  Capabilities limits = cameraLimits();
  AxisCapability& zoom = limits.axes[ZOOM];
  zoom.feedback = false;
  zoom.absolute = false;
  zoom.limitation = "this Axis camera gives no zoom table";
  zoom.remedy = "set axis/zoom_table";
  // Without a way to its widest view: left alone (NaN), not judged, and said so.
  const ValidatedGoal left = validatePositionGoal({ 0.1, 0.1, 1.0 }, limits, false);
  ASSERT_TRUE(left.accepted) << left.message;
  EXPECT_TRUE(std::isnan(left.values[ZOOM]));
  EXPECT_FALSE(left.judged[ZOOM]);
  EXPECT_EQ(left.message, "zoom 1 (the widest view) left as it is: this Axis camera gives no zoom table");
  // With one: sent as 1, judged only where the device reports its zoom.
  zoom.widest_view = true;
  const ValidatedGoal sent = validatePositionGoal({ 0.1, 0.1, 1.0 }, limits, false);
  ASSERT_TRUE(sent.accepted) << sent.message;
  EXPECT_DOUBLE_EQ(sent.values[ZOOM], 1.0);
  EXPECT_FALSE(sent.judged[ZOOM]);
  EXPECT_EQ(sent.message, "zoom 1 sent as the widest view, not judged: this Axis camera gives no zoom table");
  zoom.feedback = true;
  const ValidatedGoal judged = validatePositionGoal({ 0.1, 0.1, 1.0 }, limits, false);
  ASSERT_TRUE(judged.accepted) << judged.message;
  EXPECT_TRUE(judged.judged[ZOOM]);
  EXPECT_EQ(judged.message, "");
  // Any other zoom is still refused, naming the setting that fixes it.
  EXPECT_EQ(validatePositionGoal({ 0.1, 0.1, 2.0 }, limits, true).message, "this Axis camera gives no zoom table: zoom "
                                                                           "goals are not supported; set "
                                                                           "axis/zoom_table");
}

TEST(GoalValidation, TheDevicesOwnWordsAndRemedyNameWhatIsMissing)
{
  Capabilities limits = cameraLimits();
  limits.axes[ZOOM].feedback = false;
  limits.axes[ZOOM].absolute = false;
  limits.axes[ZOOM].limitation = "this camera reports no zoom position";
  limits.axes[ZOOM].remedy = "set axis/zoom_table";
  const ValidatedGoal refused = validatePositionGoal({ 0.1, 0.1, 4.0 }, limits, false);
  EXPECT_EQ(refused.message, "this camera reports no zoom position: zoom goals are not supported; set axis/zoom_table");
  // Zoom 0 leaves it alone: accepted, commanded as NaN ("leave it where it is") and never judged.
  const ValidatedGoal left_alone = validatePositionGoal({ 0.1, 0.1, 0.0 }, limits, false);
  ASSERT_TRUE(left_alone.accepted) << left_alone.message;
  EXPECT_TRUE(std::isnan(left_alone.values[ZOOM]));
  EXPECT_TRUE(left_alone.judged[PAN]);
  EXPECT_TRUE(left_alone.judged[TILT]);
  EXPECT_FALSE(left_alone.judged[ZOOM]);
  // Its speed can still be driven.
  const ValidatedGoal velocity = validateVelocityGoal({ 0.0, 0.0, 2.0 }, limits, false);
  EXPECT_TRUE(velocity.accepted) << velocity.message;
  EXPECT_TRUE(velocity.judged[ZOOM]);
}

TEST(GoalValidation, ACameraWithoutPositionFeedbackTakesVelocityGoalsOnly)
{
  Capabilities limits = cameraLimits();
  for (Axis axis : { PAN, TILT })
  {
    limits.axes[axis].feedback = false;
    limits.axes[axis].limitation = "GetStatus answers no position";
  }
  EXPECT_EQ(validatePositionGoal({ 0.1, 0.1, 2.0 }, limits, false).message, "GetStatus answers no position: pan goals "
                                                                            "are not supported");
  EXPECT_TRUE(validateVelocityGoal({ 0.3, -0.2, 0.0 }, limits, false).accepted);
  EXPECT_EQ(findUnsupported(limits, TILT, AxisRequest::OFFSET), "GetStatus answers no position: tilt relative goals "
                                                                "are not supported");
  EXPECT_EQ(findUnsupported(limits, ZOOM, AxisRequest::OFFSET), "");
}

TEST(GoalValidation, ADeviceThatCannotDriveAnAxisAtASpeedRefusesThatVelocityOnly)
{
  Capabilities limits = cameraLimits();
  limits.axes[ZOOM].velocity = false;
  EXPECT_EQ(validateVelocityGoal({ 0.1, 0.0, 1.0 }, limits, false).message, "the device cannot move its zoom at a "
                                                                            "speed: zoom velocity goals are not "
                                                                            "supported");
  const ValidatedGoal pan_only = validateVelocityGoal({ 0.1, 0.0, 0.0 }, limits, false);
  ASSERT_TRUE(pan_only.accepted);
  EXPECT_FALSE(pan_only.judged[ZOOM]);
  EXPECT_TRUE(validatePositionGoal({ 0.1, 0.0, 3.0 }, limits, false).accepted);  // positions still go
}

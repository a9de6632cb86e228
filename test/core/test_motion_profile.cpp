#include <gtest/gtest.h>

#include <cmath>

#include "ptz_action_server/core/motion/motion_profile.h"

using ptz_action_server::AxisMotionLimits;
using ptz_action_server::AxisMotionState;
using ptz_action_server::TrapezoidProfile;

namespace
{
const AxisMotionLimits PAN_LIMITS{ 1.5, 3.0, 0.0 };
constexpr double STEP = 1e-3;  // s, sampling step for continuity checks

/// Samples the whole plan and checks speed and acceleration bounds and continuity (no jumps without base speed).
void expectSmooth(const TrapezoidProfile& profile, const AxisMotionLimits& limits)
{
  AxisMotionState previous = profile.at(0.0);
  for (double t = STEP; t <= profile.duration() + 2 * STEP; t += STEP)
  {
    const AxisMotionState state = profile.at(t);
    ASSERT_LE(std::abs(state.velocity), limits.max_speed + 1e-9) << "t=" << t;
    ASSERT_LE(std::abs(state.position - previous.position), limits.max_speed * STEP + 1e-9) << "t=" << t;
    if (t < profile.duration())
    {
      ASSERT_LE(std::abs(state.velocity - previous.velocity), limits.acceleration * STEP + 1e-9) << "t=" << t;
    }
    previous = state;
  }
}
}  // namespace

TEST(TrapezoidProfile, TrapezoidMatchesClosedForm)
{
  // 2 rad at 1.5 rad/s and 3 rad/s^2: the ramps cover 0.75 rad, so there is a cruise.
  const TrapezoidProfile profile = TrapezoidProfile::plan({ 0.0, 0.0 }, 2.0, 1.5, PAN_LIMITS);
  const double expected = 2.0 / 1.5 + 1.5 / 3.0;
  EXPECT_NEAR(profile.duration(), expected, 1e-9);
  EXPECT_NEAR(TrapezoidProfile::minimumDuration(2.0, PAN_LIMITS), expected, 1e-9);
  EXPECT_NEAR(profile.at(0.5).velocity, 1.5, 1e-9);               // end of the ramp
  EXPECT_NEAR(profile.at(0.5).position, 0.375, 1e-9);             // a t^2 / 2
  EXPECT_NEAR(profile.at(expected / 2).position, 1.0, 1e-9);      // symmetric
  EXPECT_NEAR(profile.at(expected - 0.25).velocity, 0.75, 1e-9);  // braking
  EXPECT_DOUBLE_EQ(profile.at(expected + 1.0).position, 2.0);
  EXPECT_DOUBLE_EQ(profile.at(expected + 1.0).velocity, 0.0);
  expectSmooth(profile, PAN_LIMITS);
}

TEST(TrapezoidProfile, TriangleMatchesClosedForm)
{
  // 0.3 rad is shorter than both ramps (0.75 rad): the speed peaks at sqrt(a d) below the max.
  const TrapezoidProfile profile = TrapezoidProfile::plan({ 1.0, 0.0 }, 0.7, 1.5, PAN_LIMITS);
  const double expected = 2.0 * std::sqrt(0.3 / 3.0);
  EXPECT_NEAR(profile.duration(), expected, 1e-9);
  EXPECT_NEAR(TrapezoidProfile::minimumDuration(-0.3, PAN_LIMITS), expected, 1e-9);
  EXPECT_NEAR(profile.at(expected / 2).velocity, -std::sqrt(3.0 * 0.3), 1e-9);
  EXPECT_NEAR(profile.at(expected / 2).position, 0.85, 1e-9);
  EXPECT_DOUBLE_EQ(profile.finalPosition(), 0.7);
  expectSmooth(profile, PAN_LIMITS);
}

TEST(TrapezoidProfile, BaseSpeedStartsAndStopsWithAJump)
{
  const AxisMotionLimits limits{ 1.0, 2.0, 0.2 };
  const TrapezoidProfile profile = TrapezoidProfile::plan({ 0.0, 0.0 }, 1.0, 1.0, limits);
  // Ramps from 0.2 to 1.0 take 0.4 s and 0.24 rad each; 0.52 rad of cruise at 1.0.
  EXPECT_NEAR(profile.duration(), 0.8 + 0.52, 1e-9);
  EXPECT_NEAR(TrapezoidProfile::minimumDuration(1.0, limits), 0.8 + 0.52, 1e-9);
  EXPECT_NEAR(profile.at(1e-9).velocity, 0.2, 1e-6);
  EXPECT_NEAR(profile.at(profile.duration() - 1e-9).velocity, 0.2, 1e-6);
}

TEST(TrapezoidProfile, ConstantRateWhenBaseSpeedIsMaxSpeed)
{
  const AxisMotionLimits zoom{ 8.0, 1000.0, 8.0 };
  const TrapezoidProfile profile = TrapezoidProfile::plan({ 1.0, 0.0 }, 9.0, 8.0, zoom);
  EXPECT_NEAR(profile.duration(), 1.0, 1e-9);
  EXPECT_NEAR(profile.at(0.5).position, 5.0, 1e-9);
}

TEST(TrapezoidProfile, RetargetFurtherOnKeepsMovingWithoutAStop)
{
  const TrapezoidProfile first = TrapezoidProfile::plan({ 0.0, 0.0 }, 1.0, 1.5, PAN_LIMITS);
  const AxisMotionState middle = first.at(0.4);
  ASSERT_GT(middle.velocity, 0.5);
  const TrapezoidProfile second = TrapezoidProfile::plan(middle, 2.5, 1.5, PAN_LIMITS);
  EXPECT_DOUBLE_EQ(second.at(0.0).position, middle.position);
  EXPECT_NEAR(second.at(0.0).velocity, middle.velocity, 1e-9);
  for (double t = STEP; t < second.duration() - STEP; t += STEP)
  {
    ASSERT_GT(second.at(t).velocity, 0.0) << "stopped at t=" << t;
  }
  EXPECT_DOUBLE_EQ(second.finalPosition(), 2.5);
  expectSmooth(second, PAN_LIMITS);
}

TEST(TrapezoidProfile, RetargetBehindBrakesThenReturns)
{
  const TrapezoidProfile first = TrapezoidProfile::plan({ 0.0, 0.0 }, 2.0, 1.5, PAN_LIMITS);
  const AxisMotionState cruising = first.at(1.0);  // at full speed, 1.125 rad
  const TrapezoidProfile second = TrapezoidProfile::plan(cruising, 0.5, 1.5, PAN_LIMITS);
  // It brakes for 0.5 s (0.375 rad further on) before it turns back.
  EXPECT_NEAR(second.at(0.5).position, cruising.position + 0.375, 1e-9);
  EXPECT_NEAR(second.at(0.5).velocity, 0.0, 1e-9);
  EXPECT_LT(second.at(0.6).velocity, 0.0);
  EXPECT_NEAR(second.duration(), 0.5 + TrapezoidProfile::minimumDuration(1.0, PAN_LIMITS), 1e-9);
  EXPECT_DOUBLE_EQ(second.at(10.0).position, 0.5);
  expectSmooth(second, PAN_LIMITS);
}

TEST(TrapezoidProfile, RetargetTooCloseToStopOvershootsAndComesBack)
{
  const AxisMotionState fast{ 0.0, 1.5 };  // needs 0.375 rad to stop
  const TrapezoidProfile profile = TrapezoidProfile::plan(fast, 0.1, 1.5, PAN_LIMITS);
  EXPECT_NEAR(profile.at(0.5).position, 0.375, 1e-9);
  EXPECT_DOUBLE_EQ(profile.finalPosition(), 0.1);
  expectSmooth(profile, PAN_LIMITS);
}

TEST(TrapezoidProfile, SlowerCruiseDeceleratesToIt)
{
  const TrapezoidProfile profile = TrapezoidProfile::plan({ 0.0, 1.5 }, 3.0, 0.5, PAN_LIMITS);
  EXPECT_NEAR(profile.at(1.0 / 3.0).velocity, 0.5, 1e-9);
  EXPECT_NEAR(profile.at(1.0).velocity, 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(profile.finalPosition(), 3.0);
  expectSmooth(profile, PAN_LIMITS);
}

TEST(TrapezoidProfile, StopDeceleratesAndDoesNotJump)
{
  const TrapezoidProfile profile = TrapezoidProfile::stop({ 1.0, -1.5 }, PAN_LIMITS);
  EXPECT_NEAR(profile.duration(), 0.5, 1e-9);
  EXPECT_NEAR(profile.finalPosition(), 1.0 - 0.375, 1e-9);
  EXPECT_DOUBLE_EQ(profile.at(0.0).position, 1.0);
  EXPECT_DOUBLE_EQ(profile.at(0.0).velocity, -1.5);
  EXPECT_NEAR(profile.at(0.25).velocity, -0.75, 1e-9);
  expectSmooth(profile, PAN_LIMITS);
}

TEST(TrapezoidProfile, RestAndZeroLengthMovesTakeNoTime)
{
  EXPECT_DOUBLE_EQ(TrapezoidProfile::rest(0.3).duration(), 0.0);
  EXPECT_DOUBLE_EQ(TrapezoidProfile::plan({ 0.3, 0.0 }, 0.3, 1.5, PAN_LIMITS).duration(), 0.0);
  EXPECT_DOUBLE_EQ(TrapezoidProfile::stop({ 0.3, 0.0 }, PAN_LIMITS).at(1.0).position, 0.3);
  EXPECT_DOUBLE_EQ(TrapezoidProfile::minimumDuration(0.0, PAN_LIMITS), 0.0);
}

/**
 * \file
 * \brief What the node refuses to believe of a device: NaN, a place outside its limits, a jump faster than it moves.
 */
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ptz_action_server/core/device/state_plausibility.h"

using namespace ptz_action_server;

namespace
{
TimePoint at(double seconds)
{
  return TimePoint() + std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(seconds));
}

Capabilities panTiltZoom()
{
  Capabilities capabilities;
  capabilities.axes[PAN] = fullAxis(AxisRange{ -2.0, 2.0 }, 1.0, 0.0);
  capabilities.axes[TILT] = fullAxis(AxisRange{ -1.0, 0.5 }, 0.5, 0.0);
  capabilities.axes[ZOOM] = fullAxis(AxisRange{ 1.0, 20.0 }, 2.0, 0.0);
  return capabilities;
}

TEST(StatePlausibility, NaNAndInfinityAreImpossibleOnEveryAxisTheDeviceReports)
{
  StatePlausibility judge;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(judge.judge({ { nan, 0.0, 1.0 } }, at(0), panTiltZoom()), "pan is NaN");
  EXPECT_EQ(judge.judge({ { 0.0, -inf, 1.0 } }, at(0), panTiltZoom()), "tilt is infinite");
  EXPECT_EQ(judge.judge({ { 0.0, 0.0, nan } }, at(0), panTiltZoom()), "zoom is NaN");
  // An axis the device lacks, or does not report, says nothing.
  Capabilities no_zoom = panTiltZoom();
  no_zoom.axes[ZOOM] = absentAxis();
  EXPECT_EQ(judge.judge({ { 0.0, 0.0, nan } }, at(0), no_zoom), "");
  Capabilities blind_pan = panTiltZoom();
  blind_pan.axes[PAN].feedback = false;
  EXPECT_EQ(judge.judge({ { nan, 0.0, 1.0 } }, at(0.1), blind_pan), "");
}

TEST(StatePlausibility, APlaceOutsideTheLimitsIsImpossibleBeyondASmallMargin)
{
  StatePlausibility judge;
  // 2 % of the 4 rad pan range: 0.08 rad past the stop still reads as the stop.
  EXPECT_EQ(judge.judge({ { 2.07, 0.0, 1.0 } }, at(0), panTiltZoom()), "");
  judge.forget();
  EXPECT_EQ(judge.judge({ { 2.10, 0.0, 1.0 } }, at(0), panTiltZoom()), "pan 2.10 rad is outside the device's limits "
                                                                       "[-2.00, 2.00]");
  EXPECT_EQ(judge.judge({ { 0.0, 0.0, 0.5 } }, at(0), panTiltZoom()), "zoom 0.50 X is outside the device's limits "
                                                                      "[1.00, 20.00]");
  EXPECT_EQ(judge.judge({ { 0.0, -1.2, 1.0 } }, at(0), panTiltZoom()), "tilt -1.20 rad is outside the device's limits "
                                                                       "[-1.00, 0.50]");
}

TEST(StatePlausibility, AJumpFasterThanTwiceTheTopSpeedIsImpossibleAndTheReferenceStays)
{
  StatePlausibility judge;
  ASSERT_EQ(judge.judge({ { 0.0, 0.0, 1.0 } }, at(0.0), panTiltZoom()), "");
  // 0.05 s later: 2 x 1 rad/s x (0.05 + 0.1 s slack) + 0.02 = 0.32 rad is the most pan may have moved.
  EXPECT_EQ(judge.judge({ { 0.30, 0.0, 1.0 } }, at(0.05), panTiltZoom()), "");
  EXPECT_EQ(judge.judge({ { 1.50, 0.0, 1.0 } }, at(0.10), panTiltZoom()), "pan jumped 1.20 rad in 0.05 s: faster than "
                                                                          "its top speed of 1.00 rad/s");
  // Judged against the last possible state, not the dropped one.
  EXPECT_EQ(judge.judge({ { 0.35, 0.0, 1.0 } }, at(0.10), panTiltZoom()), "");
  // Over a longer time, the same distance is possible.
  EXPECT_EQ(judge.judge({ { 1.50, 0.0, 1.0 } }, at(1.0), panTiltZoom()), "");
  // Zoom has no jump check: devices give no zoom speed to trust.
  EXPECT_EQ(judge.judge({ { 1.50, 0.0, 19.0 } }, at(1.01), panTiltZoom()), "");
  // Tilt has its own top speed.
  EXPECT_EQ(judge.judge({ { 1.50, 0.4, 19.0 } }, at(1.02), panTiltZoom()), "tilt jumped 0.40 rad in 0.01 s: faster "
                                                                           "than its top speed of 0.50 rad/s");
}

TEST(StatePlausibility, ReportsThatGoOnFromAJumpStayInDoubtUntilOneJumpsBack)
{
  StatePlausibility judge;
  ASSERT_EQ(judge.judge({ { 0.0, 0.0, 1.0 } }, at(0.0), panTiltZoom()), "");
  const std::string jump = "pan jumped 1.50 rad in 0.05 s: faster than its top speed of 1.00 rad/s";
  ASSERT_EQ(judge.judge({ { 1.5, 0.0, 1.0 } }, at(0.05), panTiltZoom()), jump);
  // Smoothly on from the jumped place, back towards the last believed one: by 0.8 s a device at 1 rad/s could be
  // there, but these reports follow the jump, not the device: still the jump's.
  for (double time = 0.1; time < 0.85; time += 0.05)
  {
    EXPECT_EQ(judge.judge({ { 1.5 - (time - 0.05), 0.0, 1.0 } }, at(time), panTiltZoom()), jump) << time;
  }
  // A report that jumps back to where the device can be is believed.
  EXPECT_EQ(judge.judge({ { 0.1, 0.0, 1.0 } }, at(0.85), panTiltZoom()), "");
  EXPECT_EQ(judge.judge({ { 0.12, 0.0, 1.0 } }, at(0.9), panTiltZoom()), "");
}

TEST(StatePlausibility, AfterForgetTheNextPossiblePlaceIsBelieved)
{
  StatePlausibility judge;
  ASSERT_EQ(judge.judge({ { -1.5, 0.0, 1.0 } }, at(0.0), panTiltZoom()), "");
  ASSERT_NE(judge.judge({ { 1.5, 0.0, 1.0 } }, at(0.05), panTiltZoom()), "");
  judge.forget();
  EXPECT_EQ(judge.judge({ { 1.5, 0.0, 1.0 } }, at(0.10), panTiltZoom()), "");
  EXPECT_EQ(judge.judge({ { 1.52, 0.0, 1.0 } }, at(0.15), panTiltZoom()), "");
}

TEST(StatePlausibility, AFullTurnOfPanIsComparedTheShortWayRound)
{
  Capabilities turning = panTiltZoom();
  turning.axes[PAN].range = AxisRange{ -M_PI, M_PI };
  StatePlausibility judge;
  ASSERT_EQ(judge.judge({ { 3.10, 0.0, 1.0 } }, at(0.0), turning), "");
  // Across the seam: 0.08 rad, not 6.2.
  EXPECT_EQ(judge.judge({ { -3.10, 0.0, 1.0 } }, at(0.05), turning), "");
}

}  // namespace

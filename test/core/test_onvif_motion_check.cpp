/**
 * \file
 * \brief onvif::MotionCheck on statuses written by hand: what it takes for a camera that ignores Stop, one that
 * answers AbsoluteMove and does not move, a zoom that stops short, and what it must never take for them (a camera
 * that brakes, a blocked motor, statuses that arrive late).
 */
#include <gtest/gtest.h>

#include <cmath>

#include "ptz_action_server/core/onvif/onvif_motion_check.h"

namespace ptz_action_server
{
namespace
{
using namespace onvif;

const TimePoint START(std::chrono::seconds(100));

/// A status at \p seconds after START, with pan \p pan and zoom \p zoom, and MoveStatus \p moving for both groups.
Observation at(double seconds, double pan, double zoom = 1.0, const char* moving = "")
{
  Observation status;
  status.at = addSeconds(START, seconds);
  status.position = { { pan, 0.0, zoom } };
  status.reported = { true, true, true };
  status.pan_tilt_status = moving;
  status.zoom_status = moving;
  return status;
}

MotionCheckConfig config()
{
  MotionCheckConfig config;
  config.deceleration = 3.0;
  config.max_speed = 1.5;
  config.poll_period = 0.1;
  config.start_timeout = 0.5;
  return config;
}

TEST(OnvifMotionCheck, ACameraThatBrakesAfterStopIsNeverTakenForOneThatKeepsMoving)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0));
  check.stopSent(START, { { 1.5, 0.0, 0.0 } });
  // Braking at 3 rad/s^2 from 1.5 rad/s: 0.5 s, still moving at every status until then.
  double pan = 0.0;
  for (int index = 1; index <= 6; ++index)
  {
    const double t = 0.1 * index;
    pan = t < 0.5 ? 1.5 * t - 1.5 * t * t : 0.375;
    EXPECT_EQ(check.observe(at(t, pan, 1.0, t < 0.5 ? "MOVING" : "IDLE")).kind, MotionFinding::NONE) << t;
  }
  EXPECT_EQ(check.observe(at(0.7, pan, 1.0, "IDLE")).kind, MotionFinding::NONE);
}

TEST(OnvifMotionCheck, ACameraStillMovingOnceItWouldHaveBrakedKeptMovingAndIsToldOnce)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0));
  check.stopSent(START, { { 0.3, 0.0, 0.0 } });
  // Twice the estimate (0.6 rad/s) takes 0.2 s to brake: 2 polls, plus 2 more.
  MotionFinding finding;
  int statuses = 0;
  while (finding.kind == MotionFinding::NONE && statuses < 20)
  {
    ++statuses;
    finding = check.observe(at(0.1 * statuses, 0.03 * statuses, 1.0, "MOVING"));
  }
  EXPECT_EQ(finding.kind, MotionFinding::KEPT_MOVING_AFTER_STOP);
  EXPECT_EQ(statuses, 4);
  EXPECT_TRUE(finding.axes[PAN]);
  EXPECT_FALSE(finding.axes[ZOOM]);
  EXPECT_NEAR(finding.speed[PAN], 0.3, 1e-9);
  EXPECT_NEAR(finding.after, 0.4, 1e-9);
  // Once: the watch is over.
  EXPECT_EQ(check.observe(at(0.5, 0.15, 1.0, "MOVING")).kind, MotionFinding::NONE);
}

TEST(OnvifMotionCheck, StatusesThatArriveLateAreCountedNotTimed)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0));
  check.stopSent(START, { { 1.5, 0.0, 0.0 } });
  // A busy machine: each status a second after the last. The camera, braking, is judged by how many came (seven for
  // 1.5 rad/s), not by the seconds they took.
  for (int index = 1; index <= 6; ++index)
  {
    EXPECT_EQ(check.observe(at(1.0 * index, 0.1 * index, 1.0, "MOVING")).kind, MotionFinding::NONE) << index;
  }
  EXPECT_EQ(check.observe(at(7.0, 0.7, 1.0, "MOVING")).kind, MotionFinding::KEPT_MOVING_AFTER_STOP);
}

TEST(OnvifMotionCheck, AnAbsoluteMoveThatNothingFollowsIsIgnoredOnlyOnceItsTimeAndThreeStatusesHavePassed)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0));
  check.absoluteMoveSent(START, { { 0.0, 0.0, 1.0 } }, { { 0.5, 0.0, 3.0 } });
  EXPECT_EQ(check.observe(at(0.2, 0.0, 1.0, "IDLE")).kind, MotionFinding::NONE);
  EXPECT_EQ(check.observe(at(0.6, 0.0, 1.0, "IDLE")).kind, MotionFinding::NONE);  // two statuses only
  const MotionFinding finding = check.observe(at(0.7, 0.0, 1.0, "IDLE"));
  EXPECT_EQ(finding.kind, MotionFinding::ABSOLUTE_MOVE_IGNORED);
  EXPECT_TRUE(finding.axes[PAN] && finding.axes[TILT] && finding.axes[ZOOM]);
}

TEST(OnvifMotionCheck, ABlockedMotorThatTheCameraDrivesIsNoIgnoredMove)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0));
  check.absoluteMoveSent(START, { { 0.0, 0.0, 1.0 } }, { { 0.5, 0.0, 1.0 } });
  for (int index = 1; index <= 20; ++index)
  {
    EXPECT_EQ(check.observe(at(0.1 * index, 0.0, 1.0, "MOVING")).kind, MotionFinding::NONE) << index;
  }
}

TEST(OnvifMotionCheck, OnlyTheGroupThatDidNotBeginIsNamed)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0));
  // The pan-tilt goes, the zoom stays (its MoveStatus given per group).
  check.absoluteMoveSent(START, { { 0.0, 0.0, 1.0 } }, { { 0.5, 0.0, 3.0 } });
  MotionFinding finding;
  for (int index = 1; index <= 6 && finding.kind == MotionFinding::NONE; ++index)
  {
    Observation status = at(0.1 * index, 0.05 * index, 1.0);
    status.pan_tilt_status = "MOVING";
    status.zoom_status = "IDLE";
    finding = check.observe(status);
  }
  EXPECT_EQ(finding.kind, MotionFinding::ABSOLUTE_MOVE_IGNORED);
  EXPECT_FALSE(finding.axes[PAN]);
  EXPECT_TRUE(finding.axes[ZOOM]);
}

TEST(OnvifMotionCheck, AZoomThatRestsShortOfItsTargetStoppedShortAndOneThatGetsThereDidNot)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0, 1.0));
  check.absoluteMoveSent(START, { { 0.0, 0.0, 1.0 } }, { { std::nan(""), std::nan(""), 10.0 } });
  EXPECT_EQ(check.observe(at(0.1, 0.0, 2.0, "MOVING")).kind, MotionFinding::NONE);
  EXPECT_EQ(check.observe(at(0.2, 0.0, 4.24, "IDLE")).kind, MotionFinding::NONE);
  const MotionFinding finding = check.observe(at(0.3, 0.0, 4.24, "IDLE"));
  EXPECT_EQ(finding.kind, MotionFinding::ZOOM_STOPPED_SHORT);
  EXPECT_EQ(finding.zoom, 4.24);
  EXPECT_EQ(finding.zoom_target, 10.0);

  check.absoluteMoveSent(START, { { 0.0, 0.0, 4.24 } }, { { std::nan(""), std::nan(""), 2.0 } });
  EXPECT_EQ(check.observe(at(0.1, 0.0, 3.0, "MOVING")).kind, MotionFinding::NONE);
  EXPECT_EQ(check.observe(at(0.2, 0.0, 2.0, "IDLE")).kind, MotionFinding::NONE);
  EXPECT_EQ(check.observe(at(0.3, 0.0, 2.0, "IDLE")).kind, MotionFinding::NONE);
}

TEST(OnvifMotionCheck, AnotherCommandEndsTheWatch)
{
  MotionCheck check(config());
  check.observe(at(0.0, 0.0));
  check.absoluteMoveSent(START, { { 0.0, 0.0, 1.0 } }, { { 0.5, 0.0, 1.0 } });
  check.clear();
  for (int index = 1; index <= 10; ++index)
  {
    EXPECT_EQ(check.observe(at(0.1 * index, 0.0, 1.0, "IDLE")).kind, MotionFinding::NONE);
  }
}

}  // namespace
}  // namespace ptz_action_server

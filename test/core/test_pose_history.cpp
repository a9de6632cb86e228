#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

#include "ptz_action_server/core/motion/pose_history.h"

using namespace ptz_action_server;

namespace
{
constexpr double NOT_KNOWN = std::numeric_limits<double>::quiet_NaN();

HeaderStamp at(double seconds)
{
  return headerStampFromSeconds(seconds);
}

PoseHistoryConfig config(double window, double tolerance, std::size_t capacity)
{
  PoseHistoryConfig limits;
  limits.window = headerStampFromSeconds(window);
  limits.newer_tolerance = headerStampFromSeconds(tolerance);
  limits.capacity = capacity;
  return limits;
}

void expectPose(const PoseLookup& lookup, double pan, double tilt, double zoom)
{
  ASSERT_TRUE(lookup.found()) << lookup.error;
  EXPECT_TRUE(lookup.error.empty());
  EXPECT_NEAR(lookup.pose[PAN], pan, 1e-12);
  EXPECT_NEAR(lookup.pose[TILT], tilt, 1e-12);
  EXPECT_NEAR(lookup.pose[ZOOM], zoom, 1e-12);
}
}  // namespace

TEST(PoseHistory, InterpolatesBetweenTheSamplesAroundAStamp)
{
  PoseHistory history;
  EXPECT_EQ(history.add(at(100.0), { 0.0, 0.1, 1.0 }), PoseHistory::Added::KEPT);
  EXPECT_EQ(history.add(at(101.0), { 1.0, 0.3, 3.0 }), PoseHistory::Added::KEPT);
  expectPose(history.at(at(100.25)), 0.25, 0.15, 1.5);
  EXPECT_EQ(history.at(at(100.25)).status, PoseLookupStatus::INTERPOLATED);
  // At a sample's own stamp: that sample, at either end of the history.
  expectPose(history.at(at(100.0)), 0.0, 0.1, 1.0);
  expectPose(history.at(at(101.0)), 1.0, 0.3, 3.0);
  const PoseLookup lookup = history.at(at(100.5));
  EXPECT_EQ(lookup.oldest, at(100.0));
  EXPECT_EQ(lookup.newest, at(101.0));
}

TEST(PoseHistory, SaysWhenAStampIsOutsideTheHistory)
{
  PoseHistory history(config(10.0, 0.2, 64));
  const PoseLookup empty = history.at(at(5.0));
  EXPECT_EQ(empty.status, PoseLookupStatus::EMPTY);
  EXPECT_FALSE(empty.found());
  EXPECT_NE(empty.error.find("no pose"), std::string::npos) << empty.error;

  history.add(at(50.0), { 0.5, 0.0, 1.0 });
  history.add(at(51.0), { 0.7, 0.0, 1.0 });
  // A little newer than the newest (an image between two state samples): the newest pose.
  const PoseLookup held = history.at(at(51.15));
  EXPECT_EQ(held.status, PoseLookupStatus::HELD);
  expectPose(held, 0.7, 0.0, 1.0);
  // Newer by more than the tolerance.
  const PoseLookup too_new = history.at(at(51.25));
  EXPECT_EQ(too_new.status, PoseLookupStatus::TOO_NEW);
  EXPECT_FALSE(too_new.found());
  EXPECT_TRUE(std::isnan(too_new.pose[PAN]));
  EXPECT_NE(too_new.error.find("newer than the camera's latest known pose (51.000 s"), std::string::npos)
      << too_new.error;
  // Older than the oldest sample.
  const PoseLookup too_old = history.at(at(49.9));
  EXPECT_EQ(too_old.status, PoseLookupStatus::TOO_OLD);
  EXPECT_NE(too_old.error.find("older than the camera's pose history (50.000 to 51.000 s"), std::string::npos)
      << too_old.error;
  // An image header without a stamp says so.
  EXPECT_NE(history.at(HeaderStamp(0)).error.find("no stamp"), std::string::npos);
}

TEST(PoseHistory, ForgetsWhatIsOlderThanItsWindow)
{
  PoseHistory history(config(1.0, 0.2, 256));
  for (int step = 0; step <= 30; ++step)
  {
    history.add(at(10.0 + 0.1 * step), { 0.1 * step, 0.0, 1.0 });
  }
  EXPECT_EQ(history.size(), 11u);  // 12.0 s back to 13.0 s
  EXPECT_EQ(history.at(at(11.95)).status, PoseLookupStatus::TOO_OLD);
  expectPose(history.at(at(12.05)), 2.05, 0.0, 1.0);
  // A sample more than a window behind the newest is not kept.
  EXPECT_EQ(history.add(at(11.9), { 9.0, 9.0, 9.0 }), PoseHistory::Added::TOO_OLD);
  EXPECT_EQ(history.size(), 11u);
  // The clock went back (a bag played again): cleared, the history starts again.
  history.clear();
  EXPECT_EQ(history.size(), 0u);
  EXPECT_EQ(history.add(at(1.0), { 0.0, 0.0, 1.0 }), PoseHistory::Added::KEPT);
  expectPose(history.at(at(1.0)), 0.0, 0.0, 1.0);
}

TEST(PoseHistory, AFullRingForgetsItsOldestSample)
{
  PoseHistory history(config(100.0, 0.2, 8));
  for (int step = 0; step < 20; ++step)
  {
    history.add(at(step), { 0.1 * step, 0.0, 1.0 });
  }
  EXPECT_EQ(history.size(), 8u);
  EXPECT_EQ(history.at(at(12.0)).oldest, at(12.0));
  EXPECT_EQ(history.at(at(11.5)).status, PoseLookupStatus::TOO_OLD);
  // Older than every sample of a full ring: nowhere to go.
  EXPECT_EQ(history.add(at(11.0), { 0.0, 0.0, 1.0 }), PoseHistory::Added::DROPPED);
  // A late sample in the middle takes the oldest's place.
  EXPECT_EQ(history.add(at(15.5), { 3.0, 0.0, 1.0 }), PoseHistory::Added::KEPT);
  EXPECT_EQ(history.size(), 8u);
  EXPECT_EQ(history.at(at(15.0)).oldest, at(13.0));
  expectPose(history.at(at(15.25)), 2.25, 0.0, 1.0);
}

TEST(PoseHistory, LateSamplesGoToTheirPlaceAndSameStampsMerge)
{
  PoseHistory history;
  history.add(at(1.0), { 0.0, 0.0, 1.0 });
  history.add(at(3.0), { 1.0, 0.0, 1.0 });
  EXPECT_EQ(history.add(at(2.0), { 1.5, 0.0, 1.0 }), PoseHistory::Added::KEPT);  // late: between the two
  expectPose(history.at(at(1.5)), 0.75, 0.0, 1.0);
  expectPose(history.at(at(2.5)), 1.25, 0.0, 1.0);
  // The renderer's exact pose at a stamp the state tick also took: the known axes of the later one win.
  EXPECT_EQ(history.add(at(2.0), { 1.8, NOT_KNOWN, 2.0 }), PoseHistory::Added::MERGED);
  expectPose(history.at(at(2.0)), 1.8, 0.0, 2.0);
  EXPECT_EQ(history.size(), 3u);
}

TEST(PoseHistory, EachAxisFromTheSamplesThatKnowIt)
{
  PoseHistory history;
  history.add(at(1.0), { 0.0, 0.0, 1.0 });
  history.add(at(2.0), { 0.5, 0.1, NOT_KNOWN });  // a report without zoom
  history.add(at(3.0), { 1.0, 0.2, 3.0 });
  expectPose(history.at(at(2.5)), 0.75, 0.15, 2.5);  // zoom between 1 s and 3 s
  // An axis no sample knows stays unknown; the others are found.
  PoseHistory pan_tilt_unit;
  pan_tilt_unit.add(at(1.0), { 0.0, 0.0, NOT_KNOWN });
  pan_tilt_unit.add(at(2.0), { 1.0, 0.0, NOT_KNOWN });
  const PoseLookup lookup = pan_tilt_unit.at(at(1.5));
  EXPECT_TRUE(lookup.found());
  EXPECT_NEAR(lookup.pose[PAN], 0.5, 1e-12);
  EXPECT_TRUE(std::isnan(lookup.pose[ZOOM]));
}

TEST(PoseHistory, PanTakesTheShorterWayRound)
{
  PoseHistory history;
  history.add(at(1.0), { 3.0, 0.0, 1.0 });
  history.add(at(2.0), { -3.0, 0.0, 1.0 });  // 0.28 rad clockwise, across +-pi, not 6 rad back
  const double step = 2.0 * M_PI - 6.0;
  EXPECT_NEAR(history.at(at(1.25)).pose[PAN], 3.0 + 0.25 * step, 1e-12);
  EXPECT_NEAR(history.at(at(1.75)).pose[PAN], 3.0 + 0.75 * step - 2.0 * M_PI, 1e-12);  // past pi: on the other side
  for (const double seconds : { 1.1, 1.5, 1.9 })
  {
    EXPECT_LE(std::abs(history.at(at(seconds)).pose[PAN]), M_PI);
  }
}

TEST(PoseHistory, ABadConfigurationIsRefused)
{
  EXPECT_THROW(PoseHistory(config(0.0, 0.2, 64)), ConfigError);
  EXPECT_THROW(PoseHistory(config(1.0, -0.1, 64)), ConfigError);
  EXPECT_THROW(PoseHistory(config(1.0, 0.2, 1)), ConfigError);
}

TEST(PoseHistory, AReaderSeesConsistentPosesWhileAWriterAdds)
{
  // Poses linear in time, written in pairs out of order into a ring that wraps many times: every pose a reader
  // finds between two samples must be on the line, however the samples around it arrived.
  PoseHistory history(config(10.0, 0.0, 64));
  constexpr int SAMPLES = 20000;
  constexpr double PERIOD = 0.01;
  const auto pose_at = [](double seconds) { return AxisValues{ 0.01 * seconds, -0.005 * seconds, 1.0 + seconds }; };
  std::atomic<bool> written{ false };
  std::atomic<int> newest_written{ 0 };
  std::thread writer([&] {
    for (int pair = 0; pair + 1 < SAMPLES; pair += 2)
    {
      for (const int step : { pair + 1, pair })
      {
        history.add(at(step * PERIOD), pose_at(step * PERIOD));
      }
      newest_written = pair + 1;
    }
    written = true;
  });
  int checked = 0;
  int lookups = 0;
  const auto check = [&](int step) {
    const double seconds = (step + 0.37) * PERIOD;
    const PoseLookup lookup = history.at(at(seconds));
    ++lookups;
    if (lookup.status == PoseLookupStatus::INTERPOLATED)
    {
      const AxisValues expected = pose_at(seconds);
      for (const Axis axis : ALL_AXES)
      {
        ASSERT_NEAR(lookup.pose[axis], expected[axis], 1e-7) << seconds;
      }
      ++checked;
    }
  };
  while (!written)
  {
    const int newest = newest_written;
    check(newest - (lookups % 40));  // from just behind the writer back to beyond the ring
  }
  writer.join();
  for (int step = SAMPLES - 60; step < SAMPLES - 1; ++step)
  {
    check(step);
  }
  EXPECT_EQ(history.size(), 64u);
  EXPECT_GE(checked, 59);
}

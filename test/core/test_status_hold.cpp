#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ptz_action_server/core/goal/status_hold.h"

namespace ptz_action_server
{
namespace
{
class StatusHoldTest : public ::testing::Test
{
protected:
  StatusHold::Change record(const std::string& what)
  {
    return [this, what] { done.push_back(what); };
  }
  ManualClock clock;
  std::vector<std::string> done;
};

TEST_F(StatusHoldTest, ChangesWithoutANewGoalRunAtOnce)
{
  StatusHold hold(0.02);
  hold.run(record("succeed old"), clock.now());
  EXPECT_EQ(done, std::vector<std::string>({ "succeed old" }));
  EXPECT_EQ(hold.release(clock.now()), TimePoint::max());
}

TEST_F(StatusHoldTest, ChangesAfterAGoalWaitForTheHoldInOrder)
{
  StatusHold hold(0.02);
  hold.goalArrived(clock.now());
  hold.run(record("preempt old"), clock.now());
  hold.run(record("accept new"), clock.now());
  hold.run(record("succeed new"), clock.now());
  EXPECT_TRUE(done.empty());
  clock.advance(0.019);
  EXPECT_EQ(hold.release(clock.now()), addSeconds(clock.now(), 0.001));
  EXPECT_TRUE(done.empty());
  clock.advance(0.001);
  EXPECT_EQ(hold.release(clock.now()), TimePoint::max());
  EXPECT_EQ(done, std::vector<std::string>({ "preempt old", "accept new", "succeed new" }));
  EXPECT_FALSE(hold.holding(clock.now()));
}

TEST_F(StatusHoldTest, AChangeAfterTheHoldStillWaitsBehindHeldOnes)
{
  StatusHold hold(0.02);
  hold.goalArrived(clock.now());
  hold.run(record("accept"), clock.now());
  clock.advance(0.05);  // the release is late (a busy main thread)
  EXPECT_TRUE(hold.holding(clock.now())) << "a change is still held";
  hold.run(record("succeed"), clock.now());
  EXPECT_TRUE(done.empty());
  hold.release(clock.now());
  EXPECT_EQ(done, std::vector<std::string>({ "accept", "succeed" }));
}

TEST_F(StatusHoldTest, AGoalStormDelaysEachChangeByTheHoldOnly)
{
  StatusHold hold(0.02);
  for (int goal = 0; goal < 10; ++goal)
  {
    hold.goalArrived(clock.now());
    hold.run(record("accept " + std::to_string(goal)), clock.now());
    clock.advance(0.005);
    hold.release(clock.now());
  }
  // Goals every 5 ms never let the hold lapse, yet each change runs 20 ms after its goal.
  // At 50 ms the goals of 0 to 30 ms have been told, those of 35 to 45 ms wait.
  EXPECT_EQ(done.size(), 7u);
  EXPECT_EQ(done.back(), "accept 6");
  EXPECT_EQ(hold.heldCount(), 3u);
}

TEST_F(StatusHoldTest, ZeroHoldNeverHolds)
{
  StatusHold hold(0.0);
  hold.goalArrived(clock.now());
  hold.run(record("reject"), clock.now());
  EXPECT_EQ(done, std::vector<std::string>({ "reject" }));
}

}  // namespace
}  // namespace ptz_action_server

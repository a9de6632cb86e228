#include <string>

#include <gtest/gtest.h>

#include "ptz_action_server/core/goal/ended_goal_list.h"

namespace ptz_action_server
{
namespace
{
TEST(EndedGoalList, KeepsEachGoalsBytesInOrderUntilItExpires)
{
  EndedGoalList list;
  list.add("a", "AAA", 1.0);
  list.add("b", "BB", 1.5);
  list.add("c", "C", 2.0);
  EXPECT_EQ(list.count(), 3u);
  EXPECT_EQ(list.bytes(), "AAABBC");
  EXPECT_TRUE(list.contains("b"));
  EXPECT_FALSE(list.contains("d"));

  list.expire(1.0);  // "a" expires at 1.0: still there at 1.0
  EXPECT_EQ(list.bytes(), "AAABBC");
  list.expire(1.2);
  EXPECT_EQ(list.count(), 2u);
  EXPECT_EQ(list.bytes(), "BBC");
  EXPECT_FALSE(list.contains("a"));
  list.expire(2.1);
  EXPECT_EQ(list.count(), 0u);
  EXPECT_EQ(list.bytes(), "");
  EXPECT_FALSE(list.contains("c"));
}

TEST(EndedGoalList, AGoalWaitsForTheOlderOnesToExpire)
{
  EndedGoalList list;
  list.add("slow", "S", 2.0);
  list.add("quick", "Q", 1.0);
  list.expire(1.5);
  EXPECT_EQ(list.bytes(), "SQ");
  list.expire(2.5);
  EXPECT_EQ(list.bytes(), "");
}

TEST(EndedGoalList, RemovingAnIdKeepsTheOthersInOrder)
{
  EndedGoalList list;
  list.add("a", "AA", 1.0);
  list.add("b", "BBB", 2.0);
  list.add("c", "C", 3.0);
  list.expire(1.5);  // "a" left: the entries start past its bytes
  list.remove("b");
  EXPECT_FALSE(list.contains("b"));
  EXPECT_EQ(list.count(), 1u);
  EXPECT_EQ(list.bytes(), "C");
  list.remove("unknown");
  EXPECT_EQ(list.bytes(), "C");
  list.add("d", "DD", 4.0);
  EXPECT_EQ(list.bytes(), "CDD");
  list.expire(3.5);
  EXPECT_EQ(list.bytes(), "DD");
}

TEST(EndedGoalList, AStormOfGoalsKeepsOnlyTheUnexpiredBytes)
{
  // A goal every tick for 2000 ticks, each kept 200 ticks: the list holds the last 200 ticks' goals.
  EndedGoalList list;
  for (int index = 0; index < 2000; ++index)
  {
    const double now = index;
    list.expire(now);
    list.add("goal" + std::to_string(index), std::string(40, static_cast<char>('a' + index % 26)), now + 200.0);
  }
  EXPECT_EQ(list.count(), 201u);  // added at ticks 1799 .. 1999, expiring at 1999 .. 2199
  EXPECT_EQ(list.bytes().size(), 201u * 40u);
  EXPECT_EQ(list.bytes().front(), static_cast<char>('a' + 1799 % 26));
  EXPECT_TRUE(list.contains("goal1999"));
  EXPECT_FALSE(list.contains("goal1798"));
}

}  // namespace
}  // namespace ptz_action_server

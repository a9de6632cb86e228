/**
 * \file
 * \brief rostest client, the action status list as clients read it: an ended goal is listed with its terminal status
 * for status_list_timeout, then leaves; a goal sent again with an ended goal's id is rejected. sim_node.test sets
 * position_rel's status_list_timeout to 3 s.
 */
#include <algorithm>
#include <mutex>
#include <string>
#include <vector>

#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/ros.h>
#include <unistd.h>

#include "ptz_action_server/PtzActionGoal.h"
#include "ptz_action_server/PtzActionResult.h"

namespace
{
using actionlib_msgs::GoalStatus;
using actionlib_msgs::GoalStatusArray;

constexpr double WAIT = 20.0;         // s
constexpr double LIST_TIMEOUT = 3.0;  // s, sim_node.test's move_ptz/position_rel/status_list_timeout

class StatusListTest : public ::testing::Test
{
protected:
  StatusListTest()
  {
    status_subscriber_ = node_handle_.subscribe("move_ptz/position_rel/status", 100, &StatusListTest::onList, this);
    result_subscriber_ = node_handle_.subscribe("move_ptz/position_rel/result", 100, &StatusListTest::onResult, this);
    goal_publisher_ = node_handle_.advertise<ptz_action_server::PtzActionGoal>("move_ptz/position_rel/goal", 10);
  }

  struct Seen
  {
    ros::WallTime at;
    std::vector<GoalStatus> entries;  ///< the list's entries of one id
  };

  void onList(const GoalStatusArray::ConstPtr& list)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    Seen seen{ ros::WallTime::now(), {} };
    for (const GoalStatus& status : list->status_list)
    {
      if (status.goal_id.id == watched_)
      {
        seen.entries.push_back(status);
      }
    }
    lists_.push_back(seen);
  }
  void onResult(const ptz_action_server::PtzActionResult::ConstPtr& result)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (result->status.goal_id.id == watched_)
    {
      results_.push_back(result->status);
    }
  }

  /// Waits until \p predicate holds (under the lock), or WAIT passes.
  template <class Predicate>
  bool waitFor(const Predicate& predicate)
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(WAIT);
    while (ros::WallTime::now() < deadline)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (predicate())
        {
          return true;
        }
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }

  /// A relative goal of no length (it succeeds at once) with the id \p id.
  void sendStill(const std::string& id)
  {
    ptz_action_server::PtzActionGoal goal;
    goal.header.stamp = ros::Time::now();
    goal.goal_id.id = id;
    goal.goal_id.stamp = goal.header.stamp;
    goal_publisher_.publish(goal);
  }

  ros::NodeHandle node_handle_;
  ros::Subscriber status_subscriber_;
  ros::Subscriber result_subscriber_;
  ros::Publisher goal_publisher_;
  std::mutex mutex_;
  std::string watched_;
  std::vector<Seen> lists_;
  std::vector<GoalStatus> results_;
};

TEST_F(StatusListTest, AnEndedGoalIsListedUntilTheTimeoutAndItsIdIsNotTakenAgain)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    watched_ = "status_list_test_" + std::to_string(getpid());
  }
  ASSERT_TRUE(waitFor([&] {
    return goal_publisher_.getNumSubscribers() > 0 && status_subscriber_.getNumPublishers() > 0 &&
           result_subscriber_.getNumPublishers() > 0;
  }));
  sendStill(watched_);
  ASSERT_TRUE(waitFor([&] { return results_.size() == 1; })) << "the goal never ended";
  EXPECT_EQ(results_[0].status, GoalStatus::SUCCEEDED) << results_[0].text;

  // Listed as succeeded once it ended (the list of the transition, then the periodic ones).
  std::size_t first_listed = 0;
  ASSERT_TRUE(waitFor([&] {
    for (; first_listed < lists_.size(); ++first_listed)
    {
      const auto& entries = lists_[first_listed].entries;
      if (!entries.empty() && entries.back().status == GoalStatus::SUCCEEDED)
      {
        return true;
      }
    }
    return false;
  }));

  // The same id again: rejected with a reason, the ended goal's result kept.
  sendStill(watched_);
  ASSERT_TRUE(waitFor([&] { return results_.size() == 2; })) << "the goal sent again got no result";
  EXPECT_EQ(results_[1].status, GoalStatus::REJECTED);
  EXPECT_NE(results_[1].text.find("ended"), std::string::npos) << results_[1].text;

  // Then the id leaves the list, each list naming it at most once meanwhile.
  ASSERT_TRUE(waitFor([&] {
    return lists_.size() > first_listed + 1 && lists_.back().entries.empty() &&
           std::any_of(lists_.begin() + first_listed, lists_.end(), [](const Seen& seen) {
             return !seen.entries.empty() && seen.entries.back().status == GoalStatus::REJECTED;
           });
  })) << "the goal never left the status list";
  std::lock_guard<std::mutex> lock(mutex_);
  ros::WallTime last_listed = lists_[first_listed].at;
  for (std::size_t index = first_listed; index < lists_.size(); ++index)
  {
    EXPECT_LE(lists_[index].entries.size(), 1u) << "the id is listed twice";
    if (!lists_[index].entries.empty())
    {
      last_listed = lists_[index].at;
    }
  }
  // Listed for the timeout after the rejection's handle went: at least half of it after it was first listed.
  EXPECT_GE((last_listed - lists_[first_listed].at).toSec(), LIST_TIMEOUT / 2);
}

}  // namespace

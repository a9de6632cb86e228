/**
 * \file
 * \brief rostest client, the action status list as clients read it: an ended goal is listed with its terminal status
 * for status_list_timeout, then leaves; a cancel of it changes nothing; a goal sent again with its id is rejected.
 * sim_node.test sets position_rel's status_list_timeout to 3 s.
 */
#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <actionlib_msgs/GoalID.h>
#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/ros.h>
#include <unistd.h>

#include "ptz_action_server/PtzActionGoal.h"
#include "ptz_action_server/PtzActionResult.h"
#include "../core/wait_until.h"

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
    cancel_publisher_ = node_handle_.advertise<actionlib_msgs::GoalID>("move_ptz/position_rel/cancel", 10);
  }

  /// One status list: when it came, and its entries of the watched ids.
  struct Seen
  {
    ros::WallTime at;
    std::map<std::string, std::vector<GoalStatus>> entries;
  };

  void onList(const GoalStatusArray::ConstPtr& list)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    Seen seen{ ros::WallTime::now(), {} };
    for (const GoalStatus& status : list->status_list)
    {
      if (std::find(watched_.begin(), watched_.end(), status.goal_id.id) != watched_.end())
      {
        seen.entries[status.goal_id.id].push_back(status);
      }
    }
    lists_.push_back(seen);
  }
  void onResult(const ptz_action_server::PtzActionResult::ConstPtr& result)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    results_[result->status.goal_id.id].push_back(result->status);
  }

  /// Waits until \p predicate holds (under the lock), or WAIT passes.
  template <class Predicate>
  bool waitFor(const Predicate& predicate)
  {
    return ptz_action_server::waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          return predicate();
        },
        WAIT);
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

  /// The index of the first list from \p from on that names \p id as succeeded (under the lock), or none.
  std::optional<std::size_t> listedSucceeded(const std::string& id, std::size_t from) const
  {
    for (std::size_t index = from; index < lists_.size(); ++index)
    {
      const auto found = lists_[index].entries.find(id);
      if (found != lists_[index].entries.end() && found->second.back().status == GoalStatus::SUCCEEDED)
      {
        return index;
      }
    }
    return std::nullopt;
  }

  /// Sends a still goal of \p id and waits until it succeeded and a list says so; returns that list's index.
  std::size_t succeed(const std::string& id)
  {
    sendStill(id);
    std::optional<std::size_t> listed;
    EXPECT_TRUE(waitFor([&] {
      listed = listedSucceeded(id, 0);
      return results_[id].size() == 1 && listed;
    })) << id
        << " never ended, or was never listed as succeeded";
    std::lock_guard<std::mutex> lock(mutex_);
    EXPECT_EQ(results_[id].front().status, GoalStatus::SUCCEEDED) << results_[id].front().text;
    return listed.value_or(0);
  }

  ros::NodeHandle node_handle_;
  ros::Subscriber status_subscriber_;
  ros::Subscriber result_subscriber_;
  ros::Publisher goal_publisher_;
  ros::Publisher cancel_publisher_;
  std::mutex mutex_;
  std::vector<std::string> watched_;
  std::vector<Seen> lists_;
  std::map<std::string, std::vector<GoalStatus>> results_;
};

TEST_F(StatusListTest, AnEndedGoalIsListedUntilTheTimeoutAndItsIdIsNotTakenAgain)
{
  const std::string cancelled = "status_list_cancelled_" + std::to_string(getpid());
  const std::string again = "status_list_again_" + std::to_string(getpid());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    watched_ = { cancelled, again };
  }
  ASSERT_TRUE(waitFor([&] {
    return goal_publisher_.getNumSubscribers() > 0 && cancel_publisher_.getNumSubscribers() > 0 &&
           status_subscriber_.getNumPublishers() > 0 && result_subscriber_.getNumPublishers() > 0;
  }));

  // A goal that ends, then is cancelled (a client cancelling as its goal ends): the cancel changes nothing.
  const std::size_t cancelled_listed = succeed(cancelled);
  actionlib_msgs::GoalID cancel;
  cancel.id = cancelled;
  cancel_publisher_.publish(cancel);

  // A goal that ends, then the same id again: rejected with a reason, the ended goal's result kept.
  succeed(again);
  sendStill(again);
  ASSERT_TRUE(waitFor([&] { return results_[again].size() == 2; })) << "the goal sent again got no result";
  {
    std::lock_guard<std::mutex> lock(mutex_);
    EXPECT_EQ(results_[again][1].status, GoalStatus::REJECTED);
    EXPECT_NE(results_[again][1].text.find("ended"), std::string::npos) << results_[again][1].text;
  }

  // Then both leave the list, each named at most once by each list meanwhile.
  ASSERT_TRUE(waitFor([&] { return lists_.size() > cancelled_listed + 1 && lists_.back().entries.empty(); })) << "an "
                                                                                                                 "ended"
                                                                                                                 " goal"
                                                                                                                 " neve"
                                                                                                                 "r "
                                                                                                                 "left "
                                                                                                                 "the "
                                                                                                                 "statu"
                                                                                                                 "s "
                                                                                                                 "list";
  std::lock_guard<std::mutex> lock(mutex_);
  ros::WallTime last_listed = lists_[cancelled_listed].at;
  bool listed_rejected = false;
  for (std::size_t index = cancelled_listed; index < lists_.size(); ++index)
  {
    for (const auto& [id, entries] : lists_[index].entries)
    {
      EXPECT_EQ(entries.size(), 1u) << id << " is listed twice";
      EXPECT_NE(entries.front().status, GoalStatus::RECALLING) << "the cancel of the ended goal was kept";
      listed_rejected = listed_rejected || (id == again && entries.front().status == GoalStatus::REJECTED);
      if (id == cancelled)
      {
        last_listed = lists_[index].at;
      }
    }
  }
  EXPECT_TRUE(listed_rejected);
  // Listed for the timeout after its handle went: at least half of it after it was first listed as succeeded.
  EXPECT_GE((last_listed - lists_[cancelled_listed].at).toSec(), LIST_TIMEOUT / 2);
}

}  // namespace

#include "goal_supervisor_fixture.h"

using namespace ptz_action_server;
using namespace goal_supervisor_test;

namespace
{
/// The activity listener's calls, as "accepted <action>" and "idle".
class GoalSupervisorActivityTest : public GoalSupervisorTest
{
protected:
  GoalSupervisorActivityTest()
  {
    supervisor_.setActivityListener([this](const GoalHandle* goal) {
      events_.push_back(goal ? "accepted " + goal->action() : std::string("idle"));
    });
  }
  std::vector<std::string> events_;
};

TEST_F(GoalSupervisorActivityTest, TellsEachAcceptedGoalAndIdleOnlyWhenNoGoalFollows)
{
  const auto first = submit(positionGoal(1.0, 0.0, 1.0), "first", "tour");
  const auto second = submit(velocityGoal(0.1, 0.0, 0.0), "second", "velocity");  // preempts: no idle between
  EXPECT_EQ(first->end.rfind("PREEMPTED", 0), 0U) << first->end;
  EXPECT_EQ(events_, (std::vector<std::string>{ "accepted tour", "accepted velocity" }));

  supervisor_.cancel("velocity", "second");
  backend_->at({ 0.2, 0.0, 1.0 }, false);
  tick();
  ASSERT_FALSE(second->end.empty());
  EXPECT_EQ(events_.back(), "idle");

  // A rejected goal is neither accepted nor makes the supervisor idle again.
  events_.clear();
  submit(positionGoal(100.0, 0.0, 1.0), "refused");
  EXPECT_TRUE(events_.empty());
  // A goal the device already satisfies is accepted, then ends at once.
  submit(positionGoal(0.2, 0.0, 1.0), "there");
  EXPECT_EQ(events_, (std::vector<std::string>{ "accepted position_abs", "idle" }));
}

}  // namespace

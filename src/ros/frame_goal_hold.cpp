#include "ptz_action_server/ros/frame_goal_hold.h"

namespace ptz_action_server
{
namespace
{
constexpr double CHECK_PERIOD = 0.02;  ///< s between checks of tf while a goal waits
}  // namespace

FrameGoalHold::FrameGoalHold(const ros::NodeHandle& node_handle, FrameListener& frames, std::string base_frame)
  : node_handle_(node_handle)
  , frames_(frames)
  , base_frame_(std::move(base_frame))
  , timer_(node_handle_.getCallbackQueue(), [this] { check(); })
{
}

bool FrameGoalHold::mustWait(const std::string& frame_id)
{
  frames_.listen();
  return !frame_id.empty() && !frames_.ready(base_frame_, frame_id);
}

void FrameGoalHold::hold(Goal goal)
{
  goal_ = std::move(goal);
  timer_.startPeriodic(CHECK_PERIOD);
}

void FrameGoalHold::supersede(ActionKind kind)
{
  if (goal_)
  {
    const Goal goal = take();
    goal.reject(std::string("superseded by a new ") + actionName(kind) + " goal while waiting for tf to have '" +
                goal.frame_id + "'");
  }
}

bool FrameGoalHold::cancel(const std::string& id)
{
  if (!goal_ || goal_->id != id)
  {
    return false;
  }
  const Goal goal = take();
  goal.cancel("cancelled while waiting for tf to have '" + goal.frame_id + "'");
  return true;
}

FrameGoalHold::Goal FrameGoalHold::take()
{
  Goal goal = std::move(*goal_);
  goal_.reset();
  timer_.stop();
  return goal;
}

void FrameGoalHold::check()
{
  if (goal_ && frames_.ready(base_frame_, goal_->frame_id))
  {
    take().submit();
  }
}

}  // namespace ptz_action_server

#include "ptz_action_server/ros/tour_goals.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace ptz_action_server
{
namespace tour_goals
{
constexpr const char* TOUR_ACTION = "tour";
constexpr const char* IDLE_RETURN_ACTION = "idle_return";
constexpr double TOUR_FEEDBACK_PERIOD = 1.0;  // s between feedbacks while a tour dwells or waits
}  // namespace tour_goals

/// What a move goal reaches the TourGoals through; null once they are gone.
struct TourGoals::Link
{
  TourGoals* goals = nullptr;
};

/// A move of the tours as the supervisor sees it: its news go to TourGoals::onMove().
class TourGoals::MoveGoal : public GoalHandle
{
public:
  MoveGoal(const char* action, std::string id, std::shared_ptr<Link> link)
    : action_(action), id_(std::move(id)), link_(std::move(link))
  {
  }
  const std::string& action() const override
  {
    return action_;
  }
  const std::string& id() const override
  {
    return id_;
  }
  void accept(const std::string&) override
  {
  }
  void reject(const std::string& text) override
  {
    tell(MoveEvent::FAILED, text);
  }
  void publishFeedback(const AxisValues&) override
  {
    tell(MoveEvent::FEEDBACK, {});
  }
  void succeed(const std::string& text) override
  {
    tell(MoveEvent::REACHED, text);
  }
  void abort(const std::string& text) override
  {
    tell(MoveEvent::FAILED, text);
  }
  void preempt(const std::string& text) override
  {
    tell(MoveEvent::PREEMPTED, text);
  }

private:
  void tell(MoveEvent event, const std::string& text) const
  {
    if (link_->goals)
    {
      link_->goals->onMove(id_, event, text);
    }
  }

  const std::string action_;
  const std::string id_;
  const std::shared_ptr<Link> link_;
};

TourGoals::TourGoals(const ros::NodeHandle& node_handle, const TourSettings& settings, GoalSupervisor& supervisor,
                     std::shared_ptr<PtzBackend> backend, const PresetServices& presets, const TourServices& tours,
                     StatusPoster post_status, std::function<void(const std::function<void()>&)> batch)
  : node_handle_(node_handle)
  , supervisor_(supervisor)
  , backend_(std::move(backend))
  , presets_(presets)
  , tours_(tours)
  , post_status_(std::move(post_status))
  , batch_(std::move(batch))
  , runner_(settings, clock_.now())
  , link_(std::make_shared<Link>())
  , timer_(node_handle_.getCallbackQueue(), [this] { onTimer(); })
{
  link_->goals = this;
  supervisor_.setActivityListener([this](const GoalHandle* goal) { onActivity(goal); });
  if (!settings.idle_preset.empty() && settings.idle_seconds > 0.0)
  {
    ROS_INFO("idle return: to preset '%s' after %.1f s without a goal", settings.idle_preset.c_str(),
             settings.idle_seconds);
  }
  armTimer();
}

TourGoals::~TourGoals()
{
  supervisor_.setActivityListener(nullptr);
  link_->goals = nullptr;
  timer_.stop();
}

void TourGoals::onGoal(Handle handle)
{
  const auto goal = handle.getGoal();
  const std::optional<Tour> tour = tours_.find(goal->name);
  if (!tour)
  {
    const std::string text = "no tour named '" + goal->name + "'";
    ROS_WARN("tour goal rejected: %s", text.c_str());
    post_status_.post([handle, text]() mutable { handle.setRejected(PtzTourResult(), text); });
    return;
  }
  if (goal_)
  {
    endGoal({ TourOrder::Kind::PREEMPT, {}, 0.0, "preempted by a new tour goal" });
  }
  goal_ = handle;
  post_status_.post([handle]() mutable { handle.setAccepted(""); });
  ROS_INFO("tour '%s': %zu stops, %s", tour->name.c_str(), tour->stops.size(),
           goal->rounds == 0 ? "until cancelled or preempted" : (std::to_string(goal->rounds) + " rounds").c_str());
  apply(runner_.start(*tour, goal->rounds, clock_.now()));
}

void TourGoals::onCancel(const Handle& handle)
{
  if (goal_ && goal_->getGoalID().id == handle.getGoalID().id)
  {
    apply(runner_.cancel(clock_.now()));
  }
}

void TourGoals::shutdown(const std::string& reason)
{
  timer_.stop();
  endGoal({ TourOrder::Kind::ABORT, {}, 0.0, reason });
}

void TourGoals::onActivity(const GoalHandle* goal)
{
  if (!goal)
  {
    runner_.goalsIdle(clock_.now());
    apply({});
  }
  else if (goal->action() != tour_goals::TOUR_ACTION && goal->action() != tour_goals::IDLE_RETURN_ACTION)
  {
    apply(runner_.operatorGoal(goal->action()));
  }
}

void TourGoals::onMove(const std::string& id, MoveEvent event, const std::string& text)
{
  if (id != move_id_)
  {
    if (id.rfind(tour_goals::IDLE_RETURN_ACTION, 0) == 0 && event != MoveEvent::FEEDBACK)
    {
      if (event == MoveEvent::REACHED)
      {
        ROS_INFO("idle return: back at its preset");
      }
      else
      {
        ROS_WARN("idle return: %s", text.c_str());
      }
    }
    return;  // the idle return's, or a move of an earlier tour
  }
  switch (event)
  {
    case MoveEvent::REACHED:
      apply(runner_.stopReached(clock_.now()));
      break;
    case MoveEvent::FAILED:
      apply(runner_.stopFailed(text, clock_.now()));
      break;
    case MoveEvent::PREEMPTED:
      apply(runner_.stopPreempted(text));
      break;
    case MoveEvent::FEEDBACK:
      publishFeedback();
      break;
  }
}

void TourGoals::apply(const TourOrder& order)
{
  switch (order.kind)
  {
    case TourOrder::Kind::NOTHING:
      break;
    case TourOrder::Kind::MOVE:
      move_id_ = (goal_ ? goal_->getGoalID().id : std::string("tour")) + "/" + std::to_string(++moves_);
      if (!submitMove(tour_goals::TOUR_ACTION, move_id_, order.preset, order.speed))
      {
        apply(runner_.stopFailed("no preset named '" + order.preset + "'", clock_.now()));
        return;
      }
      break;
    case TourOrder::Kind::STOP_MOVE:
      if (supervisor_.isRunning(tour_goals::TOUR_ACTION, move_id_))
      {
        supervisor_.cancel(tour_goals::TOUR_ACTION, move_id_);  // its preempt ends the tour once the device rests
      }
      else
      {
        apply(runner_.stopPreempted("cancelled"));
        return;
      }
      break;
    case TourOrder::Kind::IDLE_RETURN:
      if (submitMove(tour_goals::IDLE_RETURN_ACTION,
                     std::string(tour_goals::IDLE_RETURN_ACTION) + "_" + std::to_string(++moves_), order.preset, 0.0))
      {
        ROS_INFO("idle return: to preset '%s'", order.preset.c_str());
      }
      break;
    case TourOrder::Kind::SUCCEED:
    case TourOrder::Kind::PREEMPT:
    case TourOrder::Kind::ABORT:
      endGoal(order);
      break;
  }
  publishFeedback();
  armTimer();
}

bool TourGoals::submitMove(const char* action, const std::string& id, const std::string& preset, double speed)
{
  const std::optional<AxisValues> pose = presets_.find(preset);
  if (!pose)
  {
    ROS_WARN("%s: no preset named '%s'", action, preset.c_str());
    return false;
  }
  ConvertedGoal converted;
  converted.command = tourMoveCommand(*pose, speed);
  supervisor_.submit(std::make_unique<MoveGoal>(action, id, link_), backend_->sample(), converted);
  return true;
}

void TourGoals::endGoal(const TourOrder& order)
{
  if (!goal_)
  {
    return;
  }
  PtzTourResult result;
  result.success = order.kind == TourOrder::Kind::SUCCEED;
  result.stops_visited = runner_.stopsVisited();
  const std::string text = order.text;
  Handle handle = *goal_;
  goal_.reset();
  switch (order.kind)
  {
    case TourOrder::Kind::SUCCEED:
      ROS_INFO("tour goal succeeded: %s", text.c_str());
      post_status_.post([handle, result, text]() mutable { handle.setSucceeded(result, text); });
      break;
    case TourOrder::Kind::ABORT:
      ROS_WARN("tour goal aborted: %s", text.c_str());
      post_status_.post([handle, result, text]() mutable { handle.setAborted(result, text); });
      break;
    default:
      ROS_INFO("tour goal preempted: %s", text.c_str());
      post_status_.post([handle, result, text]() mutable { handle.setCanceled(result, text); });
  }
}

void TourGoals::publishFeedback()
{
  if (!goal_ || !runner_.running())
  {
    return;
  }
  const TourProgress progress = runner_.progress(clock_.now());
  PtzTourFeedback feedback;
  feedback.state = progress.phase == TourPhase::DWELLING ? PtzTourFeedback::DWELLING :
                   progress.phase == TourPhase::PAUSED   ? PtzTourFeedback::PAUSED :
                                                           PtzTourFeedback::MOVING;
  feedback.tour = progress.tour;
  feedback.round = progress.round;
  feedback.stop = static_cast<std::uint32_t>(progress.stop);
  feedback.preset = progress.preset;
  feedback.time_left = static_cast<float>(progress.time_left);
  if (post_status_.holding())
  {
    // Feedback never overtakes the goal's held acceptance.
    post_status_.post([handle = *goal_, feedback]() mutable { handle.publishFeedback(feedback); });
    return;
  }
  goal_->publishFeedback(feedback);
}

void TourGoals::armTimer()
{
  TimePoint due = runner_.nextDeadline();
  const TourPhase phase = runner_.progress(clock_.now()).phase;
  if (goal_ && (phase == TourPhase::DWELLING || phase == TourPhase::PAUSED))
  {
    due = std::min(due, addSeconds(clock_.now(), tour_goals::TOUR_FEEDBACK_PERIOD));
  }
  timer_.startAt(due);
}

void TourGoals::onTimer()
{
  batch_([this] { apply(runner_.tick(clock_.now())); });
}

}  // namespace ptz_action_server

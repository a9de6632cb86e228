/**
 * \file
 * \brief PanelClient's tours: the tour goals (sent, cancelled), the tour line from the tour action's goal, feedback
 * and result topics (any client's goal), and the tour services on the worker thread.
 */
#include "ptz_action_server/panel/panel_client.h"

#include <algorithm>

#include "ptz_action_server/DeleteTour.h"
#include "ptz_action_server/ListTours.h"

namespace ptz_action_server::panel
{
static_assert(PtzTourFeedback::MOVING == TOUR_MOVING && PtzTourFeedback::DWELLING == TOUR_DWELLING &&
                  PtzTourFeedback::PAUSED == TOUR_PAUSED,
              "tour_model.h's feedback states are PtzTour's");

void PanelClient::subscribeTourParts(ros::NodeHandle& node, std::uint64_t generation)
{
  subscribers_.push_back(node.subscribe<PtzTourActionGoal>(
      "move_ptz/tour/goal", 10,
      [this, generation](const PtzTourActionGoal::ConstPtr& goal) { onTourGoal(generation, goal); }));
  subscribers_.push_back(node.subscribe<PtzTourActionFeedback>(
      "move_ptz/tour/feedback", 10,
      [this, generation](const PtzTourActionFeedback::ConstPtr& feedback) { onTourFeedback(generation, feedback); }));
  subscribers_.push_back(node.subscribe<PtzTourActionResult>(
      "move_ptz/tour/result", 10,
      [this, generation](const PtzTourActionResult::ConstPtr& result) { onTourResult(generation, result); }));
  tour_client_ = std::make_unique<TourClient>(node, "move_ptz/tour", false);
}

void PanelClient::onTourGoal(std::uint64_t generation, const PtzTourActionGoal::ConstPtr& goal)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation == generation_)
  {
    tour_goals_.goal(goal->goal_id.id, goal->goal.name, goal->goal.rounds);
  }
}

void PanelClient::onTourFeedback(std::uint64_t generation, const PtzTourActionFeedback::ConstPtr& feedback)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  TourFeedback progress;
  progress.state = feedback->feedback.state;
  progress.tour = feedback->feedback.tour;
  progress.round = feedback->feedback.round;
  progress.stop = feedback->feedback.stop;
  progress.preset = feedback->feedback.preset;
  progress.time_left = feedback->feedback.time_left;
  tour_goals_.feedback(feedback->status.goal_id.id, progress);
  const bool listed = std::any_of(snapshot_.tours.begin(), snapshot_.tours.end(),
                                  [&](const TourListing& tour) { return tour.name == progress.tour; });
  if (!listed && tour_listed_for_ != progress.tour)
  {
    // Saved since the panel listed the tours (by another client): list them again, once, for its stop count.
    tour_listed_for_ = progress.tour;
    const std::string ns = ns_;
    post([this, ns, generation] { listTours(ns, generation); });
  }
}

void PanelClient::onTourResult(std::uint64_t generation, const PtzTourActionResult::ConstPtr& result)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  tour_goals_.result(result->status.goal_id.id, result->status.status, result->status.text,
                     result->result.stops_visited);
  if (result->status.status == actionlib_msgs::GoalStatus::REJECTED)
  {
    // The tour line keeps showing a tour that still runs: say the rejection here.
    snapshot_.message = "tour goal rejected: " + result->status.text;
  }
}

void PanelClient::startTour(const std::string& name, std::uint32_t rounds)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (tour_client_)
  {
    PtzTourGoal goal;
    goal.name = name;
    goal.rounds = rounds;
    tour_client_->sendGoal(goal);
    jogging_ = false;  // the tour's first move preempts the velocity goal
  }
}

void PanelClient::stopTour()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (tour_client_)
  {
    tour_client_->cancelAllGoals();
  }
}

void PanelClient::listTours(const std::string& ns, std::uint64_t generation)
{
  ListTours list;
  const std::string name = inNamespace(ns, "move_ptz/list_tours");
  if (!ros::service::call(name, list))
  {
    setMessage(generation, "no tours: " + name + " did not answer");
    return;
  }
  std::vector<TourListing> tours;
  for (const PtzNamedTour& named : list.response.tours)
  {
    TourListing tour;
    tour.name = named.name;
    for (const PtzTourStop& stop : named.stops)
    {
      tour.presets.push_back(stop.preset);
      tour.dwells.push_back(stop.dwell);
    }
    tours.push_back(std::move(tour));
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  snapshot_.tours = std::move(tours);
  ++snapshot_.tours_serial;
  if (!list.response.message.empty())
  {
    snapshot_.message = list.response.message;
  }
}

void PanelClient::refreshTours()
{
  postForCamera([this](const std::string& ns, std::uint64_t generation) {
    if (!ns.empty())
    {
      listTours(ns, generation);
    }
  });
}

void PanelClient::deleteTour(const std::string& name)
{
  postForCamera([this, name](const std::string& ns, std::uint64_t generation) {
    DeleteTour call;
    call.request.name = name;
    const std::string service = inNamespace(ns, "move_ptz/delete_tour");
    setMessage(generation, ros::service::call(service, call) ? call.response.message : service + " did not answer");
    listTours(ns, generation);
  });
}

}  // namespace ptz_action_server::panel

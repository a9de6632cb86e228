#include "ptz_action_server/panel/tour_model.h"

#include <algorithm>
#include <cstdio>

#include "ptz_action_server/panel/panel_model.h"

namespace ptz_action_server::panel
{
namespace
{
/// actionlib_msgs/GoalStatus.
constexpr std::uint8_t PREEMPTED = 2;
constexpr std::uint8_t SUCCEEDED = 3;
constexpr std::uint8_t ABORTED = 4;
/// Goals the watch keeps: the running one and the few before it are all the line needs.
constexpr std::size_t MAX_GOALS = 8;

std::string seconds(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f s", value);
  return text;
}

std::string count(std::size_t n, const char* one, const char* many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
}  // namespace

std::string tourListText(const TourListing& tour)
{
  return tour.name + "  (" + count(tour.presets.size(), "stop", "stops") + ")";
}

std::string tourStopsText(const TourListing& tour)
{
  std::string text;
  for (std::size_t i = 0; i < tour.presets.size(); ++i)
  {
    char dwell[32];
    std::snprintf(dwell, sizeof(dwell), " %g s", i < tour.dwells.size() ? tour.dwells[i] : 0.0);
    text += (i == 0 ? "" : ", ") + tour.presets[i] + dwell;
  }
  return text;
}

std::string tourProgressText(const TourFeedback& feedback, std::size_t stops, std::uint32_t rounds)
{
  std::string text = feedback.tour + ": stop " + std::to_string(feedback.stop + 1);
  if (stops > 0)
  {
    text += " of " + std::to_string(stops);
  }
  text += " (" + feedback.preset + ")";
  switch (feedback.state)
  {
    case TOUR_MOVING:
      text += ", moving there (dwell " + seconds(feedback.time_left) + ")";
      break;
    case TOUR_DWELLING:
      text += ", " + seconds(feedback.time_left) + " left";
      break;
    case TOUR_PAUSED:
      text += feedback.time_left < 0.0 ? ", paused while another goal runs" :
                                         ", paused, resumes in " + seconds(feedback.time_left);
      break;
    default:
      break;
  }
  text += ", round " + std::to_string(feedback.round);
  if (rounds > 0)
  {
    text += " of " + std::to_string(rounds);
  }
  return text;
}

std::string tourEndText(const std::string& tour, std::uint8_t status, const std::string& text,
                        std::uint32_t stops_visited)
{
  const std::string name = goalStatusName(status);
  std::string line = (tour.empty() ? std::string("tour") : tour) + ": ";
  if (text.empty())
  {
    line += name;
  }
  else if (text.rfind(name, 0) == 0)
  {
    line += text;  // "preempted at stop 2 of 3 ..." says it already
  }
  else
  {
    line += name + ": " + text;
  }
  if (status == PREEMPTED || status == ABORTED || (status == SUCCEEDED && text.empty()))
  {
    line += " (" + count(stops_visited, "stop", "stops") + " visited)";
  }
  return line;
}

TourWatch::Goal& TourWatch::find(const std::string& id)
{
  const auto found = std::find_if(goals_.begin(), goals_.end(), [&](const Goal& goal) { return goal.id == id; });
  if (found != goals_.end())
  {
    return *found;
  }
  if (goals_.size() >= MAX_GOALS)
  {
    goals_.erase(goals_.begin());  // the first heard
  }
  Goal goal;
  goal.id = id;
  goal.heard = ++events_;
  goals_.push_back(goal);
  return goals_.back();
}

void TourWatch::goal(const std::string& id, const std::string& tour, std::uint32_t rounds)
{
  Goal& goal = find(id);
  goal.tour = tour;
  goal.rounds = rounds;
}

void TourWatch::feedback(const std::string& id, const TourFeedback& feedback)
{
  Goal& goal = find(id);
  if (goal.ended)
  {
    return;  // a feedback that crossed the result
  }
  goal.feedback = feedback;
  if (goal.tour.empty())
  {
    goal.tour = feedback.tour;
  }
}

void TourWatch::result(const std::string& id, std::uint8_t status, const std::string& text, std::uint32_t stops_visited)
{
  Goal& goal = find(id);
  goal.ended = true;
  goal.status = status;
  goal.text = text;
  goal.stops_visited = stops_visited;
  goal.ended_at = ++events_;
}

void TourWatch::clear()
{
  goals_.clear();
}

const TourWatch::Goal* TourWatch::running() const
{
  const Goal* newest = nullptr;
  for (const Goal& goal : goals_)
  {
    if (!goal.ended && (newest == nullptr || goal.heard > newest->heard))
    {
      newest = &goal;
    }
  }
  return newest;
}

std::string TourWatch::text(const std::vector<TourListing>& tours) const
{
  if (const Goal* goal = running())
  {
    if (!goal->feedback)
    {
      return goal->tour + ": starting";
    }
    const auto listed = std::find_if(tours.begin(), tours.end(),
                                     [&](const TourListing& tour) { return tour.name == goal->feedback->tour; });
    return tourProgressText(*goal->feedback, listed == tours.end() ? 0 : listed->presets.size(),
                            goal->rounds.value_or(0));
  }
  const Goal* last = nullptr;
  for (const Goal& goal : goals_)
  {
    if (goal.ended && (last == nullptr || goal.ended_at > last->ended_at))
    {
      last = &goal;
    }
  }
  return last == nullptr ? NO_TOUR_TEXT : tourEndText(last->tour, last->status, last->text, last->stops_visited);
}

}  // namespace ptz_action_server::panel

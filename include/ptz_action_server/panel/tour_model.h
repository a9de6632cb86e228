/**
 * \file
 * \brief The panel's Tours box without Qt, rviz or ROS: the tours' list lines and the tour line, which follows any
 * client's move_ptz/tour goal from its goal, feedback and result topics (PtzPanel shows it, test_core tests it).
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ptz_action_server::panel
{
/// PtzTour's feedback states (PtzTourFeedback::MOVING, ...; panel_client_tours.cpp checks they agree).
inline constexpr std::uint8_t TOUR_MOVING = 1;
inline constexpr std::uint8_t TOUR_DWELLING = 2;
inline constexpr std::uint8_t TOUR_PAUSED = 3;
/// The tour line before any tour goal is heard of.
inline constexpr const char* NO_TOUR_TEXT = "no tour";

/// One tour as move_ptz/list_tours lists it.
struct TourListing
{
  std::string name;
  std::vector<std::string> presets;  ///< each stop's preset, in order
  std::vector<double> dwells;        ///< each stop's dwell, s
};

/// The tours list's line: "gate_round  (3 stops)".
std::string tourListText(const TourListing& tour);
/// Its stops, for the line's tooltip: "gate 10 s, yard 4 s, home 2 s".
std::string tourStopsText(const TourListing& tour);

/// A move_ptz/tour goal's feedback (PtzTour's feedback fields).
struct TourFeedback
{
  std::uint8_t state = TOUR_MOVING;  ///< TOUR_MOVING, TOUR_DWELLING or TOUR_PAUSED
  std::string tour;
  std::uint32_t round = 1;  ///< from 1
  std::uint32_t stop = 0;   ///< the stop's index, from 0
  std::string preset;
  double time_left = 0.0;  ///< s: the dwell left, until it resumes (-1: while another goal runs), the stop's dwell
};

/// A running tour's line: "gate_round: stop 2 of 3 (yard), 3.5 s left, round 1 of 2". `stops` is the tour's number
/// of stops (0: unknown, then "stop 2 (yard)"), `rounds` the goal's (0: until stopped, "round 1"; or unknown).
std::string tourProgressText(const TourFeedback& feedback, std::size_t stops, std::uint32_t rounds);
/// An ended tour goal's line: "gate_round: succeeded: visited 6 stops in 2 rounds", "gate_round: preempted: cancelled
/// at stop 1 of 2 (door) of tour 'gate_round' (1 stop visited)", "x: rejected: no tour named 'x'". `status` is
/// actionlib's GoalStatus; the count is added for a preempted or aborted goal and a success without a text.
std::string tourEndText(const std::string& tour, std::uint8_t status, const std::string& text,
                        std::uint32_t stops_visited);

/**
 * \brief Follows the node's tour goals, whoever sent them, for the tour line.
 *
 * The line shows the newest goal still running (its progress, or "starting" before its first feedback); with none
 * running, how the last goal to end ended; NO_TOUR_TEXT before any. A goal first heard through its feedback or result
 * (the panel started after it was sent) counts from then. Keeps the last few goals only.
 */
class TourWatch
{
public:
  /// A goal was sent (the action's goal topic): its id, tour and rounds.
  void goal(const std::string& id, const std::string& tour, std::uint32_t rounds);
  void feedback(const std::string& id, const TourFeedback& feedback);
  /// The goal ended (the result topic): actionlib's status, its text and the result's stops_visited.
  void result(const std::string& id, std::uint8_t status, const std::string& text, std::uint32_t stops_visited);
  /// Forget every goal (the panel switched to another camera).
  void clear();
  /// The tour line; `tours` gives the stop counts.
  std::string text(const std::vector<TourListing>& tours) const;

private:
  struct Goal
  {
    std::string id;
    std::string tour;
    std::optional<std::uint32_t> rounds;  ///< known when its goal message was heard
    std::optional<TourFeedback> feedback;
    bool ended = false;
    std::uint8_t status = 0;
    std::string text;
    std::uint32_t stops_visited = 0;
    std::uint64_t heard = 0;     ///< when first heard, in events
    std::uint64_t ended_at = 0;  ///< when it ended, in events
  };
  Goal& find(const std::string& id);
  const Goal* running() const;

  std::vector<Goal> goals_;
  std::uint64_t events_ = 0;
};

}  // namespace ptz_action_server::panel

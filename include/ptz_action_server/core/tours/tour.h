/**
 * \file
 * \brief A tour: a named, ordered list of presets, each with a dwell time and a speed; and its validation.
 */
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ptz_action_server
{
/// One stop of a tour.
struct TourStop
{
  std::string preset;  ///< the preset's name (PresetStore), home included
  double dwell = 0.0;  ///< s the device stays at the preset once it is there
  double speed = 0.0;  ///< fraction of the device's top speed in (0, 1]; 0: the node's default speed
};

/// A named tour: its stops in the order they are visited, round after round.
struct Tour
{
  std::string name;
  std::vector<TourStop> stops;
};

/// Limits a tour is checked against.
struct TourLimits
{
  static constexpr std::size_t MAX_NAME = 64;    ///< longest tour name, in characters
  static constexpr std::size_t MAX_STOPS = 100;  ///< most stops in a tour
  static constexpr std::size_t MAX_TOURS = 100;  ///< most tours in a file
  static constexpr double MAX_DWELL = 86400.0;   ///< s, a day
};

/// "" when \p name may name a tour, else why not (empty, too long, not printable ASCII, spaces around it).
std::string checkTourName(const std::string& name);

/// "" when \p tour may be saved, else why not (its name, no stops, too many, a stop without a preset, a dwell or a
/// speed out of range).
std::string checkTour(const Tour& tour);

}  // namespace ptz_action_server

/**
 * \file
 * \brief Velocity and "settled" from a stream of position reports, for devices that report positions only.
 */
#pragma once

#include <deque>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Keeps recent position reports and derives velocity and motion from them.
 *
 * The device counts as moving while its position differs from where it was at least \p settle_window ago; the
 * velocity is the change over the same span. Not thread-safe: the owner locks.
 */
class MotionEstimator
{
public:
  explicit MotionEstimator(double settle_window = 0.05, std::size_t history = 32);

  /// Adds a report of \p position measured at \p at.
  void add(TimePoint at, const AxisValues& position);
  /// Forgets every report (after a reconnect: old positions say nothing about the new device).
  void clear();

  /// Fills \p sample's stamp, position, velocity and moving from the reports (link and faults are the caller's).
  void fill(PtzSample& sample) const;

private:
  struct Report
  {
    TimePoint at;
    AxisValues position;
  };

  double settle_window_;
  std::size_t history_;
  std::deque<Report> reports_;  ///< newest last
};

}  // namespace ptz_action_server

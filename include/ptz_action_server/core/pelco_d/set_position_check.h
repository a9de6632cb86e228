/**
 * \file
 * \brief Tells a Pelco-D camera that ignores set-position (0x4B, 0x4D, 0x4F) from one on its way there.
 */
#pragma once

#include <array>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
namespace pelco
{
/**
 * \brief Watches one position goal sent as set-position: did the camera move?
 *
 * Many conference cameras answer the position queries but take no set-position, and Pelco-D has no error reply:
 * they ignore it without a word. After a set-position the camera must move (any axis by more than `moved`) within
 * `wait` (and `rounds` poll rounds). If it has not, a speed command toward the target (the probe) tells a camera that
 * ignores set-position (it moves at a speed) from one that cannot move at all (it does not either: the goal is left to
 * stall, as on any device). Once a set-position has moved the camera, it takes them: nothing is checked again.
 *
 * Not thread-safe: the protocol's I/O thread owns it.
 */
class SetPositionCheck
{
public:
  struct Config
  {
    double wait = 0.5;  ///< s a set-position has to show movement, and the probe after it
    /// Whole poll rounds each phase waits for as well: on a starved machine, time passes with no fresh position.
    unsigned rounds = 3;
    AxisValues moved{ { 0.00175, 0.00175, 0.2 } };  ///< how far an axis must go to count as moved (rad, rad, X)
  };

  /// What update() found.
  enum class Step
  {
    NONE,      ///< nothing to do (no check under way, or still waiting)
    HONOURED,  ///< the camera moved on the set-position: it takes them
    PROBE,     ///< it has not moved: send the probe, a speed command toward the target (directions())
    IGNORED,   ///< the probe moved it: the camera ignores set-position (stop it)
    STUCK,     ///< the probe did not move it either: nothing told (stop it)
  };

  explicit SetPositionCheck(const Config& config) : config_(config)
  {
  }

  /// A set-position to \p target (NaN: axis left alone) went out at \p at, the camera at rest at \p from. False (and
  /// nothing watched) when no axis has far enough to go for its movement to tell anything, or the camera already
  /// showed that it takes set-position.
  bool begin(const AxisValues& from, const AxisValues& target, TimePoint at);
  /// Another command replaced the goal, or the link went down.
  void cancel()
  {
    phase_ = Phase::IDLE;
  }
  bool probing() const
  {
    return phase_ == Phase::PROBING;
  }
  /// The camera's position from a whole poll round, at \p now.
  Step update(const AxisValues& position, TimePoint now);
  /// The probe's direction on each axis toward the target: -1, 0 (no need to move) or +1.
  const std::array<int, AXIS_COUNT>& directions() const
  {
    return directions_;
  }

private:
  enum class Phase
  {
    IDLE,
    WATCHING,  ///< the set-position went out: waiting for the camera to move
    PROBING,   ///< it did not: the probe went out
  };

  bool movedFrom(const AxisValues& from, const AxisValues& position) const;

  const Config config_;
  Phase phase_ = Phase::IDLE;
  bool honoured_ = false;  ///< a set-position moved the camera once
  AxisValues from_{};      ///< where the camera was when the phase began
  TimePoint since_{};      ///< when the phase began
  unsigned rounds_ = 0;    ///< whole poll rounds since the phase began
  std::array<int, AXIS_COUNT> directions_{};
};

}  // namespace pelco
}  // namespace ptz_action_server

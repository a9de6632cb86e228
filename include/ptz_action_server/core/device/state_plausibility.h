/**
 * \file
 * \brief Judges each state a device reports before the node believes it: no NaN, nothing outside the device's own
 * limits, no jump faster than its top speed.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Tells an impossible state from a possible one, axis by axis (only axes the device has and reports).
 *
 * - NaN or infinite: impossible.
 * - Outside the device's range by more than a margin (2 % of the range, at least 0.02): impossible; a device at its
 *   stop may read a little past it.
 * - Pan or tilt further from the last believed state than twice the top speed allows over the time between them
 *   plus JUMP_SLACK (reports can arrive bunched): a jump, impossible. Zoom has no jump check: devices give no
 *   trustworthy zoom speed. A pan range of a full turn or more is compared the short way round.
 * - After a jump, the reports that go on smoothly from the jumped place stay impossible (with the jump's reason),
 *   even once they come within reach of the last believed state: only a report that jumps back, to a place possible
 *   from the last believed one, is believed. A glitch is one or a few dropped reports; a device that goes on
 *   reporting the new place is dropped until its owner gives up on it (DeviceSession: a loss after state_timeout,
 *   then forget(), and the device is believed from its next report on: it may have been moved by hand, or re-homed).
 *
 * Not thread-safe: the owner serialises calls.
 */
class StatePlausibility
{
public:
  static constexpr double JUMP_SLACK = 0.1;         ///< s added to the time between two reports
  static constexpr double JUMP_SPEED_FACTOR = 2.0;  ///< how much faster than its top speed a device may seem
  static constexpr double RANGE_MARGIN_SHARE = 0.02;
  static constexpr double MIN_MARGIN = 0.02;  ///< rad (or X) past the range a position may read

  /// "" if \p position, reported at \p at, is possible for a device with \p capabilities (and becomes the reference);
  /// otherwise why not ("pan is NaN", "tilt 2.10 rad is outside the device's limits [-1.57, 0.52]", "pan jumped
  /// 2.50 rad in 0.05 s: faster than its top speed of 1.00 rad/s").
  std::string judge(const AxisValues& position, TimePoint at, const Capabilities& capabilities);
  /// The next report is judged without a reference for jumps.
  void forget()
  {
    has_reference_ = false;
    jump_reason_.clear();
  }

private:
  /// Why \p position at \p at cannot follow \p from at \p from_at, or "".
  static std::string findJump(const AxisValues& from, TimePoint from_at, const AxisValues& position, TimePoint at,
                              const Capabilities& capabilities);

  bool has_reference_ = false;
  AxisValues reference_{};  ///< the last believed state
  TimePoint reference_at_{};
  std::string jump_reason_;  ///< "" or the jump the reports since reference_ made: they are in doubt
  AxisValues previous_{};    ///< the last finite report in doubt
  TimePoint previous_at_{};
};

}  // namespace ptz_action_server

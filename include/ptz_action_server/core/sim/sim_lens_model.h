/**
 * \file
 * \brief The simulated lens: focus and iris, each moving at a speed, to a position or by itself (auto).
 */
#pragma once

#include <array>

#include "ptz_action_server/core/lens.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// One simulated lens function, in shares 0..1 of its range.
struct SimLensAxisConfig
{
  bool present = true;
  double travel_time = 2.0;  ///< s from one end to the other at the top speed
  double auto_value = 0.5;   ///< where it settles by itself in auto (the subject's focus, the scene's exposure)
  double initial = 0.5;
  bool initial_auto = true;
};

/// The simulated lens. The sim backend and the emulators (VISCA, Pelco-D, Axis, ONVIF) move this same model.
struct SimLensConfig
{
  SimLensAxisConfig focus{ true, 2.0, 0.7, 0.5, true };
  SimLensAxisConfig iris{ true, 1.0, 0.4, 0.5, true };

  const SimLensAxisConfig& of(LensFunction function) const
  {
    return function == LensFunction::FOCUS ? focus : iris;
  }
};

/// What a device with this lens can do: every command, with feedback; absent functions say so.
LensCapabilities simLensCapabilities(const SimLensConfig& config);

/**
 * \brief Motion of a lens' focus and iris: linear at their top speed (lenses start and stop at once next to a
 * pan-tilt head), within 0..1. In auto each goes to its auto value by itself; a one-push focus does so once and stays
 * manual. Whether a command is allowed in a mode is the emulator's to say (a VISCA camera refuses a manual focus in
 * auto focus): the model does what it is told.
 *
 * Not thread-safe (the owner holds a mutex); time is passed in and must not go back.
 */
class SimLensModel
{
public:
  explicit SimLensModel(const SimLensConfig& config = SimLensConfig(), TimePoint now = TimePoint());

  bool present(LensFunction function) const
  {
    return config_.of(function).present;
  }
  void setAuto(LensFunction function, bool automatic, TimePoint now);
  bool isAuto(LensFunction function) const
  {
    return axis(function).automatic;
  }
  /// Drives at \p share (-1..1) of the top speed until an end, a stop (0) or another command.
  void drive(LensFunction function, double share, TimePoint now);
  /// Goes to \p position (clamped to 0..1) at the top speed.
  void goTo(LensFunction function, double position, TimePoint now);
  /// Focusses once by itself: to the auto value, staying manual.
  void onePush(TimePoint now);
  double position(LensFunction function, TimePoint now) const;
  bool moving(LensFunction function, TimePoint now) const;
  /// The drive share last commanded (0 when going to a position or at rest), for tests.
  double driveShare(LensFunction function) const
  {
    return axis(function).share;
  }

  const SimLensConfig& config() const
  {
    return config_;
  }

private:
  struct Motion
  {
    double from = 0.5;      ///< the position at since
    TimePoint since{};      ///< when the current motion began
    double share = 0.0;     ///< a drive's share of the top speed (0: going to target)
    double target = 0.5;    ///< where it goes when not driven
    bool automatic = true;  ///< auto: target is the auto value
  };
  Motion& axis(LensFunction function)
  {
    return axes_[static_cast<std::size_t>(function)];
  }
  const Motion& axis(LensFunction function) const
  {
    return axes_[static_cast<std::size_t>(function)];
  }
  /// Starts a new motion from where \p function is at \p now.
  void restart(LensFunction function, TimePoint now);

  SimLensConfig config_;
  std::array<Motion, LENS_FUNCTION_COUNT> axes_;
};

/// \p model's modes and positions at \p now, as a backend reports them (the functions it lacks: unknown, NaN).
LensState lensStateOf(const SimLensModel& model, TimePoint now);

}  // namespace ptz_action_server

/**
 * \file
 * \brief Focus and iris: what a device's lens can do, the commands for it and its state, as plain types.
 *
 * Positions are shares of the device's own range, so that one client drives every camera alike: focus 0 is the near
 * end and 1 the far end (infinity), iris 0 the most closed the device goes and 1 fully open. Velocities are shares of
 * the device's top lens speed, in -1..1: negative focusses nearer (closes the iris), positive farther (opens it).
 */
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace ptz_action_server
{
/// The two functions of a lens this package drives.
enum class LensFunction : std::uint8_t
{
  FOCUS = 0,
  IRIS = 1,
};
constexpr std::size_t LENS_FUNCTION_COUNT = 2;
constexpr std::array<LensFunction, LENS_FUNCTION_COUNT> ALL_LENS_FUNCTIONS = { LensFunction::FOCUS,
                                                                               LensFunction::IRIS };
/// "focus" / "iris".
const char* lensFunctionName(LensFunction function);

/// Whether focus (iris) runs by itself or as commanded. The values are LensState.msg's.
enum class LensMode : std::uint8_t
{
  UNKNOWN = 0,  ///< the device does not say (and was not told since it started)
  AUTO = 1,
  MANUAL = 2,
};
/// "unknown" / "auto" / "manual".
const char* lensModeName(LensMode mode);

/// What a device can do with its focus or its iris, as its backend found out.
struct LensControl
{
  bool present = false;    ///< the device has it and its backend drives it
  bool auto_mode = false;  ///< switches between automatic and manual (focus/set_auto, iris/set_auto)
  bool velocity = false;   ///< drives at a speed until stopped (focus near/far, iris close/open)
  bool absolute = false;   ///< goes to a position, a share 0..1 of its range
  bool feedback = false;   ///< reports its position (otherwise lens_state carries NaN)
  bool one_push = false;   ///< focus only: focusses once by itself and stays manual (focus/one_push)
  /// Why something is missing, in the device's terms ("Pelco-D has no iris position"); "" for the plain words.
  std::string limitation;
};

/// Focus and iris of a device: a part of Capabilities. The default is a device without either.
struct LensCapabilities
{
  LensControl focus;
  LensControl iris;

  const LensControl& of(LensFunction function) const
  {
    return function == LensFunction::FOCUS ? focus : iris;
  }
  LensControl& of(LensFunction function)
  {
    return function == LensFunction::FOCUS ? focus : iris;
  }
};

/// One lens command (PtzBackend::lens()).
struct LensCommand
{
  enum class Kind : std::uint8_t
  {
    MODE,      ///< value 1: automatic, 0: manual
    ONE_PUSH,  ///< focus once by itself (value unused)
    VELOCITY,  ///< value -1..1 of the top speed; 0 stops
    POSITION,  ///< value 0..1 of the range
  };
  LensFunction function = LensFunction::FOCUS;
  Kind kind = Kind::VELOCITY;
  double value = 0.0;

  static LensCommand mode(LensFunction function, bool automatic)
  {
    return { function, Kind::MODE, automatic ? 1.0 : 0.0 };
  }
  static LensCommand onePush()
  {
    return { LensFunction::FOCUS, Kind::ONE_PUSH, 0.0 };
  }
  static LensCommand velocity(LensFunction function, double share)
  {
    return { function, Kind::VELOCITY, share };
  }
  static LensCommand position(LensFunction function, double share)
  {
    return { function, Kind::POSITION, share };
  }
  bool automatic() const
  {
    return value > 0.5;
  }
};
/// "focus velocity -0.5", "iris auto", "focus one-push", for logs and tests.
std::string describe(const LensCommand& command);

/// The lens as its backend last knew it. Small and copyable without allocation: the node reads it every tick.
struct LensState
{
  std::array<LensMode, LENS_FUNCTION_COUNT> mode{ { LensMode::UNKNOWN, LensMode::UNKNOWN } };
  /// 0..1 of the range (see the file's comment); NaN: not reported (yet)
  std::array<double, LENS_FUNCTION_COUNT> position{ { std::numeric_limits<double>::quiet_NaN(),
                                                      std::numeric_limits<double>::quiet_NaN() } };
  std::uint64_t fault_count = 0;  ///< lens commands the device refused or could not take

  LensMode modeOf(LensFunction function) const
  {
    return mode[static_cast<std::size_t>(function)];
  }
  double positionOf(LensFunction function) const
  {
    return position[static_cast<std::size_t>(function)];
  }
};

/**
 * \brief Why \p command cannot go to a device with \p lens ("" if it can): a function or a kind the device lacks
 * (with its limitation), a NaN, a velocity outside -1..1, a position outside 0..1. \p backend names the device.
 */
std::string checkLensCommand(const LensCapabilities& lens, const LensCommand& command, const std::string& backend);

/// What \p function of \p lens can do, in a few words: "auto/manual, velocity, position, feedback, one-push", or
/// "none (the 'flir' backend drives no focus)".
std::string describeLens(const LensCapabilities& lens, LensFunction function, const std::string& backend);

/**
 * \brief The lens state a backend keeps for the node: written on the backend's thread, read from any.
 *
 * The protocol (or the simulated device) sets what it learns; a refused command is a lens fault, counted apart from
 * the device's PtzSample::fault_count so that a refused focus command never ends a pan goal.
 */
class LensReport
{
public:
  void setMode(LensFunction function, LensMode mode);
  void setPosition(LensFunction function, double position);
  /// A lens command failed: counted, and \p text kept as the last lens fault.
  void fault(const std::string& text);
  LensState state() const;
  std::string lastFault() const;

private:
  mutable std::mutex mutex_;
  LensState state_;
  std::string last_fault_;
};

/// Appends the lens' state and faults to a backend's diagnostics, for the functions \p lens has.
void lensDiagnostics(const LensCapabilities& lens, const LensState& state, const std::string& last_fault,
                     std::vector<std::pair<std::string, std::string>>& values);

}  // namespace ptz_action_server

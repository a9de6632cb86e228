/**
 * \file
 * \brief Keyboard teleoperation without ROS: a terminal's bytes decoded into keys, and the keys played as a joystick
 * for the TeleopController (so keys and gamepads share one set of rules).
 */
#pragma once

#include <string>
#include <vector>

#include "ptz_action_server/core/teleop/teleop.h"

namespace ptz_action_server
{
/// A key of `ptz_move teleop`.
enum class TeleopKey
{
  LEFT,
  RIGHT,
  UP,
  DOWN,
  ZOOM_IN,   ///< + (or =, the same key without shift)
  ZOOM_OUT,  ///< - (or _)
  HOME,      ///< h
  PRESET,    ///< 1..9
  STOP,      ///< space
  QUIT,      ///< q
};

struct KeyPress
{
  TeleopKey key = TeleopKey::STOP;
  int preset = -1;  ///< 0 for '1', ... 8 for '9'
};

/// Decodes a terminal's bytes (arrows as ESC [ A..D or ESC O A..D) into keys; a sequence may span reads.
class KeyDecoder
{
public:
  /// The keys completed by \p bytes; other bytes are dropped.
  std::vector<KeyPress> feed(const std::string& bytes);

private:
  std::string pending_;  ///< an escape sequence begun but not finished
};

/// Speeds and timing of the keyboard teleop.
struct KeyboardTeleopConfig
{
  double pan_speed = 0.5;    ///< rad/s while an arrow is held
  double tilt_speed = 0.5;   ///< rad/s
  double zoom_speed = 2.0;   ///< X/s while + or - is held
  double key_timeout = 0.7;  ///< s: a key counts as held until this long after its last repeat (terminals repeat a
                             ///< held key after 250 to 660 ms, then 25 to 33 times a second; none send a release)
};

/**
 * \brief The keys as a joystick: the dead-man is held all the time (space releases it for one frame: a stop), the
 * arrows and +/- deflect an axis fully while held, h and the digits press a button for one frame.
 *
 * A terminal sends no key releases: a moving key is held until key_timeout after it was last seen, and the last
 * moving key replaces the one before (terminals repeat only the last key).
 */
class KeyboardTeleop
{
public:
  explicit KeyboardTeleop(const KeyboardTeleopConfig& config);

  /// The joystick mapping the keys play on, for the TeleopController.
  TeleopConfig teleopConfig() const;

  /// A key arrived at \p now (QUIT is the caller's: it is ignored here).
  void press(const KeyPress& press, TimePoint now);

  /// The joystick as the keys hold it at \p now; a one-frame press is reported once.
  JoyInput input(TimePoint now);

private:
  static constexpr int DEADMAN = 0;
  static constexpr int HOME = 1;
  static constexpr int FIRST_PRESET = 2;
  static constexpr int PRESETS = 9;

  KeyboardTeleopConfig config_;
  bool moving_ = false;
  TeleopKey moving_key_ = TeleopKey::STOP;
  TimePoint last_seen_{};
  int button_ = -1;  ///< pressed for the next frame only
  bool stop_ = false;
};

}  // namespace ptz_action_server

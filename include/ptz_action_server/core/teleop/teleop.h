/**
 * \file
 * \brief Joystick teleoperation without ROS: a gamepad's axes and buttons become velocity, stop and preset commands,
 * sent only when they change, never without the dead-man button, and stopped when the joystick goes quiet.
 */
#pragma once

#include <string>
#include <vector>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// One joystick axis driving one camera axis: velocity = scale * the axis's value (after the deadband).
struct TeleopAxis
{
  int axis = -1;       ///< index in Joy's axes; -1: none
  double scale = 0.0;  ///< rad/s (X/s for zoom) at full deflection; negative flips the direction
};

/// How a joystick drives the camera (the ptz_teleop node's parameters, config/teleop/*.yaml).
struct TeleopConfig
{
  int deadman_button = 4;     ///< must be held for anything to move; releasing it stops
  TeleopAxis pan{ 0, -1.0 };  ///< positive pan turns clockwise (right); the stick's left is positive
  TeleopAxis tilt{ 1, 0.7 };  ///< stick up is positive: tilt up
  TeleopAxis zoom{ 4, 4.0 };  ///< zoom on an axis (up: in), or
  int zoom_in_button = -1;    ///< zoom on two buttons, at zoom_button_speed
  int zoom_out_button = -1;
  double zoom_button_speed = 4.0;   ///< X/s
  double deadband = 0.1;            ///< |value| below it reads 0; above it the range is stretched back to 0..1
  double step = 0.05;               ///< deflections are rounded to this fraction of full scale (jitter sends nothing)
  int home_button = -1;             ///< goes to the "home" preset
  std::vector<int> preset_buttons;  ///< go to the first presets, in order
  std::vector<std::string> preset_names;  ///< by button; a missing or empty name: the list_presets order
  double stale_timeout = 0.5;             ///< s without a Joy message that stops the camera

  /// "" or what is wrong (a negative timeout, a deadband outside [0, 1), ...).
  std::string check() const;
};

/// A gamepad's axes and buttons, as sensor_msgs/Joy carries them.
struct JoyInput
{
  std::vector<float> axes;
  std::vector<int> buttons;
};

/// What the teleop asks the node to do.
struct TeleopCommand
{
  enum class Type
  {
    VELOCITY,  ///< a move_ptz/velocity goal with velocity
    STOP,      ///< cancel the goal the teleop sent last (the node decelerates the device to rest)
    PRESET,    ///< a move_ptz/preset goal: name, or if empty the preset_index-th saved preset (list_presets order)
  };
  Type type = Type::STOP;
  AxisValues velocity{};
  std::string name;
  int preset_index = -1;
};

/**
 * \brief Turns Joy messages into TeleopCommands.
 *
 * A command is produced only when what the operator asks for changes: a stick held still sends nothing more, however
 * fast the joystick publishes. Without the dead-man button nothing moves; releasing it stops what the teleop started
 * (a preset goal as well as a velocity). Sticks back at rest stop a velocity. A joystick silent for stale_timeout
 * stops the camera too (the next message is taken as it comes). Presses count on the button's rising edge.
 *
 * Not thread-safe: one thread calls everything.
 */
class TeleopController
{
public:
  explicit TeleopController(const TeleopConfig& config);

  /// Limits the velocity of each axis to \p max_speed (0: the axis cannot move at a speed).
  void setSpeedLimits(const AxisValues& max_speed);

  /// The commands for a Joy message received at \p now (none, one, or a stop then a preset).
  std::vector<TeleopCommand> onJoy(const JoyInput& input, TimePoint now);

  /// Called periodically: a STOP when the joystick has been silent for stale_timeout while something moves.
  std::vector<TeleopCommand> onTick(TimePoint now);

  /// The velocity \p input asks for with the dead-man held (deadband, step and speed limits applied).
  AxisValues velocityOf(const JoyInput& input) const;

  const TeleopConfig& config() const
  {
    return config_;
  }

private:
  enum class Active
  {
    NONE,
    VELOCITY,
    PRESET,
  };

  /// True for a button held in \p input (false if it has no such button).
  static bool held(const JoyInput& input, int button);
  /// A rising edge of \p button since the last message.
  bool pressed(const JoyInput& input, int button) const;
  double shaped(const JoyInput& input, const TeleopAxis& binding) const;
  TeleopCommand stop();

  TeleopConfig config_;
  AxisValues max_speed_;
  Active active_ = Active::NONE;
  AxisValues sent_velocity_{};
  std::vector<int> last_buttons_;
  TimePoint last_joy_{};
  bool heard_ = false;
};

}  // namespace ptz_action_server

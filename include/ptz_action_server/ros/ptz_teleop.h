/**
 * \file
 * \brief The ptz_teleop node's ROS side: Joy in, move_ptz/velocity and move_ptz/preset goals out (TeleopController
 * decides what to send).
 */
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>
#include <sensor_msgs/Joy.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/PtzPresetAction.h"
#include "ptz_action_server/core/teleop/teleop.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// Reads the teleop's private parameters (config/teleop/*.yaml): ~deadman_button, ~pan/axis, ~pan/scale,
/// ~tilt/axis, ~tilt/scale, ~zoom/axis, ~zoom/scale, ~zoom_in_button, ~zoom_out_button, ~zoom_button_speed,
/// ~deadband, ~step, ~home_button, ~preset_buttons, ~preset_names, ~stale_timeout. Throws ConfigError.
TeleopConfig loadTeleopConfig(const ParamReader& params);

/**
 * \brief Sends what a TeleopController decides to one camera: goals to move_ptz/velocity and move_ptz/preset in
 * \p node_handle's namespace (the camera's: /ptz); a stop cancels the goal it sent last, by its time (see execute()). A
 * preset without a name is the saved preset of its rank in move_ptz/list_presets (home excluded), asked for when it is
 * wanted.
 *
 * Used from one thread (the action clients' callbacks may run on another: they only update their own state).
 */
class TeleopGoals
{
public:
  explicit TeleopGoals(const ros::NodeHandle& node_handle);

  TeleopGoals(const TeleopGoals&) = delete;
  TeleopGoals& operator=(const TeleopGoals&) = delete;

  /**
   * \brief Sends \p commands in order. A velocity or preset command whose action server is not connected yet is held,
   * not sent (a goal published before its subscriber connects is lost, and a held stick sends nothing new): sendHeld()
   * sends it once the server is there; a later command replaces it, and a stop drops it.
   */
  void execute(const std::vector<TeleopCommand>& commands);
  /// Sends the command held by execute() if its action server is now connected (the teleop's 20 Hz timer calls it).
  void sendHeld();

  /// Waits up to \p timeout s for both action servers; false if one is missing.
  bool waitForServers(double timeout);
  /// Waits up to \p timeout s until the goal sent last has ended (after a stop: the node took the cancel).
  bool waitUntilDone(double timeout);

  /// What it did last, for a status line: "velocity pan -0.50 tilt 0.00 zoom 0.00", "preset home", "stop".
  const std::string& lastCommand() const
  {
    return last_command_;
  }

private:
  /// The name of the preset_index-th saved preset, or "" (logged) if there is none.
  std::string savedPreset(int preset_index) const;
  /// Sends \p command, or holds it while its action server is not connected (logged, throttled).
  void send(const TeleopCommand& command);

  enum class Sent
  {
    NONE,
    VELOCITY,
    PRESET,
  };

  ros::NodeHandle node_handle_;
  Sent sent_ = Sent::NONE;
  ros::Time sent_stamp_;  ///< the time sendGoal() of the last goal returned: its goal_id stamp is no later
  std::string last_command_;
  std::optional<TeleopCommand> held_;  ///< a velocity or preset command waiting for its action server
  actionlib::SimpleActionClient<PtzAction> velocity_client_;
  actionlib::SimpleActionClient<PtzPresetAction> preset_client_;
};

/// The speeds a TeleopController may command, from the node's latched capabilities (0: the axis takes no velocity).
AxisValues teleopSpeedLimits(const PtzCapabilities& capabilities);

/**
 * \brief Drives one camera from a joystick: subscribes to joy (sensor_msgs/Joy) in \p node_handle's namespace and
 * sends the TeleopController's commands through TeleopGoals.
 *
 * Velocities are clamped to the speeds the node's latched capabilities give; Joy messages wait until those are known.
 *
 * One thread: \p node_handle's queue runs every callback and the stale-joystick timer.
 */
class PtzTeleop
{
public:
  PtzTeleop(const ros::NodeHandle& node_handle, const TeleopConfig& config);

  PtzTeleop(const PtzTeleop&) = delete;
  PtzTeleop& operator=(const PtzTeleop&) = delete;

private:
  void onJoy(const sensor_msgs::Joy::ConstPtr& joy);
  void onCapabilities(const PtzCapabilities::ConstPtr& capabilities);

  ros::NodeHandle node_handle_;
  TeleopController controller_;
  TeleopGoals goals_;
  SystemClock clock_;
  bool ready_ = false;  ///< the capabilities are known
  ros::Subscriber joy_subscriber_;
  ros::Subscriber capabilities_subscriber_;
  ros::SteadyTimer stale_timer_;
};

}  // namespace ptz_action_server

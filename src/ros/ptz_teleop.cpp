#include "ptz_action_server/ros/ptz_teleop.h"

#include <algorithm>

#include "ptz_action_server/ListPresets.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace ptz_action_server
{
namespace
{
constexpr double MAX_SPEED_LIMIT = 100.0;  ///< rad/s, X/s: above any device

TeleopAxis loadAxis(const ParamReader& params, const std::string& name, const TeleopAxis& default_value)
{
  TeleopAxis axis;
  axis.axis = params.integer(name + "/axis", default_value.axis, -1, 255);
  axis.scale = params.number(name + "/scale", default_value.scale, -MAX_SPEED_LIMIT, MAX_SPEED_LIMIT);
  return axis;
}

template <class T>
std::vector<T> loadList(const ParamReader& params, const std::string& name, const std::vector<T>& default_value)
{
  if (!params.has(name))
  {
    return default_value;
  }
  std::vector<T> values;
  if (!params.nodeHandle().getParam(name, values))
  {
    throw ConfigError("parameter " + params.resolve(name) + " must be a list of the same type");
  }
  return values;
}
}  // namespace

TeleopConfig loadTeleopConfig(const ParamReader& params)
{
  TeleopConfig config;
  config.deadman_button = params.integer("deadman_button", config.deadman_button, 0, 255);
  config.pan = loadAxis(params, "pan", config.pan);
  config.tilt = loadAxis(params, "tilt", config.tilt);
  config.zoom = loadAxis(params, "zoom", config.zoom);
  config.zoom_in_button = params.integer("zoom_in_button", config.zoom_in_button, -1, 255);
  config.zoom_out_button = params.integer("zoom_out_button", config.zoom_out_button, -1, 255);
  config.zoom_button_speed = params.number("zoom_button_speed", config.zoom_button_speed, 0.0, MAX_SPEED_LIMIT);
  config.deadband = params.number("deadband", config.deadband, 0.0, 0.95);
  config.step = params.number("step", config.step, 0.0, 1.0);
  config.home_button = params.integer("home_button", config.home_button, -1, 255);
  config.preset_buttons = loadList(params, "preset_buttons", config.preset_buttons);
  config.preset_names = loadList(params, "preset_names", config.preset_names);
  config.stale_timeout = params.number("stale_timeout", config.stale_timeout, 0.01, 60.0);
  const std::string problem = config.check();
  if (!problem.empty())
  {
    throw ConfigError("teleop parameters under " + params.resolve("") + ": " + problem);
  }
  return config;
}

TeleopGoals::TeleopGoals(const ros::NodeHandle& node_handle)
  : node_handle_(node_handle)
  , velocity_client_(node_handle_, "move_ptz/velocity", false)
  , preset_client_(node_handle_, "move_ptz/preset", false)
{
}

void TeleopGoals::execute(const std::vector<TeleopCommand>& commands)
{
  for (const TeleopCommand& command : commands)
  {
    if (command.type != TeleopCommand::Type::STOP)
    {
      send(command);
      continue;
    }
    held_.reset();
    // A stop often comes a millisecond after its goal, before the node's first status of it: cancelGoal() would put
    // the handle where a status list sent before the goal reached the node reads as "goal LOST" (and its result then
    // comes to a handle already DONE). A cancel by time leaves the handle waiting for its first status, and cancels
    // the same goal (and only older ones, which it preempted).
    if (sent_ == Sent::VELOCITY && !velocity_client_.getState().isDone())
    {
      velocity_client_.cancelGoalsAtAndBeforeTime(sent_stamp_);
    }
    else if (sent_ == Sent::PRESET && !preset_client_.getState().isDone())
    {
      preset_client_.cancelGoalsAtAndBeforeTime(sent_stamp_);
    }
    sent_ = Sent::NONE;
    last_command_ = "stop";
  }
}

void TeleopGoals::sendHeld()
{
  if (held_)
  {
    const TeleopCommand command = *held_;
    send(command);
  }
}

void TeleopGoals::send(const TeleopCommand& command)
{
  const bool velocity = command.type == TeleopCommand::Type::VELOCITY;
  if (!(velocity ? velocity_client_.isServerConnected() : preset_client_.isServerConnected()))
  {
    held_ = command;
    ROS_WARN_THROTTLE(5.0, "ptz teleop: %s is not connected yet: the command waits for it",
                      node_handle_.resolveName(velocity ? "move_ptz/velocity" : "move_ptz/preset").c_str());
    return;
  }
  held_.reset();
  if (velocity)
  {
    velocity_client_.sendGoal(makePtzGoal(command.velocity[PAN], command.velocity[TILT], command.velocity[ZOOM]));
    sent_stamp_ = ros::Time::now();
    sent_ = Sent::VELOCITY;
    last_command_ = formatText("velocity pan %+.2f tilt %+.2f zoom %+.2f", command.velocity[PAN],
                               command.velocity[TILT], command.velocity[ZOOM]);
    return;
  }
  PtzPresetGoal goal;
  goal.name = command.name.empty() ? savedPreset(command.preset_index) : command.name;
  if (goal.name.empty())
  {
    last_command_ = formatText("no saved preset %d", command.preset_index + 1);
    return;
  }
  preset_client_.sendGoal(goal);
  sent_stamp_ = ros::Time::now();
  sent_ = Sent::PRESET;
  last_command_ = "preset " + goal.name;
}

bool TeleopGoals::waitForServers(double timeout)
{
  return velocity_client_.waitForServer(ros::Duration(timeout)) && preset_client_.waitForServer(ros::Duration(timeout));
}

bool TeleopGoals::waitUntilDone(double timeout)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  const auto done = [this] { return velocity_client_.getState().isDone() && preset_client_.getState().isDone(); };
  while (!done() && ros::WallTime::now() < deadline)
  {
    ros::WallDuration(0.01).sleep();
  }
  return done();
}

std::string TeleopGoals::savedPreset(int preset_index) const
{
  ListPresets service;
  const std::string name = node_handle_.resolveName("move_ptz/list_presets");
  if (!ros::service::call(name, service))
  {
    ROS_WARN("ptz teleop: %s did not answer: preset %d does nothing", name.c_str(), preset_index + 1);
    return {};
  }
  std::vector<std::string> saved;
  std::copy_if(service.response.names.begin(), service.response.names.end(), std::back_inserter(saved),
               [](const std::string& preset) { return preset != "home"; });
  if (preset_index < 0 || static_cast<std::size_t>(preset_index) >= saved.size())
  {
    ROS_WARN("ptz teleop: preset %d: only %zu presets are saved", preset_index + 1, saved.size());
    return {};
  }
  return saved[preset_index];
}

AxisValues teleopSpeedLimits(const PtzCapabilities& capabilities)
{
  const auto speed = [](const PtzAxisCapability& axis) { return axis.present && axis.velocity ? axis.max_speed : 0.0; };
  return { { speed(capabilities.pan), speed(capabilities.tilt), speed(capabilities.zoom) } };
}

PtzTeleop::PtzTeleop(const ros::NodeHandle& node_handle, const TeleopConfig& config)
  : node_handle_(node_handle), controller_(config), goals_(node_handle_)
{
  capabilities_subscriber_ = node_handle_.subscribe("capabilities", 1, &PtzTeleop::onCapabilities, this);
  // Joy drivers publish at their own rate (or only on changes): the tcp_nodelay keeps a button's latency low.
  joy_subscriber_ = node_handle_.subscribe("joy", 10, &PtzTeleop::onJoy, this, ros::TransportHints().tcpNoDelay());
  const double period = std::min(0.05, config.stale_timeout / 5.0);
  stale_timer_ = node_handle_.createSteadyTimer(ros::WallDuration(period), [this](const ros::SteadyTimerEvent&) {
    goals_.execute(controller_.onTick(clock_.now()));
    goals_.sendHeld();
  });
}

void PtzTeleop::onCapabilities(const PtzCapabilities::ConstPtr& capabilities)
{
  controller_.setSpeedLimits(teleopSpeedLimits(*capabilities));
  if (!ready_)
  {
    ROS_INFO("ptz_teleop: driving %s (backend %s)", node_handle_.getNamespace().c_str(), capabilities->backend.c_str());
  }
  ready_ = true;
}

void PtzTeleop::onJoy(const sensor_msgs::Joy::ConstPtr& joy)
{
  if (!ready_)
  {
    ROS_WARN_THROTTLE(5.0, "ptz_teleop: no capabilities from %s yet: the joystick is ignored",
                      node_handle_.resolveName("capabilities").c_str());
    return;
  }
  JoyInput input;
  input.axes = joy->axes;
  input.buttons = joy->buttons;
  goals_.execute(controller_.onJoy(input, clock_.now()));
}

}  // namespace ptz_action_server

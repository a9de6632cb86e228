#include "ptz_action_server/ros/preset_services.h"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// $ROS_HOME, else ~/.ros, as ROS itself places its logs.
std::string rosHome()
{
  if (const char* ros_home = std::getenv("ROS_HOME"); ros_home && *ros_home)
  {
    return ros_home;
  }
  const char* home = std::getenv("HOME");
  return std::string(home && *home ? home : ".") + "/.ros";
}

/// "/ptz/ptz_action_server" -> "ptz_ptz_action_server": one file per node, whatever its namespace.
std::string fileNameOf(const std::string& node_name)
{
  std::string name = node_name;
  while (!name.empty() && name.front() == '/')
  {
    name.erase(0, 1);
  }
  for (char& character : name)
  {
    character = character == '/' ? '_' : character;
  }
  return name.empty() ? "ptz_action_server" : name;
}

std::string describe(const std::string& name, const AxisValues& pose)
{
  return formatText("'%s': pan %.4f rad, tilt %.4f rad, zoom %.2f X", name.c_str(), pose[PAN], pose[TILT], pose[ZOOM]);
}
}  // namespace

PresetConfig PresetConfig::load(const ParamReader& params)
{
  PresetConfig config;
  const std::string default_file =
      rosHome() + "/ptz_action_server/" + fileNameOf(params.nodeHandle().getNamespace()) + "_presets.yaml";
  config.file = params.text("presets_file", default_file);
  if (config.file.empty())
  {
    throw ConfigError("parameter " + params.resolve("presets_file") + " is empty: give a file path or leave it unset");
  }
  config.home[PAN] = params.number("home/pan", config.home[PAN], -2.0 * M_PI, 2.0 * M_PI);
  config.home[TILT] = params.number("home/tilt", config.home[TILT], -M_PI, M_PI);
  config.home_zoom_set = params.has("home/zoom");
  config.home[ZOOM] = params.number("home/zoom", config.home[ZOOM], 0.0, 1000.0);
  return config;
}

PresetServices::PresetServices(const ros::NodeHandle& node_handle, const PresetConfig& config,
                               const Capabilities& limits, std::shared_ptr<PtzBackend> backend)
  : queue_(SharedCallbackQueue::shared())
  , node_handle_(node_handle)
  , backend_(std::move(backend))
  , has_zoom_(limits.axes[ZOOM].present && limits.axes[ZOOM].absolute && limits.axes[ZOOM].feedback)
  , unpositioned_zoom_(limits.axes[ZOOM].present ? 0.0 : 1.0)
{
  node_handle_.setCallbackQueue(queue_->queue());
  AxisValues home = config.home;
  if (!config.home_zoom_set)
  {
    home[ZOOM] = has_zoom_ ? limits.axes[ZOOM].range.min : unpositioned_zoom_;
  }
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = limits.axes[axis];
    if (capability.present && capability.absolute && capability.feedback && !capability.range.contains(home[axis]))
    {
      ROS_WARN("home %s %.4f is outside the limits [%.4f, %.4f]: goals to home are rejected (or clamped with "
               "clamp_goals)",
               axisName(axis), home[axis], capability.range.min, capability.range.max);
    }
  }
  store_ = std::make_unique<PresetStore>(config.file, home);
  const std::string error = store_->load();
  if (error.empty())
  {
    ROS_INFO("%zu presets from %s (and home)", store_->list().size() - 1, config.file.c_str());
  }
  else
  {
    ROS_ERROR("%s. Only 'home' is available, and saving and deleting presets are refused so the file is kept as it "
              "is: fix or move it and restart the node.",
              error.c_str());
  }
  save_service_ = node_handle_.advertiseService("move_ptz/save_preset", &PresetServices::save, this);
  delete_service_ = node_handle_.advertiseService("move_ptz/delete_preset", &PresetServices::remove, this);
  list_service_ = node_handle_.advertiseService("move_ptz/list_presets", &PresetServices::list, this);
  speed_service_ = node_handle_.advertiseService("move_ptz/set_preset_speed", &PresetServices::setSpeed, this);
}

PresetServices::~PresetServices()
{
  save_service_.shutdown();
  delete_service_.shutdown();
  list_service_.shutdown();
  speed_service_.shutdown();
}

// Saves and deletes write and fsync a small file before answering, so that a success means the preset survives a
// power loss. That blocks only the shared service queue's thread, never the goals or the state tick.
bool PresetServices::save(SavePreset::Request& request, SavePreset::Response& response)
{
  const PtzSample sample = backend_->sample();
  AxisValues pose = sample.position;
  if (!has_zoom_)
  {
    pose[ZOOM] = unpositioned_zoom_;  // a zoom the node cannot position: the preset leaves it alone
  }
  if (!sample.link_up)
  {
    response.message = "the link to the device is down, so its pose is unknown: nothing saved";
  }
  else
  {
    response.message = store_->save(request.name, pose);
  }
  response.success = response.message.empty();
  if (response.success)
  {
    response.message = "saved " + describe(request.name, pose);
    ROS_INFO("preset %s", response.message.c_str());
  }
  else
  {
    ROS_WARN("preset '%s' not saved: %s", request.name.c_str(), response.message.c_str());
  }
  return true;
}

bool PresetServices::remove(DeletePreset::Request& request, DeletePreset::Response& response)
{
  response.message = store_->remove(request.name);
  response.success = response.message.empty();
  if (response.success)
  {
    response.message = "deleted '" + request.name + "'";
    ROS_INFO("preset %s", response.message.c_str());
  }
  else
  {
    ROS_WARN("preset '%s' not deleted: %s", request.name.c_str(), response.message.c_str());
  }
  return true;
}

bool PresetServices::setSpeed(SetPresetSpeed::Request& request, SetPresetSpeed::Response& response)
{
  response.message = store_->setSpeed(request.name, request.speed);
  response.success = response.message.empty();
  if (response.success)
  {
    response.message = request.speed > 0.0F ? formatText("'%s' runs at speed %g", request.name.c_str(), request.speed) :
                                              "'" + request.name + "' runs at the default speed";
    ROS_INFO("preset %s", response.message.c_str());
  }
  else
  {
    ROS_WARN("preset '%s' speed not set: %s", request.name.c_str(), response.message.c_str());
  }
  return true;
}

bool PresetServices::list(ListPresets::Request&, ListPresets::Response& response)
{
  for (const NamedPose& preset : store_->list())
  {
    response.names.push_back(preset.first);
    response.pan.push_back(preset.second[PAN]);
    response.tilt.push_back(preset.second[TILT]);
    response.zoom.push_back(preset.second[ZOOM]);
  }
  response.message = store_->loadError();
  return true;
}

}  // namespace ptz_action_server

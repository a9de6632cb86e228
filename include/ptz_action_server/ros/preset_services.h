/**
 * \file
 * \brief The preset services (save, delete, list) around the node's PresetStore, on a queue of their own.
 */
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <ros/ros.h>

#include "ptz_action_server/DeletePreset.h"
#include "ptz_action_server/ListPresets.h"
#include "ptz_action_server/SavePreset.h"
#include "ptz_action_server/SetPresetSpeed.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/presets/preset_store.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/ros/shared_callback_queue.h"

namespace ptz_action_server
{
/// Where presets are kept and where home is.
struct PresetConfig
{
  std::string file;                      ///< the presets YAML file
  AxisValues home{ { 0.0, 0.0, 1.0 } };  ///< pan, tilt (rad), zoom (X)
  bool home_zoom_set = false;            ///< false: home's zoom is the zoom axis's lowest value (1.0 without zoom)

  /// Reads ~presets_file (default $ROS_HOME/ptz_action_server/<node name>_presets.yaml, ROS_HOME defaulting to
  /// ~/.ros, the node name's slashes as underscores), ~home/pan, ~home/tilt, ~home/zoom.
  static PresetConfig load(const ParamReader& params);
};

/**
 * \brief The presets of the node: move_ptz/save_preset, move_ptz/delete_preset and move_ptz/list_presets, and the
 * lookup the preset action converts its goals with.
 *
 * The services run on the process's SharedCallbackQueue (one thread for every camera), so the file write and fsync
 * of a save never hold up goals or the state tick; the store is thread-safe for the lookups from the goal queue.
 */
class PresetServices
{
public:
  /// Loads the presets file (an unreadable one is reported and kept: see PresetStore) and advertises the services
  /// in \p node_handle's namespace. \p limits tell home's default zoom and whether the device has a zoom at all.
  PresetServices(const ros::NodeHandle& node_handle, const PresetConfig& config, const Capabilities& limits,
                 std::shared_ptr<PtzBackend> backend);
  /// Shuts the services down: once it returns, no service callback of this node runs any more.
  ~PresetServices();

  PresetServices(const PresetServices&) = delete;
  PresetServices& operator=(const PresetServices&) = delete;

  /// The pose of preset \p name, home included.
  std::optional<AxisValues> find(const std::string& name) const
  {
    return store_->find(name);
  }
  /// The speed of a goal to preset \p name (PresetStore::speed(): 0 for the default speed).
  double speed(const std::string& name) const
  {
    return store_->speed(name);
  }

private:
  bool save(SavePreset::Request& request, SavePreset::Response& response);
  bool remove(DeletePreset::Request& request, DeletePreset::Response& response);
  bool list(ListPresets::Request& request, ListPresets::Response& response);
  bool setSpeed(SetPresetSpeed::Request& request, SetPresetSpeed::Response& response);

  std::shared_ptr<SharedCallbackQueue> queue_;  ///< declared first: everything below registers on it
  ros::NodeHandle node_handle_;                 ///< the node's namespace, on queue_
  std::shared_ptr<PtzBackend> backend_;
  bool has_zoom_;
  /// The zoom a preset holds on a device whose zoom takes no position goals: 1 without zoom (what it reports), 0 (left
  /// alone) for a zoom the node cannot position or see.
  double unpositioned_zoom_;
  std::unique_ptr<PresetStore> store_;
  ros::ServiceServer save_service_;
  ros::ServiceServer delete_service_;
  ros::ServiceServer list_service_;
  ros::ServiceServer speed_service_;
};

}  // namespace ptz_action_server

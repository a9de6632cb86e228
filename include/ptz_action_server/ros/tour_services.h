/**
 * \file
 * \brief The tour services (save, delete, list) around the node's TourStore, on the presets' queue, and the tours'
 * settings.
 */
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <ros/ros.h>

#include "ptz_action_server/DeleteTour.h"
#include "ptz_action_server/ListTours.h"
#include "ptz_action_server/SaveTour.h"
#include "ptz_action_server/core/tours/tour_runner.h"
#include "ptz_action_server/core/tours/tour_store.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/ros/preset_services.h"
#include "ptz_action_server/ros/shared_callback_queue.h"

namespace ptz_action_server
{
/// Where tours are kept, how they yield, and the idle return.
struct TourConfig
{
  std::string file;       ///< the tours YAML file
  TourSettings settings;  ///< resume after an operator, idle return

  /// Reads ~tours_file (default: beside \p presets_file, "_tours.yaml" for its "_presets.yaml"), ~tour/resume_after,
  /// ~idle_return/preset and ~idle_return/seconds.
  static TourConfig load(const ParamReader& params, const std::string& presets_file);
};

/**
 * \brief The tours of the node: move_ptz/save_tour, move_ptz/delete_tour and move_ptz/list_tours, and the lookup the
 * tour action starts its goals with.
 *
 * As the preset services, they run on the process's SharedCallbackQueue, so a save's write and fsync never hold up
 * goals or the state tick; the store is thread-safe for the lookups from the goal queue.
 */
class TourServices
{
public:
  /// Loads the tours file (an unreadable one is reported and kept: see TourStore) and advertises the services in
  /// \p node_handle's namespace. A tour is saved only if every preset it names is in \p presets, which must outlive
  /// the services.
  TourServices(const ros::NodeHandle& node_handle, const std::string& file, const PresetServices& presets);
  /// Shuts the services down: once it returns, no service callback of this node runs any more.
  ~TourServices();

  TourServices(const TourServices&) = delete;
  TourServices& operator=(const TourServices&) = delete;

  /// The tour named \p name.
  std::optional<Tour> find(const std::string& name) const
  {
    return store_.find(name);
  }

private:
  bool save(SaveTour::Request& request, SaveTour::Response& response);
  bool remove(DeleteTour::Request& request, DeleteTour::Response& response);
  bool list(ListTours::Request& request, ListTours::Response& response);

  std::shared_ptr<SharedCallbackQueue> queue_;  ///< declared first: everything below registers on it
  ros::NodeHandle node_handle_;                 ///< the node's namespace, on queue_
  const PresetServices& presets_;
  TourStore store_;
  ros::ServiceServer save_service_;
  ros::ServiceServer delete_service_;
  ros::ServiceServer list_service_;
};

}  // namespace ptz_action_server

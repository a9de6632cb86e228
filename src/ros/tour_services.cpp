#include "ptz_action_server/ros/tour_services.h"

#include <utility>

namespace ptz_action_server
{
TourConfig TourConfig::load(const ParamReader& params, const std::string& presets_file)
{
  TourConfig config;
  const std::string suffix = "_presets.yaml";
  std::string default_file = presets_file + ".tours.yaml";
  if (presets_file.size() > suffix.size() &&
      presets_file.compare(presets_file.size() - suffix.size(), suffix.size(), suffix) == 0)
  {
    default_file = presets_file.substr(0, presets_file.size() - suffix.size()) + "_tours.yaml";
  }
  config.file = params.text("tours_file", default_file);
  if (config.file.empty())
  {
    throw ConfigError("parameter " + params.resolve("tours_file") + " is empty: give a file path or leave it unset");
  }
  TourSettings& settings = config.settings;
  settings.resume_after = params.number("tour/resume_after", settings.resume_after, 0.0, TourLimits::MAX_DWELL);
  settings.idle_preset = params.text("idle_return/preset", settings.idle_preset);
  settings.idle_seconds = params.number("idle_return/seconds", settings.idle_seconds, 0.0, TourLimits::MAX_DWELL);
  return config;
}

TourServices::TourServices(const ros::NodeHandle& node_handle, const std::string& file, const PresetServices& presets)
  : queue_(SharedCallbackQueue::shared()), node_handle_(node_handle), presets_(presets), store_(file)
{
  node_handle_.setCallbackQueue(queue_->queue());
  const std::string error = store_.load();
  if (error.empty())
  {
    ROS_INFO("%zu tours from %s", store_.list().size(), file.c_str());
  }
  else
  {
    ROS_ERROR("%s. No tour is available, and saving and deleting tours are refused so the file is kept as it is: fix "
              "or move it and restart the node.",
              error.c_str());
  }
  save_service_ = node_handle_.advertiseService("move_ptz/save_tour", &TourServices::save, this);
  delete_service_ = node_handle_.advertiseService("move_ptz/delete_tour", &TourServices::remove, this);
  list_service_ = node_handle_.advertiseService("move_ptz/list_tours", &TourServices::list, this);
}

TourServices::~TourServices()
{
  save_service_.shutdown();
  delete_service_.shutdown();
  list_service_.shutdown();
}

// As the presets': a success means the tour survives a power loss; the write blocks only the shared service queue.
bool TourServices::save(SaveTour::Request& request, SaveTour::Response& response)
{
  Tour tour;
  tour.name = request.tour.name;
  for (const PtzTourStop& stop : request.tour.stops)
  {
    tour.stops.push_back({ stop.preset, stop.dwell, stop.speed });
    if (response.message.empty() && !presets_.find(stop.preset))
    {
      response.message = "stop " + std::to_string(tour.stops.size() - 1) + ": no preset named '" + stop.preset + "'";
    }
  }
  if (response.message.empty())
  {
    response.message = store_.save(tour);
  }
  response.success = response.message.empty();
  if (response.success)
  {
    response.message = "saved tour '" + tour.name + "' of " + std::to_string(tour.stops.size()) + " stops";
    ROS_INFO("%s", response.message.c_str());
  }
  else
  {
    ROS_WARN("tour '%s' not saved: %s", tour.name.c_str(), response.message.c_str());
  }
  return true;
}

bool TourServices::remove(DeleteTour::Request& request, DeleteTour::Response& response)
{
  response.message = store_.remove(request.name);
  response.success = response.message.empty();
  if (response.success)
  {
    response.message = "deleted tour '" + request.name + "'";
    ROS_INFO("%s", response.message.c_str());
  }
  else
  {
    ROS_WARN("tour '%s' not deleted: %s", request.name.c_str(), response.message.c_str());
  }
  return true;
}

bool TourServices::list(ListTours::Request&, ListTours::Response& response)
{
  for (const Tour& tour : store_.list())
  {
    PtzNamedTour named;
    named.name = tour.name;
    for (const TourStop& stop : tour.stops)
    {
      PtzTourStop message;
      message.preset = stop.preset;
      message.dwell = stop.dwell;
      message.speed = stop.speed;
      named.stops.push_back(message);
    }
    response.tours.push_back(named);
  }
  response.message = store_.loadError();
  return true;
}

}  // namespace ptz_action_server

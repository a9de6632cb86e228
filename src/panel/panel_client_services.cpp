/**
 * \file
 * \brief PanelClient's work off its spinner: the service calls, one at a time on the worker thread, and the discovery
 * thread that polls the master for cameras and the look_at_clicked_point service.
 */
#include "ptz_action_server/panel/panel_client.h"

#include <ros/master.h>
#include <std_srvs/SetBool.h>

#include "ptz_action_server/DeletePreset.h"
#include "ptz_action_server/ListPresets.h"
#include "ptz_action_server/SavePreset.h"

namespace ptz_action_server::panel
{
namespace
{
constexpr std::chrono::milliseconds DISCOVERY_PERIOD{ 1000 };
}  // namespace

void PanelClient::setMessage(std::uint64_t generation, const std::string& message)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation == generation_)
  {
    snapshot_.message = message;
  }
}

void PanelClient::listPresets(const std::string& ns, std::uint64_t generation)
{
  ListPresets list;
  const std::string name = inNamespace(ns, "move_ptz/list_presets");
  if (!ros::service::call(name, list))
  {
    setMessage(generation, "no presets: " + name + " did not answer");
    return;
  }
  std::vector<Preset> presets;
  for (std::size_t i = 0; i < list.response.names.size(); ++i)
  {
    Preset preset;
    preset.name = list.response.names[i];
    preset.pan = i < list.response.pan.size() ? list.response.pan[i] : 0.0;
    preset.tilt = i < list.response.tilt.size() ? list.response.tilt[i] : 0.0;
    preset.zoom = i < list.response.zoom.size() ? list.response.zoom[i] : 0.0;
    presets.push_back(preset);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  snapshot_.presets = std::move(presets);
  ++snapshot_.presets_serial;
  if (!list.response.message.empty())
  {
    snapshot_.message = list.response.message;
  }
}

void PanelClient::refreshPresets()
{
  postForCamera([this](const std::string& ns, std::uint64_t generation) {
    if (!ns.empty())
    {
      listPresets(ns, generation);
    }
  });
}

template <class Service>
void PanelClient::changePreset(const std::string& service_name, const std::string& name)
{
  postForCamera([this, service_name, name](const std::string& ns, std::uint64_t generation) {
    Service call;
    call.request.name = name;
    const std::string service = inNamespace(ns, "move_ptz/" + service_name);
    setMessage(generation, ros::service::call(service, call) ? call.response.message : service + " did not answer");
    listPresets(ns, generation);
  });
}

void PanelClient::savePreset(const std::string& name)
{
  changePreset<SavePreset>("save_preset", name);
}

void PanelClient::deletePreset(const std::string& name)
{
  changePreset<DeletePreset>("delete_preset", name);
}

void PanelClient::setLookAt(bool enabled)
{
  postForCamera([this, enabled](const std::string& ns, std::uint64_t generation) {
    std_srvs::SetBool request;
    request.request.data = enabled;
    const std::string service = inNamespace(ns, LOOK_SERVICE);
    if (!ros::service::call(service, request))
    {
      setMessage(generation, service + " did not answer");
    }
    else
    {
      setMessage(generation, request.response.message.empty() ?
                                 std::string("look at clicked point ") + (enabled ? "on" : "off") :
                                 request.response.message);
    }
  });
}

void PanelClient::postForCamera(std::function<void(const std::string& ns, std::uint64_t generation)> job)
{
  std::lock_guard<std::mutex> lock(mutex_);
  post([job = std::move(job), ns = ns_, generation = generation_] { job(ns, generation); });
}

void PanelClient::post(std::function<void()> job)
{
  {
    std::lock_guard<std::mutex> lock(jobs_mutex_);
    jobs_.push_back(std::move(job));
  }
  jobs_changed_.notify_one();
}

void PanelClient::workerLoop()
{
  while (running_)
  {
    std::function<void()> job;
    {
      std::unique_lock<std::mutex> lock(jobs_mutex_);
      jobs_changed_.wait(lock, [this] { return !running_ || !jobs_.empty(); });
      if (!running_)
      {
        return;
      }
      job = std::move(jobs_.front());
      jobs_.pop_front();
    }
    job();
  }
}

void PanelClient::discoveryLoop()
{
  while (running_)
  {
    // Both calls may wait (the master's topic list for a master that is gone): off the widget's thread, unlocked.
    ros::master::V_TopicInfo master_topics;
    std::vector<std::string> namespaces;
    std::vector<std::string> image_topics;
    // check() never waits; getTopics waits for a master that is gone, which would hold the destructor's join.
    if (ros::master::check() && ros::master::getTopics(master_topics))
    {
      std::vector<TopicInfo> topics;
      for (const ros::master::TopicInfo& topic : master_topics)
      {
        topics.push_back({ topic.name, topic.datatype });
      }
      namespaces = cameraNamespaces(topics);
      image_topics = imageTopics(topics, "/");
    }
    std::string ns;
    std::uint64_t generation = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ns = ns_;
      generation = generation_;
    }
    const bool look = !ns.empty() && ros::service::exists(inNamespace(ns, LOOK_SERVICE), false);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      snapshot_.namespaces = namespaces;
      snapshot_.image_topics = image_topics;
      if (generation == generation_)
      {
        snapshot_.look_available = look;
      }
    }
    std::unique_lock<std::mutex> lock(discovery_mutex_);
    discovery_wake_.wait_for(lock, DISCOVERY_PERIOD, [this] { return !running_; });
  }
}

}  // namespace ptz_action_server::panel

/**
 * \file
 * \brief The rviz panel's ROS side, without Qt: it watches one camera's namespace and sends its goals and service
 * calls, so the widget never waits on the network.
 *
 * Threads: subscriptions and the action clients run on the client's own callback queue and spinner (not rviz's);
 * service calls run one at a time on a worker thread; the master's topic list and the look_at_clicked_point service
 * are polled once a second on a discovery thread (a master call can wait for a master that is gone). Every result
 * goes into one mutex-protected snapshot that the widget reads on its timer. Goals are sent from the caller's thread:
 * actionlib's sendGoal and cancelGoal only publish.
 */
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <actionlib_msgs/GoalStatusArray.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/PtzPresetAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/panel/panel_model.h"

namespace ptz_action_server::panel
{
/// The node's look-here switch (written by the node's clicked_point part): a std_srvs/SetBool service and its latched
/// state, both in the camera's namespace.
inline constexpr const char* LOOK_SERVICE = "look_at_clicked_point";
inline constexpr const char* LOOK_STATE_TOPIC = "look_at_clicked_point/enabled";

/// One preset as move_ptz/list_presets lists it.
struct Preset
{
  std::string name;
  double pan = 0.0;
  double tilt = 0.0;
  double zoom = 0.0;
};

/// Everything the panel shows, copied out under the client's lock.
struct PanelSnapshot
{
  std::vector<std::string> namespaces;  ///< every camera on the master
  std::string ns;                       ///< the camera watched, "" for none
  bool fresh = false;                   ///< a ptz_state within STATE_TIMEOUT
  std::string banner;                   ///< "", NO_STATE_TEXT, or why the controls are greyed though ptz_state arrives
  bool has_state = false;               ///< a ptz_state arrived from this camera
  int mode = 0;
  double pan = 0.0, tilt = 0.0, zoom = 0.0;
  Link link = Link::UNKNOWN;
  Abilities abilities;
  std::string goal = "no goal";    ///< goalText of the node's action status topics
  bool actions_connected = false;  ///< the velocity, position_abs and preset servers are connected
  bool look_available = false;     ///< the look_at_clicked_point service exists
  bool look_enabled = false;       ///< its latched state (false until heard)
  std::vector<Preset> presets;
  std::uint64_t presets_serial = 0;  ///< counts preset list replies, so the widget refills only on news
  std::string message;               ///< the outcome of the last service call, or why it failed
};

class PanelClient
{
public:
  /// Starts the spinner and the worker and discovery threads; watches no camera until setNamespace.
  PanelClient();
  /// Stops and joins the threads.
  ~PanelClient();
  PanelClient(const PanelClient&) = delete;
  PanelClient& operator=(const PanelClient&) = delete;

  /// Watches the camera in `ns` ("" for none): drops what it knew of the previous one, subscribes, creates the
  /// action clients; the presets are listed whenever its ptz_state starts (or resumes) arriving.
  void setNamespace(const std::string& ns);
  PanelSnapshot snapshot() const;

  /// A velocity goal (move_ptz/velocity); replaces the panel's previous velocity goal.
  void jog(const Velocity& velocity);
  /// Cancels the panel's own velocity goal, if it sent one (a released jog control).
  void stopJog();
  /// An all-zero velocity goal: stops whatever goal moves the camera.
  void stopAll();
  /// A move_ptz/position_abs goal: rad, rad, X.
  void goAbsolute(double pan, double tilt, double zoom);
  /// A move_ptz/preset goal ("home" for home).
  void goPreset(const std::string& name);
  /// Service calls, on the worker thread; save and delete refresh the list after.
  void refreshPresets();
  void savePreset(const std::string& name);
  void deletePreset(const std::string& name);
  void setLookAt(bool enabled);

private:
  using PtzClient = actionlib::SimpleActionClient<PtzAction>;
  using PresetClient = actionlib::SimpleActionClient<PtzPresetAction>;

  void onState(std::uint64_t generation, const PtzState::ConstPtr& state);
  void onCapabilities(std::uint64_t generation, const PtzCapabilities::ConstPtr& capabilities);
  void onDiagnostics(std::uint64_t generation, const diagnostic_msgs::DiagnosticArray::ConstPtr& array);
  void onStatus(std::uint64_t generation, const std::string& action,
                const actionlib_msgs::GoalStatusArray::ConstPtr& status);
  void onLookState(std::uint64_t generation, const std_msgs::Bool::ConstPtr& enabled);
  /// Queues a job for the worker thread.
  void post(std::function<void()> job);
  void workerLoop();
  void discoveryLoop();
  /// The worker's preset list call for the camera in `ns`.
  void listPresets(const std::string& ns, std::uint64_t generation);
  void setMessage(std::uint64_t generation, const std::string& message);
  /// Calls the preset service `move_ptz/<service>` with \p name on the worker, shows its answer, lists the presets.
  template <class Service>
  void changePreset(const std::string& service, const std::string& name);
  double now() const;

  ros::CallbackQueue queue_;  ///< the client's callbacks, off rviz's queue
  std::unique_ptr<ros::AsyncSpinner> spinner_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();

  mutable std::mutex mutex_;      ///< guards everything below but the threads and the run flag
  std::uint64_t generation_ = 0;  ///< counts setNamespace calls: callbacks and replies of an earlier camera are dropped
  std::string ns_;
  std::vector<ros::Subscriber> subscribers_;
  std::unique_ptr<PtzClient> velocity_client_;
  std::unique_ptr<PtzClient> absolute_client_;
  std::unique_ptr<PresetClient> preset_client_;
  bool jogging_ = false;  ///< the panel's velocity goal may still run
  StateWatch watch_;
  PanelSnapshot snapshot_;
  std::map<std::string, std::vector<GoalStatusEntry>> statuses_;  ///< per action
  /// The newest goal seen to end: the node drops finished goals from its status lists after a second, the panel keeps
  /// showing how the last one ended.
  std::optional<GoalStatusEntry> last_finished_;

  std::atomic<bool> running_{ true };
  std::mutex jobs_mutex_;
  std::condition_variable jobs_changed_;
  std::deque<std::function<void()>> jobs_;
  std::thread worker_;
  std::mutex discovery_mutex_;
  std::condition_variable discovery_wake_;
  std::thread discovery_;
};

}  // namespace ptz_action_server::panel

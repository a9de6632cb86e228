/**
 * \file
 * \brief The rviz panel's ROS side, without Qt: it watches one camera's namespace and sends its goals and service
 * calls, so the widget never waits on the network.
 *
 * Threads: subscriptions and the action clients run on the client's own callback queue and spinner (not rviz's);
 * service calls run one at a time on a worker thread; the master's topic list and the look_at_clicked_point service
 * are polled once a second on a discovery thread (a master call can wait for a master that is gone). Every result
 * goes into one mutex-protected snapshot that the widget reads on its timer. Goals are sent from the caller's thread:
 * actionlib's sendGoal and cancelGoal only publish. The tours part (tours list, tour goals, the tour line) is in
 * panel_client_tours.cpp.
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
#include <image_transport/subscriber.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Bool.h>

#include "ptz_action_server/FieldOfView.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/PtzPixelAction.h"
#include "ptz_action_server/PtzPresetAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/PtzTourAction.h"
#include "ptz_action_server/panel/image_frame.h"
#include "ptz_action_server/panel/image_view_model.h"
#include "ptz_action_server/panel/panel_model.h"
#include "ptz_action_server/panel/tour_model.h"

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
  std::uint64_t presets_serial = 0;       ///< counts preset list replies, so the widget refills only on news
  std::string message;                    ///< the outcome of the last service call, or why it failed
  std::vector<std::string> image_topics;  ///< every sensor_msgs/Image topic on the master
  std::string image_topic;                ///< the image subscribed to, "" for none
  std::string image_message;              ///< "" while images arrive and show, else what the view says instead
  bool pixel_connected = false;           ///< the move_ptz/pixel server is connected
  std::optional<PixelAim> pixel_aim;      ///< the pixel goal to draw (any client's), while pending or active
  std::vector<TourListing> tours;         ///< move_ptz/list_tours' answer
  std::uint64_t tours_serial = 0;         ///< counts tour list replies, as presets_serial
  std::string tour = NO_TOUR_TEXT;        ///< the tour line (TourWatch): any client's tour goal
  bool tour_connected = false;            ///< the move_ptz/tour server is connected
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
  /// A move_ptz/tour goal: the tour `name`, `rounds` rounds (0: until stopped or preempted).
  void startTour(const std::string& name, std::uint32_t rounds);
  /// Cancels every move_ptz/tour goal, whoever sent it: the device stops and the tour ends preempted.
  void stopTour();
  /// move_ptz/list_tours on the worker (also done whenever the presets are listed on ptz_state's arrival).
  void refreshTours();
  /// move_ptz/delete_tour on the worker, then the list again.
  void deleteTour(const std::string& name);

  /// Subscribes to the image `topic` through image_transport ("" for none), dropping the previous one and its image.
  void setImageTopic(const std::string& topic);
  /// The newest image converted for display; null before the first of the topic.
  std::shared_ptr<const ImageFrame> latestFrame() const;
  /// Called on the client's spinner after each new frame (the widget posts itself a repaint); set before the first
  /// image topic and cleared (empty) before the listener's owner goes.
  void setFrameListener(std::function<void()> listener);
  /// The camera's view at ROS time `stamp` (s), from its ptz_state and field_of_view; nullopt when not known then.
  std::optional<View> viewAt(double stamp) const;
  /// A move_ptz/pixel goal on `frame` (its header and size): centre `target`, and with a box zoom to it.
  void aimAtPixel(const ImageFrame& frame, const PixelBox& target);

private:
  using PtzClient = actionlib::SimpleActionClient<PtzAction>;
  using PresetClient = actionlib::SimpleActionClient<PtzPresetAction>;
  using PixelClient = actionlib::SimpleActionClient<PtzPixelAction>;
  using TourClient = actionlib::SimpleActionClient<PtzTourAction>;

  void onState(std::uint64_t generation, const PtzState::ConstPtr& state);
  void onCapabilities(std::uint64_t generation, const PtzCapabilities::ConstPtr& capabilities);
  void onDiagnostics(std::uint64_t generation, const diagnostic_msgs::DiagnosticArray::ConstPtr& array);
  void onStatus(std::uint64_t generation, const std::string& action,
                const actionlib_msgs::GoalStatusArray::ConstPtr& status);
  void onLookState(std::uint64_t generation, const std_msgs::Bool::ConstPtr& enabled);
  void onImage(std::uint64_t image_generation, const sensor_msgs::ImageConstPtr& image);
  void onFieldOfView(std::uint64_t generation, const FieldOfView::ConstPtr& view);
  void onPixelGoal(std::uint64_t generation, const PtzPixelActionGoal::ConstPtr& goal);
  /// The picture's subscriptions of the camera in ns_ (field_of_view, the pixel goals), under mutex_.
  void subscribeImageParts(ros::NodeHandle& node, std::uint64_t generation);
  /// The tours' subscriptions (the tour action's goal, feedback and result topics) and client, under mutex_.
  void subscribeTourParts(ros::NodeHandle& node, std::uint64_t generation);
  void onTourGoal(std::uint64_t generation, const PtzTourActionGoal::ConstPtr& goal);
  void onTourFeedback(std::uint64_t generation, const PtzTourActionFeedback::ConstPtr& feedback);
  void onTourResult(std::uint64_t generation, const PtzTourActionResult::ConstPtr& result);
  /// Queues a job for the worker thread.
  void post(std::function<void()> job);
  /// post() of a job for the camera shown now: it gets that camera's namespace and generation, read under mutex_.
  void postForCamera(std::function<void(const std::string& ns, std::uint64_t generation)> job);
  void workerLoop();
  void discoveryLoop();
  /// The worker's preset list call for the camera in `ns`.
  void listPresets(const std::string& ns, std::uint64_t generation);
  /// The worker's tour list call for the camera in `ns`.
  void listTours(const std::string& ns, std::uint64_t generation);
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
  std::unique_ptr<PixelClient> pixel_client_;
  std::unique_ptr<TourClient> tour_client_;
  bool jogging_ = false;  ///< the panel's velocity goal may still run
  StateWatch watch_;
  PanelSnapshot snapshot_;
  std::map<std::string, std::vector<GoalStatusEntry>> statuses_;  ///< per action
  /// The newest goal seen to end: the node drops finished goals from its status lists after a second, the panel keeps
  /// showing how the last one ended.
  std::optional<GoalStatusEntry> last_finished_;
  ViewTrack views_;              ///< the camera's recent views, for drawing the aim on later images
  PixelGoalWatch pixel_goals_;   ///< the pixel goal to draw
  TourWatch tour_goals_;         ///< the tour line's goals
  std::string tour_listed_for_;  ///< a tour heard in feedback that was not listed: listed once for it

  std::uint64_t image_generation_ = 0;  ///< counts setImageTopic calls: images of an earlier topic are dropped
  std::string image_topic_;
  std::string image_message_;
  image_transport::Subscriber image_subscriber_;
  std::shared_ptr<const ImageFrame> latest_frame_;
  std::mutex listener_mutex_;  ///< guards frame_listener_ (called without mutex_ held)
  std::function<void()> frame_listener_;

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

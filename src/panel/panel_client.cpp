#include "ptz_action_server/panel/panel_client.h"

#include <array>
#include <tuple>

// Only the node's table of actions (constexpr names), not its servers: the panel links nothing of the node.
#include "ptz_action_server/ros/action_servers.h"

namespace ptz_action_server::panel
{
namespace
{
/// The node's actions whose status topics feed the goal line: every one the node serves, from its own table.
constexpr std::array<const char*, NODE_ACTION_COUNT> STATUS_ACTIONS = std::apply(
    [](const auto&... row) { return std::array<const char*, NODE_ACTION_COUNT>{ row.name... }; }, NODE_ACTIONS);

AxisAbility toAbility(const PtzAxisCapability& axis)
{
  AxisAbility ability;
  ability.present = axis.present;
  ability.absolute = axis.absolute;
  ability.velocity = axis.velocity;
  ability.min = axis.min;
  ability.max = axis.max;
  ability.max_speed = axis.max_speed;
  return ability;
}

PtzGoal ptzGoal(double pan, double tilt, double zoom)
{
  PtzGoal goal;
  goal.pan = static_cast<float>(pan);
  goal.tilt = static_cast<float>(tilt);
  goal.zoom = static_cast<float>(zoom);
  return goal;
}
}  // namespace

PanelClient::PanelClient()
{
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
  worker_ = std::thread([this] { workerLoop(); });
  discovery_ = std::thread([this] { discoveryLoop(); });
}

PanelClient::~PanelClient()
{
  running_ = false;
  jobs_changed_.notify_all();
  discovery_wake_.notify_all();
  worker_.join();
  discovery_.join();
  spinner_->stop();
  std::lock_guard<std::mutex> lock(mutex_);
  subscribers_.clear();
  image_subscriber_.shutdown();
  velocity_client_.reset();
  absolute_client_.reset();
  preset_client_.reset();
  pixel_client_.reset();
  tour_client_.reset();
}

double PanelClient::now() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void PanelClient::setNamespace(const std::string& ns)
{
  // The old camera's subscriptions and action clients end after mutex_ is released (these are destroyed after the
  // lock, declared below): ending a subscription waits for its callback under way, which may be waiting for mutex_.
  std::vector<ros::Subscriber> old_subscribers;
  std::unique_ptr<PtzClient> old_velocity_client;
  std::unique_ptr<PtzClient> old_absolute_client;
  std::unique_ptr<PresetClient> old_preset_client;
  std::unique_ptr<PixelClient> old_pixel_client;
  std::unique_ptr<TourClient> old_tour_client;
  std::uint64_t generation = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (ns == ns_ && generation_ != 0)
    {
      return;
    }
    generation = ++generation_;  // from here on, the old camera's callbacks change nothing
    ns_ = ns;
    old_subscribers.swap(subscribers_);
    old_velocity_client = std::move(velocity_client_);
    old_absolute_client = std::move(absolute_client_);
    old_preset_client = std::move(preset_client_);
    old_pixel_client = std::move(pixel_client_);
    old_tour_client = std::move(tour_client_);
    jogging_ = false;
    watch_.reset();
    statuses_.clear();
    last_finished_.reset();
    views_.clear();
    pixel_goals_.clear();
    tour_goals_.clear();
    tour_listed_for_.clear();
    const std::vector<std::string> namespaces = snapshot_.namespaces;
    const std::vector<std::string> image_topics = snapshot_.image_topics;
    snapshot_ = PanelSnapshot();
    snapshot_.namespaces = namespaces;
    snapshot_.image_topics = image_topics;
    snapshot_.ns = ns;
    if (ns.empty())
    {
      return;
    }
    ros::NodeHandle node(ns);
    node.setCallbackQueue(&queue_);
    ros::NodeHandle root("/");
    root.setCallbackQueue(&queue_);
    subscribers_.push_back(node.subscribe<PtzState>(
        STATE_TOPIC, 1, [this, generation](const PtzState::ConstPtr& state) { onState(generation, state); }));
    subscribers_.push_back(node.subscribe<PtzCapabilities>(
        "capabilities", 1, [this, generation](const PtzCapabilities::ConstPtr& capabilities) {
          onCapabilities(generation, capabilities);
        }));
    subscribers_.push_back(node.subscribe<std_msgs::Bool>(
        LOOK_STATE_TOPIC, 1, [this, generation](const std_msgs::Bool::ConstPtr& on) { onLookState(generation, on); }));
    subscribers_.push_back(root.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 10, [this, generation](const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
          onDiagnostics(generation, array);
        }));
    for (const char* action : STATUS_ACTIONS)
    {
      const std::string name = action;
      subscribers_.push_back(node.subscribe<actionlib_msgs::GoalStatusArray>(
          "move_ptz/" + name + "/status", 1,
          [this, generation, name](const actionlib_msgs::GoalStatusArray::ConstPtr& status) {
            onStatus(generation, name, status);
          }));
    }
    // spin_thread = false: the clients' callbacks run on queue_, which node hands them.
    velocity_client_ = std::make_unique<PtzClient>(node, "move_ptz/velocity", false);
    absolute_client_ = std::make_unique<PtzClient>(node, "move_ptz/position_abs", false);
    preset_client_ = std::make_unique<PresetClient>(node, "move_ptz/preset", false);
    pixel_client_ = std::make_unique<PixelClient>(node, "move_ptz/pixel", false);
    subscribeImageParts(node, generation);
    subscribeTourParts(node, generation);
  }
  discovery_wake_.notify_all();
}

PanelSnapshot PanelClient::snapshot() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  PanelSnapshot copy = snapshot_;
  const double t = now();
  copy.fresh = watch_.fresh(t);
  copy.actions_connected = velocity_client_ && velocity_client_->isServerConnected() && absolute_client_ &&
                           absolute_client_->isServerConnected() && preset_client_ &&
                           preset_client_->isServerConnected();
  copy.banner = copy.ns.empty() ? "no camera picked" : watch_.banner(t);
  if (copy.banner.empty() && !copy.actions_connected)
  {
    copy.banner = "connecting to the node's actions";
  }
  std::vector<GoalStatusEntry> goals;
  for (const auto& [action, entries] : statuses_)
  {
    goals.insert(goals.end(), entries.begin(), entries.end());
  }
  if (last_finished_)
  {
    goals.push_back(*last_finished_);
  }
  copy.goal = goalText(goals);
  copy.image_topic = image_topic_;
  copy.image_message = image_message_;
  copy.pixel_connected = pixel_client_ && pixel_client_->isServerConnected();
  copy.pixel_aim = pixel_goals_.active(t);
  copy.tour = tour_goals_.text(snapshot_.tours);
  copy.tour_connected = tour_client_ && tour_client_->isServerConnected();
  return copy;
}

void PanelClient::onState(std::uint64_t generation, const PtzState::ConstPtr& state)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  const double t = now();
  if (!watch_.fresh(t))
  {
    // The camera appeared or came back (a restarted node may have other presets): list them again.
    const std::string ns = ns_;
    post([this, ns, generation] {
      listPresets(ns, generation);
      listTours(ns, generation);
    });
  }
  watch_.received(t);
  snapshot_.has_state = true;
  snapshot_.mode = state->mode;
  snapshot_.pan = state->pan;
  snapshot_.tilt = state->tilt;
  snapshot_.zoom = state->zoom;
  // PtzState has no stamp: its arrival stands for it (the node publishes it as it takes it, at 10 Hz).
  views_.addPose(ros::Time::now().toSec(), state->pan, state->tilt);
}

void PanelClient::onCapabilities(std::uint64_t generation, const PtzCapabilities::ConstPtr& capabilities)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  snapshot_.abilities.known = true;
  snapshot_.abilities.pan = toAbility(capabilities->pan);
  snapshot_.abilities.tilt = toAbility(capabilities->tilt);
  snapshot_.abilities.zoom = toAbility(capabilities->zoom);
}

void PanelClient::onDiagnostics(std::uint64_t generation, const diagnostic_msgs::DiagnosticArray::ConstPtr& array)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  for (const diagnostic_msgs::DiagnosticStatus& status : array->status)
  {
    if (!diagnosticsOfNamespace(ns_, status.name))
    {
      continue;
    }
    for (const diagnostic_msgs::KeyValue& value : status.values)
    {
      if (value.key == "link")
      {
        snapshot_.link = value.value == "up" ? Link::UP : Link::DOWN;
      }
    }
  }
}

void PanelClient::onStatus(std::uint64_t generation, const std::string& action,
                           const actionlib_msgs::GoalStatusArray::ConstPtr& status)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  std::vector<GoalStatusEntry>& entries = statuses_[action];
  entries.clear();
  for (const actionlib_msgs::GoalStatus& goal : status->status_list)
  {
    entries.push_back({ action, goal.status, goal.text, goal.goal_id.stamp.toSec(), goal.goal_id.id });
    const bool finished =
        goal.status != actionlib_msgs::GoalStatus::PENDING && goal.status != actionlib_msgs::GoalStatus::ACTIVE &&
        goal.status != actionlib_msgs::GoalStatus::PREEMPTING && goal.status != actionlib_msgs::GoalStatus::RECALLING;
    if (finished && (!last_finished_ || entries.back().stamp >= last_finished_->stamp))
    {
      last_finished_ = entries.back();
    }
  }
  if (action == "pixel")
  {
    pixel_goals_.status(entries);
  }
}

void PanelClient::onLookState(std::uint64_t generation, const std_msgs::Bool::ConstPtr& enabled)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation == generation_)
  {
    snapshot_.look_enabled = enabled->data;
  }
}

void PanelClient::jog(const Velocity& velocity)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (velocity_client_)
  {
    velocity_client_->sendGoal(ptzGoal(velocity.pan, velocity.tilt, velocity.zoom));
    jogging_ = true;
  }
}

void PanelClient::stopJog()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (velocity_client_ && jogging_)
  {
    velocity_client_->cancelGoal();
    jogging_ = false;
  }
}

void PanelClient::stopAll()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (velocity_client_)
  {
    velocity_client_->sendGoal(ptzGoal(0.0, 0.0, 0.0));
    jogging_ = false;
  }
}

void PanelClient::goAbsolute(double pan, double tilt, double zoom)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (absolute_client_)
  {
    absolute_client_->sendGoal(ptzGoal(pan, tilt, zoom));
    jogging_ = false;  // the position goal preempts the velocity goal
  }
}

void PanelClient::goPreset(const std::string& name)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (preset_client_)
  {
    PtzPresetGoal goal;
    goal.name = name;
    preset_client_->sendGoal(goal);
    jogging_ = false;
  }
}

}  // namespace ptz_action_server::panel

#include "ptz_action_server/ros/ptz_action_server.h"

#include <chrono>
#include <optional>
#include <string>
#include <type_traits>

#include <boost/make_shared.hpp>

#include "ptz_action_server/core/capabilities.h"
#include "ptz_action_server/core/limits.h"
#include "ptz_action_server/core/motion/pixel_aim_choice.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/ros/capabilities_message.h"
#include "ptz_action_server/ros/function_callback.h"
#include "ptz_action_server/ros/logged_goal.h"
#include "ptz_action_server/ros/state_publisher.h"

namespace ptz_action_server
{
namespace
{
/// A device's own reports go into the pose history at most this often (200 Hz keeps the history's 10 s window).
constexpr std::chrono::milliseconds REPORT_SPACING(5);
}  // namespace

PtzActionServer::PtzActionServer(const ros::NodeHandle& node_handle, const NodeConfig& config,
                                 const PtzKinematics& kinematics, std::shared_ptr<PtzBackend> backend)
  : node_handle_(node_handle)
  , config_(config)
  , kinematics_(kinematics)
  , backend_(std::move(backend))
  , status_hold_(config.status_hold)
  , status_release_timer_(node_handle_.getCallbackQueue(), [this] { releaseHeldStatuses(); })
  , servers_(node_handle_, config.action_queue_size, config.status_list_timeout)
{
}

PtzActionServer::~PtzActionServer()
{
  // Stop the state thread, the status release and the backend's reports first: they post callbacks that point at
  // this object.
  state_publisher_.reset();
  status_release_timer_.stop();
  velocity_topic_.reset();
  controls_.reset();
  if (listener_target_)
  {
    std::lock_guard<std::mutex> lock(listener_target_->mutex);
    listener_target_->server = nullptr;
  }
  node_handle_.getCallbackQueue()->removeByID(reinterpret_cast<uint64_t>(this));
  if (tours_)
  {
    tours_->shutdown("the node is shutting down");
  }
  if (supervisor_)
  {
    supervisor_->shutdown("the node is shutting down");
  }
  status_hold_.release(TimePoint::max());  // the last words reach the clients without waiting
}

void PtzActionServer::start()
{
  // A goal is judged as soon as the backend reports a settled state, not at the next 10 Hz tick.
  listener_target_ = std::make_shared<ListenerTarget>();
  listener_target_->server = this;
  if (!backend_->setSampleListener([target = listener_target_] {
        std::lock_guard<std::mutex> lock(target->mutex);
        if (target->server)
        {
          target->server->onBackendSample();
        }
      }))
  {
    ROS_INFO("%s: the backend does not report new state; goals are judged on the 10 Hz state tick",
             backend_->name().c_str());
  }
  backend_->start();
  // Goals are checked against the tighter of the device's and the URDF's limits.
  const LimitIntersection intersection = intersectLimits(backend_->capabilities(), urdfLimits(kinematics_));
  for (const std::string& warning : intersection.warnings)
  {
    ROS_WARN("%s: %s", backend_->name().c_str(), warning.c_str());
  }
  limits_ = intersection.limits;
  capabilities_publisher_ = node_handle_.advertise<PtzCapabilities>("capabilities", 1, true);
  PtzCapabilities capabilities_message = toMessage(backend_->name(), limits_);
  capabilities_message.pixel_aim = describePixelAim(config_.pixel.aim_way, limits_);
  capabilities_publisher_.publish(capabilities_message);
  if (config_.pixel.aim_way == PixelAimWay::DEVICE && !limits_.view_centre)
  {
    ROS_WARN("pixel_aim is device, and the %s device has no command of its own to centre a point of its picture: "
             "pixel goals will be refused (set pixel_aim: auto or computed)",
             backend_->name().c_str());
  }
  poses_ = std::make_shared<PoseRecorder>(limits_);
  supervisor_ = std::make_unique<GoalSupervisor>(backend_, limits_, config_.monitor, config_.clamp_goals);
  supervising_ = true;

  // The 10 Hz state tick on its own thread; its samples reach the supervisor through the main queue.
  state_publisher_ = std::make_unique<StatePublisher>(
      node_handle_, config_.node_name, kinematics_, backend_, *supervisor_, limits_, config_.publish_tf,
      [this](const GoalSample& sample) {
        node_handle_.getCallbackQueue()->addCallback(
            boost::make_shared<FunctionCallback>([this, sample] { supervisor_->supervise(sample); }),
            reinterpret_cast<uint64_t>(this));
      });
  if (config_.field_of_view.model)
  {
    state_publisher_->addFieldOfView(config_.field_of_view);
  }
  state_publisher_->setTickHook([this] { return servers_.publishStatuses(); });
  state_publisher_->setPoseRecorder(poses_.get());
  state_publisher_->setTickCosts(tick_costs_);
  state_publisher_->start();

  presets_ = std::make_unique<PresetServices>(node_handle_, config_.presets, limits_, backend_);
  lens_ = std::make_unique<LensInterface>(node_handle_, backend_, limits_.lens, backend_->name(), config_.lens);
  tour_services_ = std::make_unique<TourServices>(node_handle_, config_.tours.file, *presets_);
  tours_ = std::make_unique<TourGoals>(node_handle_, config_.tours.settings, *supervisor_, backend_, *presets_,
                                       *tour_services_, statusPoster(),
                                       [this](const std::function<void()>& changes) { servers_.batch(changes); });
  frame_listener_ = std::make_unique<FrameListener>(node_handle_, config_.frame_listen_time, config_.frame_wait);
  frame_hold_ = std::make_unique<FrameGoalHold>(node_handle_, *frame_listener_, kinematics_.baseFrame());
  PixelGoals::CalibrationSource calibration;
  if (!config_.field_of_view.camera_info_topic.empty())
  {
    calibration = [this]() -> std::optional<CalibratedIntrinsics> {
      const FieldOfViewPublisher* view = state_publisher_ ? state_publisher_->fieldOfView() : nullptr;
      return view ? view->calibration() : std::nullopt;
    };
  }
  pixel_goals_ = std::make_unique<PixelGoals>(kinematics_, limits_, *poses_, config_.pixel, calibration,
                                              node_handle_.resolveName(config_.field_of_view.camera_info_topic));
  translator_ = std::make_unique<GoalTranslator>(kinematics_, limits_, *frame_listener_, *presets_, *pixel_goals_);
  frame_tracking_ = std::make_unique<FrameTracking>(node_handle_, kinematics_, limits_, config_.track, *supervisor_,
                                                    *frame_listener_, *backend_);
  detection_tracking_ = std::make_unique<DetectionTracking>(
      node_handle_,
      DetectionTracking::Parts{ kinematics_, limits_, config_.track, config_.detection_tracking, config_.monitor,
                                config_.pixel, calibration, *supervisor_, *backend_, *poses_, *presets_ });

  controls_ =
      std::make_unique<OperatorControls>(node_handle_, config_.node_name, backend_->name(), limits_, *supervisor_);
  if (config_.cmd_velocity.enabled)
  {
    velocity_topic_ = std::make_unique<VelocityTopic>(
        node_handle_, config_.cmd_velocity, *supervisor_, [this](const PtzGoal& velocity, PtzSample& current) {
          frame_hold_->supersede(ActionKind::VELOCITY);
          current = backend_->sample();
          return translator_->convert(velocity, ActionKind::VELOCITY, current);
        });
  }
  servers_.start([this](auto handle, ActionKind kind) { onGoal(handle, kind); },
                 [this](auto handle, ActionKind kind) { onCancel(handle, kind); });
  look_at_clicked_point_ = std::make_unique<LookAtClickedPoint>(
      node_handle_, config_.look_at_clicked_point, [this](const geometry_msgs::PointStamped& point) { lookAt(point); });
  if (!config_.pixel.image_topic.empty())
  {
    const std::string image_topic = node_handle_.resolveName(config_.pixel.image_topic);
    image_clicks_ = std::make_unique<ImageClicks>(
        node_handle_, image_topic, image_topic == local_image_topic_ ? local_images_ : nullptr,
        [this](const ros::Time& stamp, const PixelGoal& goal) { centrePixel(stamp, goal); });
  }
  ROS_INFO("ptz_action_server ready with backend '%s': pan %s; tilt %s; zoom %s; device extras: %s",
           backend_->name().c_str(), describeAxis(limits_, PAN).c_str(), describeAxis(limits_, TILT).c_str(),
           describeAxis(limits_, ZOOM).c_str(), describeExtras(limits_).c_str());
  ROS_INFO("%s: focus %s; iris %s", backend_->name().c_str(),
           describeLens(limits_.lens, LensFunction::FOCUS, backend_->name()).c_str(),
           describeLens(limits_.lens, LensFunction::IRIS, backend_->name()).c_str());
}

void PtzActionServer::postStatus(StatusHold::Change change)
{
  status_hold_.run(std::move(change), clock_.now());
  if (status_hold_.heldCount() > 0 && !status_release_armed_)
  {
    armStatusRelease(status_hold_.release(clock_.now()));
  }
}

StatusPoster PtzActionServer::statusPoster()
{
  return { [this](StatusHold::Change change) { postStatus(std::move(change)); },
           [this] { return status_hold_.holding(clock_.now()); } };
}

void PtzActionServer::armStatusRelease(TimePoint due)
{
  status_release_armed_ = due != TimePoint::max();
  status_release_timer_.startAt(due);
}

void PtzActionServer::releaseHeldStatuses()
{
  servers_.batch([this] { armStatusRelease(status_hold_.release(clock_.now())); });
}

void PtzActionServer::onBackendSample()
{
  if (!supervising_)
  {
    return;
  }
  const PtzSample sample = backend_->sample();
  poses_->record(rosStampOf(sample.stamp, clock_), sample, REPORT_SPACING);
  // Only the final verdict matters between ticks; one queued check covers every report that comes before it runs.
  if (!supervisor_->goalActive() || verdict_check_queued_.exchange(true))
  {
    return;
  }
  node_handle_.getCallbackQueue()->addCallback(boost::make_shared<FunctionCallback>([this] {
                                                 verdict_check_queued_ = false;
                                                 supervisor_->supervise(supervisor_->sample(), false);
                                               }),
                                               reinterpret_cast<uint64_t>(this));
}

template <class Action>
void PtzActionServer::onGoal(actionlib::ServerGoalHandle<Action> handle, ActionKind kind)
{
  status_hold_.goalArrived(clock_.now());
  frame_hold_->supersede(kind);
  // A goal on a tf frame starts the tf listener, and waits for the frame if it is not known yet.
  const std::optional<std::string> frame_id = GoalTranslator::frameOf(*handle.getGoal());
  if (frame_id && frame_hold_->mustWait(*frame_id))
  {
    const auto result = [] { return typename Action::_action_result_type::_result_type(); };
    frame_hold_->hold({ handle.getGoalID().id, *frame_id, [this, handle, kind] { submit(handle, kind); },
                        [this, handle, result](const std::string& text) {
                          postStatus([handle, result, text]() mutable { handle.setRejected(result(), text); });
                        },
                        [this, handle, result](const std::string& text) {
                          postStatus([handle, result, text]() mutable { handle.setCanceled(result(), text); });
                        } });
    return;
  }
  submit(handle, kind);
}

template <class Action>
void PtzActionServer::submit(actionlib::ServerGoalHandle<Action> handle, ActionKind kind)
{
  const PtzSample current = backend_->sample();
  if constexpr (std::is_same_v<Action, PtzTrackDetectionsAction>)
  {
    // Its result and feedback are not Ptz's: DetectionTracking converts, submits and runs it.
    detection_tracking_->submit(handle, statusPoster(), current);
  }
  else
  {
    const auto goal = handle.getGoal();
    const ConvertedGoal converted = translator_->convert(*goal, kind, current);
    typename GoalHandleAdapter<Action>::Result result;
    GoalTranslator::fillResult(result, converted);
    supervisor_->submit(std::make_unique<GoalHandleAdapter<Action>>(handle, kind, statusPoster(), result), current,
                        converted);
    if constexpr (std::is_same_v<Action, PtzFrameAction>)
    {
      const std::string& id = handle.getGoalID().id;
      if (kind == ActionKind::TRACK_FRAME && supervisor_->isRunning(actionName(kind), id))
      {
        frame_tracking_->start(actionName(kind), id, goal->frame_id, goal->zoom);
      }
    }
  }
}

template <class Action>
void PtzActionServer::onCancel(actionlib::ServerGoalHandle<Action> handle, ActionKind kind)
{
  if (!frame_hold_->cancel(handle.getGoalID().id))
  {
    supervisor_->cancel(actionName(kind), handle.getGoalID().id);
  }
}

void PtzActionServer::onGoal(actionlib::ServerGoalHandle<PtzTourAction> handle, ActionKind kind)
{
  status_hold_.goalArrived(clock_.now());
  frame_hold_->supersede(kind);
  tours_->onGoal(handle);
}

void PtzActionServer::onCancel(actionlib::ServerGoalHandle<PtzTourAction> handle, ActionKind)
{
  tours_->onCancel(handle);
}

void PtzActionServer::lookAt(const geometry_msgs::PointStamped& point)
{
  // No status hold: a clicked point has no actionlib client that could miss its status.
  frame_hold_->supersede(ActionKind::CLICKED_POINT);
  const std::string id = std::string(CLICKED_POINT_GOAL.action) + "_" + std::to_string(++clicked_points_);
  const auto submit_point = [this, point, id] {
    const PtzSample current = backend_->sample();
    supervisor_->submit(std::make_unique<LoggedGoal>(CLICKED_POINT_GOAL, id, describePoint(point)), current,
                        translator_->convert(point, current));
  };
  if (frame_hold_->mustWait(point.header.frame_id))
  {
    const std::string where = describePoint(point);
    frame_hold_->hold({ id, point.header.frame_id, submit_point,
                        [where](const std::string& text) {
                          ROS_WARN("look_at_clicked_point: not aiming at %s: %s", where.c_str(), text.c_str());
                        },
                        [](const std::string&) {} });
    return;
  }
  submit_point();
}

void PtzActionServer::centrePixel(const ros::Time& stamp, const PixelGoal& goal)
{
  // No status hold: a click has no actionlib client that could miss its status.
  frame_hold_->supersede(ActionKind::IMAGE_CLICK);
  const std::string id = std::string(IMAGE_CLICK_GOAL.action) + "_" + std::to_string(++image_clicks_count_);
  const PtzSample current = backend_->sample();
  supervisor_->submit(std::make_unique<LoggedGoal>(IMAGE_CLICK_GOAL, id, describePixel(goal, stamp)), current,
                      pixel_goals_->convert(goal, stamp, current));
}

}  // namespace ptz_action_server

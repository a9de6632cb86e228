#include "ptz_action_server/ros/ptz_action_server.h"

#include <algorithm>
#include <cmath>

#include <boost/make_shared.hpp>
#include <tf2/exceptions.h>
#include <tf2_eigen/tf2_eigen.h>

#include "ptz_action_server/core/goal_validation.h"
#include "ptz_action_server/core/limits.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
constexpr double STATE_RATE = 10.0;  ///< Hz, fixed by the contract
constexpr double STATE_RATE_TOLERANCE = 0.02;
constexpr int STATE_RATE_WINDOW = 10;             ///< ticks the measured rate is averaged over
constexpr double FRAME_LOOKUP_CACHE_TIME = 10.0;  ///< s of tf history kept for frame goals

Eigen::Isometry3d identity()
{
  return Eigen::Isometry3d::Identity();
}

/// Hands one state sample from the state thread to the main queue.
class SampleCallback : public ros::CallbackInterface
{
public:
  SampleCallback(std::function<void(const PtzSample&)> handler, const PtzSample& sample)
    : handler_(std::move(handler)), sample_(sample)
  {
  }
  CallResult call() override
  {
    handler_(sample_);
    return Success;
  }

private:
  std::function<void(const PtzSample&)> handler_;
  PtzSample sample_;
};
}  // namespace

const char* actionName(ActionKind kind)
{
  switch (kind)
  {
    case ActionKind::POSITION_ABS:
      return "position_abs";
    case ActionKind::POSITION_REL:
      return "position_rel";
    case ActionKind::VELOCITY:
      return "velocity";
    case ActionKind::POSITION_ABS_TF:
      return "position_abs_tf";
    case ActionKind::FRAME:
      return "frame";
  }
  return "?";
}

namespace
{
/// actionlib's goal handle of any of the three action types, seen through the supervisor's GoalHandle.
template <class Action>
class GoalHandleAdapter : public GoalHandle
{
public:
  using Handle = actionlib::ServerGoalHandle<Action>;
  using Result = typename Action::_action_result_type::_result_type;
  using Feedback = typename Action::_action_feedback_type::_feedback_type;

  GoalHandleAdapter(const Handle& handle, ActionKind kind)
    : handle_(handle), action_(actionName(kind)), id_(handle.getGoalID().id)
  {
  }
  const std::string& action() const override
  {
    return action_;
  }
  const std::string& id() const override
  {
    return id_;
  }
  void accept(const std::string& text) override
  {
    handle_.setAccepted(text);
  }
  void reject(const std::string& text) override
  {
    ROS_WARN_THROTTLE(1.0, "%s goal rejected: %s", action_.c_str(), text.c_str());
    handle_.setRejected(result(false), text);
  }
  void publishFeedback(const AxisValues& remaining) override
  {
    feedback_.pan_remaining = static_cast<float>(remaining[PAN]);
    feedback_.tilt_remaining = static_cast<float>(remaining[TILT]);
    feedback_.zoom_remaining = static_cast<float>(remaining[ZOOM]);
    handle_.publishFeedback(feedback_);
  }
  void succeed(const std::string& text) override
  {
    ROS_DEBUG("%s goal succeeded: %s", action_.c_str(), text.c_str());
    handle_.setSucceeded(result(true), text);
  }
  void abort(const std::string& text) override
  {
    ROS_WARN("%s goal aborted: %s", action_.c_str(), text.c_str());
    handle_.setAborted(result(false), text);
  }
  void preempt(const std::string& text) override
  {
    ROS_DEBUG("%s goal preempted: %s", action_.c_str(), text.c_str());
    handle_.setCanceled(result(false), text);
  }

private:
  static Result result(bool success)
  {
    Result result;
    result.success = success;
    return result;
  }

  Handle handle_;
  std::string action_;
  std::string id_;
  Feedback feedback_;
};
}  // namespace

NodeConfig NodeConfig::load(const ParamReader& params)
{
  NodeConfig config;
  config.backend = params.text("backend", config.backend);
  config.clamp_goals = params.flag("clamp_goals", config.clamp_goals);
  config.publish_tf = params.flag("publish_tf", config.publish_tf);
  config.names.pan_joint = params.text("pan_joint", config.names.pan_joint);
  config.names.tilt_joint = params.text("tilt_joint", config.names.tilt_joint);
  config.names.camera_link = params.text("camera_link", config.names.camera_link);
  GoalMonitorConfig& monitor = config.monitor;
  monitor.tolerance[PAN] = params.number("tolerance/pan", monitor.tolerance[PAN], 1e-6, 0.5);
  monitor.tolerance[TILT] = params.number("tolerance/tilt", monitor.tolerance[TILT], 1e-6, 0.5);
  monitor.tolerance[ZOOM] = params.number("tolerance/zoom", monitor.tolerance[ZOOM], 1e-6, 10.0);
  monitor.stall_timeout = params.number("stall_timeout", monitor.stall_timeout, 0.05, 60.0);
  monitor.fixed_timeout = params.number("goal_timeout", monitor.fixed_timeout, 0.0, 3600.0);
  monitor.timeout_scale = params.number("goal_timeout_scale", monitor.timeout_scale, 1.0, 100.0);
  monitor.timeout_margin = params.number("goal_timeout_margin", monitor.timeout_margin, 0.0, 600.0);
  monitor.stop_timeout = params.number("stop_timeout", monitor.stop_timeout, 0.1, 60.0);
  config.action_queue_size = params.integer("action_queue_size", config.action_queue_size, 1, 100000);
  config.status_list_timeout = params.number("status_list_timeout", config.status_list_timeout, 0.1, 3600.0);
  return config;
}

PtzActionServer::PtzActionServer(const ros::NodeHandle& node_handle, const NodeConfig& config,
                                 const PtzKinematics& kinematics, std::shared_ptr<PtzBackend> backend)
  : node_handle_(node_handle)
  , state_node_handle_(node_handle)
  , config_(config)
  , kinematics_(kinematics)
  , backend_(std::move(backend))
{
  state_node_handle_.setCallbackQueue(&state_queue_);
}

PtzActionServer::~PtzActionServer()
{
  // Stop the state thread first: it posts samples that point at this object.
  state_timer_.stop();
  if (state_spinner_)
  {
    state_spinner_->stop();
  }
  node_handle_.getCallbackQueue()->removeByID(reinterpret_cast<uint64_t>(this));
  if (supervisor_)
  {
    supervisor_->shutdown("the node is shutting down");
  }
}

void PtzActionServer::start()
{
  backend_->start();

  // Goals are checked against the tighter of the device's and the URDF's limits.
  const LimitIntersection intersection = intersectLimits(backend_->capabilities(), urdfLimits(kinematics_));
  for (const std::string& warning : intersection.warnings)
  {
    ROS_WARN("%s: %s", backend_->name().c_str(), warning.c_str());
  }
  limits_ = intersection.limits;
  supervisor_ = std::make_unique<GoalSupervisor>(backend_, limits_, config_.monitor, config_.clamp_goals,
                                                 std::make_shared<SystemClock>());

  // Publishers and the 10 Hz state timer on their own queue and spinner.
  state_publisher_ = state_node_handle_.advertise<PtzState>("ptz_state", 10);
  joint_state_publisher_ = state_node_handle_.advertise<sensor_msgs::JointState>("joint_states", 10);
  joint_state_message_.name = { kinematics_.panJoint().name, kinematics_.tiltJoint().name };
  joint_state_message_.position.assign(2, 0.0);
  joint_state_message_.velocity.assign(2, 0.0);
  if (config_.publish_tf)
  {
    transform_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    static_broadcaster_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
    joint_transforms_.resize(2);
    const JointModel* joints[] = { &kinematics_.panJoint(), &kinematics_.tiltJoint() };
    for (std::size_t index = 0; index < 2; ++index)
    {
      joint_transforms_[index].header.frame_id = joints[index]->parent_link;
      joint_transforms_[index].child_frame_id = joints[index]->child_link;
    }
    publishStaticTransforms();
  }

  diagnostics_ = std::make_unique<diagnostic_updater::Updater>(state_node_handle_, ros::NodeHandle("~"));
  diagnostics_->setHardwareID(backend_->name());
  diagnostics_->add("Backend", this, &PtzActionServer::diagnoseBackend);
  state_rate_min_ = STATE_RATE;
  state_rate_max_ = STATE_RATE;
  state_rate_ = std::make_unique<diagnostic_updater::FrequencyStatus>(
      diagnostic_updater::FrequencyStatusParam(&state_rate_min_, &state_rate_max_, STATE_RATE_TOLERANCE,
                                               STATE_RATE_WINDOW),
      "ptz_state rate");
  diagnostics_->add(*state_rate_);

  state_timer_ = state_node_handle_.createSteadyTimer(ros::WallDuration(1.0 / STATE_RATE),
                                                      [this](const ros::SteadyTimerEvent&) { onStateTick(); });
  state_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &state_queue_);
  state_spinner_->start();

  tf_buffer_ = std::make_unique<tf2_ros::Buffer>(ros::Duration(FRAME_LOOKUP_CACHE_TIME));
  // No dedicated thread: tf2_ros polls its queue every 10 ms, which alone costs more than the idle budget.
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, node_handle_, false);

  // A storm of goals from several clients must lose none: large actionlib queues, and finished goals leave the
  // status list after status_list_timeout, since actionlib republishes the whole list on every goal transition.
  // Parameters already set under an action's namespace win.
  for (ActionKind kind : { ActionKind::POSITION_ABS, ActionKind::POSITION_REL, ActionKind::VELOCITY,
                           ActionKind::POSITION_ABS_TF, ActionKind::FRAME })
  {
    ros::NodeHandle action_handle(node_handle_, std::string("move_ptz/") + actionName(kind));
    for (const char* name : { "actionlib_server_sub_queue_size", "actionlib_server_pub_queue_size" })
    {
      if (!action_handle.hasParam(name))
      {
        action_handle.setParam(name, config_.action_queue_size);
      }
    }
    if (!action_handle.hasParam("status_list_timeout"))
    {
      action_handle.setParam("status_list_timeout", config_.status_list_timeout);
    }
  }
  auto make_ptz_server = [this](ActionKind kind) {
    return std::make_unique<PtzServer>(
        node_handle_, std::string("move_ptz/") + actionName(kind),
        [this, kind](PtzServer::GoalHandle handle) { onGoal<PtzAction>(handle, kind); },
        [this, kind](PtzServer::GoalHandle handle) { onCancel<PtzAction>(handle, kind); }, false);
  };
  position_abs_server_ = make_ptz_server(ActionKind::POSITION_ABS);
  position_rel_server_ = make_ptz_server(ActionKind::POSITION_REL);
  velocity_server_ = make_ptz_server(ActionKind::VELOCITY);
  position_abs_tf_server_ = std::make_unique<PtzRelToServer>(
      node_handle_, "move_ptz/position_abs_tf",
      [this](PtzRelToServer::GoalHandle handle) { onGoal<PtzRelToAction>(handle, ActionKind::POSITION_ABS_TF); },
      [this](PtzRelToServer::GoalHandle handle) { onCancel<PtzRelToAction>(handle, ActionKind::POSITION_ABS_TF); },
      false);
  frame_server_ = std::make_unique<PtzFrameServer>(
      node_handle_, "move_ptz/frame",
      [this](PtzFrameServer::GoalHandle handle) { onGoal<PtzFrameAction>(handle, ActionKind::FRAME); },
      [this](PtzFrameServer::GoalHandle handle) { onCancel<PtzFrameAction>(handle, ActionKind::FRAME); }, false);
  position_abs_server_->start();
  position_rel_server_->start();
  velocity_server_->start();
  position_abs_tf_server_->start();
  frame_server_->start();
  ROS_INFO("ptz_action_server ready with backend '%s': pan [%.3f, %.3f] rad, tilt [%.3f, %.3f] rad, zoom %s",
           backend_->name().c_str(), limits_.axes[PAN].range.min, limits_.axes[PAN].range.max,
           limits_.axes[TILT].range.min, limits_.axes[TILT].range.max,
           limits_.axes[ZOOM].present ?
               formatText("[%.1f, %.1f] X", limits_.axes[ZOOM].range.min, limits_.axes[ZOOM].range.max).c_str() :
               "none");
}

template <class Action>
void PtzActionServer::onGoal(actionlib::ServerGoalHandle<Action> handle, ActionKind kind)
{
  const auto goal = handle.getGoal();
  supervisor_->submit(
      std::make_unique<GoalHandleAdapter<Action>>(handle, kind),
      [&](const PtzSample& current, GoalCommand& command) { return toCommand(*goal, kind, current, command); });
}

template <class Action>
void PtzActionServer::onCancel(actionlib::ServerGoalHandle<Action> handle, ActionKind kind)
{
  supervisor_->cancel(actionName(kind), handle.getGoalID().id);
}

std::string PtzActionServer::toCommand(const PtzGoal& goal, ActionKind kind, const PtzSample& sample,
                                       GoalCommand& command) const
{
  const AxisValues values{ { goal.pan, goal.tilt, goal.zoom } };
  switch (kind)
  {
    case ActionKind::POSITION_REL:
      command.values = values;
      for (Axis axis : ALL_AXES)
      {
        command.values[axis] += limits_.axes[axis].present ? sample.position[axis] : 0.0;
      }
      return findNonFinite(values, "offset");
    case ActionKind::VELOCITY:
      command.velocity = true;
      command.values = values;
      return findNonFinite(values, "velocity");
    default:
      command.values = values;
      return findNonFinite(values, "position");
  }
}

std::string PtzActionServer::toCommand(const PtzRelToGoal& goal, ActionKind, const PtzSample&,
                                       GoalCommand& command) const
{
  std::string reason = findNonFinite({ { goal.pan, goal.tilt, goal.zoom } }, "position");
  Eigen::Isometry3d frame_in_base = identity();
  if (reason.empty())
  {
    reason = lookupFrame(goal.frame_id, frame_in_base);
  }
  if (!reason.empty())
  {
    return reason;
  }
  // The goal's pan and tilt follow the contract's convention in the axes of frame_id.
  const Eigen::Vector3d in_base = frame_in_base.linear() * directionOf(goal.pan, goal.tilt);
  command.values[ZOOM] = goal.zoom;
  if (!kinematics_.aimAlong(in_base, command.values[PAN], command.values[TILT]))
  {
    return "no pan and tilt aim the camera along that direction of '" + goal.frame_id + "'";
  }
  return {};
}

std::string PtzActionServer::toCommand(const PtzFrameGoal& goal, ActionKind, const PtzSample&,
                                       GoalCommand& command) const
{
  std::string reason = findNonFinite({ { 0.0, 0.0, goal.zoom } }, "position");
  Eigen::Isometry3d frame_in_base = identity();
  if (reason.empty())
  {
    reason = lookupFrame(goal.frame_id, frame_in_base);
  }
  if (!reason.empty())
  {
    return reason;
  }
  command.values[ZOOM] = goal.zoom;
  if (!kinematics_.aimAt(frame_in_base.translation(), command.values[PAN], command.values[TILT]))
  {
    return "cannot point at the origin of '" + goal.frame_id + "': it is too close to the camera";
  }
  return {};
}

std::string PtzActionServer::lookupFrame(const std::string& frame_id, Eigen::Isometry3d& frame_in_base) const
{
  if (frame_id.empty())
  {
    return "frame_id is empty";
  }
  try
  {
    // Time 0: the latest transform, without waiting, so other goals are never held up.
    frame_in_base = tf2::transformToEigen(tf_buffer_->lookupTransform(kinematics_.baseFrame(), frame_id, ros::Time(0)));
  }
  catch (const tf2::TransformException& error)
  {
    return "frame '" + frame_id + "' is unknown to tf: " + error.what();
  }
  return {};
}

void PtzActionServer::onStateTick()
{
  const PtzSample sample = backend_->sample();
  state_message_.mode = static_cast<int8_t>(supervisor_->mode());
  state_message_.pan = static_cast<float>(sample.position[PAN]);
  state_message_.tilt = static_cast<float>(sample.position[TILT]);
  state_message_.zoom = static_cast<float>(sample.position[ZOOM]);
  state_publisher_.publish(state_message_);
  state_rate_->tick();

  const ros::Time stamp = toRosTime(sample.stamp);
  joint_state_message_.header.stamp = stamp;
  joint_state_message_.position[0] = sample.position[PAN];
  joint_state_message_.position[1] = sample.position[TILT];
  joint_state_message_.velocity[0] = sample.velocity[PAN];
  joint_state_message_.velocity[1] = sample.velocity[TILT];
  joint_state_publisher_.publish(joint_state_message_);

  if (transform_broadcaster_)
  {
    const double values[] = { sample.position[PAN], sample.position[TILT] };
    const JointModel* joints[] = { &kinematics_.panJoint(), &kinematics_.tiltJoint() };
    for (std::size_t index = 0; index < 2; ++index)
    {
      joint_transforms_[index].header.stamp = stamp;
      joint_transforms_[index].transform = tf2::eigenToTransform(joints[index]->transform(values[index])).transform;
    }
    transform_broadcaster_->sendTransform(joint_transforms_);
  }
  diagnostics_->update();

  if (supervisor_->goalActive())
  {
    node_handle_.getCallbackQueue()->addCallback(
        boost::make_shared<SampleCallback>([this](const PtzSample& handed) { supervisor_->supervise(handed); }, sample),
        reinterpret_cast<uint64_t>(this));
  }
}

void PtzActionServer::publishStaticTransforms()
{
  std::vector<geometry_msgs::TransformStamped> transforms;
  const ros::Time now = ros::Time::now();
  for (const JointModel& joint : kinematics_.fixedJoints())
  {
    geometry_msgs::TransformStamped transform = tf2::eigenToTransform(joint.transform(0.0));
    transform.header.stamp = now;
    transform.header.frame_id = joint.parent_link;
    transform.child_frame_id = joint.child_link;
    transforms.push_back(transform);
  }
  if (!transforms.empty())
  {
    static_broadcaster_->sendTransform(transforms);
  }
}

void PtzActionServer::diagnoseBackend(diagnostic_updater::DiagnosticStatusWrapper& status)
{
  const PtzSample sample = backend_->sample();
  if (sample.link_up)
  {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "link up");
  }
  else
  {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "link down");
  }
  status.add("backend", backend_->name());
  status.add("link", sample.link_up ? "up" : "down");
  status.add("state age (s)", secondsBetween(sample.stamp, clock_.now()));
  status.add("mode", static_cast<int>(supervisor_->mode()));
  status.add("device faults", sample.fault_count);
  std::vector<DiagnosticValue> values;
  backend_->diagnostics(values);
  for (const DiagnosticValue& value : values)
  {
    status.add(value.first, value.second);
  }
}

ros::Time PtzActionServer::toRosTime(TimePoint stamp) const
{
  const double age = std::max(0.0, secondsBetween(stamp, clock_.now()));
  return ros::Time::now() - ros::Duration(age);
}

}  // namespace ptz_action_server

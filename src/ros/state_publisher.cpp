#include "ptz_action_server/ros/state_publisher.h"

#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <limits>

#include <tf2_eigen/tf2_eigen.h>

#include "ptz_action_server/core/capabilities.h"

namespace ptz_action_server
{
namespace
{
constexpr double STATE_RATE = 10.0;  ///< Hz, fixed by the contract
constexpr double STATE_RATE_TOLERANCE = 0.02;
constexpr int STATE_RATE_WINDOW = 10;  ///< ticks the measured rate is averaged over

/// When the first tick of a camera started now is due: on one grid of the period for every camera of the process, so
/// a nodelet manager's cameras tick together, in one wake-up of the timer thread (and of roscpp's poll thread, which
/// then writes all their messages in one pass over its publications) instead of one each, spread over the period.
TimerThread::Clock::time_point firstTick(TimerThread::Clock::duration period)
{
  static const TimerThread::Clock::time_point grid = TimerThread::Clock::now();
  return grid + ((TimerThread::Clock::now() - grid) / period + 1) * period;
}

static_assert(static_cast<int>(GoalMode::IDLE) == PtzState::MODE_IDLE &&
                  static_cast<int>(GoalMode::POSITION) == PtzState::MODE_POSITION &&
                  static_cast<int>(GoalMode::VELOCITY) == PtzState::MODE_VELOCITY,
              "GoalMode must keep PtzState's mode values");
}  // namespace

StatePublisher::StatePublisher(const ros::NodeHandle& node_handle, const std::string& node_name,
                               const PtzKinematics& kinematics, std::shared_ptr<PtzBackend> backend,
                               const GoalSupervisor& supervisor, const Capabilities& limits, bool publish_tf,
                               SampleHandler hand_over)
  : node_handle_(node_handle)
  , node_name_(node_name)
  , kinematics_(kinematics)
  , backend_(std::move(backend))
  , supervisor_(supervisor)
  , limits_(limits)
  , publish_tf_(publish_tf)
  , hand_over_(std::move(hand_over))
{
}

StatePublisher::~StatePublisher()
{
  if (timer_)
  {
    timer_->cancel(tick_);
  }
  if (transforms_)
  {
    transforms_->removeStatic(this);
  }
}

void StatePublisher::start()
{
  state_publisher_.advertise<PtzState>(node_handle_, "ptz_state", 10);
  joint_state_publisher_.advertise<sensor_msgs::JointState>(node_handle_, "joint_states", 10);
  for (Axis axis : { PAN, TILT })
  {
    if (limits_.axes[axis].feedback)
    {
      reported_joints_.push_back(axis);
      joint_state_message_.name.push_back(joint(axis).name);
    }
    else
    {
      ROS_WARN("%s: the device reports no %s position: ptz_state carries NaN for it, and joint_states and tf leave "
               "out %s",
               backend_->name().c_str(), axisName(axis), joint(axis).name.c_str());
    }
  }
  joint_state_message_.position.assign(reported_joints_.size(), 0.0);
  joint_state_message_.velocity.assign(reported_joints_.size(), 0.0);
  if (publish_tf_)
  {
    transforms_ = SharedTransforms::shared();
    joint_transforms_.resize(reported_joints_.size());
    for (std::size_t index = 0; index < reported_joints_.size(); ++index)
    {
      joint_transforms_[index].header.frame_id = joint(reported_joints_[index]).parent_link;
      joint_transforms_[index].child_frame_id = joint(reported_joints_[index]).child_link;
    }
    publishStaticTransforms();
  }

  // What the device can do does not change: described once, not in every diagnostics message.
  for (Axis axis : ALL_AXES)
  {
    capability_values_.emplace_back(std::string("can: ") + axisName(axis), describeAxis(limits_, axis));
  }
  capability_values_.emplace_back("can: device", describeExtras(limits_));

  takeWarnings();  // those of the start-up, before the first tick
  diagnostics_ = std::make_unique<diagnostic_updater::Updater>(node_handle_, ros::NodeHandle(node_name_), node_name_);
  diagnostics_->setHardwareID(backend_->name());
  diagnostics_->add("Backend", this, &StatePublisher::diagnoseBackend);
  state_rate_min_ = STATE_RATE;
  state_rate_max_ = STATE_RATE;
  state_rate_ = std::make_unique<diagnostic_updater::FrequencyStatus>(
      diagnostic_updater::FrequencyStatusParam(&state_rate_min_, &state_rate_max_, STATE_RATE_TOLERANCE,
                                               STATE_RATE_WINDOW),
      "ptz_state rate");
  diagnostics_->add(*state_rate_);

  const auto period =
      std::chrono::duration_cast<TimerThread::Clock::duration>(std::chrono::duration<double>(1.0 / STATE_RATE));
  timer_ = TimerThread::shared();
  tick_ = timer_->every(period, firstTick(period), [this] { onTick(); });
}

void StatePublisher::addFieldOfView(const FieldOfViewSettings& settings)
{
  field_of_view_ = std::make_unique<FieldOfViewPublisher>(node_handle_, settings, backend_, kinematics_.cameraFrame());
}

void StatePublisher::onTick()
{
  TickCostMeter meter(tick_costs_);
  if (meter.active())
  {
    ++tick_costs_->ticks;
    tick_costs_->tick_thread = static_cast<std::int64_t>(syscall(SYS_gettid));
  }
  const GoalSample tagged = supervisor_.sample();
  const PtzSample& sample = tagged.sample;
  state_message_.mode = static_cast<int8_t>(supervisor_.mode());
  state_message_.pan = reported(PAN, sample);
  state_message_.tilt = reported(TILT, sample);
  state_message_.zoom = reported(ZOOM, sample);
  const ros::Time now = ros::Time::now();
  const ros::Time stamp = rosStampOf(sample.stamp, clock_, now);
  if (poses_)
  {
    poses_->checkClock(now);
    poses_->record(stamp, sample);
  }
  meter.lap(TickCosts::SAMPLE);

  if (state_publisher_.publish(state_message_))
  {
    meter.sent(TickCosts::STATE);
  }
  state_rate_->tick();
  meter.lap(TickCosts::STATE);

  if (joint_state_publisher_.listened())
  {
    joint_state_message_.header.stamp = stamp;
    for (std::size_t index = 0; index < reported_joints_.size(); ++index)
    {
      joint_state_message_.position[index] = sample.position[reported_joints_[index]];
      joint_state_message_.velocity[index] = sample.velocity[reported_joints_[index]];
    }
    if (joint_state_publisher_.publish(joint_state_message_))
    {
      meter.sent(TickCosts::JOINT_STATES);
    }
  }
  meter.lap(TickCosts::JOINT_STATES);

  if (field_of_view_ && limits_.axes[ZOOM].feedback == limits_.axes[ZOOM].present &&
      field_of_view_->publish(stamp, sample.position[ZOOM]))
  {
    meter.sent(TickCosts::FIELD_OF_VIEW);
  }
  meter.lap(TickCosts::FIELD_OF_VIEW);

  // A state the device has not renewed (its link is down) is not sent again: tf takes no repeated stamps (the last
  // one sent is kept, so a listener that comes later gets the next new state).
  if (transforms_ && !joint_transforms_.empty() && sample.stamp > last_transform_stamp_ && transforms_->listened())
  {
    last_transform_stamp_ = sample.stamp;
    for (std::size_t index = 0; index < reported_joints_.size(); ++index)
    {
      const Axis axis = reported_joints_[index];
      joint_transforms_[index].header.stamp = stamp;
      joint_transforms_[index].transform =
          tf2::eigenToTransform(joint(axis).transform(sample.position[axis])).transform;
    }
    if (transforms_->send(joint_transforms_))
    {
      meter.sent(TickCosts::TF);
    }
  }
  meter.lap(TickCosts::TF);

  diagnostics_->update();
  meter.lap(TickCosts::DIAGNOSTICS);

  if (supervisor_.goalActive())
  {
    hand_over_(tagged);
  }
  meter.lap(TickCosts::HAND_OVER);

  if (tick_hook_)
  {
    meter.sent(TickCosts::STATUS_LISTS, static_cast<std::uint64_t>(tick_hook_()));
  }
  meter.lap(TickCosts::STATUS_LISTS);
}

const JointModel& StatePublisher::joint(Axis axis) const
{
  return axis == PAN ? kinematics_.panJoint() : kinematics_.tiltJoint();
}

float StatePublisher::reported(Axis axis, const PtzSample& sample) const
{
  // A zoom the device does not have is 1 (the contract); a position it does not report is unknown.
  const AxisCapability& capability = limits_.axes[axis];
  return capability.present && !capability.feedback ? std::numeric_limits<float>::quiet_NaN() :
                                                      static_cast<float>(sample.position[axis]);
}

void StatePublisher::publishStaticTransforms()
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
    transforms_->setStatic(this, transforms);
  }
}

void StatePublisher::takeWarnings()
{
  for (std::string& text : backend_->takeWarnings())
  {
    ROS_WARN("%s: %s", backend_->name().c_str(), text.c_str());
    warnings_.push_back(std::move(text));
  }
}

void StatePublisher::diagnoseBackend(diagnostic_updater::DiagnosticStatusWrapper& status)
{
  if (tick_costs_ && tick_costs_->enabled)
  {
    ++tick_costs_->messages[TickCosts::DIAGNOSTICS];  // once per diagnostics message
  }
  takeWarnings();
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
  status.add("mode", static_cast<int>(supervisor_.mode()));
  status.add("device faults", sample.fault_count);
  for (const auto& [key, value] : capability_values_)
  {
    status.add(key, value);
  }
  for (std::size_t index = 0; index < warnings_.size(); ++index)
  {
    status.add("warning " + std::to_string(index + 1), warnings_[index]);
  }
  std::vector<DiagnosticValue> values;
  backend_->diagnostics(values);
  lensDiagnostics(limits_.lens, backend_->lensState(), backend_->lastLensFault(), values);
  for (const DiagnosticValue& value : values)
  {
    status.add(value.first, value.second);
  }
}

}  // namespace ptz_action_server

#include "ptz_action_server/ros/joint_topics_backend.h"

#include <algorithm>

#include <boost/make_shared.hpp>
#include <std_msgs/Float64.h>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/ros/function_callback.h"

namespace ptz_action_server
{
namespace
{
constexpr double IDLE_WAKE_PERIOD = 0.1;  ///< s between link checks while the setpoint rests
constexpr std::array<Axis, 2> JOINT_AXES{ { PAN, TILT } };
}  // namespace

JointTopicsBackend::JointTopicsBackend(const JointTopicsConfig& config, const ros::NodeHandle& node_handle,
                                       std::shared_ptr<const Clock> clock)
  : config_(config)
  , clock_(std::move(clock))
  , node_handle_(node_handle)
  , setpoint_(config.setpoint, clock_->now())
  , estimator_(config.settle_window)
  , supervisor_(config.state_timeout, clock_)
{
  node_handle_.setCallbackQueue(&queue_);
  supervisor_.name(stateSource(), stateSource());  // topics have no connection: "connected" and ready from the start
  supervisor_.connected();
  supervisor_.ready();
}

JointTopicsBackend::~JointTopicsBackend()
{
  running_ = false;
  if (thread_.joinable())
  {
    thread_.join();
  }
  state_subscriber_.shutdown();
}

Capabilities JointTopicsBackend::capabilities() const
{
  return config_.setpoint.capabilities();
}

std::string JointTopicsBackend::stateSource() const
{
  return "joint states naming " + config_.joint_names[0] + " and " + config_.joint_names[1] + " on " +
         node_handle_.resolveName(config_.state_topic);
}

void JointTopicsBackend::start()
{
  for (Axis axis : JOINT_AXES)
  {
    command_publishers_[axis] = node_handle_.advertise<std_msgs::Float64>(config_.command_topics[axis], 10);
  }
  state_subscriber_ = node_handle_.subscribe(config_.state_topic, 10, &JointTopicsBackend::onJointState, this,
                                             ros::TransportHints().tcpNoDelay());
  running_ = true;
  thread_ = std::thread([this] { run(); });

  std::unique_lock<std::mutex> lock(mutex_);
  if (!supervisor_.waitForStartup(lock, config_.startup_timeout))
  {
    const std::uint64_t foreign = states_without_joints_;
    lock.unlock();
    running_ = false;
    thread_.join();
    throw BackendError(
        formatText("no %s within %.1f s: ", stateSource().c_str(), config_.startup_timeout) +
        (foreign > 0 ?
             formatText("%llu states came, but without both joints", static_cast<unsigned long long>(foreign)) :
             formatText("%u publisher(s) on the topic", state_subscriber_.getNumPublishers())));
  }
  setpoint_ = restingAtMeasured(clock_->now());
}

void JointTopicsBackend::goTo(const AxisValues& position)
{
  post([position](SimDeviceModel& setpoint, TimePoint now) { setpoint.goTo(position, now); });
}

void JointTopicsBackend::moveAtVelocity(const AxisValues& velocity)
{
  post([velocity](SimDeviceModel& setpoint, TimePoint now) { setpoint.moveAtVelocity(velocity, now); });
}

void JointTopicsBackend::stop()
{
  post([](SimDeviceModel& setpoint, TimePoint now) { setpoint.stop(now); });
}

void JointTopicsBackend::post(Command command)
{
  queue_.addCallback(boost::make_shared<FunctionCallback>([this, command] {
    const TimePoint now = clock_->now();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!setpoint_moving_)
      {
        setpoint_ = restingAtMeasured(now);  // the joints are where they were measured, not at an old setpoint
      }
      command(setpoint_, now);
      setpoint_moving_ = true;
    }
    publishSetpoints(now, true);
  }));
}

void JointTopicsBackend::run()
{
  while (running_)
  {
    const TimePoint now = clock_->now();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      supervisor_.check();
    }
    const double wait = publishSetpoints(now, false);
    queue_.callAvailable(ros::WallDuration(wait));
  }
}

double JointTopicsBackend::publishSetpoints(TimePoint now, bool now_anyway)
{
  const double period = 1.0 / config_.command_rate;
  AxisValues values{};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!setpoint_moving_)
    {
      return IDLE_WAKE_PERIOD;
    }
    if (!now_anyway && now < next_setpoint_at_)
    {
      return secondsBetween(now, next_setpoint_at_);
    }
    const PtzSample setpoint = setpoint_.sample(now);
    values = setpoint.position;
    setpoint_moving_ = setpoint.moving;  // the last one published is the resting setpoint
    next_setpoint_at_ = addSeconds(now, period);
    ++setpoints_published_;
  }
  for (Axis axis : JOINT_AXES)
  {
    std_msgs::Float64 command;
    command.data = values[axis];
    command_publishers_[axis].publish(command);
  }
  return period;
}

void JointTopicsBackend::onJointState(const sensor_msgs::JointState::ConstPtr& message)
{
  std::array<double, 2> positions{};
  for (Axis axis : JOINT_AXES)
  {
    const auto name = std::find(message->name.begin(), message->name.end(), config_.joint_names[axis]);
    const auto index = static_cast<std::size_t>(name - message->name.begin());
    if (name == message->name.end() || index >= message->position.size())
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++states_without_joints_;
      return;
    }
    positions[axis] = message->position[index];
  }
  recordJointState(positions);
  if (listener_)
  {
    listener_();
  }
}

void JointTopicsBackend::recordJointState(const std::array<double, 2>& positions)
{
  const TimePoint now = clock_->now();
  std::lock_guard<std::mutex> lock(mutex_);
  ++states_received_;
  measured_[PAN] = positions[PAN];
  measured_[TILT] = positions[TILT];
  supervisor_.stateReported();  // a silence the thread has not noticed yet still counts
  const LinkSupervisor::Rise rise = supervisor_.refresh();
  if (rise != LinkSupervisor::Rise::NONE)
  {
    estimator_.clear();  // positions from before a loss say nothing about the motion now
  }
  if (rise == LinkSupervisor::Rise::RECOVERED)
  {
    // Back after a loss: hold the joints where they are; the old goal is not resumed. This runs on the queue that
    // serves the commands too, so a command sent on seeing the link up comes after it.
    setpoint_ = restingAtMeasured(now);
    setpoint_moving_ = true;
    next_setpoint_at_ = now;
  }
  estimator_.add(now, measured_);
}

SimDeviceModel JointTopicsBackend::restingAtMeasured(TimePoint now) const
{
  SimDeviceConfig config = config_.setpoint;
  for (Axis axis : JOINT_AXES)
  {
    config.axes[axis].initial_position = measured_[axis];
  }
  return SimDeviceModel(config, now);
}

PtzSample JointTopicsBackend::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  PtzSample sample;
  estimator_.fill(sample);
  sample.position[ZOOM] = 1.0;
  sample.moving = sample.moving || setpoint_moving_;
  // A silence counts from the moment it is over the timeout, even before the backend's thread has noticed it.
  supervisor_.check();
  sample.link_up = supervisor_.up();
  sample.link_losses = supervisor_.losses();
  return sample;
}

std::string JointTopicsBackend::lastLinkLoss() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  supervisor_.check();
  return supervisor_.lastLoss();
}

void JointTopicsBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  values.emplace_back("pan command topic", node_handle_.resolveName(config_.command_topics[PAN]));
  values.emplace_back("tilt command topic", node_handle_.resolveName(config_.command_topics[TILT]));
  values.emplace_back("joint state topic", node_handle_.resolveName(config_.state_topic));
  addCounts(values, { { "joint states received", states_received_ },
                      { "joint states without both joints", states_without_joints_ },
                      { "setpoints published", setpoints_published_ } });
}

}  // namespace ptz_action_server

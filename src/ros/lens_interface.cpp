#include "ptz_action_server/ros/lens_interface.h"

#include <utility>

namespace ptz_action_server
{
namespace
{
PtzLensCapability lensControlMessage(const LensControl& control)
{
  PtzLensCapability message;
  message.present = control.present;
  message.auto_mode = control.auto_mode;
  message.velocity = control.velocity;
  message.absolute = control.absolute;
  message.feedback = control.feedback;
  message.one_push = control.one_push;
  message.limitation = control.limitation;
  return message;
}
}  // namespace

LensInterfaceConfig LensInterfaceConfig::load(const ParamReader& params)
{
  LensInterfaceConfig config;
  config.velocity_timeout = params.number("lens/velocity_timeout", config.velocity_timeout, 0.05, 60.0);
  config.state_rate = params.number("lens/state_rate", config.state_rate, 0.1, 100.0);
  return config;
}

PtzLensCapabilities toLensMessage(const std::string& backend, const LensCapabilities& lens)
{
  PtzLensCapabilities message;
  message.backend = backend;
  message.focus = lensControlMessage(lens.focus);
  message.iris = lensControlMessage(lens.iris);
  return message;
}

LensInterface::LensInterface(const ros::NodeHandle& node_handle, std::shared_ptr<PtzBackend> backend,
                             const LensCapabilities& lens, const std::string& backend_name,
                             const LensInterfaceConfig& config)
  : node_handle_(node_handle)
  , backend_(std::move(backend))
  , lens_(lens)
  , backend_name_(backend_name)
  , commander_(*backend_, lens, backend_name, config.velocity_timeout)
  , deadman_timer_(node_handle_.getCallbackQueue(), [this] { expire(); })
  , state_timer_(node_handle_.getCallbackQueue(), [this] { publishState(); })
  , state_period_(1.0 / config.state_rate)
{
  capabilities_publisher_ = node_handle_.advertise<PtzLensCapabilities>("lens_capabilities", 1, true);
  capabilities_publisher_.publish(toLensMessage(backend_name_, lens_));
  // The state is sampled only while someone listens: at rest with nobody listening the timer never wakes.
  state_publisher_ = node_handle_.advertise<PtzLensState>(
      "lens_state", 1, [this](const ros::SingleSubscriberPublisher&) { followListeners(); },
      [this](const ros::SingleSubscriberPublisher&) { followListeners(); }, ros::VoidConstPtr(), true);
  const auto velocity = [this](LensFunction function) {
    return [this, function](const std_msgs::Float64::ConstPtr& message) {
      sendFromTopic(LensCommand::velocity(function, message->data));
    };
  };
  const auto position = [this](LensFunction function) {
    return [this, function](const std_msgs::Float64::ConstPtr& message) {
      sendFromTopic(LensCommand::position(function, message->data));
    };
  };
  focus_velocity_ = node_handle_.subscribe<std_msgs::Float64>("cmd/focus", 10, velocity(LensFunction::FOCUS));
  iris_velocity_ = node_handle_.subscribe<std_msgs::Float64>("cmd/iris", 10, velocity(LensFunction::IRIS));
  focus_position_ = node_handle_.subscribe<std_msgs::Float64>("cmd/focus_position", 10, position(LensFunction::FOCUS));
  iris_position_ = node_handle_.subscribe<std_msgs::Float64>("cmd/iris_position", 10, position(LensFunction::IRIS));
  focus_auto_ = node_handle_.advertiseService<std_srvs::SetBool::Request, std_srvs::SetBool::Response>(
      "focus/set_auto", [this](std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response) {
        return setAuto(LensFunction::FOCUS, request, response);
      });
  iris_auto_ = node_handle_.advertiseService<std_srvs::SetBool::Request, std_srvs::SetBool::Response>(
      "iris/set_auto", [this](std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response) {
        return setAuto(LensFunction::IRIS, request, response);
      });
  one_push_ = node_handle_.advertiseService("focus/one_push", &LensInterface::onePush, this);
  publishState();  // latched: a late subscriber gets the lens as it was at start-up at least
  followListeners();
}

LensInterface::~LensInterface()
{
  state_timer_.stop();
  deadman_timer_.stop();
  commander_.expire(TimePoint::max());  // a focus still driving stops with the node
}

std::string LensInterface::send(const LensCommand& command)
{
  const std::string refusal = commander_.command(command, clock_.now());
  deadman_timer_.startAt(commander_.nextDeadline());
  return refusal;
}

void LensInterface::sendFromTopic(const LensCommand& command)
{
  const std::string refusal = send(command);
  if (!refusal.empty())
  {
    ROS_WARN_THROTTLE(1.0, "%s: %s refused: %s", backend_name_.c_str(), describe(command).c_str(), refusal.c_str());
  }
}

bool LensInterface::setAuto(LensFunction function, std_srvs::SetBool::Request& request,
                            std_srvs::SetBool::Response& response)
{
  const LensCommand command = LensCommand::mode(function, request.data);
  const std::string refusal = send(command);
  response.success = refusal.empty();
  response.message = refusal.empty() ? describe(command) + " sent" : refusal;
  return true;
}

bool LensInterface::onePush(std_srvs::Trigger::Request& /*request*/, std_srvs::Trigger::Response& response)
{
  const std::string refusal = send(LensCommand::onePush());
  response.success = refusal.empty();
  response.message = refusal.empty() ? "focus one-push sent" : refusal;
  return true;
}

void LensInterface::expire()
{
  for (LensFunction function : commander_.expire(clock_.now()))
  {
    ROS_DEBUG("%s: the %s velocity stream stopped: %s stopped", backend_name_.c_str(), lensFunctionName(function),
              lensFunctionName(function));
  }
  deadman_timer_.startAt(commander_.nextDeadline());
}

void LensInterface::followListeners()
{
  const std::lock_guard<std::mutex> lock(state_timer_mutex_);  // the constructor's thread and the node's queue
  const bool listened = state_publisher_.getNumSubscribers() > 0;
  if (listened && !state_timer_running_)
  {
    state_timer_.startPeriodic(state_period_);
  }
  else if (!listened && state_timer_running_)
  {
    state_timer_.stop();
  }
  state_timer_running_ = listened;
}

void LensInterface::publishState()
{
  if (state_publisher_.getNumSubscribers() == 0 && state_published_)
  {
    return;
  }
  const LensState state = backend_->lensState();
  state_message_.header.stamp = ros::Time::now();
  state_message_.focus_mode = static_cast<std::uint8_t>(state.modeOf(LensFunction::FOCUS));
  state_message_.focus = static_cast<float>(state.positionOf(LensFunction::FOCUS));
  state_message_.iris_mode = static_cast<std::uint8_t>(state.modeOf(LensFunction::IRIS));
  state_message_.iris = static_cast<float>(state.positionOf(LensFunction::IRIS));
  state_message_.faults = static_cast<std::uint32_t>(state.fault_count);
  state_publisher_.publish(state_message_);
  state_published_ = true;
}

}  // namespace ptz_action_server

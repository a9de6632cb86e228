#include "ptz_action_server/ros/velocity_topic.h"

namespace ptz_action_server
{
VelocityTopicConfig VelocityTopicConfig::load(const ParamReader& params)
{
  VelocityTopicConfig config;
  config.enabled = params.flag("cmd_velocity/enabled", config.enabled);
  config.timeout = params.number("cmd_velocity/timeout", config.timeout, 0.01, 60.0);
  return config;
}

/// A goal of the stream, as the supervisor sees it: no client, so its refusals go to the log.
class VelocityTopic::StreamGoal : public GoalHandle
{
public:
  StreamGoal(std::string id, std::weak_ptr<VelocityTopic*> topic) : id_(std::move(id)), topic_(std::move(topic))
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
    if (!text.empty())
    {
      ROS_INFO_THROTTLE(5.0, "cmd/velocity: %s", text.c_str());
    }
  }
  void reject(const std::string& text) override
  {
    ROS_WARN_THROTTLE(5.0, "cmd/velocity: velocity refused: %s", text.c_str());
  }
  void publishFeedback(const AxisValues&) override
  {
  }
  void succeed(const std::string&) override
  {
    ended();  // at a limit
  }
  void abort(const std::string& text) override
  {
    ROS_WARN_THROTTLE(5.0, "cmd/velocity: stopped: %s", text.c_str());
    ended();
  }
  void preempt(const std::string&) override
  {
    ended();
  }

private:
  void ended()
  {
    if (const std::shared_ptr<VelocityTopic*> topic = topic_.lock())
    {
      (*topic)->onGoalEnded(id_);
    }
  }

  const std::string action_ = ACTION;
  const std::string id_;
  const std::weak_ptr<VelocityTopic*> topic_;
};

VelocityTopic::VelocityTopic(const ros::NodeHandle& node_handle, const VelocityTopicConfig& config,
                             GoalSupervisor& supervisor, Converter convert)
  : config_(config)
  , supervisor_(supervisor)
  , convert_(std::move(convert))
  , silence_timer_(node_handle.getCallbackQueue(), [this] { onSilence(); })
  , self_(std::make_shared<VelocityTopic*>(this))
{
  ros::NodeHandle node(node_handle);
  subscriber_ =
      node.subscribe<PtzGoal>("cmd/velocity", 1, [this](const PtzGoal::ConstPtr& velocity) { onVelocity(*velocity); });
}

VelocityTopic::~VelocityTopic()
{
  subscriber_.shutdown();
  silence_timer_.stop();
  self_.reset();
}

void VelocityTopic::onVelocity(const PtzGoal& velocity)
{
  silence_timer_.startOnce(config_.timeout);
  const bool running = !goal_id_.empty() && supervisor_.isRunning(ACTION, goal_id_);
  const bool same = velocity.pan == last_.pan && velocity.tilt == last_.tilt && velocity.zoom == last_.zoom;
  const bool zero = velocity.pan == 0.0F && velocity.tilt == 0.0F && velocity.zoom == 0.0F;
  if ((running && same) || (!running && (zero || (yielded_ && same))))
  {
    return;  // the stream goes on as it is; or it has nothing of its own moving to change
  }
  yielded_ = false;
  goal_id_ = std::string(ACTION) + "_" + std::to_string(++goals_);
  last_ = velocity;
  PtzSample current;
  const ConvertedGoal converted = convert_(velocity, current);
  supervisor_.submit(std::make_unique<StreamGoal>(goal_id_, self_), current, converted);
}

void VelocityTopic::onSilence()
{
  yielded_ = false;
  last_ = PtzGoal();
  if (!goal_id_.empty())
  {
    supervisor_.cancel(ACTION, goal_id_);  // the device decelerates to rest; the goal ends once it does
    goal_id_.clear();                      // its end is no other goal's doing
  }
}

void VelocityTopic::onGoalEnded(const std::string& id)
{
  // Preempted by another goal, at a limit or failed: the same velocity again would do no better. The stream's own
  // replacements and its cancel end goals that are no longer goal_id_.
  if (id == goal_id_)
  {
    yielded_ = true;
  }
}

}  // namespace ptz_action_server

#include "ptz_action_server/ros/detection_tracking.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <ros/names.h>

#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace detection_tracking
{
constexpr std::uint32_t DETECTIONS_QUEUE = 10;  ///< Detections messages waiting; older images are stale anyway
constexpr double DROPPED_WARNING_PERIOD = 2.0;  ///< s between warnings about dropped detections

/// A history of one pose: the pose a detection arrives at, looked up at its image's stamp.
PoseHistoryConfig arrivalPoseConfig()
{
  PoseHistoryConfig config;
  config.capacity = 2;
  return config;
}

/// \p count as a loggable number.
unsigned long long counted(std::uint64_t count)
{
  return static_cast<unsigned long long>(count);
}
}  // namespace detection_tracking

DetectionTrackingSettings DetectionTrackingSettings::load(const ParamReader& params)
{
  DetectionTrackingSettings settings;
  settings.lost_timeout = params.number("track/lost_timeout", settings.lost_timeout, 0.05, 3600.0);
  settings.pose_history = params.flag("track/pose_history", settings.pose_history);
  return settings;
}

/// The goal being followed.
struct DetectionTracking::Goal
{
  std::string id;
  std::shared_ptr<DetectionGoalState> state;
  DetectionTracker tracker;
  std::string lost_preset;
  std::optional<GoalMonitor> returning;  ///< on the way to the lost preset: its arrival
};

DetectionTracking::DetectionTracking(const ros::NodeHandle& node_handle, const Parts& parts)
  : node_handle_(node_handle)
  , kinematics_(parts.kinematics)
  , limits_(parts.limits)
  , steering_(parts.steering)
  , settings_(parts.settings)
  , monitor_(parts.monitor)
  , pixel_(parts.pixel)
  , calibration_(parts.calibration)
  , supervisor_(parts.supervisor)
  , backend_(parts.backend)
  , poses_(parts.poses)
  , presets_(parts.presets)
  , arrival_pose_(detection_tracking::arrivalPoseConfig())
  , timer_(node_handle_.getCallbackQueue(), [this] { steer(); })
{
  if (!settings_.pose_history)
  {
    ROS_WARN("track/pose_history is false: track_detections goals see each detection from the camera's pose when it "
             "arrives, not when its image was taken (for benchmarks: a moving camera then overshoots)");
  }
}

DetectionTracking::~DetectionTracking()
{
  timer_.stop();
}

DetectionTrackerConfig DetectionTracking::configOf(const PtzTrackDetectionsGoal& goal) const
{
  DetectionTrackerConfig config;
  config.steering = steering_;
  config.target_id = goal.target_id;
  config.zoom_fraction = goal.zoom_fraction;
  config.dead_zone = goal.dead_zone;
  config.max_speed = goal.max_speed;
  config.lost_timeout = goal.lost_timeout == 0.0f ? settings_.lost_timeout : goal.lost_timeout;
  return config;
}

ConvertedGoal DetectionTracking::convert(const PtzTrackDetectionsGoal& goal, const DetectionTrackerConfig& config,
                                         const PtzSample& current) const
{
  if (goal.detections_topic.empty())
  {
    return ConvertedGoal::rejected("detections_topic is empty: name the topic of ptz_action_server/Detections");
  }
  std::string error;
  if (!ros::names::validate(goal.detections_topic, error))
  {
    return ConvertedGoal::rejected("detections_topic '" + goal.detections_topic + "' is not a topic name: " + error);
  }
  const std::string bad = findBadTrackingConfig(config);
  if (!bad.empty())
  {
    return ConvertedGoal::rejected(bad);
  }
  if (!goal.lost_preset.empty() && !presets_.find(goal.lost_preset))
  {
    return ConvertedGoal::rejected("no preset named '" + goal.lost_preset + "' (lost_preset)");
  }
  if (!pixel_.lens && !calibration_)
  {
    return ConvertedGoal::rejected("no field of view is configured (field_of_view/horizontal and vertical, or "
                                   "field_of_view/table) and no camera_info_topic: a detection's direction is unknown");
  }
  ConvertedGoal converted;
  GoalCommand& command = converted.command;
  command.track = true;
  // The first aim is where the camera is: it holds until the first detection.
  for (const Axis axis : { PAN, TILT })
  {
    const AxisCapability& capability = limits_.axes[axis];
    if (capability.present && !(capability.feedback && std::isfinite(current.position[axis])))
    {
      return ConvertedGoal::rejected(formatText("the device does not report its %s: a detection's direction needs the "
                                                "camera's pose when its image was taken",
                                                axisName(axis)));
    }
    command.values[axis] = capability.present ? current.position[axis] : 0.0;
  }
  // The zoom stays where it is (0: left alone on a device that cannot position or report it).
  const AxisCapability& zoom = limits_.axes[ZOOM];
  command.values[ZOOM] = zoom.present && zoom.absolute && zoom.feedback ? current.position[ZOOM] : 0.0;
  return converted;
}

PixelCamera DetectionTracking::camera() const
{
  PixelCamera camera;
  camera.field_of_view = pixel_.lens ? &*pixel_.lens : nullptr;
  camera.image_upside_down = pixel_.image_upside_down;
  if (calibration_)
  {
    camera.calibration = calibration_();
  }
  return camera;
}

void DetectionTracking::submit(const Handle& handle, const StatusPoster& post_status, const PtzSample& current)
{
  const PtzTrackDetectionsGoal& goal = *handle.getGoal();
  const DetectionTrackerConfig config = configOf(goal);
  const ConvertedGoal converted = convert(goal, config, current);
  auto state = std::make_shared<DetectionGoalState>();
  state->handle = handle;
  state->post_status = post_status;
  supervisor_.submit(std::make_unique<DetectionGoalHandle>(state), current, converted);
  if (converted.rejection.empty() &&
      supervisor_.isRunning(actionName(ActionKind::TRACK_DETECTIONS), handle.getGoalID().id))
  {
    start(goal, config, std::move(state));
  }
}

void DetectionTracking::start(const PtzTrackDetectionsGoal& goal, const DetectionTrackerConfig& config,
                              std::shared_ptr<DetectionGoalState> state)
{
  stop();  // the goal it replaces was preempted
  const std::string id = state->handle.getGoalID().id;
  try
  {
    goal_.reset(new Goal{ id, std::move(state), DetectionTracker(kinematics_, limits_, camera(), config, clock_.now()),
                          goal.lost_preset, std::nullopt });
  }
  catch (const ConfigError& error)
  {
    supervisor_.abort(actionName(ActionKind::TRACK_DETECTIONS), id, error.what());
    return;
  }
  detections_ = node_handle_.subscribe(goal.detections_topic, detection_tracking::DETECTIONS_QUEUE,
                                       &DetectionTracking::onDetections, this, ros::TransportHints().tcpNoDelay());
  ROS_INFO("track_detections: following %s%s", detections_.getTopic().c_str(),
           config.target_id.empty() ? "" : (" of id '" + config.target_id + "'").c_str());
  timer_.startPeriodic(1.0 / steering_.rate);
}

void DetectionTracking::onDetections(const Detections::ConstPtr& message)
{
  if (!goal_ || goal_->returning)
  {
    return;
  }
  constexpr std::uint32_t MAX_SIZE = 1U << 30;
  image_.stamp = headerStampOf(message->header.stamp);
  image_.width = static_cast<int>(std::min(message->image_width, MAX_SIZE));
  image_.height = static_cast<int>(std::min(message->image_height, MAX_SIZE));
  image_.detections.resize(message->detections.size());
  for (std::size_t index = 0; index < message->detections.size(); ++index)
  {
    const Detection& in = message->detections[index];
    ImageDetection& out = image_.detections[index];
    out.id = in.id;  // assigned: the string keeps its buffer
    out.score = in.score;
    out.u = in.u;
    out.v = in.v;
    out.width = in.width;
    out.height = in.height;
  }
  const PoseHistory* history = &poses_.history();
  if (!settings_.pose_history)
  {
    // As a tracker without the history sees it: the image taken where the camera is now.
    AxisValues pose = backend_.sample().position;
    for (const Axis axis : ALL_AXES)
    {
      if (limits_.axes[axis].present && !limits_.axes[axis].feedback)
      {
        pose[axis] = std::numeric_limits<double>::quiet_NaN();
      }
    }
    arrival_pose_.clear();
    arrival_pose_.add(image_.stamp, pose);
    history = &arrival_pose_;
  }
  const DetectionObservation observation = goal_->tracker.observe(image_, *history, clock_.now());
  if (observation.use == DetectionUse::DROPPED)
  {
    ROS_WARN_THROTTLE(detection_tracking::DROPPED_WARNING_PERIOD, "track_detections: detections on %s dropped: %s",
                      detections_.getTopic().c_str(), observation.problem.c_str());
  }
}

void DetectionTracking::steer()
{
  if (!goal_ || !supervisor_.isRunning(actionName(ActionKind::TRACK_DETECTIONS), goal_->id))
  {
    stop();  // the goal ended: preempted, cancelled or aborted
    return;
  }
  const PtzSample current = backend_.sample();
  if (goal_->returning)
  {
    judgeReturn(current);
    return;
  }
  const TrackingStep step = goal_->tracker.step(current, headerStampOf(ros::Time::now()), clock_.now());
  if (step.state == TrackingState::TRACKING)
  {
    supervisor_.steer(actionName(ActionKind::TRACK_DETECTIONS), goal_->id, step.command, step.aim);
    goal_->state->publishFeedback(step.feedback);
  }
  else if (step.state == TrackingState::LOST)
  {
    lose(step.lost_reason, current);
  }
}

void DetectionTracking::lose(const std::string& reason, const PtzSample& current)
{
  Goal& goal = *goal_;
  if (goal.lost_preset.empty())
  {
    end(reason);  // the supervisor stops the device: it holds where it is
    return;
  }
  const std::optional<AxisValues> pose = presets_.find(goal.lost_preset);
  if (!pose)
  {
    end(reason + "; no preset named '" + goal.lost_preset + "' any more: holding");
    return;
  }
  const ValidatedGoal validated = validatePositionGoal(*pose, limits_, true);
  if (!validated.accepted)
  {
    end(reason + "; preset '" + goal.lost_preset + "' refused: " + validated.message);
    return;
  }
  GoalCommand command;
  command.values = validated.values;
  if (!supervisor_.steer(actionName(ActionKind::TRACK_DETECTIONS), goal.id, command, validated.values))
  {
    stop();
    return;
  }
  Capabilities judged = limits_;
  for (const Axis axis : ALL_AXES)
  {
    judged.axes[axis].present = validated.judged[axis];
  }
  goal.returning.emplace(GoalMonitor::forPosition(validated.values, current, judged, monitor_, clock_.now()));
  goal.state->lost = reason;
  detections_.shutdown();
  ROS_INFO("track_detections: %s; going to preset '%s'", reason.c_str(), goal.lost_preset.c_str());
}

void DetectionTracking::judgeReturn(const PtzSample& current)
{
  const GoalVerdict verdict = goal_->returning->update(current, clock_.now());
  if (verdict.phase == GoalPhase::SUCCEEDED)
  {
    end("at preset '" + goal_->lost_preset + "'");
  }
  else if (verdict.phase == GoalPhase::ABORTED)
  {
    end("did not reach preset '" + goal_->lost_preset + "': " + verdict.reason);
  }
}

void DetectionTracking::end(const std::string& text)
{
  supervisor_.abort(actionName(ActionKind::TRACK_DETECTIONS), goal_->id, text);
  stop();
}

void DetectionTracking::stop()
{
  timer_.stop();
  detections_.shutdown();
  if (goal_)
  {
    const DetectionCounts& counts = goal_->tracker.counts();
    ROS_INFO("track_detections goal %s: %llu images of detections: %llu used, %llu without a match, %llu dropped, "
             "%llu stale",
             goal_->id.c_str(), detection_tracking::counted(counts.images), detection_tracking::counted(counts.used),
             detection_tracking::counted(counts.no_match), detection_tracking::counted(counts.dropped),
             detection_tracking::counted(counts.stale));
    goal_.reset();
  }
}

}  // namespace ptz_action_server

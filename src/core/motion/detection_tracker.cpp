#include "ptz_action_server/core/motion/detection_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/motion/pinhole_view.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace detection_tracker
{
constexpr double NO_VALUE = std::numeric_limits<double>::quiet_NaN();

/// \p limits with pan and tilt no faster than \p max_speed (0: as they are).
Capabilities speedLimited(const Capabilities& limits, double max_speed)
{
  Capabilities limited = limits;
  if (max_speed > 0.0)
  {
    for (const Axis axis : { PAN, TILT })
    {
      limited.axes[axis].max_speed = std::min(limited.axes[axis].max_speed, max_speed);
    }
  }
  return limited;
}

/// Velocity commands: asked for, and every pan and tilt the device has takes them.
bool takesVelocities(const Capabilities& limits, const FrameTrackerConfig& steering)
{
  const auto takes = [&limits](Axis axis) { return !limits.axes[axis].present || limits.axes[axis].velocity; };
  return steering.feed_forward && takes(PAN) && takes(TILT);
}

FrameTrackerConfig steeringOf(const DetectionTrackerConfig& config, bool velocity)
{
  FrameTrackerConfig steering = config.steering;
  steering.feed_forward = velocity;
  steering.timeout = config.lost_timeout;
  return steering;
}

const DetectionTrackerConfig& checked(const DetectionTrackerConfig& config)
{
  const std::string problem = findBadTrackingConfig(config);
  if (!problem.empty())
  {
    throw ConfigError(problem);
  }
  return config;
}

/// The zoom an image of a device without zoom was taken at: the calibration's (or the wide end), as aimAtPixel()
/// takes it; else the reported one.
double lensZoom(const Capabilities& limits, const PixelCamera& camera, double reported)
{
  if (limits.axes[ZOOM].present)
  {
    return reported;
  }
  return camera.calibration ? camera.calibration->zoom : 1.0;
}
}  // namespace detection_tracker

std::string findBadTrackingConfig(const DetectionTrackerConfig& config)
{
  if (!(config.zoom_fraction >= 0.0 && config.zoom_fraction <= 1.0))
  {
    return formatText("zoom_fraction %g must be in (0, 1], or 0 to leave the zoom", config.zoom_fraction);
  }
  if (!(config.dead_zone >= 0.0 && config.dead_zone < 1.0))
  {
    return formatText("dead_zone %g must be in [0, 1): a part of the half image", config.dead_zone);
  }
  if (!(config.max_speed >= 0.0 && std::isfinite(config.max_speed)))
  {
    return formatText("max_speed %g rad/s must be positive, or 0 for the device's own", config.max_speed);
  }
  if (!(config.lost_timeout > 0.0 && std::isfinite(config.lost_timeout)))
  {
    return formatText("lost_timeout %g s must be positive", config.lost_timeout);
  }
  if (!(config.steering.rate > 0.0 && std::isfinite(config.steering.rate)))
  {
    return formatText("the tracking rate %g Hz must be positive", config.steering.rate);
  }
  return "";
}

DetectionTracker::DetectionTracker(const PtzKinematics& kinematics, const Capabilities& limits,
                                   const PixelCamera& camera, const DetectionTrackerConfig& config, TimePoint start)
  : kinematics_(kinematics)
  , limits_(detection_tracker::speedLimited(limits, config.max_speed))
  , camera_(camera)
  , config_(detection_tracker::checked(config))
  , velocity_(detection_tracker::takesVelocities(limits, config.steering))
  , tracker_(kinematics, limits_, detection_tracker::steeringOf(config, velocity_), detection_tracker::NO_VALUE)
  , start_(start)
  , zoom_aim_(detection_tracker::NO_VALUE)
{
}

DetectionObservation DetectionTracker::observe(const ImageDetections& image, const PoseHistory& history, TimePoint now)
{
  ++counts_.images;
  if (tracker_.hasPosition() && image.stamp <= last_stamp_)
  {
    ++counts_.stale;
    return { DetectionUse::STALE, "" };
  }
  candidates_.clear();
  for (const ImageDetection& detection : image.detections)
  {
    if (config_.target_id.empty() || detection.id == config_.target_id)
    {
      candidates_.push_back(Candidate{ &detection, PixelAim() });
    }
  }
  if (candidates_.empty())
  {
    ++counts_.no_match;
    return { DetectionUse::NO_MATCH, "" };
  }
  DetectionObservation dropped{ DetectionUse::DROPPED, "" };
  const PoseLookup pose = history.at(image.stamp);
  if (!pose.found())
  {
    dropped.problem = "the camera's pose when the image was taken is unknown: " + pose.error;
  }
  for (Candidate& candidate : candidates_)
  {
    if (!pose.found())
    {
      break;
    }
    PixelGoal goal;
    goal.u = candidate.detection->u;
    goal.v = candidate.detection->v;
    goal.image_width = image.width;
    goal.image_height = image.height;
    candidate.aim = aimAtPixel(goal, pose.pose, camera_, kinematics_, limits_);
    if (!candidate.aim.ok() && dropped.problem.empty())
    {
      dropped.problem = formatText("detection '%s' at (%g, %g) px: %s", candidate.detection->id.c_str(),
                                   candidate.detection->u, candidate.detection->v, candidate.aim.error.c_str());
    }
  }
  const Candidate* chosen = pose.found() ? choose(candidates_, image.stamp, pose.pose[PAN]) : nullptr;
  if (chosen == nullptr)
  {
    ++counts_.dropped;
    last_problem_ = dropped.problem;
    return dropped;
  }
  if (!tracker_.observeAim(chosen->aim.pan, chosen->aim.tilt, secondsOf(image.stamp), now))
  {
    ++counts_.stale;  // a stamp within the double's resolution of the newest
    return { DetectionUse::STALE, "" };
  }
  const ImageDetection& detection = *chosen->detection;
  // The principal point of the image: the same at every zoom (intrinsicsAtZoom() held to succeed, aimAtPixel() did).
  PinholeIntrinsics principal;
  intrinsicsAtZoom(camera_, camera_.calibration ? camera_.calibration->zoom : 1.0, image.width, image.height,
                   principal);
  last_u_error_ = detection.u - principal.cx;
  last_v_error_ = detection.v - principal.cy;
  last_stamp_ = image.stamp;
  last_ = detection;
  last_width_ = image.width;
  last_height_ = image.height;
  holdZoom(detection, image, pose.pose);
  ++counts_.used;
  at_last_match_ = counts_;
  return { DetectionUse::USED, "" };
}

const DetectionTracker::Candidate* DetectionTracker::choose(const std::vector<Candidate>& candidates, HeaderStamp stamp,
                                                            double image_pan) const
{
  const Candidate* chosen = nullptr;
  if (!tracker_.hasPosition())
  {
    for (const Candidate& candidate : candidates)
    {
      if (candidate.aim.ok() && (chosen == nullptr || candidate.detection->score > chosen->detection->score))
      {
        chosen = &candidate;
      }
    }
    return chosen;
  }
  const AxisValues expected = tracker_.aimAt(secondsOf(stamp), image_pan);
  const Eigen::Vector3d expected_direction = kinematics_.cameraInBase(expected[PAN], expected[TILT]).linear().col(0);
  double nearest = -2.0;  // the largest cosine of the angle to the expected direction
  for (const Candidate& candidate : candidates)
  {
    const double cosine = candidate.aim.ok() ? candidate.aim.direction.dot(expected_direction) : -2.0;
    if (candidate.aim.ok() && cosine > nearest)
    {
      nearest = cosine;
      chosen = &candidate;
    }
  }
  return chosen;
}

void DetectionTracker::holdZoom(const ImageDetection& detection, const ImageDetections& image, const AxisValues& pose)
{
  const AxisCapability& zoom = limits_.axes[ZOOM];
  const double fraction = config_.zoom_fraction;
  if (!(fraction > 0.0) || !zoom.present || !zoom.absolute || !zoom.feedback ||
      !(detection.width > 0.0 && detection.height > 0.0))
  {
    return;
  }
  const double ratio = std::max(detection.width / image.width, detection.height / image.height) / fraction;
  if (ratio >= 1.0 - ZOOM_BAND && ratio <= 1.0 + ZOOM_BAND)
  {
    return;
  }
  // Zoom in only on a target near the centre: one off to the side would leave the narrower view.
  const bool central = std::abs(last_u_error_) <= 0.25 * image.width && std::abs(last_v_error_) <= 0.25 * image.height;
  if (ratio < 1.0 && !central)
  {
    return;
  }
  // The box grown by 1 / fraction fills the view where the box itself spans the fraction of it.
  PixelGoal goal;
  goal.u = detection.u;
  goal.v = detection.v;
  goal.box_width = detection.width / fraction;
  goal.box_height = detection.height / fraction;
  goal.image_width = image.width;
  goal.image_height = image.height;
  const PixelAim aim = aimAtPixel(goal, pose, camera_, kinematics_, limits_);
  if (aim.ok() && std::isfinite(aim.zoom))
  {
    zoom_aim_ = aim.zoom;
  }
}

bool DetectionTracker::correcting(const AxisValues& aim, const PtzSample& current)
{
  const double dead_zone = config_.dead_zone;
  const double zoom = detection_tracker::lensZoom(limits_, camera_, current.position[ZOOM]);
  PinholeIntrinsics view;
  if (!(dead_zone > 0.0) || !std::isfinite(zoom) || !std::isfinite(current.position[PAN]) ||
      !std::isfinite(current.position[TILT]) ||
      !intrinsicsAtZoom(camera_, zoom, last_width_, last_height_, view).empty())
  {
    correcting_ = true;
    return true;
  }
  // Where the target, carried forward to now, is in the current view.
  const Eigen::Vector3d target = kinematics_.cameraInBase(aim[PAN], aim[TILT]).linear().col(0);
  Eigen::Vector3d optical = cameraLinkToOptical(
      kinematics_.cameraInBase(current.position[PAN], current.position[TILT]).linear().transpose() * target);
  if (camera_.image_upside_down)
  {
    optical.x() = -optical.x();
    optical.y() = -optical.y();
  }
  double u = 0.0;
  double v = 0.0;
  if (!pixelOf(view, optical, u, v))
  {
    correcting_ = true;
    return true;
  }
  const double off_centre =
      std::max(std::abs(u - view.cx) / (0.5 * view.width), std::abs(v - view.cy) / (0.5 * view.height));
  correcting_ = off_centre > (correcting_ ? 0.5 * dead_zone : dead_zone);
  return correcting_;
}

void DetectionTracker::steerZoom(const PtzSample& current, TrackingStep& step) const
{
  const AxisCapability& zoom = limits_.axes[ZOOM];
  if (!zoom.present || !zoom.absolute || !zoom.feedback || !std::isfinite(current.position[ZOOM]))
  {
    return;  // as FrameTracker commands it: left alone, or its widest view
  }
  const double target = std::isfinite(zoom_aim_) ? zoom_aim_ : current.position[ZOOM];
  step.aim[ZOOM] = std::min(std::max(target, zoom.range.min), zoom.range.max);
  if (!velocity_)
  {
    step.command.values[ZOOM] = step.aim[ZOOM];
    return;
  }
  const double speed = config_.steering.gain * (step.aim[ZOOM] - current.position[ZOOM]);
  step.command.values[ZOOM] = std::min(std::max(speed, -zoom.max_speed), zoom.max_speed);
}

TrackingStep DetectionTracker::step(const PtzSample& current, HeaderStamp stamp, TimePoint now)
{
  TrackingStep step;
  step.feedback.detection_age = detection_tracker::NO_VALUE;
  const TimePoint last_match = tracker_.hasPosition() ? tracker_.lastNewPositionAt() : start_;
  const double silent_for = secondsBetween(last_match, now);
  if (silent_for > config_.lost_timeout)
  {
    step.state = TrackingState::LOST;
    step.lost_reason = lostReason(silent_for);
  }
  if (!tracker_.hasPosition())
  {
    return step;  // WAITING, or LOST before anything matched
  }
  step.feedback.u_error = last_u_error_;
  step.feedback.v_error = last_v_error_;
  step.feedback.detection_age = secondsOf(stamp - last_stamp_);
  step.feedback.target_id = last_.id;
  if (step.state == TrackingState::LOST)
  {
    return step;
  }
  step.state = TrackingState::TRACKING;
  const double command_stamp = secondsOf(stamp);
  const AxisValues aim = tracker_.aimAt(command_stamp, current.position[PAN]);
  const bool correct = correcting(aim, current);
  PtzSample steered = current;
  if (!correct)
  {
    // No error to correct: the feed-forward alone.
    steered.position[PAN] = aim[PAN];
    steered.position[TILT] = aim[TILT];
  }
  step.command = tracker_.command(steered, command_stamp, step.aim);
  if (!velocity_)
  {
    for (const Axis axis : { PAN, TILT })
    {
      double& position = step.command.values[axis];
      if (!std::isfinite(current.position[axis]))
      {
        continue;
      }
      if (!correct)
      {
        position = current.position[axis];  // hold where it is
      }
      else if (config_.max_speed > 0.0)
      {
        // At most a step's travel at the speed limit ahead of the camera.
        const double reach = config_.max_speed / config_.steering.rate;
        position = current.position[axis] + std::min(std::max(position - current.position[axis], -reach), reach);
      }
    }
  }
  steerZoom(current, step);
  step.feedback.pan_error = step.aim[PAN] - current.position[PAN];
  step.feedback.tilt_error = step.aim[TILT] - current.position[TILT];
  return step;
}

std::string DetectionTracker::lostReason(double silent_for) const
{
  std::string reason =
      formatText("lost: no detection%s matched for %.2f s (lost_timeout %.2f s)",
                 config_.target_id.empty() ? "" : formatText(" of '%s'", config_.target_id.c_str()).c_str(), silent_for,
                 config_.lost_timeout);
  const DetectionCounts& since = at_last_match_;
  const std::uint64_t images = counts_.images - since.images;
  if (images == 0)
  {
    return reason + "; no detections arrived";
  }
  reason += formatText("; %llu images since: %llu without a match", static_cast<unsigned long long>(images),
                       static_cast<unsigned long long>(counts_.no_match - since.no_match));
  const std::uint64_t dropped = counts_.dropped - since.dropped;
  if (dropped > 0)
  {
    reason += formatText(", %llu dropped (%s)", static_cast<unsigned long long>(dropped), last_problem_.c_str());
  }
  const std::uint64_t stale = counts_.stale - since.stale;
  if (stale > 0)
  {
    reason += formatText(", %llu older than the newest used", static_cast<unsigned long long>(stale));
  }
  return reason;
}

}  // namespace ptz_action_server

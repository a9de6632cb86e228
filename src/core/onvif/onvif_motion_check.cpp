#include "ptz_action_server/core/onvif/onvif_motion_check.h"

#include <algorithm>
#include <cmath>

namespace ptz_action_server
{
namespace onvif
{
namespace
{
/// A position change beyond this is a move (rad, rad, X): far above the rounding of a status, far below a poll
/// period's travel.
constexpr AxisValues MOVED{ { 1e-4, 1e-4, 1e-3 } };
/// Speeds below this (rad/s, X/s) say nothing of a camera's braking.
constexpr double SPEED_FLOOR = 1e-3;

bool says(const std::string& move_status, const char* word)
{
  return move_status == word;
}

const std::string& groupStatus(const Observation& status, Axis axis)
{
  return axis == ZOOM ? status.zoom_status : status.pan_tilt_status;
}
}  // namespace

void MotionCheck::stopSent(TimePoint at, const AxisValues& velocity)
{
  watch_ = Watch::STOP;
  sent_at_ = at;
  velocity_ = velocity;
  statuses_ = 0;
}

void MotionCheck::absoluteMoveSent(TimePoint at, const AxisValues& from, const AxisValues& target)
{
  watch_ = Watch::ABSOLUTE_MOVE;
  sent_at_ = at;
  from_ = from;
  target_ = target;
  statuses_ = 0;
  for (Axis axis : ALL_AXES)
  {
    must_move_[axis] = !std::isnan(target[axis]) && std::abs(target[axis] - from[axis]) > config_.expected[axis];
    began_[axis] = false;
  }
}

bool MotionCheck::moved(Axis axis, const Observation& before, const Observation& after) const
{
  return (after.reported[axis] && std::abs(after.position[axis] - before.position[axis]) > MOVED[axis]) ||
         says(groupStatus(after, axis), "MOVING");
}

MotionFinding MotionCheck::observe(const Observation& status)
{
  MotionFinding finding;
  if (have_last_ && watch_ == Watch::STOP)
  {
    finding = observeStop(status);
  }
  else if (watch_ == Watch::ABSOLUTE_MOVE)
  {
    finding = observeAbsoluteMove(status);
  }
  last_ = status;
  have_last_ = true;
  return finding;
}

MotionFinding MotionCheck::observeStop(const Observation& status)
{
  MotionFinding finding;
  ++statuses_;
  std::array<bool, AXIS_COUNT> moving{};
  for (Axis axis : ALL_AXES)
  {
    moving[axis] = moved(axis, last_, status);
  }
  if (std::none_of(moving.begin(), moving.end(), [](bool axis_moves) { return axis_moves; }))
  {
    watch_ = Watch::NOTHING;  // at rest: it stopped
    return finding;
  }
  // Judged by statuses, not by the time they took to come: a status is asked once a poll period at most, so the k-th
  // one after the Stop shows the camera (k - 1) poll periods after it at least, however late it arrives here.
  // The speed it had: the estimate averages the last reports, a poll behind a camera that was still speeding up, so
  // twice it (within the max speed); unknown, its fastest.
  const double estimate = std::max(std::abs(velocity_[PAN]), std::abs(velocity_[TILT]));
  const double speed =
      estimate > SPEED_FLOOR ? std::max(estimate, std::min(2.0 * estimate, config_.max_speed)) : config_.max_speed;
  const int braking = static_cast<int>(std::ceil(speed / config_.deceleration / config_.poll_period)) + 2;
  if (statuses_ < braking)
  {
    return finding;  // still braking, as far as anyone can tell
  }
  const double span = secondsBetween(last_.at, status.at);
  for (Axis axis : ALL_AXES)
  {
    finding.speed[axis] =
        span > 0.0 && status.reported[axis] ? std::abs(status.position[axis] - last_.position[axis]) / span : 0.0;
    // The axes it moves: those that changed (or all of a group whose MoveStatus says MOVING, when it reports none).
    moving[axis] = moving[axis] && (finding.speed[axis] > 0.0 || !status.reported[axis]);
  }
  watch_ = Watch::NOTHING;
  finding.kind = MotionFinding::KEPT_MOVING_AFTER_STOP;
  finding.axes = moving;
  finding.after = secondsBetween(sent_at_, status.at);
  return finding;
}

MotionFinding MotionCheck::observeAbsoluteMove(const Observation& status)
{
  MotionFinding finding;
  ++statuses_;
  finding.after = secondsBetween(sent_at_, status.at);
  bool all_there = true;
  for (Axis axis : ALL_AXES)
  {
    if (!must_move_[axis])
    {
      continue;
    }
    const bool moving = says(groupStatus(status, axis), "MOVING");
    // An axis whose position the camera does not report cannot be judged: taken as moving.
    began_[axis] =
        began_[axis] || moving || !status.reported[axis] || std::abs(status.position[axis] - from_[axis]) > MOVED[axis];
    all_there =
        all_there && status.reported[axis] && std::abs(status.position[axis] - target_[axis]) <= config_.expected[axis];
  }
  if (all_there)
  {
    watch_ = Watch::NOTHING;
    return finding;
  }
  // Pan and tilt travel together: the pan-tilt began if either did.
  const bool pan_tilt_expected = must_move_[PAN] || must_move_[TILT];
  const bool pan_tilt_began = began_[PAN] || began_[TILT];
  // Three statuses at least: two poll periods of the camera's time, however late they arrive.
  if (config_.start_timeout > 0.0 && finding.after >= config_.start_timeout && statuses_ >= 3)
  {
    finding.axes[PAN] = finding.axes[TILT] = pan_tilt_expected && !pan_tilt_began;
    finding.axes[ZOOM] = must_move_[ZOOM] && !began_[ZOOM];
    if (finding.axes[PAN] || finding.axes[ZOOM])
    {
      watch_ = Watch::NOTHING;
      finding.kind = MotionFinding::ABSOLUTE_MOVE_IGNORED;
      return finding;
    }
  }
  // A zoom that went towards its target and rests short of it: its lens ends there.
  const double remaining = target_[ZOOM] - status.position[ZOOM];
  if (must_move_[ZOOM] && began_[ZOOM] && status.reported[ZOOM] && last_.at >= sent_at_ && statuses_ >= 2 &&
      !moved(ZOOM, last_, status) && std::abs(remaining) > config_.expected[ZOOM] &&
      remaining * (target_[ZOOM] - from_[ZOOM]) > 0.0)
  {
    watch_ = Watch::NOTHING;
    finding.kind = MotionFinding::ZOOM_STOPPED_SHORT;
    finding.zoom = status.position[ZOOM];
    finding.zoom_target = target_[ZOOM];
  }
  return finding;
}

}  // namespace onvif
}  // namespace ptz_action_server

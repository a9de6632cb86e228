#include "ptz_action_server/core/goal/goal_supervisor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/goal/goal_validation.h"

namespace ptz_action_server
{
namespace
{
/// A point this close to the picture's centre (share of its size) need not move the device.
constexpr double VIEW_CENTRED = 0.02;
/// A box whose magnification is within this of 1 (natural log) need not zoom.
constexpr double VIEW_ZOOMED = 0.02;
}  // namespace

GoalSupervisor::GoalSupervisor(std::shared_ptr<PtzBackend> backend, const Capabilities& limits,
                               const GoalMonitorConfig& config, bool clamp_goals, std::shared_ptr<const Clock> clock)
  : backend_(std::move(backend)), limits_(limits), config_(config), clamp_goals_(clamp_goals), clock_(std::move(clock))
{
}

void GoalSupervisor::submit(std::unique_ptr<GoalHandle> goal, const PtzSample& current, const ConvertedGoal& converted)
{
  if (!current.link_up)
  {
    goal->reject("the " + backend_->name() + " device link is down");
    return;
  }
  if (!converted.rejection.empty())
  {
    goal->reject(converted.rejection);
    return;
  }
  GoalCommand command = converted.command;
  if (command.view)
  {
    // Where the device goes is its own to know: nothing to validate, every axis it has is judged as it reports.
    if (!limits_.view_centre)
    {
      goal->reject("the " + backend_->name() + " device cannot aim in its own picture");
      return;
    }
    std::array<bool, AXIS_COUNT> judged{};
    for (Axis axis : ALL_AXES)
    {
      judged[axis] = limits_.axes[axis].present;
    }
    activate(std::move(goal), command, judged, command.note, AxisValues{});
    return;
  }
  // A tracked target outside the limits is followed as far as the limits allow.
  const bool clamp = clamp_goals_ || command.track;
  const ValidatedGoal validated = command.velocity ? validateVelocityGoal(command.values, limits_, clamp) :
                                                     validatePositionGoal(command.values, limits_, clamp);
  if (!validated.accepted)
  {
    goal->reject(validated.message);
    return;
  }
  command.values = validated.values;
  std::string note = command.note;
  if (!validated.message.empty())
  {
    note += (note.empty() ? "" : "; ") + validated.message;
  }
  ResolvedSpeed speed;
  if (!command.velocity && !command.track)
  {
    speed = resolveSpeed(command.speed, default_speed_, limits_);
    if (!speed.accepted)
    {
      goal->reject(speed.message);
      return;
    }
    if (!speed.message.empty())
    {
      note += (note.empty() ? "" : "; ") + speed.message;
    }
  }
  activate(std::move(goal), command, validated.judged, command.track ? std::string() : note, speed.speed);
}

std::string GoalSupervisor::setDefaultSpeed(double fraction)
{
  std::string reason = checkDefaultSpeed(fraction);
  if (reason.empty())
  {
    default_speed_ = fraction;
  }
  return reason;
}

void GoalSupervisor::activate(std::unique_ptr<GoalHandle> goal, const GoalCommand& command,
                              const std::array<bool, AXIS_COUNT>& judged, const std::string& note,
                              const AxisValues& speed)
{
  if (active_goal_)
  {
    // Retarget from where the device is: no stop in between.
    tellEnd(backend_->sample());
    active_goal_->preempt(withNote("preempted by a new " + goal->action() + " goal"));
    finish(true);
  }
  goal->accept(note);
  const PtzSample start = backend_->sample();
  ++goal_serial_;
  const bool stop_goal = command.velocity && std::all_of(command.values.begin(), command.values.end(),
                                                         [](double value) { return value == 0.0; });
  if (command.view)
  {
    view_ending_ = ViewEnding{ start.position, askedAxes(*command.view) };
    backend_->aimInView(*command.view);
  }
  else if (stop_goal)
  {
    backend_->stop();
  }
  else if (command.velocity)
  {
    backend_->moveAtVelocity(command.values);
  }
  else if (asksSpeed(speed))
  {
    backend_->goToAtSpeed(command.values, speed);
  }
  else
  {
    backend_->goTo(command.values);
  }
  // The goal is judged on the axes it asks for only, and expected to take as long as its speed makes it.
  Capabilities judged_axes = limits_;
  for (Axis axis : ALL_AXES)
  {
    judged_axes.axes[axis].present = judged[axis];
    if (speed[axis] > 0.0)
    {
      judged_axes.axes[axis].max_speed = speed[axis];
    }
  }
  if (command.view)
  {
    monitor_ = std::make_unique<GoalMonitor>(
        GoalMonitor::forView(start, judged_axes, config_, clock_->now(), view_ending_->asked));
  }
  else if (command.track)
  {
    monitor_ = std::make_unique<GoalMonitor>(
        GoalMonitor::forTrack(command.values, start, judged_axes, config_, clock_->now()));
  }
  else if (command.velocity)
  {
    monitor_ = std::make_unique<GoalMonitor>(
        GoalMonitor::forVelocity(command.values, start, judged_axes, config_, clock_->now()));
  }
  else
  {
    monitor_ = std::make_unique<GoalMonitor>(
        GoalMonitor::forPosition(command.values, start, judged_axes, config_, clock_->now()));
  }
  active_goal_ = std::move(goal);
  note_ = note;
  mode_ = command.velocity ? GoalMode::VELOCITY : GoalMode::POSITION;
  if (activity_listener_)
  {
    activity_listener_(active_goal_.get());
  }
  // A goal the device already satisfies (zero length, or a stop while at rest) ends here, not a tick later. Its
  // feedback waits for the state tick: a goal replaced within milliseconds (a joystick, a storm of clients) would
  // otherwise send one feedback to every client of the action, as many messages as results.
  judge(backend_->sample(), false, clock_->now());
}

void GoalSupervisor::cancel(const std::string& action, const std::string& id)
{
  if (!isRunning(action, id))
  {
    return;  // not ours, already ended, or already stopping
  }
  // Stop the device first; the goal ends once it rests (supervise).
  const PtzSample start = backend_->sample();
  ++goal_serial_;
  backend_->stop();
  stopping_ = true;
  monitor_ = std::make_unique<GoalMonitor>(GoalMonitor::forStop(start, config_, clock_->now(), limits_));
  judge(backend_->sample(), true, clock_->now());
}

bool GoalSupervisor::isRunning(const std::string& action, const std::string& id) const
{
  return active_goal_ && !stopping_ && active_goal_->action() == action && active_goal_->id() == id;
}

bool GoalSupervisor::steer(const std::string& action, const std::string& id, const GoalCommand& command,
                           const AxisValues& aim)
{
  if (!isRunning(action, id))
  {
    return false;
  }
  if (command.velocity)
  {
    backend_->moveAtVelocity(command.values);
  }
  else
  {
    backend_->goTo(command.values);
  }
  monitor_->retarget(aim);
  mode_ = command.velocity ? GoalMode::VELOCITY : GoalMode::POSITION;
  return true;
}

void GoalSupervisor::abort(const std::string& action, const std::string& id, const std::string& reason)
{
  if (isRunning(action, id))
  {
    backend_->stop();
    tellEnd(backend_->sample());
    active_goal_->abort(withNote(reason));
    finish();
  }
}

GoalSample GoalSupervisor::sample() const
{
  GoalSample tagged;
  // The serial before the sample: a sample tagged with the active goal's serial was taken after its start sample.
  tagged.goal_serial = goal_serial_.load();
  tagged.sample = backend_->sample();
  tagged.taken_at = clock_->now();  // after the backend: every report in the sample came before it
  return tagged;
}

void GoalSupervisor::supervise(const GoalSample& sample, bool publish_feedback)
{
  // A sample taken for an earlier goal, or before the cancel, knows nothing of what the active monitor started from.
  if (sample.goal_serial == goal_serial_.load())
  {
    // Judged at the time it was taken: a sample that waited in the queue on a busy machine, the link still up in it,
    // must not make the wait look like a stalled axis (the silence after it is the link supervision's to report).
    judge(sample.sample, publish_feedback, sample.taken_at);
  }
}

void GoalSupervisor::judge(const PtzSample& sample, bool publish_feedback, TimePoint taken_at)
{
  if (!active_goal_)
  {
    return;
  }
  GoalVerdict verdict = monitor_->update(sample, taken_at);
  if (verdict.phase == GoalPhase::ABORTED && !verdict.link_lost && !verdict.device_fault)
  {
    // A stall or a timeout is confirmed on the device as it is now: a device that fell silent just after the sample
    // (its last reports unchanged) has lost its link, which is what the user must be told.
    const GoalVerdict current = monitor_->update(backend_->sample(), clock_->now());
    if (current.link_lost)
    {
      verdict = current;
    }
  }
  if (verdict.phase == GoalPhase::ACTIVE)
  {
    if (!stopping_ && publish_feedback)
    {
      active_goal_->publishFeedback(verdict.remaining);
    }
    return;
  }
  tellEnd(sample);
  if (stopping_)
  {
    active_goal_->preempt(withNote("cancelled: " + verdict.reason));
  }
  else if (verdict.phase == GoalPhase::SUCCEEDED)
  {
    if (verdict.stop_device)
    {
      backend_->stop();
    }
    active_goal_->succeed(withNote(verdict.reason));
  }
  else
  {
    backend_->stop();  // a failed goal must not leave the device moving
    std::string reason = verdict.reason;
    if (verdict.device_fault)
    {
      reason += ": " + backend_->lastFault();
    }
    else if (verdict.link_lost)
    {
      const std::string loss = backend_->lastLinkLoss();
      reason += ": " + (loss.empty() ? std::string("the device stopped reporting its state") : loss);
    }
    active_goal_->abort(withNote(reason));
  }
  finish();
}

void GoalSupervisor::shutdown(const std::string& reason)
{
  if (active_goal_)
  {
    backend_->stop();
    tellEnd(backend_->sample());
    active_goal_->abort(withNote(reason));
    finish();
  }
}

std::array<bool, AXIS_COUNT> GoalSupervisor::askedAxes(const ViewTarget& view) const
{
  const bool zooms = view.box() && limits_.view_box_zoom && limits_.axes[ZOOM].present &&
                     std::abs(std::log(view.magnification())) > VIEW_ZOOMED;
  return { { std::abs(view.x - 0.5) > VIEW_CENTRED, std::abs(view.y - 0.5) > VIEW_CENTRED, zooms } };
}

void GoalSupervisor::tellEnd(const PtzSample& sample)
{
  if (view_ending_)
  {
    active_goal_->ended(view_ending_->at(sample, limits_));
  }
}

std::string GoalSupervisor::withNote(const std::string& text) const
{
  return note_.empty() ? text : text + " (" + note_ + ")";
}

void GoalSupervisor::finish(bool replaced)
{
  active_goal_.reset();
  note_.clear();
  monitor_.reset();
  stopping_ = false;
  view_ending_.reset();
  mode_ = GoalMode::IDLE;
  if (activity_listener_ && !replaced)
  {
    activity_listener_(nullptr);
  }
}

}  // namespace ptz_action_server

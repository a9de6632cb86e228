#include "ptz_action_server/core/goal/goal_validation.h"

#include "ptz_action_server/core/text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ptz_action_server
{
namespace
{
const char* unitOf(Axis axis, bool velocity)
{
  if (axis == ZOOM)
  {
    return velocity ? "X/s" : "X";
  }
  return velocity ? "rad/s" : "rad";
}

void appendNote(std::string& message, const std::string& note)
{
  message += message.empty() ? "clamped " : ", ";
  message += note;
}

/// Shared rule for positions and velocities: value must lie in [low, high] (with LIMIT_EPSILON of slack).
bool checkRange(Axis axis, double low, double high, bool velocity, bool clamp, ValidatedGoal& goal)
{
  const double value = goal.values[axis];
  if (value >= low - LIMIT_EPSILON && value <= high + LIMIT_EPSILON)
  {
    goal.values[axis] = std::clamp(value, low, high);
    return true;
  }
  const char* unit = unitOf(axis, velocity);
  const double bounded = std::clamp(value, low, high);
  if (!clamp)
  {
    goal.message = velocity ? formatText("%s velocity %.4f %s exceeds the maximum speed %.4f %s", axisName(axis), value,
                                         unit, high, unit) :
                              formatText("%s %.4f %s is outside the limits [%.4f, %.4f] %s", axisName(axis), value,
                                         unit, low, high, unit);
    return false;
  }
  appendNote(goal.message, formatText("%s %.4f -> %.4f %s", axisName(axis), value, bounded, unit));
  goal.values[axis] = bounded;
  goal.clamped = true;
  return true;
}

/// Adds \p note to the goal's notes (after any clamping note).
void addNote(std::string& notes, const std::string& note)
{
  notes += (notes.empty() ? "" : "; ") + note;
}

/// What the device lacks on \p axis, in its own words when it has them.
std::string lackOf(const AxisCapability& capability, const char* plain)
{
  return capability.limitation.empty() ? plain : capability.limitation;
}

/**
 * \brief The seed's zoom rule for a zoom the goal cannot have as asked: true when the goal goes on without it.
 *
 * A device without zoom ignores the zoom field ("if the camera does not support zoom ... the zoom field is
 * ignored"): \p notes says so unless the value asked nothing (0, unset; 1, the zoom it reports). A device with a zoom
 * it cannot position takes zoom 0 as "leave it" and zoom 1 as its widest view (see commandedZoom()), judged only with
 * feedback. Any other zoom on such a device is not the goal's to ignore: false.
 */
bool goesOnWithoutZoom(const AxisCapability& capability, bool velocity, ValidatedGoal& goal, std::string& notes)
{
  double& zoom = goal.values[ZOOM];
  if (!capability.present)
  {
    if (zoom != 0.0 && !(zoom == 1.0 && !velocity))
    {
      addNote(notes, formatText("zoom %s%.4f %s ignored: %s", velocity ? "velocity " : "", zoom, unitOf(ZOOM, velocity),
                                lackOf(capability, "the device has no zoom").c_str()));
    }
    zoom = velocity ? 0.0 : commandedZoom(capability, zoom);
    return true;
  }
  if (velocity || (capability.absolute && capability.feedback) || (zoom != 0.0 && zoom != 1.0))
  {
    return false;
  }
  if (zoom == 1.0)
  {
    const std::string lack = lackOf(capability, "the device cannot go to a zoom position");
    if (!capability.widest_view)
    {
      addNote(notes, "zoom 1 (the widest view) left as it is: " + lack);
    }
    else if (capability.feedback)
    {
      goal.judged[ZOOM] = true;
    }
    else
    {
      addNote(notes, "zoom 1 sent as the widest view, not judged: " + lack);
    }
  }
  zoom = commandedZoom(capability, zoom);
  return true;
}

ValidatedGoal validate(const AxisValues& values, const Capabilities& limits, bool clamp, bool velocity)
{
  ValidatedGoal goal;
  goal.values = values;
  goal.message = findNonFinite(values, velocity ? "velocity" : "position");
  if (!goal.message.empty())
  {
    return goal;
  }
  std::string notes;  // what the goal's zoom became, after the clamping note
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = limits.axes[axis];
    if (axis == ZOOM && goesOnWithoutZoom(capability, velocity, goal, notes))
    {
      continue;
    }
    const bool left_alone = velocity ? values[axis] == 0.0 && !(capability.present && capability.velocity) :
                                       leavesAxisAlone(limits, axis, values[axis]);
    if (left_alone)
    {
      goal.values[axis] = velocity ? 0.0 : capability.range.min;
      continue;
    }
    const std::string unsupported =
        findUnsupported(limits, axis, velocity ? AxisRequest::VELOCITY : AxisRequest::POSITION);
    if (!unsupported.empty())
    {
      goal.message = unsupported;
      return goal;
    }
    const bool in_range = velocity ? checkRange(axis, -capability.max_speed, capability.max_speed, true, clamp, goal) :
                                     checkRange(axis, capability.range.min, capability.range.max, false, clamp, goal);
    if (!in_range)
    {
      return goal;
    }
    goal.judged[axis] = true;
  }
  if (!notes.empty())
  {
    goal.message += (goal.message.empty() ? "" : "; ") + notes;
  }
  goal.accepted = true;
  return goal;
}
}  // namespace

std::string findNonFinite(const AxisValues& values, const char* quantity)
{
  for (Axis axis : ALL_AXES)
  {
    const double value = values[axis];
    if (std::isnan(value))
    {
      return formatText("%s %s is NaN", axisName(axis), quantity);
    }
    if (std::isinf(value))
    {
      return formatText("%s %s is %s", axisName(axis), quantity, value > 0 ? "+Inf" : "-Inf");
    }
  }
  return {};
}

std::string findUnsupported(const Capabilities& capabilities, Axis axis, AxisRequest request)
{
  const AxisCapability& capability = capabilities.axes[axis];
  const char* name = axisName(axis);
  std::string lack;
  if (!capability.present)
  {
    lack = formatText("the device has no %s", name);
  }
  else if (request == AxisRequest::VELOCITY && !capability.velocity)
  {
    lack = formatText("the device cannot move its %s at a speed", name);
  }
  else if (request != AxisRequest::VELOCITY && !capability.feedback)
  {
    lack = formatText("the device reports no %s position", name);
  }
  else if (request == AxisRequest::POSITION && !capability.absolute)
  {
    lack = formatText("the device cannot go to a %s position", name);
  }
  if (lack.empty())
  {
    return {};
  }
  const char* goals = request == AxisRequest::VELOCITY ? "velocity goals" :
                      request == AxisRequest::OFFSET   ? "relative goals" :
                                                         "goals";
  std::string text = (capability.limitation.empty() ? lack : capability.limitation) +
                     formatText(": %s %s are not supported", name, goals);
  if (!capability.remedy.empty())
  {
    text += "; " + capability.remedy;
  }
  return text;
}

double commandedZoom(const AxisCapability& zoom, double value)
{
  if (!zoom.present)
  {
    return zoom.range.min;
  }
  if (zoom.absolute && zoom.feedback)
  {
    return std::clamp(value, zoom.range.min, zoom.range.max);
  }
  return value == 1.0 && zoom.widest_view ? 1.0 : std::numeric_limits<double>::quiet_NaN();
}

bool leavesAxisAlone(const Capabilities& capabilities, Axis axis, double value)
{
  return !capabilities.axes[axis].present && value == 0.0;
}

ValidatedGoal validatePositionGoal(const AxisValues& target, const Capabilities& limits, bool clamp)
{
  return validate(target, limits, clamp, false);
}

ValidatedGoal validateVelocityGoal(const AxisValues& velocity, const Capabilities& limits, bool clamp)
{
  return validate(velocity, limits, clamp, true);
}

}  // namespace ptz_action_server

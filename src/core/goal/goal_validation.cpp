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

ValidatedGoal validate(const AxisValues& values, const Capabilities& limits, bool clamp, bool velocity)
{
  ValidatedGoal goal;
  goal.values = values;
  goal.message = findNonFinite(values, velocity ? "velocity" : "position");
  if (!goal.message.empty())
  {
    return goal;
  }
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = limits.axes[axis];
    const bool left_alone = velocity ? values[axis] == 0.0 && !(capability.present && capability.velocity) :
                                       leavesAxisAlone(limits, axis, values[axis]);
    if (left_alone)
    {
      goal.values[axis] = velocity           ? 0.0 :
                          capability.present ? std::numeric_limits<double>::quiet_NaN() :
                                               capability.range.min;
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

bool leavesAxisAlone(const Capabilities& capabilities, Axis axis, double value)
{
  const AxisCapability& capability = capabilities.axes[axis];
  if (capability.present && capability.absolute && capability.feedback)
  {
    return false;
  }
  if (axis == ZOOM)
  {
    return value == 0.0 || (!capability.present && value == 1.0);
  }
  return !capability.present && value == 0.0;
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

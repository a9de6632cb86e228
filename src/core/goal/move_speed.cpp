#include "ptz_action_server/core/goal/move_speed.h"

#include <cmath>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
void addSpeedNote(std::string& notes, const std::string& note)
{
  notes += (notes.empty() ? "" : "; ") + note;
}

const char* speedUnit(Axis axis)
{
  return axis == ZOOM ? "X/s" : "rad/s";
}
}  // namespace

std::string checkDefaultSpeed(double fraction)
{
  if (!(fraction > 0.0 && fraction <= 1.0))
  {
    return formatText("the default speed %g is not a fraction of the top speed in (0, 1]", fraction);
  }
  return {};
}

ResolvedSpeed resolveSpeed(const SpeedRequest& request, double default_fraction, const Capabilities& limits)
{
  ResolvedSpeed resolved;
  if (!std::isfinite(request.fraction) || request.fraction < 0.0)
  {
    resolved.accepted = false;
    resolved.message =
        formatText("speed %g is not a fraction of the top speed in (0, 1] (0: the default speed)", request.fraction);
    return resolved;
  }
  for (Axis axis : ALL_AXES)
  {
    if (!std::isfinite(request.rate[axis]) || request.rate[axis] < 0.0)
    {
      resolved.accepted = false;
      resolved.message = formatText("%s speed %g %s is not a speed (> 0, or 0 for the fraction)", axisName(axis),
                                    request.rate[axis], speedUnit(axis));
      return resolved;
    }
  }
  double fraction = request.fraction > 0.0 ? request.fraction : default_fraction;
  if (fraction > 1.0)
  {
    addSpeedNote(resolved.message, formatText("speed %g taken as 1 (the top speed)", fraction));
    fraction = 1.0;
  }
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = limits.axes[axis];
    if (!capability.present || !(capability.max_speed > 0.0) || limits.speed.control[axis] == SpeedControl::OWN)
    {
      continue;  // nothing moves there at any speed, or only at the device's own
    }
    const bool rate_given = request.rate[axis] > 0.0;
    double speed = rate_given ? request.rate[axis] : fraction * capability.max_speed;
    if (speed >= capability.max_speed)
    {
      if (rate_given && speed > capability.max_speed)
      {
        addSpeedNote(resolved.message,
                     formatText("%s speed %.4g %s clamped to the device's top speed %.4g %s", axisName(axis), speed,
                                speedUnit(axis), capability.max_speed, speedUnit(axis)));
      }
      speed = 0.0;  // the device's own speed: its top speed, as a goal without a speed moves
    }
    else if (speed < limits.speed.min_speed[axis])
    {
      addSpeedNote(resolved.message,
                   formatText("%s speed %.4g %s raised to the device's slowest %.4g %s", axisName(axis), speed,
                              speedUnit(axis), limits.speed.min_speed[axis], speedUnit(axis)));
      speed = limits.speed.min_speed[axis];
    }
    resolved.speed[axis] = speed;
  }
  return resolved;
}

}  // namespace ptz_action_server

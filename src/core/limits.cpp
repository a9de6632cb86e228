#include "ptz_action_server/core/limits.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
Capabilities urdfLimits(const PtzKinematics& kinematics)
{
  Capabilities limits;
  const JointModel* joints[] = { &kinematics.panJoint(), &kinematics.tiltJoint() };
  const double contract_bound[] = { M_PI, M_PI / 2.0 };
  for (Axis axis : { PAN, TILT })
  {
    const JointModel& joint = *joints[axis];
    AxisCapability& capability = limits.axes[axis];
    capability.range.min = std::max(joint.limits.min, -contract_bound[axis]);
    capability.range.max = std::min(joint.limits.max, contract_bound[axis]);
    capability.max_speed = joint.max_velocity;
    if (capability.range.min >= capability.range.max)
    {
      throw ConfigError("URDF joint '" + joint.name + "' has an empty range inside the contract's limits");
    }
  }
  limits.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  return limits;
}

LimitIntersection intersectLimits(const Capabilities& device, const Capabilities& urdf)
{
  LimitIntersection result;
  result.limits = device;
  for (Axis axis : { PAN, TILT })
  {
    AxisCapability& narrowed = result.limits.axes[axis];
    const AxisCapability& model = urdf.axes[axis];
    if (narrowed.range.min > model.range.min || narrowed.range.max < model.range.max)
    {
      result.warnings.push_back(formatText("the device's %s range [%.4f, %.4f] is narrower than the URDF's [%.4f, "
                                           "%.4f]; using the device's",
                                           axisName(axis), narrowed.range.min, narrowed.range.max, model.range.min,
                                           model.range.max));
    }
    narrowed.range.min = std::max(narrowed.range.min, model.range.min);
    narrowed.range.max = std::min(narrowed.range.max, model.range.max);
    if (model.max_speed > 0.0)
    {
      narrowed.max_speed = std::min(narrowed.max_speed, model.max_speed);
    }
    if (narrowed.range.min >= narrowed.range.max)
    {
      throw ConfigError(std::string("the device's and the URDF's ") + axisName(axis) + " ranges do not overlap");
    }
  }
  return result;
}

}  // namespace ptz_action_server

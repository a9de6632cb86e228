#include "ptz_action_server/ros/capabilities_message.h"

namespace ptz_action_server
{
namespace
{
PtzAxisCapability toMessage(const AxisCapability& axis)
{
  PtzAxisCapability message;
  message.present = axis.present;
  message.absolute = axis.present && axis.absolute && axis.feedback;
  message.velocity = axis.present && axis.velocity;
  message.feedback = axis.present && axis.feedback;
  message.min = axis.range.min;
  message.max = axis.range.max;
  message.max_speed = axis.max_speed;
  message.limitation = axis.limitation;
  if (!axis.remedy.empty())
  {
    message.limitation += (message.limitation.empty() ? "" : "; ") + axis.remedy;
  }
  return message;
}
}  // namespace

PtzCapabilities toMessage(const std::string& backend, const Capabilities& limits)
{
  PtzCapabilities message;
  message.backend = backend;
  message.pan = toMessage(limits.axes[PAN]);
  message.tilt = toMessage(limits.axes[TILT]);
  message.zoom = toMessage(limits.axes[ZOOM]);
  message.relative_moves = limits.relative_moves;
  message.device_presets = limits.device_presets;
  message.device_home = limits.device_home;
  return message;
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/capabilities.h"

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
std::string describeAxis(const Capabilities& capabilities, Axis axis)
{
  const AxisCapability& capability = capabilities.axes[axis];
  const std::string why = capability.limitation.empty() ? "" : " (" + capability.limitation + ")";
  if (!capability.present)
  {
    return "none" + (why.empty() ? formatText(" (the device has no %s)", axisName(axis)) : why);
  }
  std::string abilities;
  const std::pair<bool, const char*> parts[] = { { capability.absolute && capability.feedback, "position" },
                                                 { capability.velocity, "velocity" },
                                                 { capability.feedback, "feedback" } };
  for (const auto& part : parts)
  {
    if (part.first)
    {
      abilities += std::string(abilities.empty() ? "" : ", ") + part.second;
    }
  }
  if (abilities.empty())
  {
    abilities = "no goals";
  }
  const char* unit = axis == ZOOM ? "X" : "rad";
  abilities += formatText(", [%.4f, %.4f] %s", capability.range.min, capability.range.max, unit);
  if (!capability.remedy.empty())
  {
    return abilities + (why.empty() ? " (" + capability.remedy + ")" :
                                      why.substr(0, why.size() - 1) + "; " + capability.remedy + ")");
  }
  return abilities + why;
}

std::string describeExtras(const Capabilities& capabilities)
{
  std::string extras;
  const std::pair<bool, const char*> parts[] = { { capabilities.relative_moves, "relative moves" },
                                                 { capabilities.device_presets, "presets" },
                                                 { capabilities.device_home, "home" } };
  for (const auto& part : parts)
  {
    if (part.first)
    {
      extras += std::string(extras.empty() ? "" : ", ") + part.second;
    }
  }
  if (capabilities.view_centre)
  {
    extras += std::string(extras.empty() ? "" : ", ") +
              (capabilities.view_box_zoom ? "centres and box-zooms in its own picture" : "centres in its own picture") +
              (capabilities.view_command.empty() ? "" : " (" + capabilities.view_command + ")");
  }
  return extras.empty() ? "none" : extras;
}

}  // namespace ptz_action_server

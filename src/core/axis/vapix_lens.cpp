#include "ptz_action_server/core/axis/vapix_lens.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace vapix
{
namespace
{
std::optional<double> vapixNumber(const Reply& reply, const char* key)
{
  const std::string* text = reply.find(key);
  double value = 0.0;
  if (text && parseNumber(*text, value))
  {
    return value;
  }
  return std::nullopt;
}

std::optional<bool> vapixSwitch(const Reply& reply, const char* key)
{
  const std::string* text = reply.find(key);
  if (text && (*text == "on" || *text == "off"))
  {
    return *text == "on";
  }
  return std::nullopt;
}

LensRange vapixRange(const Reply& reply, const char* min_key, const char* max_key)
{
  LensRange range;
  const std::optional<double> min = vapixNumber(reply, min_key);
  const std::optional<double> max = vapixNumber(reply, max_key);
  if (min && max && *min < *max)
  {
    range = LensRange{ true, *min, *max };
  }
  return range;
}

LensControl vapixControl(const LensRange& range, const std::optional<double>& value,
                         const std::optional<bool>& automatic, const CommandList& commands, const char* name)
{
  const std::string function = name;
  const auto offered = [&commands](const std::string& command) { return commands.empty() || commands.has(command); };
  LensControl control;
  control.present = value.has_value() || automatic.has_value();
  if (!control.present)
  {
    control.limitation = "this Axis camera reports no " + function + " (query=position has no " + function + "=)";
    return control;
  }
  const std::string auto_name = function == "focus" ? "autofocus" : "autoiris";
  control.auto_mode = automatic.has_value() && offered(auto_name);
  control.velocity = offered("continuous" + function + "move");
  control.absolute = range.known && offered(function);
  control.feedback = range.known && value.has_value();
  if (!range.known)
  {
    control.limitation = "query=limits gives no range for the " + function + ": no position";
  }
  return control;
}
}  // namespace

double LensRange::toValue(double share) const
{
  return std::round(min + std::clamp(share, 0.0, 1.0) * (max - min));
}

double LensRange::toShare(double value) const
{
  return std::clamp((value - min) / (max - min), 0.0, 1.0);
}

LensLimits readLensLimits(const Reply& reply)
{
  return LensLimits{ vapixRange(reply, "MinFocus", "MaxFocus"), vapixRange(reply, "MinIris", "MaxIris") };
}

LensReading readLens(const Reply& reply)
{
  return LensReading{ vapixNumber(reply, "focus"), vapixNumber(reply, "iris"), vapixSwitch(reply, "autofocus"),
                      vapixSwitch(reply, "autoiris") };
}

LensCapabilities lensCapabilities(const LensLimits& limits, const LensReading& reading, const CommandList& commands)
{
  LensCapabilities lens;
  lens.focus = vapixControl(limits.focus, reading.focus, reading.autofocus, commands, "focus");
  lens.iris = vapixControl(limits.iris, reading.iris, reading.autoiris, commands, "iris");
  return lens;
}

std::string lensArguments(const LensCommand& command, const LensLimits& limits)
{
  const bool focus = command.function == LensFunction::FOCUS;
  const char* name = focus ? "focus" : "iris";
  switch (command.kind)
  {
    case LensCommand::Kind::MODE:
      return formatText("%s=%s", focus ? "autofocus" : "autoiris", command.automatic() ? "on" : "off");
    case LensCommand::Kind::VELOCITY:
      return formatText("continuous%smove=%d", name,
                        static_cast<int>(std::lround(std::clamp(command.value, -1.0, 1.0) * 100.0)));
    case LensCommand::Kind::POSITION:
      return formatText("%s=%.0f", name, (focus ? limits.focus : limits.iris).toValue(command.value));
    default:
      return "";
  }
}

}  // namespace vapix
}  // namespace ptz_action_server

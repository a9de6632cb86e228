#include "ptz_action_server/core/lens.h"

#include <cmath>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
std::size_t lensIndex(LensFunction function)
{
  return static_cast<std::size_t>(function);
}

/// "the 'flir' backend drives no focus", or the device's own words.
std::string lensLimitation(const LensControl& control, LensFunction function, const std::string& backend)
{
  return control.limitation.empty() ? "the '" + backend + "' backend drives no " + lensFunctionName(function) :
                                      control.limitation;
}

/// A sentence of what \p control lacks for \p what, with its limitation when it has one.
std::string lacks(const LensControl& control, LensFunction function, const std::string& backend, const char* what)
{
  std::string text = "the '" + backend + "' device takes no " + lensFunctionName(function) + " " + what;
  if (!control.limitation.empty())
  {
    text += " (" + control.limitation + ")";
  }
  return text;
}
}  // namespace

const char* lensFunctionName(LensFunction function)
{
  return function == LensFunction::FOCUS ? "focus" : "iris";
}

const char* lensModeName(LensMode mode)
{
  switch (mode)
  {
    case LensMode::AUTO:
      return "auto";
    case LensMode::MANUAL:
      return "manual";
    default:
      return "unknown";
  }
}

std::string describe(const LensCommand& command)
{
  const std::string name = lensFunctionName(command.function);
  switch (command.kind)
  {
    case LensCommand::Kind::MODE:
      return name + (command.automatic() ? " auto" : " manual");
    case LensCommand::Kind::ONE_PUSH:
      return name + " one-push";
    case LensCommand::Kind::VELOCITY:
      return name + formatText(" velocity %g", command.value);
    default:
      return name + formatText(" position %g", command.value);
  }
}

std::string checkLensCommand(const LensCapabilities& lens, const LensCommand& command, const std::string& backend)
{
  const LensControl& control = lens.of(command.function);
  const char* name = lensFunctionName(command.function);
  if (!control.present)
  {
    return lensLimitation(control, command.function, backend);
  }
  switch (command.kind)
  {
    case LensCommand::Kind::MODE:
      return control.auto_mode ? "" : lacks(control, command.function, backend, "auto/manual switch");
    case LensCommand::Kind::ONE_PUSH:
      return control.one_push ? "" : lacks(control, command.function, backend, "one-push");
    case LensCommand::Kind::VELOCITY:
      if (!control.velocity)
      {
        return lacks(control, command.function, backend, "velocity (near/far, close/open drive)");
      }
      if (!std::isfinite(command.value) || std::abs(command.value) > 1.0)
      {
        return formatText("%s velocity %g is outside -1..1 (a share of the top speed)", name, command.value);
      }
      return "";
    default:
      if (!control.absolute)
      {
        return lacks(control, command.function, backend, "position");
      }
      if (!std::isfinite(command.value) || command.value < 0.0 || command.value > 1.0)
      {
        return formatText("%s position %g is outside 0..1 (a share of the device's range)", name, command.value);
      }
      return "";
  }
}

std::string describeLens(const LensCapabilities& lens, LensFunction function, const std::string& backend)
{
  const LensControl& control = lens.of(function);
  if (!control.present)
  {
    return "none (" + lensLimitation(control, function, backend) + ")";
  }
  std::string text;
  const auto add = [&text](bool has, const char* what) {
    if (has)
    {
      text += text.empty() ? what : std::string(", ") + what;
    }
  };
  add(control.auto_mode, "auto/manual");
  add(control.velocity, "velocity");
  add(control.absolute, "position");
  add(control.feedback, "feedback");
  add(control.one_push, "one-push");
  if (text.empty())
  {
    text = "present, no command";
  }
  if (!control.limitation.empty())
  {
    text += " (" + control.limitation + ")";
  }
  return text;
}

void LensReport::setMode(LensFunction function, LensMode mode)
{
  std::lock_guard<std::mutex> lock(mutex_);
  state_.mode[lensIndex(function)] = mode;
}

void LensReport::setPosition(LensFunction function, double position)
{
  std::lock_guard<std::mutex> lock(mutex_);
  state_.position[lensIndex(function)] = position;
}

void LensReport::fault(const std::string& text)
{
  std::lock_guard<std::mutex> lock(mutex_);
  ++state_.fault_count;
  last_fault_ = text;
}

LensState LensReport::state() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

std::string LensReport::lastFault() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return last_fault_;
}

void lensDiagnostics(const LensCapabilities& lens, const LensState& state, const std::string& last_fault,
                     std::vector<std::pair<std::string, std::string>>& values)
{
  bool any = false;
  for (LensFunction function : ALL_LENS_FUNCTIONS)
  {
    if (!lens.of(function).present)
    {
      continue;
    }
    any = true;
    const double position = state.positionOf(function);
    values.emplace_back(lensFunctionName(function),
                        std::string(lensModeName(state.modeOf(function))) +
                            (std::isnan(position) ? ", position unknown" : formatText(", position %.3f", position)));
  }
  if (any)
  {
    values.emplace_back("lens faults", std::to_string(state.fault_count));
    if (!last_fault.empty())
    {
      values.emplace_back("last lens fault", last_fault);
    }
  }
}

}  // namespace ptz_action_server

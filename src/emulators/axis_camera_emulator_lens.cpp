#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <vector>

#include "ptz_action_server/core/axis/vapix_lens.h"
#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
namespace
{
/// The emulated camera's lens values: 1 (near, closed) .. 9999 (far, open), as query=limits gives them.
const vapix::LensRange AXIS_EMULATOR_LENS_RANGE{ true, 1.0, 9999.0 };

HttpAnswer axisLensError(const std::string& words)
{
  return HttpAnswer{ 200, "text/plain", "Error:\r\n" + words + "\r\n" };
}
}  // namespace

std::optional<HttpAnswer> AxisCameraEmulator::lensCommand(const std::map<std::string, std::string>& values,
                                                          const std::string& client, TimePoint now)
{
  struct LensArgument
  {
    const char* name;
    LensFunction function;
    LensCommand::Kind kind;
  };
  static const LensArgument ARGUMENTS[] = {
    { "autofocus", LensFunction::FOCUS, LensCommand::Kind::MODE },
    { "focus", LensFunction::FOCUS, LensCommand::Kind::POSITION },
    { "continuousfocusmove", LensFunction::FOCUS, LensCommand::Kind::VELOCITY },
    { "autoiris", LensFunction::IRIS, LensCommand::Kind::MODE },
    { "iris", LensFunction::IRIS, LensCommand::Kind::POSITION },
    { "continuousirismove", LensFunction::IRIS, LensCommand::Kind::VELOCITY },
  };
  std::vector<LensCommand> commands;
  for (const auto& [name, text] : values)
  {
    const LensArgument* argument = nullptr;
    for (const LensArgument& candidate : ARGUMENTS)
    {
      argument = name == candidate.name ? &candidate : argument;
    }
    if (argument == nullptr)
    {
      continue;
    }
    if (!lens_.present(argument->function))
    {
      return axisLensError(name + ": unknown argument");  // a camera without it does not know the command
    }
    LensCommand command{ argument->function, argument->kind, 0.0 };
    double number = 0.0;
    if (argument->kind == LensCommand::Kind::MODE && (text == "on" || text == "off"))
    {
      command.value = text == "on" ? 1.0 : 0.0;
    }
    else if (argument->kind == LensCommand::Kind::VELOCITY && parseNumber(text, number) && std::abs(number) <= 100.0)
    {
      command.value = number / 100.0;
    }
    else if (argument->kind == LensCommand::Kind::POSITION && parseNumber(text, number) && number >= 1.0 &&
             number <= 9999.0)
    {
      command.value = AXIS_EMULATOR_LENS_RANGE.toShare(number);
    }
    else
    {
      return axisLensError(name + ": bad value: " + text);
    }
    commands.push_back(command);
  }
  if (commands.empty())
  {
    return std::nullopt;
  }
  for (const auto& value : values)
  {
    if (value.first != "camera" && std::none_of(std::begin(ARGUMENTS), std::end(ARGUMENTS),
                                                [&](const LensArgument& a) { return value.first == a.name; }))
    {
      return axisLensError(value.first + ": not with a focus or iris argument");
    }
  }
  if (refusing())
  {
    return axisLensError(REFUSAL);
  }
  if (!mayMove(client, now))
  {
    return HttpAnswer{ 204, "text/plain", "" };  // taken, and nothing moves
  }
  for (const LensCommand& command : commands)
  {
    if (command.kind == LensCommand::Kind::MODE)
    {
      lens_.setAuto(command.function, command.automatic(), now);
      continue;
    }
    lens_.setAuto(command.function, false, now);  // a manual focus (iris) command turns its auto off
    if (command.kind == LensCommand::Kind::VELOCITY)
    {
      lens_.drive(command.function, command.value, now);
    }
    else
    {
      lens_.goTo(command.function, command.value, now);
    }
  }
  return HttpAnswer{ 204, "text/plain", "" };
}

std::string AxisCameraEmulator::lensLines(TimePoint now) const
{
  // In the field camera's order: iris, focus, brightness, autofocus, autoiris.
  std::string lines;
  const bool focus = lens_.present(LensFunction::FOCUS);
  const bool iris = lens_.present(LensFunction::IRIS);
  const auto value = [&](LensFunction function) {
    return AXIS_EMULATOR_LENS_RANGE.toValue(lens_.position(function, now));
  };
  lines += iris ? formatText("iris=%.0f\r\n", value(LensFunction::IRIS)) : "";
  lines += focus ? formatText("focus=%.0f\r\n", value(LensFunction::FOCUS)) : "";
  lines += "brightness=5000\r\n";
  lines += focus ? formatText("autofocus=%s\r\n", lens_.isAuto(LensFunction::FOCUS) ? "on" : "off") : "";
  lines += iris ? formatText("autoiris=%s\r\n", lens_.isAuto(LensFunction::IRIS) ? "on" : "off") : "";
  return lines;
}

LensState AxisCameraEmulator::lensState() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return lensStateOf(lens_, clock_->now());
}

}  // namespace ptz_action_server

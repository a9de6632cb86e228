#include "ptz_action_server/core/lens_commander.h"

#include <algorithm>
#include <utility>

namespace ptz_action_server
{
LensCommander::LensCommander(PtzBackend& backend, const LensCapabilities& lens, std::string name,
                             double velocity_timeout)
  : backend_(backend), lens_(lens), name_(std::move(name)), velocity_timeout_(velocity_timeout)
{
}

std::string LensCommander::command(const LensCommand& command, TimePoint now)
{
  std::string refusal = checkLensCommand(lens_, command, name_);
  if (!refusal.empty())
  {
    return refusal;
  }
  const std::size_t index = static_cast<std::size_t>(command.function);
  if (command.kind != LensCommand::Kind::VELOCITY)
  {
    velocity_[index] = 0.0;  // the device's new command replaces the drive
    deadline_[index] = TimePoint::max();
    backend_.lens(command);
    return "";
  }
  if (command.value == 0.0)
  {
    deadline_[index] = TimePoint::max();
  }
  else
  {
    deadline_[index] = addSeconds(now, velocity_timeout_);
  }
  if (command.value != velocity_[index])
  {
    velocity_[index] = command.value;
    backend_.lens(command);
  }
  return "";
}

std::vector<LensFunction> LensCommander::expire(TimePoint now)
{
  std::vector<LensFunction> stopped;
  for (LensFunction function : ALL_LENS_FUNCTIONS)
  {
    const std::size_t index = static_cast<std::size_t>(function);
    if (deadline_[index] != TimePoint::max() && deadline_[index] <= now)
    {
      deadline_[index] = TimePoint::max();
      velocity_[index] = 0.0;
      backend_.lens(LensCommand::velocity(function, 0.0));
      stopped.push_back(function);
    }
  }
  return stopped;
}

TimePoint LensCommander::nextDeadline() const
{
  return std::min(deadline_[0], deadline_[1]);
}

}  // namespace ptz_action_server

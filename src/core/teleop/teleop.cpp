#include "ptz_action_server/core/teleop/teleop.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
std::string TeleopConfig::check() const
{
  if (deadman_button < 0)
  {
    return "deadman_button must be a button index (>= 0): nothing may move without a dead-man button";
  }
  if (!(deadband >= 0.0 && deadband < 1.0))
  {
    return formatText("deadband %g is outside [0, 1)", deadband);
  }
  if (!(step >= 0.0 && step <= 1.0))
  {
    return formatText("step %g is outside [0, 1]", step);
  }
  if (!(stale_timeout > 0.0))
  {
    return formatText("stale_timeout %g must be > 0 s", stale_timeout);
  }
  if (!(zoom_button_speed >= 0.0) || !std::isfinite(pan.scale) || !std::isfinite(tilt.scale) ||
      !std::isfinite(zoom.scale))
  {
    return "scales and zoom_button_speed must be finite (and zoom_button_speed >= 0)";
  }
  return {};
}

TeleopController::TeleopController(const TeleopConfig& config) : config_(config)
{
  max_speed_.fill(std::numeric_limits<double>::infinity());
}

void TeleopController::setSpeedLimits(const AxisValues& max_speed)
{
  max_speed_ = max_speed;
}

bool TeleopController::held(const JoyInput& input, int button)
{
  return button >= 0 && static_cast<std::size_t>(button) < input.buttons.size() && input.buttons[button] != 0;
}

bool TeleopController::pressed(const JoyInput& input, int button) const
{
  const bool before =
      button >= 0 && static_cast<std::size_t>(button) < last_buttons_.size() && last_buttons_[button] != 0;
  return held(input, button) && !before;
}

double TeleopController::shaped(const JoyInput& input, const TeleopAxis& binding) const
{
  if (binding.axis < 0 || static_cast<std::size_t>(binding.axis) >= input.axes.size())
  {
    return 0.0;
  }
  const double value = std::clamp(static_cast<double>(input.axes[binding.axis]), -1.0, 1.0);
  if (!std::isfinite(value) || std::abs(value) <= config_.deadband)
  {
    return 0.0;
  }
  // Stretched so the speed starts from 0 at the deadband's edge, then rounded: a stick's jitter changes nothing.
  double stretched = (std::abs(value) - config_.deadband) / (1.0 - config_.deadband);
  if (config_.step > 0.0)
  {
    stretched = std::round(stretched / config_.step) * config_.step;
  }
  return std::copysign(std::min(stretched, 1.0), value);
}

AxisValues TeleopController::velocityOf(const JoyInput& input) const
{
  AxisValues velocity{ { shaped(input, config_.pan) * config_.pan.scale,
                         shaped(input, config_.tilt) * config_.tilt.scale,
                         shaped(input, config_.zoom) * config_.zoom.scale } };
  const bool zoom_in = held(input, config_.zoom_in_button);
  const bool zoom_out = held(input, config_.zoom_out_button);
  if (zoom_in != zoom_out)
  {
    velocity[ZOOM] = zoom_in ? config_.zoom_button_speed : -config_.zoom_button_speed;
  }
  for (Axis axis : ALL_AXES)
  {
    velocity[axis] = std::clamp(velocity[axis], -max_speed_[axis], max_speed_[axis]);
    velocity[axis] = velocity[axis] == 0.0 ? 0.0 : velocity[axis];  // no -0: it would count as a change
  }
  return velocity;
}

TeleopCommand TeleopController::stop()
{
  active_ = Active::NONE;
  sent_velocity_ = AxisValues{};
  return TeleopCommand{};
}

std::vector<TeleopCommand> TeleopController::onJoy(const JoyInput& input, TimePoint now)
{
  std::vector<TeleopCommand> commands;
  last_joy_ = now;
  heard_ = true;
  if (!held(input, config_.deadman_button))
  {
    if (active_ != Active::NONE)
    {
      commands.push_back(stop());
    }
    last_buttons_ = input.buttons;
    return commands;
  }

  // A preset button wins over the sticks (deflecting them afterwards takes over again).
  TeleopCommand preset;
  preset.type = TeleopCommand::Type::PRESET;
  bool go_to_preset = false;
  if (pressed(input, config_.home_button))
  {
    preset.name = "home";
    go_to_preset = true;
  }
  for (std::size_t index = 0; index < config_.preset_buttons.size() && !go_to_preset; ++index)
  {
    if (pressed(input, config_.preset_buttons[index]))
    {
      preset.name = index < config_.preset_names.size() ? config_.preset_names[index] : std::string();
      preset.preset_index = static_cast<int>(index);
      go_to_preset = true;
    }
  }
  last_buttons_ = input.buttons;
  if (go_to_preset)
  {
    active_ = Active::PRESET;
    sent_velocity_ = AxisValues{};
    commands.push_back(preset);
    return commands;
  }

  const AxisValues velocity = velocityOf(input);
  const bool at_rest = velocity == AxisValues{};
  if (at_rest)
  {
    if (active_ == Active::VELOCITY)
    {
      commands.push_back(stop());
    }
    return commands;
  }
  if (active_ != Active::VELOCITY || velocity != sent_velocity_)
  {
    active_ = Active::VELOCITY;
    sent_velocity_ = velocity;
    TeleopCommand move;
    move.type = TeleopCommand::Type::VELOCITY;
    move.velocity = velocity;
    commands.push_back(move);
  }
  return commands;
}

std::vector<TeleopCommand> TeleopController::onTick(TimePoint now)
{
  std::vector<TeleopCommand> commands;
  if (heard_ && active_ != Active::NONE && secondsBetween(last_joy_, now) > config_.stale_timeout)
  {
    commands.push_back(stop());
  }
  return commands;
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/sim/sim_lens_model.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace ptz_action_server
{
LensCapabilities simLensCapabilities(const SimLensConfig& config)
{
  LensCapabilities lens;
  for (LensFunction function : ALL_LENS_FUNCTIONS)
  {
    LensControl& control = lens.of(function);
    control.present = config.of(function).present;
    control.auto_mode = control.velocity = control.absolute = control.feedback = control.present;
    control.limitation =
        control.present ? "" : std::string("the simulated lens is configured without ") + lensFunctionName(function);
  }
  lens.focus.one_push = lens.focus.present;
  return lens;
}

SimLensModel::SimLensModel(const SimLensConfig& config, TimePoint now) : config_(config)
{
  for (LensFunction function : ALL_LENS_FUNCTIONS)
  {
    const SimLensAxisConfig& settings = config_.of(function);
    Motion& state = axis(function);
    state.from = std::clamp(settings.initial, 0.0, 1.0);
    state.since = now;
    state.automatic = settings.initial_auto;
    state.target = state.automatic ? settings.auto_value : state.from;
  }
}

double SimLensModel::position(LensFunction function, TimePoint now) const
{
  const Motion& state = axis(function);
  const double travel_time = config_.of(function).travel_time;
  const double reach = travel_time > 0.0 ? std::max(0.0, secondsBetween(state.since, now)) / travel_time : 1.0;
  if (state.share != 0.0)
  {
    return std::clamp(state.from + state.share * reach, 0.0, 1.0);
  }
  const double gap = state.target - state.from;
  return std::abs(gap) <= reach ? state.target : state.from + std::copysign(reach, gap);
}

bool SimLensModel::moving(LensFunction function, TimePoint now) const
{
  const Motion& state = axis(function);
  const double at = position(function, now);
  if (state.share != 0.0)
  {
    return state.share > 0.0 ? at < 1.0 : at > 0.0;
  }
  return at != state.target;
}

void SimLensModel::restart(LensFunction function, TimePoint now)
{
  Motion& state = axis(function);
  state.from = position(function, now);
  state.since = now;
}

void SimLensModel::setAuto(LensFunction function, bool automatic, TimePoint now)
{
  restart(function, now);
  Motion& state = axis(function);
  state.automatic = automatic;
  state.share = 0.0;
  state.target = automatic ? config_.of(function).auto_value : state.from;  // manual: it stays where it is
}

void SimLensModel::drive(LensFunction function, double share, TimePoint now)
{
  restart(function, now);
  Motion& state = axis(function);
  state.share = std::clamp(share, -1.0, 1.0);
  state.target = state.from;
}

void SimLensModel::goTo(LensFunction function, double position, TimePoint now)
{
  restart(function, now);
  Motion& state = axis(function);
  state.share = 0.0;
  state.target = std::clamp(position, 0.0, 1.0);
}

void SimLensModel::onePush(TimePoint now)
{
  goTo(LensFunction::FOCUS, config_.focus.auto_value, now);
}

LensState lensStateOf(const SimLensModel& model, TimePoint now)
{
  LensState state;
  for (LensFunction function : ALL_LENS_FUNCTIONS)
  {
    if (model.present(function))
    {
      const auto index = static_cast<std::size_t>(function);
      state.mode[index] = model.isAuto(function) ? LensMode::AUTO : LensMode::MANUAL;
      state.position[index] = model.position(function, now);
    }
  }
  return state;
}

}  // namespace ptz_action_server

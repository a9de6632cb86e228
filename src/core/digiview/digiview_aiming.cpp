/**
 * \file
 * \brief What goals send to DigiView (half of DigiViewProtocol; digiview_protocol.cpp is what DigiView says): targets
 * for positions, a moving target for velocities, a target where the view comes to rest for a stop, nothing while
 * DigiView is halted.
 */
#include "ptz_action_server/core/digiview/digiview_protocol.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
using namespace digiview;

bool DigiViewProtocol::refusedWhileHalted()
{
  if (!halted_)
  {
    return false;
  }
  session_.reportFault(formatText("not sent: %s is halted (SYSTEM_STATUS HALT): its views do not turn until DigiView "
                                  "is set running again",
                                  deviceName().c_str()),
                       session_.currentCommand());
  return true;
}

void DigiViewProtocol::sendTargets(const AxisValues& target)
{
  CamTargeting targeting;
  targeting.camera = settings_.camera();
  targeting.targeting_mode = 0;  // directional
  targeting.yaw = target[PAN];
  targeting.pitch = target[TILT];
  targeting.lock_flags = settings_.lock_flags;
  send(packTargeting(settings_.wire, MessageType::SET_PARAMETERS, targeting));
  CamOpticsAndControl optics;
  optics.camera = settings_.camera();
  optics.fov = settings_.fov_wide / std::clamp(target[ZOOM], 1.0, settings_.zoomMax());
  optics.crop_mode = settings_.crop_mode;
  send(packOptics(settings_.wire, MessageType::SET_PARAMETERS, optics));
}

void DigiViewProtocol::goTo(const AxisValues& position)
{
  velocity_timer_.cancel();
  if (!refusedWhileHalted())
  {
    sendTargets(position);
  }
}

void DigiViewProtocol::moveAtVelocity(const AxisValues& velocity)
{
  if (std::all_of(velocity.begin(), velocity.end(), [](double value) { return value == 0.0; }))
  {
    stop();
    return;
  }
  velocity_timer_.cancel();
  if (refusedWhileHalted())
  {
    return;
  }
  velocity_origin_ = session_.estimate().position;
  velocity_ = velocity;
  velocity_started_ = session_.now();
  velocityTick();
}

void DigiViewProtocol::velocityTick()
{
  // DigiView has no velocity command: the target moves on from where the view was, at the asked rate.
  const double elapsed = secondsBetween(velocity_started_, session_.now());
  const Capabilities limits = capabilities();
  AxisValues target{};
  for (Axis axis : ALL_AXES)
  {
    const AxisRange& range = limits.axes[axis].range;
    target[axis] = std::clamp(velocity_origin_[axis] + velocity_[axis] * elapsed, range.min, range.max);
  }
  sendTargets(target);
  velocity_timer_.expires_after(toDuration(settings_.velocity_period));
  velocity_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error && !session_.closing())
    {
      velocityTick();
    }
  });
}

void DigiViewProtocol::stop()
{
  velocity_timer_.cancel();
  // Hold where the view would come to rest: where it is, plus its braking distance if the turn decelerates.
  const PtzSample now = session_.estimate();
  AxisValues hold = now.position;
  if (settings_.acceleration > 0.0)
  {
    for (Axis axis : { PAN, TILT })
    {
      hold[axis] += now.velocity[axis] * std::abs(now.velocity[axis]) / (2.0 * settings_.acceleration);
    }
  }
  sendTargets(hold);
}

void DigiViewProtocol::hold()
{
  // Back after a loss: whatever DigiView still does belongs to a goal that has ended. Hold the view where it is.
  velocity_timer_.cancel();
  sendTargets(session_.estimate().position);
}

}  // namespace ptz_action_server

/**
 * \file
 * \brief OnvifCameraEmulator's moves: GetStatus, Stop, ContinuousMove (its Timeout), AbsoluteMove and RelativeMove
 * (also in the picture's TranslationSpaceFov), home, and how the camera moves as its modes say (the backlash approach,
 * a speed that ignores the magnitude, a Stop that does not stop, an AbsoluteMove that never moves). Its PTZ service's
 * listings and presets are onvif_camera_emulator_ptz.cpp's.
 */
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "onvif_camera_emulator_internal.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
using namespace onvif;
using namespace onvif_emulator;

namespace
{
constexpr double MOVING = 1e-6;  ///< rad/s (X/s) an axis moves faster than when MoveStatus says MOVING
}  // namespace

std::string OnvifCameraEmulator::setMoveSpeed(const Element* speed, TimePoint now)
{
  // Shares 0..1 of each axis' top speed (GenericSpeedSpace: PanTilt x the pan's, y the tilt's); without a Speed, the
  // configuration's DefaultPTZSpeed (1: the top speed).
  AxisValues share{ { 1.0, 1.0, 1.0 } };
  const PanTiltArgument pan_tilt = panTiltOf(speed);
  const ZoomArgument zoom = zoomOf(speed);
  if (config_.speed_space && speed != nullptr)
  {
    if ((pan_tilt.given && !pan_tilt.space.empty() && pan_tilt.space != GENERIC_PAN_TILT_SPEED) ||
        (zoom.given && !zoom.space.empty() && zoom.space != GENERIC_ZOOM_SPEED))
    {
      return "space";
    }
    const auto within = [](double value) { return value >= 0.0 && value <= 1.0; };
    if (!pan_tilt.numbers || !zoom.number || (pan_tilt.given && !(within(pan_tilt.x) && within(pan_tilt.y))) ||
        (zoom.given && !within(zoom.x)))
    {
      return "speed";
    }
    share = { { pan_tilt.given ? pan_tilt.x : 1.0, pan_tilt.given ? pan_tilt.y : 1.0, zoom.given ? zoom.x : 1.0 } };
  }
  for (Axis axis : ALL_AXES)
  {
    commanded_speed_[axis] = share[axis] * config_.device.axes[axis].motion.max_speed;
    model_.setCruiseSpeed(axis, commanded_speed_[axis], now);
  }
  return {};
}

AxisValues OnvifCameraEmulator::commandedSpeed() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return commanded_speed_;
}

void OnvifCameraEmulator::goToAll(const AxisValues& position, TimePoint now)
{
  velocity_axes_ = {};
  approach_.fill(std::numeric_limits<double>::quiet_NaN());
  setMoveSpeed(nullptr, now);  // the default speed
  for (Axis axis : ALL_AXES)
  {
    driving_[axis] = true;
    model_.goToAxis(axis, position[axis], now);
  }
}

void OnvifCameraEmulator::goToPanTilt(Axis axis, double target, TimePoint now)
{
  velocity_axes_[axis] = false;
  driving_[axis] = true;
  if (config_.backlash <= 0.0)
  {
    approach_[axis] = std::numeric_limits<double>::quiet_NaN();
    model_.goToAxis(axis, target, now);
    return;
  }
  // It takes up its gears' backlash: to the point below the target first, then up to it (advance()), even when it
  // stands there already.
  const AxisRange& travel = config_.device.axes[axis].range;
  approach_[axis] = std::clamp(target, travel.min, travel.max);
  model_.goToAxis(axis, std::max(travel.min, approach_[axis] - config_.backlash), now);
}

void OnvifCameraEmulator::moveAxis(Axis axis, double x, TimePoint now)
{
  const double max_speed = config_.device.axes[axis].motion.max_speed;
  // A camera that ignores the magnitude moves at its one speed for any velocity but 0.
  const double speed = config_.fixed_speed_share > 0.0 && x != 0.0 ? std::copysign(config_.fixed_speed_share, x) : x;
  approach_[axis] = std::numeric_limits<double>::quiet_NaN();
  velocity_axes_[axis] = true;
  driving_[axis] = speed != 0.0;
  model_.moveAxisAtVelocity(axis, speed * max_speed, now);
}

void OnvifCameraEmulator::advance(TimePoint now) const
{
  if (now >= velocity_until_ && !config_.stop_keeps_moving)  // those cameras go on past their Timeout too
  {
    for (Axis axis : ALL_AXES)
    {
      if (velocity_axes_[axis])
      {
        velocity_axes_[axis] = false;
        driving_[axis] = false;
        model_.moveAxisAtVelocity(axis, 0.0, velocity_until_);  // the ContinuousMove's Timeout ran out
      }
    }
  }
  const PtzSample state = model_.sample(now);
  for (Axis axis : { PAN, TILT })
  {
    const double below = std::max(config_.device.axes[axis].range.min, approach_[axis] - config_.backlash);
    if (!std::isnan(approach_[axis]) && std::abs(state.position[axis] - below) < 1e-9 &&
        std::abs(state.velocity[axis]) <= MOVING)
    {
      model_.goToAxis(axis, approach_[axis], now);  // below the target: now up to it
      approach_[axis] = std::numeric_limits<double>::quiet_NaN();
    }
  }
}

HttpAnswer OnvifCameraEmulator::move(const std::string& operation, const Element* request, TimePoint now)
{
  if (operation == "GetStatus")
  {
    const PtzSample state = model_.sample(now);
    std::array<bool, AXIS_COUNT> moves{};
    for (Axis axis : ALL_AXES)
    {
      // A blocked axis (a stall fault) does not move, but the camera still drives it: MOVING, as a real one says.
      moves[axis] = std::abs(state.velocity[axis]) > MOVING || (driving_[axis] && model_.faults().stalled[axis]);
    }
    const bool pan_tilt_moves = moves[PAN] || moves[TILT];
    const bool zoom_moves = moves[ZOOM];
    return respond(ns::PTZ, "GetStatusResponse><PTZStatus>" +
                                (config_.status_position ? positionVector("Position", state.position) : std::string()) +
                                "<sch:MoveStatus><sch:PanTilt>" + (pan_tilt_moves ? "MOVING" : "IDLE") +
                                "</sch:PanTilt><sch:Zoom>" + (zoom_moves ? "MOVING" : "IDLE") +
                                "</sch:Zoom></sch:MoveStatus><sch:UtcTime>" + isoTime(cameraUtc()) +
                                "</sch:UtcTime></PTZStatus></GetStatusResponse>");
  }
  if (operation == "Stop")
  {
    const std::string pan_tilt = text(child(request, ns::PTZ, "PanTilt"));
    const std::string zoom = text(child(request, ns::PTZ, "Zoom"));
    const bool stop_pan_tilt = pan_tilt != "false" && pan_tilt != "0";  // both default to true
    const bool stop_zoom = zoom != "false" && zoom != "0";
    for (Axis axis : ALL_AXES)
    {
      // A camera that keeps moving after Stop goes on at its ContinuousMove's speed (a position move does stop).
      if ((axis == ZOOM ? stop_zoom : stop_pan_tilt) && !(config_.stop_keeps_moving && velocity_axes_[axis]))
      {
        velocity_axes_[axis] = false;
        driving_[axis] = false;
        approach_[axis] = std::numeric_limits<double>::quiet_NaN();
        model_.moveAxisAtVelocity(axis, 0.0, now);
      }
    }
    return respond(ns::PTZ, "StopResponse></StopResponse>");
  }
  if (operation == "ContinuousMove")
  {
    const Element* velocity = child(request, ns::PTZ, "Velocity");
    const PanTiltArgument pan_tilt = panTiltOf(velocity);
    const ZoomArgument zoom = zoomOf(velocity);
    double timeout = 5.0;  // DefaultPTZTimeout
    const Element* timeout_element = child(request, ns::PTZ, "Timeout");
    if ((pan_tilt.given && !pan_tilt.space.empty() && pan_tilt.space != GENERIC_PAN_TILT_VELOCITY) ||
        (zoom.given && !zoom.space.empty() && zoom.space != GENERIC_ZOOM_VELOCITY))
    {
      return invalid("ter:SpaceNotSupported", "A space is referenced which is not supported by the PTZ node");
    }
    if (!pan_tilt.numbers || !zoom.number || std::abs(pan_tilt.x) > 1 || std::abs(pan_tilt.y) > 1 ||
        std::abs(zoom.x) > 1)
    {
      return invalid("ter:InvalidVelocity", "The requested speed is out of bounds");
    }
    if (timeout_element != nullptr && (!parseDuration(text(timeout_element), timeout) ||
                                       timeout < config_.min_timeout || timeout > config_.max_timeout))
    {
      return invalid("ter:TimeoutNotSupported", "The specified timeout argument is not within the supported timeout "
                                                "range");
    }
    // An axis left out goes on as it was; one at 0 stops.
    if (pan_tilt.given)
    {
      moveAxis(PAN, pan_tilt.x, now);
      moveAxis(TILT, pan_tilt.y, now);
    }
    if (zoom.given)
    {
      moveAxis(ZOOM, zoom.x, now);
    }
    velocity_until_ = addSeconds(now, timeout);
    return respond(ns::PTZ, "ContinuousMoveResponse></ContinuousMoveResponse>");
  }
  if (!config_.absolute)
  {
    return notSupported(operation);  // the continuous-only cameras: no positions, so no presets or home either
  }
  if (operation == "AbsoluteMove" || operation == "RelativeMove")
  {
    const bool absolute = operation == "AbsoluteMove";
    if ((absolute && config_.refuse_absolute_move) || (!absolute && !config_.relative))
    {
      return notSupported(operation);
    }
    const Element* argument = child(request, ns::PTZ, absolute ? "Position" : "Translation");
    PanTiltArgument pan_tilt = panTiltOf(argument);
    ZoomArgument zoom = zoomOf(argument);
    if (pan_tilt.space.empty())
    {
      pan_tilt.space = absolute ? defaultSpace() : GENERIC_PAN_TILT_TRANSLATION;
    }
    if (zoom.space.empty())
    {
      zoom.space = absolute ? GENERIC_ZOOM_SPACE : GENERIC_ZOOM_TRANSLATION;
    }
    const bool degrees = pan_tilt.space == (absolute ? DEGREE_SPACE : DEGREE_TRANSLATION);
    const bool generic = pan_tilt.space == (absolute ? GENERIC_PAN_TILT_SPACE : GENERIC_PAN_TILT_TRANSLATION);
    // In the picture: x, y from its centre to its right and top edges; the zoom multiplies the magnification.
    const bool fov = !absolute && config_.fov_space && pan_tilt.space == FOV_PAN_TILT_TRANSLATION;
    const bool fov_zoom = !absolute && config_.fov_space && zoom.space == FOV_ZOOM_TRANSLATION;
    if ((pan_tilt.given && !(generic || fov || (degrees && config_.degree_space))) ||
        (zoom.given && !fov_zoom && zoom.space != (absolute ? GENERIC_ZOOM_SPACE : GENERIC_ZOOM_TRANSLATION)))
    {
      return invalid("ter:SpaceNotSupported", "A space is referenced that is not supported by the PTZ node");
    }
    // The camera's own ranges, whatever GetNodes lists (generic: the whole travel; degrees: its mechanics).
    const double limit_x = degrees ? (absolute ? 180.0 : 360.0) : (absolute || fov ? 1.0 : 2.0);
    const double limit_y = degrees ? (absolute ? 90.0 : 180.0) : (absolute || fov ? 1.0 : 2.0);
    const bool zoom_in_range = absolute ? zoom.x >= 0.0 && zoom.x <= 1.0 :
                               fov_zoom ? zoom.x > 0.0 && zoom.x <= zoomMax() :
                                          std::abs(zoom.x) <= 1.0;
    if (!pan_tilt.numbers || !zoom.number || std::abs(pan_tilt.x) > limit_x || std::abs(pan_tilt.y) > limit_y ||
        !zoom_in_range)
    {
      return absolute ? invalid("ter:InvalidPosition", "The requested position is out of bounds") :
                        invalid("ter:InvalidTranslation", "The requested translation is out of bounds");
    }
    const std::string speed_problem = setMoveSpeed(child(request, ns::PTZ, "Speed"), now);
    if (speed_problem == "space")
    {
      return invalid("ter:SpaceNotSupported", "A speed space is referenced that is not supported by the PTZ node");
    }
    if (!speed_problem.empty())
    {
      return invalid("ter:InvalidSpeed", "The requested speed is out of bounds");
    }
    if (absolute && config_.absolute_never_moves)
    {
      return respond(ns::PTZ, "AbsoluteMoveResponse></AbsoluteMoveResponse>");  // answered, and nothing moves
    }
    const AxisValues at = model_.sample(now).position;
    if (pan_tilt.given)
    {
      double pan = degrees ? toRadians(pan_tilt.x) : pan_tilt.x * M_PI;
      double tilt = degrees ? toRadians(pan_tilt.y) : pan_tilt.y * M_PI / 2.0;
      if (fov)
      {
        centreOf(at[PAN], at[TILT], lens_.at(at[ZOOM]), pan_tilt.x, pan_tilt.y, pan, tilt);
        pan -= at[PAN];
        tilt -= at[TILT];
      }
      // A translation beyond the travel stops at its border.
      const AxisRange& pan_travel = config_.device.axes[PAN].range;
      const AxisRange& tilt_travel = config_.device.axes[TILT].range;
      goToPanTilt(PAN, std::clamp(absolute ? pan : at[PAN] + pan, pan_travel.min, pan_travel.max), now);
      goToPanTilt(TILT, std::clamp(absolute ? tilt : at[TILT] + tilt, tilt_travel.min, tilt_travel.max), now);
    }
    if (zoom.given)
    {
      // The lens stops where it really ends (honoured_zoom), whatever the move asked: the model clamps.
      const double z = absolute ? zoom.x :
                       fov_zoom ? std::log(at[ZOOM] * zoom.x) / std::log(zoomMax()) :
                                  std::log(at[ZOOM]) / std::log(zoomMax()) + zoom.x;
      velocity_axes_[ZOOM] = false;
      driving_[ZOOM] = true;
      model_.goToAxis(ZOOM, std::pow(zoomMax(), std::clamp(z, 0.0, 1.0)), now);
    }
    return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
  }
  if (operation == "GotoHomePosition" || operation == "SetHomePosition")
  {
    if (!config_.home)
    {
      return notSupported(operation);
    }
    if (operation == "SetHomePosition")
    {
      home_ = model_.sample(now).position;
    }
    else
    {
      goToAll(home_, now);
    }
    return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
  }
  return notSupported(operation);
}

}  // namespace ptz_action_server

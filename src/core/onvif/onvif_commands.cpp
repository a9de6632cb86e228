/**
 * \file
 * \brief OnvifProtocol's commands (AbsoluteMove, ContinuousMove, Stop) and what it does with what the motion check
 * finds the camera did after them.
 */
#include <algorithm>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// A target this close to where an axis rests is where it is (rad): a goal that leaves it there.
constexpr double SAME_POSITION = 1e-6;
/// A zoom this close (X) above the highest the camera reaches is within its reach.
constexpr double ZOOM_REACHED = 0.05;
}  // namespace

void OnvifProtocol::onFinding(const onvif::MotionFinding& finding)
{
  using onvif::MotionFinding;
  if (finding.kind == MotionFinding::KEPT_MOVING_AFTER_STOP)
  {
    sendZeroVelocity();
    stop_needs_zero_velocity_ = true;
    std::string speeds;
    for (Axis axis : ALL_AXES)
    {
      if (finding.axes[axis])
      {
        speeds += formatText("%s%s at %.3g %s/s", speeds.empty() ? "" : ", ", axisName(axis), finding.speed[axis],
                             unitOf(axis));
      }
    }
    warnOnce("Stop", formatText("the camera answered Stop but kept moving (%s, %.2f s after it): it stops only on a "
                                "ContinuousMove with zero velocity, which now follows every Stop",
                                speeds.c_str(), finding.after));
  }
  else if (finding.kind == MotionFinding::ABSOLUTE_MOVE_IGNORED)
  {
    const bool pan_tilt = finding.axes[PAN] && pan_tilt_.absolute;
    const bool zoom = finding.axes[ZOOM] && zoom_.absolute;
    pan_tilt_ignores_absolute_ = pan_tilt_ignores_absolute_ || pan_tilt;
    zoom_ignores_absolute_ = zoom_ignores_absolute_ || zoom;
    pan_tilt_.absolute = pan_tilt_.absolute && !pan_tilt;
    zoom_.absolute = zoom_.absolute && !zoom;
    const std::string what = pan_tilt && zoom ? "its pan, tilt and zoom" : pan_tilt ? "its pan-tilt" : "its zoom";
    if (pan_tilt)
    {
      pan_tilt_.limitation = IGNORES_ABSOLUTE_MOVE;
    }
    if (zoom)
    {
      zoom_.limitation = IGNORES_ABSOLUTE_MOVE;
    }
    const std::string text = formatText("the ONVIF camera answered AbsoluteMove but did not move %s (%.1f s later "
                                        "still where it was, its MoveStatus never MOVING): a camera that accepts "
                                        "AbsoluteMove and never moves; from now on position goals are steered on "
                                        "ContinuousMove and its status",
                                        what.c_str(), finding.after);
    session_.setCapabilities(cameraCapabilities());
    session_.reportFault(text, watched_command_);
    warnOnce("AbsoluteMove ignored " + what, text);
  }
  else if (finding.kind == MotionFinding::ZOOM_STOPPED_SHORT && finding.zoom_target > finding.zoom)
  {
    honoured_zoom_max_ = std::max(honoured_zoom_max_, finding.zoom);
    const std::string text = formatText("the ONVIF camera stopped its zoom at %.3gX, short of the %.3gX it accepted an "
                                        "AbsoluteMove to: it does not "
                                        "honour the zoom range its GetNodes lists (1X..%gX); zoom goals beyond %.3gX "
                                        "are not sent from now on",
                                        finding.zoom, finding.zoom_target, settings_.zoom_max, honoured_zoom_max_);
    session_.setCapabilities(cameraCapabilities());
    session_.reportFault(text, watched_command_);
    warnOnce("zoom range", text);
  }
  else if (finding.kind == MotionFinding::ZOOM_STOPPED_SHORT)
  {
    session_.reportFault(formatText("the ONVIF camera stopped its zoom at %.3gX, short of the %.3gX it accepted an "
                                    "AbsoluteMove to",
                                    finding.zoom, finding.zoom_target),
                         watched_command_);
  }
}

void OnvifProtocol::sendZeroVelocity()
{
  if (!pan_tilt_.velocity && !zoom_.velocity)
  {
    return;
  }
  ++counters_.zero_velocity_stops;
  command(paths_.ptz,
          onvif::continuousMove(profile_.token, 0.0, 0.0, zoom_.velocity, 0.0, velocity_timeout_, pan_tilt_.velocity),
          "ContinuousMove");
}

bool OnvifProtocol::command(const std::string& path, const std::string& body, const char* operation)
{
  const std::uint64_t serial = session_.currentCommand();
  std::string problem;
  const bool done = call(path, body, true, problem);
  commandResult(done, problem, serial);
  if (!done && !problem.empty() && std::string(operation) == "AbsoluteMove" &&
      onvif::faultHas(message_, "ActionNotSupported"))
  {
    absoluteMoveRefused(message_.fault_text);
  }
  if (std::string(operation) == "ContinuousMove")
  {
    velocity_sent_at_ = session_.now();
  }
  return done;
}

void OnvifProtocol::absoluteMoveRefused(const std::string& answer)
{
  if (!absolute_refused_.empty())
  {
    return;
  }
  // Some continuous-only cameras list position spaces all the same: their answer is the truth.
  std::string codes;
  for (const std::string& subcode : message_.subcodes)
  {
    codes += (codes.empty() ? "" : "/") + subcode;
  }
  absolute_refused_ = codes.empty() ? message_.fault_code : codes;  // "ter:ActionNotSupported"
  pan_tilt_.absolute = false;
  zoom_.absolute = false;
  pan_tilt_.limitation = "this camera answers AbsoluteMove with " + absolute_refused_ +
                         (pan_tilt_.limitation.empty() ? "" : " and " + pan_tilt_.limitation);
  zoom_.limitation = zoom_.present ? "this camera answers AbsoluteMove with " + absolute_refused_ : zoom_.limitation;
  session_.setCapabilities(cameraCapabilities());
  warnOnce("AbsoluteMove", "the camera lists position spaces but answered AbsoluteMove with " + answer +
                               ": it is taken as a camera that only moves at a speed (ContinuousMove) from now on");
}

void OnvifProtocol::goTo(const AxisValues& position)
{
  goToAtSpeed(position, AxisValues{});
}

void OnvifProtocol::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  velocity_body_.clear();
  motion_check_.clear();
  const bool pan_tilt = !(std::isnan(position[PAN]) && std::isnan(position[TILT]));
  const bool zoom = zoom_.present && !std::isnan(position[ZOOM]);
  if ((pan_tilt && !pan_tilt_.absolute) || (zoom && !zoom_.absolute))
  {
    ++counters_.refused_locally;
    const bool pan_tilt_lacks = pan_tilt && !pan_tilt_.absolute;
    session_.reportFault(std::string("not sent: the ONVIF camera cannot go to a ") +
                             (pan_tilt_lacks ? "pan-tilt" : "zoom") + " position (" +
                             (pan_tilt_lacks ? pan_tilt_.limitation : zoom_.limitation) + ")",
                         session_.currentCommand());
    return;
  }
  if (zoom && honoured_zoom_max_ > 0.0 && position[ZOOM] > honoured_zoom_max_ + ZOOM_REACHED)
  {
    ++counters_.refused_locally;
    session_.reportFault(formatText("not sent: zoom %.3gX is beyond the %.3gX this ONVIF camera's zoom reaches (it "
                                    "does not honour the zoom range its GetNodes lists, 1X..%gX)",
                                    position[ZOOM], honoured_zoom_max_, settings_.zoom_max),
                         session_.currentCommand());
    return;
  }
  const PtzSample now = session_.estimate();
  AxisValues sent = position;  // what the move sends each axis to (NaN: left out), for the motion check
  onvif::Vector target;
  if (pan_tilt)
  {
    // Pan and tilt travel together (a PanTilt has x and y): an axis left alone keeps where it is.
    const double pan = std::isnan(position[PAN]) ? now.position[PAN] : position[PAN];
    const double tilt = std::isnan(position[TILT]) ? now.position[TILT] : position[TILT];
    const bool degrees = pan_tilt_.move_space == onvif::DEGREE_SPACE;
    target.x = std::clamp(degrees ? toDegrees(pan) : genericOf(settings_.pan, pan), pan_tilt_.x.min, pan_tilt_.x.max);
    target.y =
        std::clamp(degrees ? toDegrees(tilt) : genericOf(settings_.tilt, tilt), pan_tilt_.y.min, pan_tilt_.y.max);
    // A goal that leaves pan and tilt where they rest (a zoom-only goal) sends no PanTilt: some cameras move pan and
    // tilt on any AbsoluteMove that carries one, even to where they are.
    const bool unchanged = pan_tilt_.feedback && !now.moving && std::abs(pan - now.position[PAN]) <= SAME_POSITION &&
                           std::abs(tilt - now.position[TILT]) <= SAME_POSITION;
    target.pan_tilt = !unchanged;
    target.pan_tilt_space = pan_tilt_.move_space;
    sent[PAN] = unchanged ? std::numeric_limits<double>::quiet_NaN() :
                degrees   ? toRadians(target.x) :
                            angleOf(settings_.pan, target.x);
    sent[TILT] = unchanged ? std::numeric_limits<double>::quiet_NaN() :
                 degrees   ? toRadians(target.y) :
                             angleOf(settings_.tilt, target.y);
  }
  if (zoom)
  {
    target.zoom = true;
    target.zoom_space = onvif::GENERIC_ZOOM_SPACE;
    target.z = std::clamp(std::log(std::max(1.0, position[ZOOM])) / std::log(settings_.zoom_max), 0.0, 1.0);
    sent[ZOOM] = std::pow(settings_.zoom_max, target.z);
  }
  // The Speed, where the node lists its space and the goal asks one (0: the camera's default speed, no Speed sent).
  // PanTilt x is the pan's share of its top speed and y the tilt's; an axis that asks none goes at its top.
  const auto share = [](double asked, double top, const onvif::Range& range) {
    const double slowest = std::max(range.min, 0.0);
    return std::clamp(asked > 0.0 && top > 0.0 ? asked / top : 1.0, slowest, std::max(range.max, slowest));
  };
  onvif::Vector move_speed;
  move_speed.pan_tilt = target.pan_tilt && pan_tilt_.speed && (speed[PAN] > 0.0 || speed[TILT] > 0.0);
  move_speed.x = share(speed[PAN], settings_.pan_max_speed, pan_tilt_.speed_range);
  move_speed.y = share(speed[TILT], settings_.tilt_max_speed, pan_tilt_.speed_range);
  move_speed.pan_tilt_space = onvif::GENERIC_PAN_TILT_SPEED;
  move_speed.zoom = target.zoom && zoom_.speed && speed[ZOOM] > 0.0;
  move_speed.z = share(speed[ZOOM], settings_.zoom_max_rate, zoom_.speed_range);
  move_speed.zoom_space = onvif::GENERIC_ZOOM_SPEED;
  if (target.pan_tilt || target.zoom)
  {
    if (command(paths_.ptz, onvif::absoluteMove(profile_.token, target, move_speed), "AbsoluteMove"))
    {
      watched_command_ = session_.currentCommand();
      motion_check_.absoluteMoveSent(session_.now(), now.position, sent);
    }
  }
}

void OnvifProtocol::moveAtVelocity(const AxisValues& velocity)
{
  const bool pan_tilt_moves = velocity[PAN] != 0.0 || velocity[TILT] != 0.0;
  if ((pan_tilt_moves && !pan_tilt_.velocity) || (velocity[ZOOM] != 0.0 && !zoom_.velocity))
  {
    ++counters_.refused_locally;
    velocity_body_.clear();
    const bool zoom_lacks = velocity[ZOOM] != 0.0 && !zoom_.velocity;
    session_.reportFault(std::string("not sent: the ONVIF camera cannot move its ") +
                             (zoom_lacks ? "zoom" : "pan-tilt") + " at a speed (" +
                             (zoom_lacks ?
                                  (zoom_.limitation.empty() ? "it lists no zoom velocity space" : zoom_.limitation) :
                                  pan_tilt_.limitation) +
                             ")",
                         session_.currentCommand());
    return;
  }
  if (!pan_tilt_.velocity && !zoom_.velocity)
  {
    return;
  }
  const double x = std::clamp(settings_.velocity_sign_pan * velocity[PAN] / settings_.pan_max_speed, -1.0, 1.0);
  const double y = std::clamp(settings_.velocity_sign_tilt * velocity[TILT] / settings_.tilt_max_speed, -1.0, 1.0);
  const double zoom = std::clamp(velocity[ZOOM] / settings_.zoom_max_rate, -1.0, 1.0);
  motion_check_.clear();
  velocity_body_ =
      onvif::continuousMove(profile_.token, x, y, zoom_.velocity, zoom, velocity_timeout_, pan_tilt_.velocity);
  command(paths_.ptz, velocity_body_, "ContinuousMove");
}

void OnvifProtocol::stop()
{
  velocity_body_.clear();
  const PtzSample before = session_.estimate();
  motion_check_.clear();
  const bool answered = command(paths_.ptz, onvif::stop(profile_.token), "Stop");
  if (stop_needs_zero_velocity_)
  {
    sendZeroVelocity();  // the camera goes on after Stop, until a ContinuousMove with zero velocity
  }
  else if (answered)
  {
    watched_command_ = session_.currentCommand();
    motion_check_.stopSent(session_.now(), before.velocity);
  }
}

}  // namespace ptz_action_server

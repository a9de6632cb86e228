#include "ptz_action_server/core/axis/axis_protocol.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
int percentOf(double value, double full)
{
  return static_cast<int>(std::lround(std::clamp(value / full, -1.0, 1.0) * 100.0));
}
}  // namespace

AxisProtocol::AxisProtocol(const AxisSettings& settings, DeviceSession& session)
  : HttpDeviceProtocol(session), settings_(settings)
{
  if (!settings_.zoom_table.empty() && settings_.zoom_max_factor != 0.0)
  {
    throw ConfigError("zoom_table and zoom_max_factor are both set: set one");
  }
  if (!settings_.zoom_table.empty())
  {
    const std::string problem = vapix::ZoomTable::parse(settings_.zoom_table, configured_table_);
    if (!problem.empty())
    {
      throw ConfigError("zoom_table '" + settings_.zoom_table + "': " + problem);
    }
  }
  else if (settings_.zoom_max_factor != 0.0)
  {
    configured_table_ = vapix::ZoomTable::linear(settings_.zoom_max_factor);
    if (configured_table_.empty())
    {
      throw ConfigError(formatText("zoom_max_factor %g: must be above 1 (the X at VAPIX zoom 9999), or 0",
                                   settings_.zoom_max_factor));
    }
  }
}

Capabilities AxisProtocol::capabilities() const
{
  // Before the camera is asked: pan and tilt as VAPIX documents them, zoom as the settings say.
  Capabilities capabilities;
  const vapix::Limits limits;
  capabilities.axes[PAN] = fullAxis({ toRadians(limits.min_pan), toRadians(limits.max_pan) }, settings_.pan_max_speed,
                                    settings_.acceleration);
  capabilities.axes[TILT] = fullAxis({ toRadians(limits.min_tilt), toRadians(limits.max_tilt) },
                                     settings_.tilt_max_speed, settings_.acceleration);
  capabilities.speed = moveSpeed();
  capabilities.axes[ZOOM] =
      configured_table_.empty() ?
          absentAxis("the Axis camera has not been asked yet") :
          fullAxis({ configured_table_.minFactor(), configured_table_.maxFactor() }, settings_.zoom_max_rate, 0.0);
  return capabilities;
}

MoveSpeedCapability AxisProtocol::moveSpeed() const
{
  MoveSpeedCapability speed;
  speed.control = { { SpeedControl::DEVICE, SpeedControl::DEVICE, SpeedControl::OWN } };
  speed.min_speed = { { settings_.pan_max_speed / 100.0, settings_.tilt_max_speed / 100.0, 0.0 } };
  return speed;
}

bool AxisProtocol::exchange(const std::string& path, const std::string& what, std::string& body, std::string& problem)
{
  request_.path = path;
  const HttpReply* answer = send(request_);
  problem.clear();
  if (answer == nullptr)
  {
    return false;  // the link is lost, with its reason
  }
  switch (answer->status)
  {
    case 200:
    case 204:
      body = answer->body;
      return true;
    case 403:
      problem = "HTTP 403 Forbidden: user '" + httpUser() + "' may not control PTZ (" + what + ")";
      break;
    case 404:
      problem = "HTTP 404 Not Found: " + path.substr(0, path.find('?')) + " (no VAPIX PTZ at this address?)";
      break;
    default:
      problem = statusProblem(answer->status, what);  // 401 too
      break;
  }
  ++counters_.error_answers;
  return false;
}

bool AxisProtocol::request(const std::string& arguments, vapix::Reply& reply, std::string& problem)
{
  arguments_path_ = formatText("%s?camera=%d&", vapix::PTZ_PATH, settings_.camera);
  arguments_path_ += arguments;
  const std::string what = "'" + arguments + "'";
  if (!exchange(arguments_path_, what, body_, problem))
  {
    return false;
  }
  const std::string malformed = vapix::parseReply(body_, reply);
  if (!malformed.empty())
  {
    ++counters_.malformed;
    problem = "malformed answer to " + what + ": " + malformed;
    return false;
  }
  if (reply.error)
  {
    problem = "the Axis camera refused " + what + ": " + reply.error_text;
    return false;
  }
  return true;
}

void AxisProtocol::onConnected()
{
  std::string problem;
  if (!request("query=limits", reply_, problem))
  {
    setupFailed(problem);
    return;
  }
  vapix::Limits limits;
  problem = vapix::readLimits(reply_, limits);
  if (!problem.empty())
  {
    ++counters_.malformed;
    setupFailed("query=limits: " + problem);
    return;
  }
  lens_limits_ = vapix::readLensLimits(reply_);
  // What the camera offers: informative only (a camera that does not answer it gets VAPIX's documented commands).
  vapix::CommandList commands;
  const std::string info_path = formatText("%s?camera=%d&info=1", vapix::PTZ_PATH, settings_.camera);
  if (exchange(info_path, "'info=1'", body_, problem))
  {
    commands = vapix::readCommandList(body_);
  }
  else if (!session_.connected())
  {
    return;
  }
  findControlQueue();
  if (control_queue_ && !requestControl())
  {
    if (!session_.connected())
    {
      return;
    }
    session_.warn(withoutControl() + ": goals fail until control is ours");
  }
  if (!request("query=position", reply_, problem))
  {
    setupFailed(problem);
    return;
  }
  vapix::Position position;
  problem = vapix::readPosition(reply_, position);
  if (!problem.empty())
  {
    ++counters_.malformed;
    setupFailed("query=position: " + problem);
    return;
  }
  if (!findZoomTable(limits))
  {
    return;
  }
  zoom_feedback_ = !zoom_table_.empty() && position.has_zoom;
  zoom_velocity_ = limits.has_zoom && (commands.empty() || commands.has("continuouszoommove"));
  widest_view_ = limits.has_zoom && !zoom_feedback_ && (commands.empty() || commands.has("zoom"));
  widest_zoom_value_ = limits.min_zoom;
  Capabilities capabilities = cameraCapabilities(limits, commands);
  const vapix::LensReading lens = vapix::readLens(reply_);
  capabilities.lens = vapix::lensCapabilities(lens_limits_, lens, commands);
  reportLens(lens);
  if (zoom_source_ != AxisZoomSource::NO_ZOOM && !zoom_table_.empty() && !position.has_zoom)
  {
    session_.warn("this Axis camera reports no zoom position (query=position has no zoom=): zoom goals other than 1 "
                  "(the widest view) are refused");
  }
  session_.setCapabilities(capabilities);
  session_.ready();
  ++counters_.positions;
  session_.reportState({ toRadians(position.pan), toRadians(position.tilt), zoomFactor(position) });
}

double AxisProtocol::zoomFactor(const vapix::Position& position) const
{
  return zoom_feedback_ ? zoom_table_.toFactor(position.zoom) : 1.0;
}

void AxisProtocol::poll()
{
  std::string problem;
  if (!request("query=position", reply_, problem))
  {
    if (!problem.empty())
    {
      session_.disconnect("query=position: " + problem);  // an HTTP error or nonsense: set up afresh after the backoff
    }
    return;
  }
  vapix::Position position;
  problem = vapix::readPosition(reply_, position);
  if (!problem.empty())
  {
    ++counters_.malformed;
    session_.disconnect("query=position: " + problem);
    return;
  }
  ++counters_.positions;
  reportLens(vapix::readLens(reply_));
  session_.reportState({ toRadians(position.pan), toRadians(position.tilt), zoomFactor(position) });
  if (control_queue_ && secondsBetween(control_asked_at_, session_.now()) >= renew_after_)
  {
    requestControl();  // keeps control (or our place in the queue) before the camera's timer runs out
  }
}

void AxisProtocol::command(const std::string& arguments)
{
  const std::uint64_t serial = session_.currentCommand();
  if (!haveControl())
  {
    // The camera would take the command and not move: say why instead.
    ++counters_.without_control;
    session_.reportFault(withoutControl(), serial);
    return;
  }
  std::string problem;
  vapix::Reply reply;
  const bool done = request(arguments, reply, problem);
  if (!done && !problem.empty())
  {
    ++counters_.refusals;
  }
  commandResult(done, problem, serial);
}

void AxisProtocol::goTo(const AxisValues& position)
{
  goToAtSpeed(position, AxisValues{});
}

void AxisProtocol::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  arguments_.clear();
  int percent = settings_.speed;
  for (const auto& [axis, top] : { std::pair<Axis, double>{ PAN, settings_.pan_max_speed },
                                   std::pair<Axis, double>{ TILT, settings_.tilt_max_speed } })
  {
    if (speed[axis] > 0.0 && top > 0.0)
    {
      percent = std::min(percent, static_cast<int>(std::ceil(100.0 * speed[axis] / top)));
    }
  }
  // A zoom it cannot map (no X-factor known) or read back is commanded only to its widest view, MinZoom (the goal
  // validation lets nothing else through); NaN leaves it alone.
  double zoom_value = 0.0;  // left out
  if (zoom_feedback_ && std::isfinite(position[ZOOM]))
  {
    zoom_value = zoom_table_.toValue(position[ZOOM]);
  }
  else if (widest_view_ && position[ZOOM] == 1.0)
  {
    zoom_value = widest_zoom_value_;
  }
  vapix::appendAbsoluteMove(arguments_, toDegrees(position[PAN]), toDegrees(position[TILT]), zoom_value, percent);
  command(arguments_);
}

void AxisProtocol::moveAtVelocity(const AxisValues& velocity)
{
  arguments_.clear();
  vapix::appendContinuousMove(arguments_, percentOf(velocity[PAN], settings_.pan_max_speed),
                              percentOf(velocity[TILT], settings_.tilt_max_speed),
                              percentOf(velocity[ZOOM], settings_.zoom_max_rate), zoom_velocity_);
  command(arguments_);
}

void AxisProtocol::stop()
{
  command("move=stop");
}

void AxisProtocol::aimInView(const ViewTarget& target)
{
  // Whole pixels of the picture the point was chosen on: its size goes along, so the camera scales them to its own.
  vapix::ImagePoint point;
  point.image_width = std::max(target.image_width, 1);
  point.image_height = std::max(target.image_height, 1);
  point.x = static_cast<int>(std::lround(std::clamp(target.x, 0.0, 1.0) * point.image_width));
  point.y = static_cast<int>(std::lround(std::clamp(target.y, 0.0, 1.0) * point.image_height));
  arguments_.clear();
  if (target.box())
  {
    vapix::appendAreaZoom(arguments_, point, static_cast<int>(std::lround(100.0 * target.magnification())));
  }
  else
  {
    vapix::appendCenter(arguments_, point);
  }
  command(arguments_);
}

void AxisProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("camera", std::to_string(settings_.camera));
  values.emplace_back("user", httpUser());  // never the password
  {
    std::lock_guard<std::mutex> lock(facts_mutex_);
    values.emplace_back("zoom X-factor", zoom_text_.empty() ? "not asked yet" : zoom_text_);
    values.emplace_back("PTZ control queue", queue_text_.empty() ? "not asked yet" : queue_text_);
    if (!model_text_.empty())
    {
      values.emplace_back("model", model_text_);
    }
  }
  addCounts(values, { { "positions read", counters_.positions },
                      { "commands refused (Error:)", counters_.refusals },
                      { "HTTP error answers", counters_.error_answers },
                      { "malformed answers", counters_.malformed },
                      { "PTZ control requests", counters_.control_requests },
                      { "commands without PTZ control", counters_.without_control } });
}

void AxisProtocol::validate(const DeviceConfig<AxisProtocol>& config)
{
  requireHttp(config.link, "an Axis camera");
}

}  // namespace ptz_action_server

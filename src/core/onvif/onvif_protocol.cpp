#include "ptz_action_server/core/onvif/onvif_protocol.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// \p range in degrees as radians within +-pi (an unbounded degree range is the whole turn).
AxisRange radians(const onvif::Range& range)
{
  return AxisRange{ toRadians(std::max(range.min, -180.0)), toRadians(std::min(range.max, 180.0)) };
}
}  // namespace

namespace
{
onvif::MotionCheckConfig motionCheckOf(const OnvifSettings& settings, const DeviceSession& session)
{
  onvif::MotionCheckConfig config;
  config.deceleration = settings.acceleration > 0.0 ? settings.acceleration : 1.0;
  config.max_speed = std::max(settings.pan_max_speed, settings.tilt_max_speed);
  config.poll_period = session.config().poll_period;
  config.start_timeout = settings.move_start_timeout;
  return config;
}
}  // namespace

OnvifProtocol::OnvifProtocol(const OnvifSettings& settings, DeviceSession& session)
  : HttpDeviceProtocol(session)
  , settings_(settings)
  , motion_check_(motionCheckOf(settings, session))
  , velocity_timeout_(settings.velocity_timeout)
{
  request_.content_type = onvif::SOAP_CONTENT_TYPE;
}

Capabilities OnvifProtocol::capabilities() const
{
  Capabilities capabilities;
  capabilities.axes[PAN].range = { -M_PI, M_PI };
  capabilities.axes[TILT].range = { -M_PI / 2.0, M_PI / 2.0 };
  capabilities.axes[ZOOM].present = false;
  capabilities.axes[ZOOM].range = { 1.0, 1.0 };
  return capabilities;
}

std::vector<std::string> OnvifProtocol::warnings() const
{
  std::lock_guard<std::mutex> lock(report_mutex_);
  return report_.warnings;
}

Capabilities OnvifProtocol::cameraCapabilities() const
{
  Capabilities capabilities;
  auto span = [this](const GenericAxisMapping& mapping, const onvif::Range& range) {
    const double low = angleOf(mapping, std::max(range.min, -1e3));
    const double high = angleOf(mapping, std::min(range.max, 1e3));
    return AxisRange{ std::min(low, high), std::max(low, high) };
  };
  AxisCapability& pan = capabilities.axes[PAN];
  AxisCapability& tilt = capabilities.axes[TILT];
  // The range of the space goals go in; without one, that of the space the status comes in.
  const std::string& space = pan_tilt_.absolute ? pan_tilt_.move_space : pan_tilt_.status_space;
  if (space == onvif::DEGREE_SPACE)
  {
    pan.range = pan_tilt_.absolute ? radians(pan_tilt_.x) : AxisRange{ -M_PI, M_PI };
    tilt.range = pan_tilt_.absolute ? radians(pan_tilt_.y) : AxisRange{ -M_PI / 2.0, M_PI / 2.0 };
  }
  else
  {
    const onvif::Range whole;  // the generic space's [-1, 1]
    pan.range = span(settings_.pan, pan_tilt_.absolute ? pan_tilt_.x : whole);
    tilt.range = span(settings_.tilt, pan_tilt_.absolute ? pan_tilt_.y : whole);
  }
  for (AxisCapability* axis : { &pan, &tilt })
  {
    axis->absolute = pan_tilt_.absolute;
    axis->velocity = pan_tilt_.velocity;
    axis->feedback = pan_tilt_.feedback;
    axis->limitation = pan_tilt_.limitation;
    axis->acceleration = settings_.acceleration;
  }
  pan.max_speed = settings_.pan_max_speed;
  tilt.max_speed = settings_.tilt_max_speed;
  AxisCapability& zoom = capabilities.axes[ZOOM];
  zoom.present = zoom_.present;
  zoom.absolute = zoom_.absolute;
  zoom.velocity = zoom_.velocity;
  zoom.feedback = zoom_.feedback;
  zoom.widest_view = zoom_.present && zoom_.absolute;  // generic zoom 0, whether or not its status reports the zoom
  zoom.limitation = zoom_.limitation;
  // The listed range, unless the camera showed it does not reach its end.
  zoom.range = { 1.0, !zoom_.present ? 1.0 : honoured_zoom_max_ > 0.0 ? honoured_zoom_max_ : settings_.zoom_max };
  zoom.max_speed = settings_.zoom_max_rate;
  capabilities.speed = moveSpeed();
  capabilities.lens = lens_;
  capabilities.relative_moves = !node_.relative_pan_tilt.empty() || !node_.relative_zoom.empty();
  capabilities.device_presets = device_presets_;
  capabilities.device_home = node_.home_supported;
  capabilities.view_centre = view_.centre;
  capabilities.view_box_zoom = view_.centre && view_.zoom != ViewPlan::Zoom::NONE;
  capabilities.view_command = "ONVIF RelativeMove in TranslationSpaceFov";
  return capabilities;
}

MoveSpeedCapability OnvifProtocol::moveSpeed() const
{
  MoveSpeedCapability speed;
  const bool pan_tilt = pan_tilt_.absolute && pan_tilt_.speed;
  const bool zoom = zoom_.absolute && zoom_.speed;
  // An axis beside one the camera takes a speed for moves at its own speed: the node shapes no axis of such a move.
  const SpeedControl without = pan_tilt || zoom ? SpeedControl::OWN : SpeedControl::NODE;
  speed.control = { { pan_tilt ? SpeedControl::DEVICE : without, pan_tilt ? SpeedControl::DEVICE : without,
                      zoom ? SpeedControl::DEVICE : without } };
  // The slowest: the listed range's low end (0 lists any speed).
  speed.min_speed = { { pan_tilt ? std::max(pan_tilt_.speed_range.min, 0.0) * settings_.pan_max_speed : 0.0,
                        pan_tilt ? std::max(pan_tilt_.speed_range.min, 0.0) * settings_.tilt_max_speed : 0.0,
                        zoom ? std::max(zoom_.speed_range.min, 0.0) * settings_.zoom_max_rate : 0.0 } };
  return speed;
}

double OnvifProtocol::angleOf(const GenericAxisMapping& mapping, double x) const
{
  return mapping.sign * mapping.scale * x + mapping.offset;
}

double OnvifProtocol::genericOf(const GenericAxisMapping& mapping, double angle) const
{
  return (angle - mapping.offset) / (mapping.sign * mapping.scale);
}

std::string OnvifProtocol::statusSpace(const onvif::Status& status) const
{
  if (!status.space.empty())
  {
    return status.space;
  }
  return profile_.default_pan_tilt_space.empty() ? onvif::GENERIC_PAN_TILT_SPACE : profile_.default_pan_tilt_space;
}

std::string OnvifProtocol::zoomStatusSpace(const onvif::Status& status) const
{
  if (!status.zoom_space.empty())
  {
    return status.zoom_space;
  }
  return profile_.default_zoom_space.empty() ? onvif::GENERIC_ZOOM_SPACE : profile_.default_zoom_space;
}

bool OnvifProtocol::call(const std::string& path, const std::string& body, bool secure, std::string& problem)
{
  problem.clear();
  unauthorized_ = false;
  request_.path = path;
  if (secure && !settings_.username.empty())
  {
    const onvif::UsernameToken token = onvif::newUsernameToken(settings_.username, onvif::isoTime(cameraTime()));
    request_.body = onvif::envelope(body, &token, settings_.password);
  }
  else
  {
    request_.body = onvif::envelope(body);
  }
  const HttpReply* reply = send(request_);
  if (reply == nullptr)
  {
    return false;
  }
  const std::string element = body.substr(1, body.find_first_of(" />") - 1);
  const std::string operation = element.substr(element.find(':') + 1);  // "tptz:Stop" -> "Stop"
  const std::string malformed = onvif::parseSoap(reply->body, message_);
  if (malformed.empty() && message_.fault)
  {
    ++counters_.faults;
    unauthorized_ = onvif::faultHas(message_, "NotAuthorized");
    problem = "the ONVIF camera refused " + operation + ": " + message_.fault_text;
    return false;
  }
  if (reply->status >= 400 || reply->status < 200)
  {
    unauthorized_ = reply->status == 401;
    problem = statusProblem(reply->status, operation, path);
  }
  else if (!malformed.empty())
  {
    ++counters_.malformed;
    problem = "malformed answer to " + operation + ": " + malformed;
  }
  if (!problem.empty())
  {
    ++counters_.error_answers;
    return false;
  }
  return true;
}

void OnvifProtocol::warnOnce(const std::string& key, const std::string& text)
{
  if (std::find(warned_.begin(), warned_.end(), key) != warned_.end())
  {
    return;
  }
  warned_.push_back(key);
  {
    std::lock_guard<std::mutex> lock(report_mutex_);
    report_.warnings.push_back(text);
  }
  session_.warn(text);
}

std::string OnvifProtocol::readState(const onvif::Status& status, AxisValues& position)
{
  position = { 0.0, 0.0, 1.0 };
  if (pan_tilt_.feedback)
  {
    if (!status.has_pan_tilt)
    {
      return "GetStatus answered no pan-tilt position, though it reported one at start-up";
    }
    const std::string space = statusSpace(status);
    if (space == onvif::DEGREE_SPACE)
    {
      position[PAN] = toRadians(status.x);
      position[TILT] = toRadians(status.y);
    }
    else if (space == onvif::GENERIC_PAN_TILT_SPACE)
    {
      position[PAN] = angleOf(settings_.pan, status.x);
      position[TILT] = angleOf(settings_.tilt, status.y);
    }
    else
    {
      return "GetStatus answered a pan-tilt position in '" + space +
             "', but this backend converts only SphericalPositionSpaceDegrees and PositionGenericSpace";
    }
    checkRanges(status, space);
  }
  if (zoom_.feedback)
  {
    if (!status.has_zoom)
    {
      return "GetStatus answered no zoom position, though it reported one at start-up";
    }
    const std::string space = zoomStatusSpace(status);
    if (space != onvif::GENERIC_ZOOM_SPACE)
    {
      return "GetStatus answered a zoom position in '" + space + "', but this backend converts only the generic one";
    }
    position[ZOOM] = std::pow(settings_.zoom_max, std::clamp(status.zoom, 0.0, 1.0));
  }
  return {};
}

void OnvifProtocol::onConnected()
{
  velocity_body_.clear();
  motion_check_.clear();
  std::string problem;
  onvif::Status status;
  if (!bringUp(problem, status))
  {
    setupFailed(problem);
    return;
  }
  AxisValues position{};
  problem = readState(status, position);  // also checks the listed ranges against where the camera is
  if (!problem.empty())
  {
    setupFailed(problem);
    return;
  }
  session_.setCapabilities(cameraCapabilities());
  session_.ready();
  ++counters_.statuses;
  if (pan_tilt_.feedback || zoom_.feedback)
  {
    session_.reportState(position);
  }
  else
  {
    session_.reportAlive();  // a camera without a position: its answers are all it says
  }
}

void OnvifProtocol::poll()
{
  std::string problem;
  if (!velocity_body_.empty() && secondsBetween(velocity_sent_at_, session_.now()) >= 0.5 * velocity_timeout_)
  {
    ++counters_.velocity_refreshes;
    command(paths_.ptz, velocity_body_, "ContinuousMove");
  }
  if (!call(paths_.ptz, onvif::getStatus(profile_.token), true, problem))
  {
    if (!problem.empty())
    {
      session_.disconnect(problem);
    }
    return;
  }
  onvif::Status status;
  problem = onvif::readStatus(message_.content, status);
  if (!problem.empty())
  {
    problem = "GetStatus answered " + problem;
  }
  AxisValues position{};
  if (problem.empty())
  {
    problem = readState(status, position);
  }
  if (!problem.empty())
  {
    ++counters_.malformed;
    session_.disconnect(problem);
    return;
  }
  ++counters_.statuses;
  onvif::Observation observed;
  observed.at = session_.now();
  observed.position = position;
  observed.reported = { pan_tilt_.feedback, pan_tilt_.feedback, zoom_.feedback };
  observed.pan_tilt_status = status.move_status;
  observed.zoom_status = status.zoom_move_status;
  onFinding(motion_check_.observe(observed));
  if (pan_tilt_.feedback || zoom_.feedback)
  {
    session_.reportState(position);
  }
  else
  {
    session_.reportAlive();
  }
  pollLens();  // after the state: a slow camera's lens answer does not hold it back
}

void OnvifProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("profile", settings_.profile.empty() ? "the first with PTZ" : settings_.profile);
  values.emplace_back("ws-security user", settings_.username);  // never the password
  {
    std::lock_guard<std::mutex> lock(report_mutex_);
    values.emplace_back("pan-tilt", report_.pan_tilt);
    values.emplace_back("presets on the camera", report_.presets);
  }
  addCounts(values, { { "statuses read", counters_.statuses },
                      { "SOAP faults to commands", counters_.faults },
                      { "HTTP error answers", counters_.error_answers },
                      { "malformed answers", counters_.malformed },
                      { "ContinuousMoves re-sent before their timeout", counters_.velocity_refreshes },
                      { "commands the camera cannot do (not sent)", counters_.refused_locally },
                      { "zero-velocity ContinuousMoves after Stop", counters_.zero_velocity_stops } });
}

void OnvifProtocol::validate(const DeviceConfig<OnvifProtocol>& config)
{
  requireHttp(config.link, "an ONVIF camera");
  if (config.settings.zoom_max <= 1.0 || config.settings.velocity_timeout < 1)
  {
    throw ConfigError("ONVIF zoom_max must be > 1 and velocity_timeout >= 1 s");
  }
}

}  // namespace ptz_action_server

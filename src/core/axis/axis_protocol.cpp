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

LinkConfig AxisProtocol::defaultLink()
{
  LinkConfig link;
  link.kind = LinkKind::HTTP;
  link.port = 80;
  link.reconnect_min = 0.1;
  return link;
}

AxisProtocol::AxisProtocol(const AxisSettings& settings, DeviceSession& session)
  : settings_(settings), session_(session), http_(session.http())
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

const char* zoomSourceName(AxisZoomSource source)
{
  switch (source)
  {
    case AxisZoomSource::NO_ZOOM:
      return "no zoom";
    case AxisZoomSource::CONFIGURED_TABLE:
      return "configured zoom_table";
    case AxisZoomSource::CONFIGURED_MAXIMUM:
      return "configured zoom_max_factor";
    case AxisZoomSource::CAMERA_TABLE:
      return "camera zoomSteps";
    case AxisZoomSource::CAMERA_MAXIMUM:
      return "camera maxOpticalZoomMag";
    case AxisZoomSource::MODEL_GUESS:
      return "model family guess";
    case AxisZoomSource::UNKNOWN:
      return "unknown";
  }
  return "?";
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
  capabilities.axes[ZOOM] =
      configured_table_.empty() ?
          absentAxis("the Axis camera has not been asked yet") :
          fullAxis({ configured_table_.minFactor(), configured_table_.maxFactor() }, settings_.zoom_max_rate, 0.0);
  return capabilities;
}

Capabilities AxisProtocol::cameraCapabilities(const vapix::Limits& limits, const vapix::CommandList& commands) const
{
  // A camera that gave no usable info=1 is taken to offer what VAPIX documents for a PTZ camera; the informative
  // flags (relative moves, presets, home) are only declared when it lists them.
  const bool listed = !commands.empty();
  const auto offered = [&](const char* name) { return !listed || commands.has(name); };
  Capabilities capabilities;
  AxisCapability& pan = capabilities.axes[PAN];
  pan = fullAxis({ toRadians(limits.min_pan), toRadians(limits.max_pan) }, settings_.pan_max_speed,
                 settings_.acceleration);
  pan.absolute = offered("pan");
  pan.velocity = offered("continuouspantiltmove");
  AxisCapability& tilt = capabilities.axes[TILT];
  tilt = fullAxis({ toRadians(limits.min_tilt), toRadians(limits.max_tilt) }, settings_.tilt_max_speed,
                  settings_.acceleration);
  tilt.absolute = offered("tilt");
  tilt.velocity = offered("continuouspantiltmove");
  for (AxisCapability* axis : { &pan, &tilt })
  {
    if (!axis->absolute)
    {
      axis->limitation = "this Axis camera does not list absolute pan/tilt in info=1";
    }
  }

  capabilities.relative_moves = listed && commands.has("rpan") && commands.has("rtilt");
  capabilities.device_presets =
      listed && (commands.offers("query", "presetposall") || commands.offers("query", "presetposcam") ||
                 commands.has("gotoserverpresetno"));
  capabilities.device_home = listed && commands.offers("move", "home");

  AxisCapability& zoom = capabilities.axes[ZOOM];
  if (zoom_source_ == AxisZoomSource::NO_ZOOM)
  {
    zoom = absentAxis("this Axis camera's limits give no zoom");
    return capabilities;
  }
  zoom = fullAxis({ 1.0, 1.0 }, settings_.zoom_max_rate, 0.0);
  zoom.velocity = zoom_velocity_;
  if (zoom_feedback_)
  {
    zoom.range = { zoom_table_.toFactor(std::max(limits.min_zoom, zoom_table_.minValue())),
                   zoom_table_.toFactor(std::min(limits.max_zoom, zoom_table_.maxValue())) };
    zoom.absolute = offered("zoom");
    if (zoom_source_ == AxisZoomSource::MODEL_GUESS)
    {
      zoom.limitation = "this Axis camera gives no zoom table: its X-factor is a guess (" + zoom_text_ + ")";
      zoom.remedy = "set axis/zoom_max_factor to its optical zoom, or axis/zoom_table";
    }
  }
  else
  {
    zoom.absolute = false;
    zoom.feedback = false;
    if (zoom_table_.empty())
    {
      zoom.limitation = "this Axis camera gives no zoom table";
      zoom.remedy = "set axis/zoom_table (or axis/zoom_max_factor, its optical zoom)";
    }
    else
    {
      zoom.limitation = "this Axis camera reports no zoom position";
    }
  }
  return capabilities;
}

AxisZoomSource AxisProtocol::zoomSource() const
{
  std::lock_guard<std::mutex> lock(facts_mutex_);
  return shared_zoom_source_;
}

bool AxisProtocol::exchange(const std::string& path, const std::string& what, std::string& body, std::string& problem)
{
  request_.path = path;
  const HttpReply& answer = http_.request(request_);
  problem.clear();
  if (!answer.delivered)
  {
    return false;  // the link is lost, with its reason
  }
  switch (answer.status)
  {
    case 200:
    case 204:
      body = answer.body;
      return true;
    case 401:
      problem = "HTTP 401 Unauthorized: the camera refused the credentials of user '" +
                session_.linkConfig().http.username + "' for " + what;
      break;
    case 403:
      problem =
          "HTTP 403 Forbidden: user '" + session_.linkConfig().http.username + "' may not control PTZ (" + what + ")";
      break;
    case 404:
      problem = "HTTP 404 Not Found: " + path.substr(0, path.find('?')) + " (no VAPIX PTZ at this address?)";
      break;
    default:
      problem = formatText("HTTP %ld answering %s", answer.status, what.c_str());
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

void AxisProtocol::setupFailed(const std::string& problem)
{
  if (problem.empty())
  {
    return;  // the link was lost: it reopens and the set-up runs again
  }
  session_.failStartup(problem);
  session_.disconnect(problem);
}

bool AxisProtocol::findZoomTable(const vapix::Limits& limits)
{
  zoom_table_ = vapix::ZoomTable();
  std::string text;
  std::string model;
  if (!limits.has_zoom)
  {
    zoom_source_ = AxisZoomSource::NO_ZOOM;
    text = "none: query=limits gives no MinZoom/MaxZoom";
  }
  else if (!configured_table_.empty())
  {
    zoom_table_ = configured_table_;
    zoom_source_ = settings_.zoom_table.empty() ? AxisZoomSource::CONFIGURED_MAXIMUM : AxisZoomSource::CONFIGURED_TABLE;
    text = settings_.zoom_table.empty() ? formatText("zoom_max_factor %gX, linear", settings_.zoom_max_factor) :
                                          "zoom_table " + settings_.zoom_table;
  }
  else
  {
    std::string problem;
    std::string body;
    const std::string arguments = "query=attributes&group=zoom";
    vapix::ZoomAttributes attributes;
    const std::string path = formatText("%s?camera=%d&%s", vapix::PTZ_PATH, settings_.camera, arguments.c_str());
    std::string refusal = "no answer";
    if (exchange(path, "'" + arguments + "'", body, problem))
    {
      problem = vapix::readZoomAttributes(body, settings_.camera, attributes);
      if (problem.empty() && attributes.refused)
      {
        refusal = attributes.refusal;
      }
      else if (problem.empty() && attributes.steps.empty() && attributes.max_optical == 0.0)
      {
        refusal = "no zoomSteps and no maxOpticalZoomMag in the answer";
      }
      else if (problem.empty())
      {
        problem = vapix::zoomTableOf(attributes, zoom_table_);
      }
      if (!problem.empty())
      {
        ++counters_.malformed;
        setupFailed(arguments + ": " + problem + " (set axis/zoom_table or axis/zoom_max_factor to override it)");
        return false;
      }
    }
    else if (!session_.connected())
    {
      return false;
    }
    else
    {
      refusal = problem;  // an HTTP error: no attributes either
    }
    if (!zoom_table_.empty())
    {
      zoom_source_ = attributes.steps.empty() ? AxisZoomSource::CAMERA_MAXIMUM : AxisZoomSource::CAMERA_TABLE;
      text = attributes.steps.empty() ?
                 formatText("the camera's maxOpticalZoomMag %gX, linear", attributes.max_optical) :
                 formatText("the camera's zoomSteps (%zu points, %g..%gX)", zoom_table_.size(), zoom_table_.minFactor(),
                            zoom_table_.maxFactor());
    }
    else
    {
      // No table from the camera: its model may tell (param.cgi), as a guess.
      vapix::Product product;
      if (exchange(vapix::BRAND_PATH, "the brand parameters", body, problem))
      {
        vapix::Reply brand;
        if (vapix::parseReply(body, brand).empty() && vapix::readProduct(brand, product).empty())
        {
          model = product.full_name.empty() ? "AXIS " + product.number : product.full_name;
        }
      }
      else if (!session_.connected())
      {
        return false;
      }
      vapix::FamilyZoom family;
      const std::string camera = model.empty() ? "this Axis camera" : model;
      const std::string why = "query=attributes&group=zoom: " + refusal;
      if (settings_.zoom_guess && !product.number.empty() && vapix::modelFamilyZoom(product.number, family))
      {
        zoom_table_ = vapix::ZoomTable::linear(family.max_optical);
        zoom_source_ = AxisZoomSource::MODEL_GUESS;
        text = formatText("GUESS: %gX optical at VAPIX zoom 9999, linear, the usual zoom of %s", family.max_optical,
                          family.models);
        session_.warn(camera + " gives no zoom table (" + why + "): its zoom X-factor is a guess, " +
                      formatText("%gX optical as is usual for %s, linear from VAPIX zoom 1 to 9999; ",
                                 family.max_optical, family.models) +
                      "set axis/zoom_max_factor to its optical zoom (data sheet) or axis/zoom_table");
      }
      else
      {
        zoom_source_ = AxisZoomSource::UNKNOWN;
        const char* reason = !settings_.zoom_guess  ? "zoom_guess is off" :
                             product.number.empty() ? "its model could not be read" :
                                                      "its model family has no default";
        text = std::string("UNKNOWN: no zoom table, ") + reason + "; zoom goals are refused";
        session_.warn(camera + " gives no zoom table (" + why + ") and " + reason +
                      ": zoom goals are not supported (velocity goals are); set axis/zoom_table or "
                      "axis/zoom_max_factor (its optical zoom)");
      }
    }
  }
  std::lock_guard<std::mutex> lock(facts_mutex_);
  shared_zoom_source_ = zoom_source_;
  zoom_text_ = text;
  if (!model.empty())
  {
    model_text_ = model;
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
  Capabilities capabilities = cameraCapabilities(limits, commands);
  if (zoom_source_ != AxisZoomSource::NO_ZOOM && !zoom_table_.empty() && !position.has_zoom)
  {
    session_.warn("this Axis camera reports no zoom position (query=position has no zoom=): zoom goals are not "
                  "supported");
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
  session_.reportState({ toRadians(position.pan), toRadians(position.tilt), zoomFactor(position) });
}

void AxisProtocol::command(const std::string& arguments)
{
  const std::uint64_t serial = session_.currentCommand();
  std::string problem;
  vapix::Reply reply;
  const bool done = request(arguments, reply, problem);
  if (!done && !problem.empty())
  {
    ++counters_.refusals;
    session_.reportFault(problem, serial);
  }
  if (done || !problem.empty())
  {
    // An answer, even a refusal: the camera is alive. A slow camera's command and the next poll, one request at a
    // time, may leave more than state_timeout between two positions; each answer within it keeps the link up.
    session_.reportAlive();
  }
}

void AxisProtocol::goTo(const AxisValues& position)
{
  arguments_.clear();
  // A zoom it cannot map (no X-factor known) or reads back is never commanded: the goal leaves it alone.
  const bool zoom = zoom_feedback_ && std::isfinite(position[ZOOM]);
  vapix::appendAbsoluteMove(arguments_, toDegrees(position[PAN]), toDegrees(position[TILT]),
                            zoom ? zoom_table_.toValue(position[ZOOM]) : 0.0, settings_.speed);
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

void AxisProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("camera", std::to_string(settings_.camera));
  values.emplace_back("user", session_.linkConfig().http.username);  // never the password
  {
    std::lock_guard<std::mutex> lock(facts_mutex_);
    values.emplace_back("zoom X-factor", zoom_text_.empty() ? "not asked yet" : zoom_text_);
    if (!model_text_.empty())
    {
      values.emplace_back("model", model_text_);
    }
  }
  addCounts(values, { { "positions read", counters_.positions },
                      { "commands refused (Error:)", counters_.refusals },
                      { "HTTP error answers", counters_.error_answers },
                      { "malformed answers", counters_.malformed } });
}

void AxisProtocol::validate(const DeviceConfig<AxisProtocol>& config)
{
  if (config.link.kind != LinkKind::HTTP)
  {
    throw ConfigError("an Axis camera is reached over HTTP");
  }
}

}  // namespace ptz_action_server

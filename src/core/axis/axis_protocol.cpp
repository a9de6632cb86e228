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

LinkConfig AxisConfig::defaultLink()
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
  if (!settings_.zoom_table.empty())
  {
    const std::string problem = vapix::ZoomTable::parse(settings_.zoom_table, zoom_table_);
    if (!problem.empty())
    {
      throw ConfigError("zoom_table '" + settings_.zoom_table + "': " + problem);
    }
  }
}

Capabilities AxisProtocol::capabilities() const
{
  return cameraCapabilities(vapix::Limits());
}

Capabilities AxisProtocol::cameraCapabilities(const vapix::Limits& limits) const
{
  Capabilities capabilities;
  AxisCapability& pan = capabilities.axes[PAN];
  pan.range = { toRadians(limits.min_pan), toRadians(limits.max_pan) };
  pan.max_speed = settings_.pan_max_speed;
  pan.acceleration = settings_.acceleration;
  AxisCapability& tilt = capabilities.axes[TILT];
  tilt.range = { toRadians(limits.min_tilt), toRadians(limits.max_tilt) };
  tilt.max_speed = settings_.tilt_max_speed;
  tilt.acceleration = settings_.acceleration;
  AxisCapability& zoom = capabilities.axes[ZOOM];
  zoom.present = !zoom_table_.empty();
  zoom.range = zoom.present ? AxisRange{ zoom_table_.toFactor(std::max(limits.min_zoom, zoom_table_.minValue())),
                                         zoom_table_.toFactor(std::min(limits.max_zoom, zoom_table_.maxValue())) } :
                              AxisRange{ 1.0, 1.0 };
  zoom.max_speed = settings_.zoom_max_rate;
  return capabilities;
}

bool AxisProtocol::request(const std::string& arguments, vapix::Reply& reply, std::string& problem)
{
  request_.path = formatText("%s?camera=%d&", vapix::PTZ_PATH, settings_.camera);
  request_.path += arguments;
  const HttpReply& answer = http_.perform(request_);
  problem.clear();
  if (!answer.delivered)
  {
    return false;  // the link is lost, with its reason
  }
  const std::string what = "'" + arguments + "'";
  switch (answer.status)
  {
    case 200:
    case 204:
      break;
    case 401:
      problem = "HTTP 401 Unauthorized: the camera refused the credentials of user '" + http_.config().http.username +
                "' for " + what;
      break;
    case 403:
      problem = "HTTP 403 Forbidden: user '" + http_.config().http.username + "' may not control PTZ (" + what + ")";
      break;
    case 404:
      problem = std::string("HTTP 404 Not Found: ") + vapix::PTZ_PATH + " (no VAPIX PTZ at this address?)";
      break;
    default:
      problem = formatText("HTTP %ld answering %s", answer.status, what.c_str());
      break;
  }
  if (!problem.empty())
  {
    ++counters_.error_answers;
    return false;
  }
  const std::string malformed = vapix::parseReply(answer.body, reply);
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
  if (settings_.zoom_table.empty() && limits.has_zoom)
  {
    if (request("query=attributes&group=zoom", reply_, problem))
    {
      const std::string* table = reply_.find("ZoomMagnification");
      problem = table == nullptr ? "no ZoomMagnification in the zoom attributes" :
                                   vapix::ZoomTable::parse(*table, zoom_table_);
      if (!problem.empty())
      {
        setupFailed("query=attributes&group=zoom: " + problem);
        return;
      }
    }
    else if (!http_.isOpen())
    {
      return;
    }
    // A camera without the zoom attributes: no zoom unless a table is configured (never a linear guess).
  }
  session_.setCapabilities(cameraCapabilities(limits));
  session_.ready();
  poll();
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
  const double zoom = zoom_table_.empty() ? 1.0 : zoom_table_.toFactor(position.zoom);
  session_.reportState({ toRadians(position.pan), toRadians(position.tilt), zoom });
}

void AxisProtocol::command(const std::string& arguments)
{
  const std::uint64_t serial = session_.currentCommand();
  std::string problem;
  vapix::Reply reply;
  if (!request(arguments, reply, problem) && !problem.empty())
  {
    ++counters_.refusals;
    session_.reportFault(problem, serial);
  }
}

void AxisProtocol::goTo(const AxisValues& position)
{
  arguments_.clear();
  vapix::appendAbsoluteMove(arguments_, toDegrees(position[PAN]), toDegrees(position[TILT]),
                            zoom_table_.empty() ? 0.0 : zoom_table_.toValue(position[ZOOM]), settings_.speed);
  command(arguments_);
}

void AxisProtocol::moveAtVelocity(const AxisValues& velocity)
{
  arguments_.clear();
  vapix::appendContinuousMove(arguments_, percentOf(velocity[PAN], settings_.pan_max_speed),
                              percentOf(velocity[TILT], settings_.tilt_max_speed),
                              percentOf(velocity[ZOOM], settings_.zoom_max_rate), !zoom_table_.empty());
  command(arguments_);
}

void AxisProtocol::stop()
{
  command("move=stop");
}

void AxisProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("camera", std::to_string(settings_.camera));
  values.emplace_back("user", http_.config().http.username);  // never the password
  values.emplace_back("zoom table", settings_.zoom_table.empty() ? "from the camera" : settings_.zoom_table);
  addCounts(values, { { "positions read", counters_.positions },
                      { "commands refused (Error:)", counters_.refusals },
                      { "HTTP error answers", counters_.error_answers },
                      { "malformed answers", counters_.malformed } });
}

std::unique_ptr<DeviceBackend> makeAxisBackend(const AxisConfig& config, std::shared_ptr<const Clock> clock)
{
  if (config.link.kind != LinkKind::HTTP)
  {
    throw ConfigError("an Axis camera is reached over HTTP");
  }
  return makeDeviceBackend<AxisProtocol>(config.link, config.session, config.axis, std::move(clock));
}

}  // namespace ptz_action_server

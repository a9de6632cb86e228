#include "ptz_action_server/core/onvif/onvif_protocol.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
double systemUtc()
{
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}
}  // namespace

LinkConfig OnvifConfig::defaultLink()
{
  LinkConfig link;
  link.kind = LinkKind::HTTP;
  link.port = 80;
  link.reconnect_min = 0.1;
  return link;
}

OnvifProtocol::OnvifProtocol(const OnvifSettings& settings, DeviceSession& session)
  : settings_(settings), session_(session), http_(session.http()), random_(std::random_device{}())
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

Capabilities OnvifProtocol::cameraCapabilities() const
{
  Capabilities capabilities;
  auto span = [this](const GenericAxisMapping& mapping) {
    const double low = angleOf(mapping, -1.0);
    const double high = angleOf(mapping, 1.0);
    return AxisRange{ std::min(low, high), std::max(low, high) };
  };
  capabilities.axes[PAN].range = use_degrees_ ?
                                     AxisRange{ toRadians(node_.degree_pan.min), toRadians(node_.degree_pan.max) } :
                                     span(settings_.pan);
  capabilities.axes[TILT].range = use_degrees_ ?
                                      AxisRange{ toRadians(node_.degree_tilt.min), toRadians(node_.degree_tilt.max) } :
                                      span(settings_.tilt);
  capabilities.axes[PAN].max_speed = settings_.pan_max_speed;
  capabilities.axes[TILT].max_speed = settings_.tilt_max_speed;
  capabilities.axes[PAN].acceleration = settings_.acceleration;
  capabilities.axes[TILT].acceleration = settings_.acceleration;
  AxisCapability& zoom = capabilities.axes[ZOOM];
  zoom.present = node_.zoom;
  zoom.range = { 1.0, node_.zoom ? settings_.zoom_max : 1.0 };
  zoom.max_speed = settings_.zoom_max_rate;
  return capabilities;
}

double OnvifProtocol::angleOf(const GenericAxisMapping& mapping, double x) const
{
  return mapping.sign * mapping.scale * x + mapping.offset;
}

double OnvifProtocol::genericOf(const GenericAxisMapping& mapping, double angle) const
{
  return std::clamp((angle - mapping.offset) / (mapping.sign * mapping.scale), -1.0, 1.0);
}

double OnvifProtocol::cameraTime() const
{
  return systemUtc() + clock_offset_;
}

bool OnvifProtocol::call(const std::string& path, const std::string& body, bool secure, std::string& problem)
{
  problem.clear();
  request_.path = path;
  if (secure && !settings_.username.empty())
  {
    onvif::UsernameToken token;
    token.username = settings_.username;
    token.nonce.resize(16);
    for (char& byte : token.nonce)
    {
      byte = static_cast<char>(random_());
    }
    token.created = onvif::isoTime(cameraTime());
    request_.body = onvif::envelope(body, &token, settings_.password);
  }
  else
  {
    request_.body = onvif::envelope(body);
  }
  const HttpReply& reply = http_.perform(request_);
  if (!reply.delivered)
  {
    return false;
  }
  const std::string element = body.substr(1, body.find_first_of(" />") - 1);
  const std::string operation = element.substr(element.find(':') + 1);  // "tptz:Stop" -> "Stop"
  const std::string malformed = onvif::parseSoap(reply.body, message_);
  if (malformed.empty() && message_.fault)
  {
    ++counters_.faults;
    problem = "the ONVIF camera refused " + operation + ": " + message_.fault_text;
    return false;
  }
  if (reply.status == 401)
  {
    problem = "HTTP 401 Unauthorized: the camera refused the credentials of user '" + http_.config().http.username +
              "' for " + operation;
  }
  else if (reply.status == 403 || reply.status == 404 || reply.status >= 400 || reply.status < 200)
  {
    problem = formatText("HTTP %ld answering %s at %s", reply.status, operation.c_str(), path.c_str());
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

void OnvifProtocol::setupFailed(const std::string& problem)
{
  if (problem.empty())
  {
    return;
  }
  session_.failStartup(problem);
  session_.disconnect(problem);
}

bool OnvifProtocol::bringUp(std::string& problem)
{
  using namespace onvif;
  double camera_utc = 0.0;
  if (!call(settings_.device_path, getSystemDateAndTime(), false, problem))
  {
    return false;
  }
  const double our_utc = systemUtc();
  problem = readSystemTime(message_.content, camera_utc);
  if (!problem.empty())
  {
    problem = "GetSystemDateAndTime: " + problem;
    return false;
  }
  clock_offset_ = camera_utc - our_utc;
  if (!call(settings_.device_path, getCapabilities(), true, problem))
  {
    return false;
  }
  if (!(problem = readCapabilities(message_.content, paths_)).empty())
  {
    problem = "GetCapabilities: " + problem;
    return false;
  }
  if (!call(paths_.media, getProfiles(), true, problem))
  {
    return false;
  }
  if (!(problem = readProfiles(message_.content, settings_.profile, profile_)).empty())
  {
    problem = "GetProfiles: " + problem;
    return false;
  }
  if (!call(paths_.ptz, getNodes(), true, problem))
  {
    return false;
  }
  if (!(problem = readNode(message_.content, profile_.node, node_)).empty())
  {
    problem = "GetNodes: " + problem;
    return false;
  }
  if (!call(paths_.ptz, getConfigurationOptions(profile_.ptz_configuration), true, problem))
  {
    return false;
  }
  double timeout_min = 0.0;
  double timeout_max = 0.0;
  if (!(problem = readTimeoutRange(message_.content, timeout_min, timeout_max)).empty())
  {
    problem = "GetConfigurationOptions: " + problem;
    return false;
  }
  if (timeout_max > 0.0 && (settings_.velocity_timeout < timeout_min || settings_.velocity_timeout > timeout_max))
  {
    problem = formatText("velocity_timeout %d s is outside the camera's PTZTimeout range [%g, %g] s",
                         settings_.velocity_timeout, timeout_min, timeout_max);
    return false;
  }
  use_degrees_ = node_.degree_space && (settings_.prefer_degrees || !node_.generic_space);
  return true;
}

void OnvifProtocol::onConnected()
{
  velocity_body_.clear();
  std::string problem;
  if (!bringUp(problem))
  {
    setupFailed(problem);
    return;
  }
  session_.setCapabilities(cameraCapabilities());
  session_.ready();
  poll();
}

void OnvifProtocol::poll()
{
  std::string problem;
  if (!velocity_body_.empty() && secondsBetween(velocity_sent_at_, session_.now()) >= 0.5 * settings_.velocity_timeout)
  {
    ++counters_.velocity_refreshes;
    command(paths_.ptz, velocity_body_, "ContinuousMove");
  }
  if (!call(paths_.ptz, onvif::getStatus(profile_.token), true, problem))
  {
    if (!problem.empty())
    {
      session_.disconnect("GetStatus: " + problem);
    }
    return;
  }
  onvif::Status status;
  problem = onvif::readStatus(message_.content, status);
  if (problem.empty() && use_degrees_ != (status.space == onvif::DEGREE_SPACE))
  {
    problem = "a position in '" + status.space + "', not in the space the goals use";
  }
  if (!problem.empty())
  {
    ++counters_.malformed;
    session_.disconnect("GetStatus: " + problem);
    return;
  }
  ++counters_.statuses;
  const double pan = use_degrees_ ? toRadians(status.x) : angleOf(settings_.pan, status.x);
  const double tilt = use_degrees_ ? toRadians(status.y) : angleOf(settings_.tilt, status.y);
  const double zoom = node_.zoom ? std::pow(settings_.zoom_max, std::clamp(status.zoom, 0.0, 1.0)) : 1.0;
  session_.reportState({ pan, tilt, zoom });
}

void OnvifProtocol::command(const std::string& path, const std::string& body, const char* operation)
{
  const std::uint64_t serial = session_.currentCommand();
  std::string problem;
  if (!call(path, body, true, problem) && !problem.empty())
  {
    session_.reportFault(problem, serial);
  }
  if (std::string(operation) == "ContinuousMove")
  {
    velocity_sent_at_ = session_.now();
  }
}

void OnvifProtocol::goTo(const AxisValues& position)
{
  velocity_body_.clear();
  const double x = use_degrees_ ? toDegrees(position[PAN]) : genericOf(settings_.pan, position[PAN]);
  const double y = use_degrees_ ? toDegrees(position[TILT]) : genericOf(settings_.tilt, position[TILT]);
  const double zoom = std::log(std::max(1.0, position[ZOOM])) / std::log(settings_.zoom_max);
  command(paths_.ptz,
          onvif::absoluteMove(profile_.token, x, y, use_degrees_ ? onvif::DEGREE_SPACE : onvif::GENERIC_PAN_TILT_SPACE,
                              node_.zoom, std::clamp(zoom, 0.0, 1.0)),
          "AbsoluteMove");
}

void OnvifProtocol::moveAtVelocity(const AxisValues& velocity)
{
  const double x = std::clamp(settings_.velocity_sign_pan * velocity[PAN] / settings_.pan_max_speed, -1.0, 1.0);
  const double y = std::clamp(settings_.velocity_sign_tilt * velocity[TILT] / settings_.tilt_max_speed, -1.0, 1.0);
  const double zoom = std::clamp(velocity[ZOOM] / settings_.zoom_max_rate, -1.0, 1.0);
  velocity_body_ = onvif::continuousMove(profile_.token, x, y, node_.zoom, zoom, settings_.velocity_timeout);
  command(paths_.ptz, velocity_body_, "ContinuousMove");
}

void OnvifProtocol::stop()
{
  velocity_body_.clear();
  command(paths_.ptz, onvif::stop(profile_.token), "Stop");
}

void OnvifProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("profile", settings_.profile.empty() ? "the first with PTZ" : settings_.profile);
  values.emplace_back("ws-security user", settings_.username);  // never the password
  addCounts(values, { { "statuses read", counters_.statuses },
                      { "SOAP faults to commands", counters_.faults },
                      { "HTTP error answers", counters_.error_answers },
                      { "malformed answers", counters_.malformed },
                      { "ContinuousMoves re-sent before their timeout", counters_.velocity_refreshes } });
}

std::unique_ptr<DeviceBackend> makeOnvifBackend(const OnvifConfig& config, std::shared_ptr<const Clock> clock)
{
  if (config.link.kind != LinkKind::HTTP)
  {
    throw ConfigError("an ONVIF camera is reached over HTTP");
  }
  if (config.onvif.zoom_max <= 1.0 || config.onvif.velocity_timeout < 1)
  {
    throw ConfigError("ONVIF zoom_max must be > 1 and velocity_timeout >= 1 s");
  }
  return makeDeviceBackend<OnvifProtocol>(config.link, config.session, config.onvif, std::move(clock));
}

}  // namespace ptz_action_server

#include "ptz_action_server/core/onvif/onvif_protocol.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

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

/// A status position this close outside a listed range (a share of the range's span) is no contradiction: rounding,
/// overshoot.
constexpr double RANGE_TOLERANCE = 0.005;

bool convertible(const std::string& space)
{
  return space == onvif::DEGREE_SPACE || space == onvif::GENERIC_PAN_TILT_SPACE;
}

std::string joined(const std::vector<std::string>& parts, const char* separator)
{
  std::string text;
  for (const std::string& part : parts)
  {
    text += (text.empty() ? "" : separator) + part;
  }
  return text;
}

std::string spaceNames(const std::vector<onvif::Space>& spaces)
{
  std::vector<std::string> names;
  for (const onvif::Space& space : spaces)
  {
    names.push_back(onvif::spaceName(space.uri));
  }
  return joined(names, ", ");
}

/// \p range in degrees as radians within +-pi (an unbounded degree range is the whole turn).
AxisRange radians(const onvif::Range& range)
{
  return AxisRange{ toRadians(std::max(range.min, -180.0)), toRadians(std::min(range.max, 180.0)) };
}
}  // namespace

LinkConfig OnvifProtocol::defaultLink()
{
  LinkConfig link;
  link.kind = LinkKind::HTTP;
  link.port = 80;
  link.reconnect_min = 0.1;
  return link;
}

OnvifProtocol::OnvifProtocol(const OnvifSettings& settings, DeviceSession& session)
  : settings_(settings), session_(session), http_(session.http())
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
  zoom.limitation = zoom_.limitation;
  zoom.range = { 1.0, zoom_.present ? settings_.zoom_max : 1.0 };
  zoom.max_speed = settings_.zoom_max_rate;
  capabilities.relative_moves = !node_.relative_pan_tilt.empty() || !node_.relative_zoom.empty();
  capabilities.device_presets = device_presets_;
  capabilities.device_home = node_.home_supported;
  return capabilities;
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
    const onvif::UsernameToken token = onvif::newUsernameToken(settings_.username, onvif::isoTime(cameraTime()));
    request_.body = onvif::envelope(body, &token, settings_.password);
  }
  else
  {
    request_.body = onvif::envelope(body);
  }
  const HttpReply& reply = http_.request(request_);
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
    problem = "HTTP 401 Unauthorized: the camera refused the credentials of user '" +
              session_.linkConfig().http.username + "' for " + operation;
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

bool OnvifProtocol::bringUp(std::string& problem, onvif::Status& status)
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
    problem = "GetSystemDateAndTime answered " + problem;
    return false;
  }
  clock_offset_ = camera_utc - our_utc;
  if (!call(settings_.device_path, getCapabilities(), true, problem))
  {
    return false;
  }
  if (!(problem = readCapabilities(message_.content, paths_)).empty())
  {
    problem = "GetCapabilities answered " + problem;
    return false;
  }
  if (!call(paths_.media, getProfiles(), true, problem))
  {
    return false;
  }
  if (!(problem = readProfiles(message_.content, settings_.profile, profile_)).empty())
  {
    problem = "GetProfiles answered " + problem;
    return false;
  }
  if (!call(paths_.ptz, getNodes(), true, problem))
  {
    return false;
  }
  if (!(problem = readNode(message_.content, profile_.node, node_)).empty())
  {
    problem = "GetNodes answered " + problem;
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
    problem = "GetConfigurationOptions answered " + problem;
    return false;
  }
  if (timeout_max > 0.0 && (settings_.velocity_timeout < timeout_min || settings_.velocity_timeout > timeout_max))
  {
    problem = formatText("velocity_timeout %d s is outside the camera's PTZTimeout range [%g, %g] s",
                         settings_.velocity_timeout, timeout_min, timeout_max);
    return false;
  }
  // Presets only say what the camera has: a camera that refuses GetPresets (ter:ActionNotSupported, as some do
  // although their node lists presets) has none, and starts all the same.
  device_presets_ = false;
  std::string presets = "none (the node lists MaximumNumberOfPresets 0)";
  if (node_.max_presets > 0)
  {
    std::vector<Preset> stored;
    if (call(paths_.ptz, getPresets(profile_.token), true, problem))
    {
      const std::string unread = readPresets(message_.content, stored);
      device_presets_ = unread.empty();
      presets = unread.empty() ? formatText("%zu stored, at most %d", stored.size(), node_.max_presets) :
                                 "none: GetPresets answered " + unread;
    }
    else if (problem.empty())
    {
      return false;  // the link went: nothing was answered
    }
    else
    {
      presets = "none: " + problem;
      problem.clear();
    }
  }
  if (!call(paths_.ptz, getStatus(profile_.token), true, problem))
  {
    return false;
  }
  if (!(problem = readStatus(message_.content, status)).empty())
  {
    problem = "GetStatus answered " + problem;
    return false;
  }
  plan(status);
  if (!pan_tilt_.absolute && !pan_tilt_.velocity && !zoom_.present)
  {
    problem = "PTZ node '" + node_.token +
              "' lists no space this backend can move (absolute pan-tilt: " + spaceNames(node_.absolute_pan_tilt) +
              "; continuous pan-tilt: " + spaceNames(node_.continuous_pan_tilt) + ")";
    return false;
  }
  std::lock_guard<std::mutex> lock(report_mutex_);
  report_.presets = presets;
  report_.pan_tilt =
      (pan_tilt_.absolute ? "AbsoluteMove in " + spaceName(pan_tilt_.move_space) : "no AbsoluteMove") +
      std::string(pan_tilt_.velocity ? ", ContinuousMove" : ", no ContinuousMove") +
      (pan_tilt_.feedback ? ", status in " + spaceName(pan_tilt_.status_space) : ", no position in the status");
  return true;
}

void OnvifProtocol::plan(const onvif::Status& status)
{
  using namespace onvif;
  PanTiltPlan pan_tilt;
  const Space* degrees = findSpace(node_.absolute_pan_tilt, DEGREE_SPACE);
  const Space* generic = findSpace(node_.absolute_pan_tilt, GENERIC_PAN_TILT_SPACE);
  pan_tilt.status_space = status.has_pan_tilt ? statusSpace(status) : "";
  pan_tilt.feedback = status.has_pan_tilt && convertible(pan_tilt.status_space);
  const Space* chosen = degrees != nullptr ? degrees : generic;
  if (degrees != nullptr && generic != nullptr &&
      (!settings_.prefer_degrees || (pan_tilt.feedback && pan_tilt.status_space == GENERIC_PAN_TILT_SPACE)))
  {
    chosen = generic;  // asked for, or the status comes in it: a goal and what confirms it in one space
  }
  pan_tilt.absolute = chosen != nullptr && absolute_refused_.empty();
  if (chosen != nullptr)
  {
    const Space* corrected = findSpace(corrected_, chosen->uri);
    pan_tilt.move_space = chosen->uri;
    pan_tilt.x = corrected != nullptr ? corrected->x : chosen->x;
    pan_tilt.y = corrected != nullptr ? corrected->y : chosen->y;
  }
  pan_tilt.velocity = findSpace(node_.continuous_pan_tilt, GENERIC_PAN_TILT_VELOCITY) != nullptr;
  std::vector<std::string> lacks;
  if (!pan_tilt.absolute && !absolute_refused_.empty())
  {
    lacks.push_back("this camera answers AbsoluteMove with " + absolute_refused_);
  }
  else if (!pan_tilt.absolute)
  {
    lacks.push_back(node_.absolute_pan_tilt.empty() ? "this camera lists no absolute pan-tilt space (no AbsoluteMove)" :
                                                      "this camera lists only absolute pan-tilt spaces this backend "
                                                      "cannot use (" +
                                                          spaceNames(node_.absolute_pan_tilt) + ")");
  }
  if (!pan_tilt.velocity)
  {
    lacks.push_back("this camera lists no generic pan-tilt velocity space (no ContinuousMove)");
  }
  if (!status.has_pan_tilt)
  {
    lacks.push_back("its GetStatus answers no pan-tilt position");
  }
  else if (!pan_tilt.feedback)
  {
    lacks.push_back("its GetStatus answers the pan-tilt position in '" + pan_tilt.status_space +
                    "', a space this backend cannot convert");
  }
  pan_tilt.limitation = joined(lacks, " and ");
  if (!pan_tilt.limitation.empty() && pan_tilt.limitation.compare(0, 4, "its ") == 0)
  {
    pan_tilt.limitation = "this camera's" + pan_tilt.limitation.substr(3);
  }
  pan_tilt_ = pan_tilt;

  ZoomPlan zoom;
  zoom.present = findSpace(node_.absolute_zoom, GENERIC_ZOOM_SPACE) != nullptr;
  zoom.absolute = zoom.present && absolute_refused_.empty();
  zoom.velocity = zoom.present && findSpace(node_.continuous_zoom, GENERIC_ZOOM_VELOCITY) != nullptr;
  const std::string zoom_space = zoomStatusSpace(status);
  zoom.feedback = zoom.present && status.has_zoom && zoom_space == GENERIC_ZOOM_SPACE;
  if (!zoom.present && !node_.absolute_zoom.empty())
  {
    zoom.limitation = "this camera lists no generic zoom position space (only " + spaceNames(node_.absolute_zoom) + ")";
  }
  else if (!zoom.present && !node_.continuous_zoom.empty())
  {
    zoom.limitation = "this camera lists no zoom position space (it only zooms at a speed)";
  }
  else if (zoom.present && !zoom.absolute)
  {
    zoom.limitation = "this camera answers AbsoluteMove with " + absolute_refused_;
  }
  else if (zoom.present && !status.has_zoom)
  {
    zoom.limitation = "this camera's GetStatus answers no zoom position";
  }
  else if (zoom.present && !zoom.feedback)
  {
    zoom.limitation = "this camera's GetStatus answers the zoom position in '" + zoom_space +
                      "', a space this backend cannot convert";
  }
  zoom_ = zoom;
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

void OnvifProtocol::checkRanges(const onvif::Status& status, const std::string& space)
{
  const onvif::Space* listed = onvif::findSpace(node_.absolute_pan_tilt, space);
  if (listed == nullptr)
  {
    return;  // not listed at all: nothing to contradict
  }
  onvif::Space in_use = *listed;
  if (const onvif::Space* corrected = onvif::findSpace(corrected_, space))
  {
    in_use = *corrected;
  }
  const bool generic = space == onvif::GENERIC_PAN_TILT_SPACE;
  bool changed = false;
  for (const auto& axis :
       { std::make_tuple("pan", "x", status.x, &in_use.x), std::make_tuple("tilt", "y", status.y, &in_use.y) })
  {
    onvif::Range& range = *std::get<3>(axis);
    const double value = std::get<2>(axis);
    const double span = range.max - range.min;
    if (!std::isfinite(span) || range.contains(value, RANGE_TOLERANCE * std::max(span, 1e-9)))
    {
      continue;
    }
    // The camera is where its status says: a listed range without that position is wrong. The generic space's range
    // is by definition the whole travel, [-1, 1]; a degree range only grows to what the camera showed.
    const onvif::Range listed_range = range;
    if (generic)
    {
      range = onvif::Range{ -1.0, 1.0 };
    }
    range.min = std::min(range.min, value);
    range.max = std::max(range.max, value);
    changed = true;
    warnOnce(space + std::get<1>(axis),
             formatText("the camera's GetNodes lists the %s %s range [%g, %g], but its GetStatus answered %s = %g: "
                        "the listed range is wrong; the backend trusts the status and uses [%g, %g]%s",
                        onvif::spaceName(space).c_str(), std::get<0>(axis), listed_range.min, listed_range.max,
                        std::get<1>(axis), value, range.min, range.max,
                        generic ? " (the generic space's whole range by the specification)" : ""));
  }
  if (!changed)
  {
    return;
  }
  auto stored = std::find_if(corrected_.begin(), corrected_.end(),
                             [&space](const onvif::Space& item) { return item.uri == space; });
  if (stored == corrected_.end())
  {
    corrected_.push_back(in_use);
  }
  else
  {
    *stored = in_use;
  }
  if (pan_tilt_.absolute && pan_tilt_.move_space == space)
  {
    pan_tilt_.x = in_use.x;
    pan_tilt_.y = in_use.y;
    if (session_.connected())
    {
      session_.setCapabilities(cameraCapabilities());
    }
  }
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
  if (!velocity_body_.empty() && secondsBetween(velocity_sent_at_, session_.now()) >= 0.5 * settings_.velocity_timeout)
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
  if (pan_tilt_.feedback || zoom_.feedback)
  {
    session_.reportState(position);
  }
  else
  {
    session_.reportAlive();
  }
}

void OnvifProtocol::command(const std::string& path, const std::string& body, const char* operation)
{
  const std::uint64_t serial = session_.currentCommand();
  std::string problem;
  const bool done = call(path, body, true, problem);
  if (!done && !problem.empty())
  {
    session_.reportFault(problem, serial);
    if (std::string(operation) == "AbsoluteMove" && onvif::faultHas(message_, "ActionNotSupported"))
    {
      absoluteMoveRefused(message_.fault_text);
    }
  }
  if (done || !problem.empty())
  {
    // An answer, even a fault: the camera is alive (a slow camera's command and the next GetStatus may leave more
    // than state_timeout between two positions; each answer within it keeps the link up).
    session_.reportAlive();
  }
  if (std::string(operation) == "ContinuousMove")
  {
    velocity_sent_at_ = session_.now();
  }
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
  velocity_body_.clear();
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
  onvif::Vector target;
  if (pan_tilt)
  {
    // Pan and tilt travel together (a PanTilt has x and y): an axis left alone keeps where it is.
    const AxisValues now = session_.estimate().position;
    const double pan = std::isnan(position[PAN]) ? now[PAN] : position[PAN];
    const double tilt = std::isnan(position[TILT]) ? now[TILT] : position[TILT];
    const bool degrees = pan_tilt_.move_space == onvif::DEGREE_SPACE;
    target.pan_tilt = true;
    target.pan_tilt_space = pan_tilt_.move_space;
    target.x = std::clamp(degrees ? toDegrees(pan) : genericOf(settings_.pan, pan), pan_tilt_.x.min, pan_tilt_.x.max);
    target.y =
        std::clamp(degrees ? toDegrees(tilt) : genericOf(settings_.tilt, tilt), pan_tilt_.y.min, pan_tilt_.y.max);
  }
  if (zoom)
  {
    target.zoom = true;
    target.zoom_space = onvif::GENERIC_ZOOM_SPACE;
    target.z = std::clamp(std::log(std::max(1.0, position[ZOOM])) / std::log(settings_.zoom_max), 0.0, 1.0);
  }
  if (target.pan_tilt || target.zoom)
  {
    command(paths_.ptz, onvif::absoluteMove(profile_.token, target), "AbsoluteMove");
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
  velocity_body_ =
      onvif::continuousMove(profile_.token, x, y, zoom_.velocity, zoom, settings_.velocity_timeout, pan_tilt_.velocity);
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
                      { "commands the camera cannot do (not sent)", counters_.refused_locally } });
}

void OnvifProtocol::validate(const DeviceConfig<OnvifProtocol>& config)
{
  if (config.link.kind != LinkKind::HTTP)
  {
    throw ConfigError("an ONVIF camera is reached over HTTP");
  }
  if (config.settings.zoom_max <= 1.0 || config.settings.velocity_timeout < 1)
  {
    throw ConfigError("ONVIF zoom_max must be > 1 and velocity_timeout >= 1 s");
  }
}

}  // namespace ptz_action_server

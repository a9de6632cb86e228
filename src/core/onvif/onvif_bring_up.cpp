/**
 * \file
 * \brief OnvifProtocol's bring-up: what a (re)connection asks the camera, and the plans it makes of the answers.
 */
#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/core/text.h"

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

}  // namespace

double OnvifProtocol::cameraTime() const
{
  return systemUtc() + clock_offset_;
}

bool OnvifProtocol::readClock(std::string& problem)
{
  using namespace onvif;
  // The specification has GetSystemDateAndTime answered without authentication (the clock is what a UsernameToken is
  // stamped in); Axis answers it HTTP 401 unless it carries one. Then it is asked again with a token in this
  // machine's clock, which such a camera takes while its clock is near ours; refused again, the bring-up goes on in
  // our clock, and the camera's answers to the next requests say whether it takes that.
  clock_offset_ = 0.0;
  bool answered = call(settings_.device_path, getSystemDateAndTime(), false, problem);
  std::string refusal;
  if (!answered && unauthorized_)
  {
    refusal = problem;
    answered = !settings_.username.empty() && call(settings_.device_path, getSystemDateAndTime(), true, problem);
    if (!answered && (unauthorized_ || settings_.username.empty()))
    {
      warnOnce("clock", "the camera refused GetSystemDateAndTime (" + refusal +
                            (settings_.username.empty() ? "" : ", and again with WS-Security") +
                            "): its clock offset is unknown; WS-Security tokens are stamped in this machine's clock");
      problem.clear();
      return true;
    }
  }
  if (!answered)
  {
    return false;  // the link went, or the camera refused it for what it is: the start fails with its words
  }
  const double our_utc = systemUtc();
  double camera_utc = 0.0;
  problem = readSystemTime(message_.content, camera_utc);
  if (!problem.empty())
  {
    problem = "GetSystemDateAndTime answered " + problem;
    return false;
  }
  clock_offset_ = camera_utc - our_utc;
  if (!refusal.empty())
  {
    warnOnce("clock", "the camera refused GetSystemDateAndTime without authentication (" + refusal +
                          "), as Axis cameras do although the specification has it answered: it is asked with "
                          "WS-Security, stamped in this machine's clock");
  }
  return true;
}

void OnvifProtocol::chooseVelocityTimeout(double min, double max)
{
  velocity_timeout_ = settings_.velocity_timeout;
  if (max <= 0.0 || (velocity_timeout_ >= min && velocity_timeout_ <= max))
  {
    return;  // no range listed (or PT0S, as some firmware lists), or the setting is in it
  }
  // Whole seconds where the range holds one (some cameras take no fractions), else its end.
  const double whole = std::clamp(velocity_timeout_, std::ceil(min), std::floor(max));
  velocity_timeout_ = whole >= min && whole <= max && whole >= 1.0 ? whole : (velocity_timeout_ < min ? min : max);
  warnOnce("velocity_timeout",
           formatText("velocity_timeout %d s is outside the camera's PTZTimeout range [%g, %g] s (it refuses a "
                      "ContinuousMove outside it): its ContinuousMoves carry a Timeout of %g s, re-sent every %g s",
                      settings_.velocity_timeout, min, max, velocity_timeout_, 0.5 * velocity_timeout_));
}

bool OnvifProtocol::bringUp(std::string& problem, onvif::Status& status)
{
  using namespace onvif;
  if (!readClock(problem))
  {
    return false;
  }
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
  chooseVelocityTimeout(timeout_min, timeout_max);
  option_spaces_ = onvif::Node();
  const std::string unread_spaces = readOptionSpaces(message_.content, option_spaces_);
  if (!unread_spaces.empty())
  {
    warnOnce("options", "GetConfigurationOptions answered " + unread_spaces + ": pixel goals are computed by the node");
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
  if (!bringUpLens(problem))
  {
    return false;
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
  planView();
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
  pan_tilt.absolute = chosen != nullptr && absolute_refused_.empty() && !pan_tilt_ignores_absolute_;
  if (chosen != nullptr)
  {
    const Space* corrected = findSpace(corrected_, chosen->uri);
    pan_tilt.move_space = chosen->uri;
    pan_tilt.x = corrected != nullptr ? corrected->x : chosen->x;
    pan_tilt.y = corrected != nullptr ? corrected->y : chosen->y;
  }
  pan_tilt.velocity = findSpace(node_.continuous_pan_tilt, GENERIC_PAN_TILT_VELOCITY) != nullptr;
  if (const Space* speed = findSpace(node_.pan_tilt_speed, GENERIC_PAN_TILT_SPEED))
  {
    pan_tilt.speed = true;
    pan_tilt.speed_range = speed->x;
  }
  std::vector<std::string> lacks;
  if (!pan_tilt.absolute && !absolute_refused_.empty())
  {
    lacks.push_back("this camera answers AbsoluteMove with " + absolute_refused_);
  }
  else if (!pan_tilt.absolute && pan_tilt_ignores_absolute_)
  {
    lacks.push_back(IGNORES_ABSOLUTE_MOVE);
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
  zoom.absolute = zoom.present && absolute_refused_.empty() && !zoom_ignores_absolute_;
  zoom.velocity = zoom.present && findSpace(node_.continuous_zoom, GENERIC_ZOOM_VELOCITY) != nullptr;
  if (const Space* speed = findSpace(node_.zoom_speed, GENERIC_ZOOM_SPEED))
  {
    zoom.speed = zoom.present;
    zoom.speed_range = speed->x;
  }
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
    zoom.limitation = absolute_refused_.empty() ? IGNORES_ABSOLUTE_MOVE :
                                                  "this camera answers AbsoluteMove with " + absolute_refused_;
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

}  // namespace ptz_action_server

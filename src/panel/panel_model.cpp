#include "ptz_action_server/panel/panel_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ptz_action_server::panel
{
std::vector<std::string> cameraNamespaces(const std::vector<TopicInfo>& topics)
{
  const std::string suffix = std::string("/") + STATE_TOPIC;
  std::vector<std::string> namespaces;
  for (const TopicInfo& topic : topics)
  {
    if (topic.datatype != STATE_TYPE || topic.name.size() < suffix.size() ||
        topic.name.compare(topic.name.size() - suffix.size(), suffix.size(), suffix) != 0)
    {
      continue;
    }
    const std::string ns = topic.name.substr(0, topic.name.size() - suffix.size());
    namespaces.push_back(ns.empty() ? "/" : ns);
  }
  std::sort(namespaces.begin(), namespaces.end());
  namespaces.erase(std::unique(namespaces.begin(), namespaces.end()), namespaces.end());
  return namespaces;
}

std::string inNamespace(const std::string& ns, const std::string& name)
{
  if (ns.empty() || ns == "/")
  {
    return "/" + name;
  }
  return (ns.back() == '/' ? ns : ns + "/") + name;
}

bool diagnosticsOfNamespace(const std::string& ns, const std::string& status_name)
{
  const std::string node = status_name.substr(0, status_name.find(": "));
  const std::size_t slash = node.rfind('/');
  const std::string parent = slash == std::string::npos ? "" : node.substr(0, slash);
  std::string wanted = ns;
  while (!wanted.empty() && wanted.front() == '/')
  {
    wanted.erase(0, 1);
  }
  while (!wanted.empty() && wanted.back() == '/')
  {
    wanted.pop_back();
  }
  return status_name.find(": ") != std::string::npos && parent == wanted;
}

std::string modeText(int mode)
{
  switch (mode)
  {
    case 0:
      return "idle";
    case 1:
      return "position";
    case 2:
      return "velocity";
    default:
      return "mode " + std::to_string(mode);
  }
}

std::string angleText(double rad)
{
  if (!std::isfinite(rad))
  {
    return "n/a";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.1f\u00b0 (%.3f rad)", rad * 180.0 / M_PI, rad);
  return text;
}

std::string zoomText(double zoom)
{
  if (!std::isfinite(zoom))
  {
    return "n/a";
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f x", zoom);
  return text;
}

std::string linkText(Link link)
{
  switch (link)
  {
    case Link::UP:
      return "up";
    case Link::DOWN:
      return "down";
    case Link::UNKNOWN:
      break;
  }
  return "unknown";
}

void StateWatch::received(double now)
{
  received_ = true;
  last_ = now;
}

void StateWatch::reset()
{
  received_ = false;
}

bool StateWatch::fresh(double now) const
{
  return received_ && now - last_ <= STATE_TIMEOUT;
}

std::string StateWatch::banner(double now) const
{
  return fresh(now) ? "" : NO_STATE_TEXT;
}

std::string goalStatusName(std::uint8_t status)
{
  static const char* const NAMES[] = { "pending",  "active",     "preempted", "succeeded", "aborted",
                                       "rejected", "preempting", "recalling", "recalled",  "lost" };
  if (status < sizeof(NAMES) / sizeof(NAMES[0]))
  {
    return NAMES[status];
  }
  return "status " + std::to_string(status);
}

std::string goalText(const std::vector<GoalStatusEntry>& goals)
{
  constexpr std::uint8_t ACTIVE = 1;
  const GoalStatusEntry* shown = nullptr;
  for (const GoalStatusEntry& goal : goals)
  {
    const bool active = goal.status == ACTIVE;
    const bool shown_active = shown != nullptr && shown->status == ACTIVE;
    if (shown == nullptr || (active && !shown_active) || (active == shown_active && goal.stamp > shown->stamp))
    {
      shown = &goal;
    }
  }
  if (shown == nullptr)
  {
    return "no goal";
  }
  std::string text = shown->action + ": " + goalStatusName(shown->status);
  if (!shown->text.empty())
  {
    text += ": " + shown->text;
  }
  return text;
}

namespace
{
double speedOr(double max_speed, double fallback)
{
  return std::isfinite(max_speed) && max_speed > 0.0 ? max_speed : fallback;
}
}  // namespace

Velocity jogVelocity(Jog jog, double fraction, const Abilities& abilities)
{
  fraction = std::isfinite(fraction) ? std::clamp(fraction, 0.05, 1.0) : 1.0;
  const double pan = fraction * speedOr(abilities.pan.max_speed, DEFAULT_PAN_TILT_SPEED);
  const double tilt = fraction * speedOr(abilities.tilt.max_speed, DEFAULT_PAN_TILT_SPEED);
  const double zoom = fraction * speedOr(abilities.zoom.max_speed, DEFAULT_ZOOM_SPEED);
  Velocity velocity;
  switch (jog)
  {
    case Jog::LEFT:
      velocity.pan = -pan;
      break;
    case Jog::RIGHT:
      velocity.pan = pan;
      break;
    case Jog::UP:
      velocity.tilt = tilt;
      break;
    case Jog::DOWN:
      velocity.tilt = -tilt;
      break;
    case Jog::ZOOM_IN:
      velocity.zoom = zoom;
      break;
    case Jog::ZOOM_OUT:
      velocity.zoom = -zoom;
      break;
  }
  return velocity;
}

Enables enables(const EnableInputs& inputs)
{
  Enables result;
  if (!inputs.fresh)
  {
    return result;
  }
  result.look_switch = inputs.look_available;
  if (inputs.link == Link::DOWN)
  {
    return result;
  }
  const Abilities& a = inputs.abilities;
  const auto moves = [](const AxisAbility& axis, bool by_velocity) {
    return axis.present && (by_velocity ? axis.velocity : axis.absolute);
  };
  result.jog_pan = moves(a.pan, true);
  result.jog_tilt = moves(a.tilt, true);
  result.jog_zoom = moves(a.zoom, true);
  result.absolute = moves(a.pan, false) || moves(a.tilt, false);
  result.presets = result.absolute;
  return result;
}

Quaternion orientationOfAim(const Aim& aim)
{
  // q = Rz(-pan) * Ry(-tilt)
  const double cz = std::cos(-aim.pan / 2.0), sz = std::sin(-aim.pan / 2.0);
  const double cy = std::cos(-aim.tilt / 2.0), sy = std::sin(-aim.tilt / 2.0);
  Quaternion q;
  q.w = cz * cy;
  q.x = -sz * sy;
  q.y = cz * sy;
  q.z = sz * cy;
  return q;
}

Aim aimOfOrientation(const Quaternion& orientation)
{
  const double norm = std::sqrt(orientation.x * orientation.x + orientation.y * orientation.y +
                                orientation.z * orientation.z + orientation.w * orientation.w);
  if (!(norm > 0.0))
  {
    return {};
  }
  const double x = orientation.x / norm, y = orientation.y / norm, z = orientation.z / norm, w = orientation.w / norm;
  // The rotated x axis: the first column of the rotation matrix.
  const double dx = 1.0 - 2.0 * (y * y + z * z);
  const double dy = 2.0 * (x * y + w * z);
  const double dz = 2.0 * (x * z - w * y);
  const double horizontal = std::hypot(dx, dy);
  Aim aim;
  aim.tilt = std::atan2(dz, horizontal);
  aim.pan = horizontal > 1e-9 ? -std::atan2(dy, dx) : 0.0;
  return aim;
}

bool RateLimiter::allow(double now)
{
  if (!(period_ > 0.0) || (any_ && now - last_ < period_))
  {
    return false;
  }
  any_ = true;
  last_ = now;
  return true;
}

void RateLimiter::reset()
{
  any_ = false;
}

}  // namespace ptz_action_server::panel

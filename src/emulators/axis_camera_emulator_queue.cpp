/**
 * \file
 * \brief AxisCameraEmulator: the PTZ control queue (VAPIX PTZ API, "Queuing API"), with the Administrator group's
 * defaults: clients told apart by a cookie, control for control_time after the holder's last move or request.
 */
#include <cmath>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
namespace
{
constexpr const char* COOKIE = "axisptzq=";
constexpr const char* OTHER = "other";
}  // namespace

std::string AxisCameraEmulator::clientOf(const std::string& cookie, std::string& set_cookie)
{
  if (!config_.control_queue)
  {
    return "";
  }
  const std::size_t at = cookie.find(COOKIE);
  if (at != std::string::npos)
  {
    const std::size_t start = at + std::char_traits<char>::length(COOKIE);
    return cookie.substr(start, cookie.find(';', start) - start);
  }
  const std::string client = "client" + std::to_string(++clients_);
  set_cookie = COOKIE + client + "; path=/";
  return client;
}

bool AxisCameraEmulator::mayMove(const std::string& client, TimePoint now)
{
  if (!config_.control_queue)
  {
    return true;
  }
  if (holder_ != client || (!held_for_good_ && now >= held_until_))
  {
    return false;
  }
  held_until_ = addSeconds(now, config_.control_time);  // TimeoutType activity: every move starts it again
  return true;
}

HttpAnswer AxisCameraEmulator::queueAnswer(const std::string& control, const std::string& client, TimePoint now)
{
  if (!config_.control_queue)
  {
    return HttpAnswer{ 200, "text/plain", "Error:\r\nPTZ control queueing is not enabled\r\n" };
  }
  if (control != "request" && control != "query" && control != "drop")
  {
    return HttpAnswer{ 200, "text/plain", "Error:\r\ncontrol: unknown value: " + control + "\r\n" };
  }
  const bool lapsed = holder_.empty() || (!held_for_good_ && now >= held_until_);
  if (lapsed)
  {
    holder_.clear();
    held_for_good_ = false;
  }
  if (control == "drop")
  {
    if (holder_ == client)
    {
      holder_.clear();
    }
    return HttpAnswer{ 200, "text/plain", "<a name=\"0\"></a><a name=\"0\"></a><a name=\"0\"></a>" };
  }
  if (control == "request" && (holder_.empty() || holder_ == client))
  {
    holder_ = client;
    held_until_ = addSeconds(now, config_.control_time);
  }
  const double left = held_for_good_ ? -1.0 : std::ceil(secondsBetween(now, held_until_));
  if (holder_ == client)
  {
    return HttpAnswer{ 200, "text/plain",
                       formatText("<a name=\"1\"></a><a name=\"%.0f\"></a><a name=\"%.0f\"></a>", left,
                                  config_.queue_period) };
  }
  // Second in line behind the holder (one client waits here at a time).
  return HttpAnswer{ 200, "text/plain",
                     formatText("<a name=\"2\"></a><a name=\"%.0f\"></a><a name=\"%.0f\"></a>", left,
                                config_.queue_period) };
}

std::string AxisCameraEmulator::queueParameters(const std::string& group) const
{
  const std::string all = formatText("root.PTZ.Various.V1.CtlQueueing=%s\r\nroot.PTZ.Various.V1.CtlQueueLimit=20\r\n"
                                     "root.PTZ.Various.V1.CtlQueuePollTime=%g\r\nroot.PTZ.Various.V1.PanEnabled="
                                     "true\r\n"
                                     "root.PTZ.Various.V1.TiltEnabled=true\r\n",
                                     config_.control_queue ? "true" : "false", config_.queue_poll_time);
  std::string lines;
  std::size_t start = 0;
  while (start < all.size())
  {
    const std::size_t end = all.find("\r\n", start) + 2;
    const std::string line = all.substr(start, end - start);
    if (line.rfind(group, 0) == 0)
    {
      lines += line;
    }
    start = end;
  }
  return lines.empty() ? "# Error: Error -1 getting param in group '" + group + "'\r\n" : lines;
}

void AxisCameraEmulator::holdControlElsewhere(double seconds)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (seconds == 0.0)
  {
    holder_.clear();
    return;
  }
  holder_ = OTHER;
  held_for_good_ = seconds < 0.0;
  held_until_ = addSeconds(clock_->now(), seconds < 0.0 ? 0.0 : seconds);
}

std::string AxisCameraEmulator::controlHolder() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return holder_.empty() || (!held_for_good_ && clock_->now() >= held_until_) ? "" : holder_;
}

}  // namespace ptz_action_server

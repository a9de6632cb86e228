#include "soak_client.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>

#include "bench_common.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/ros/ptz_goal.h"

namespace ptz_bench
{
using namespace ptz_action_server;

namespace
{
/// "link lost", "stalled", "tilt # rad is outside the limits [#, #] rad": a status text up to its first colon (if
/// early), its numbers as '#'.
std::string shortReason(const std::string& text)
{
  const std::size_t colon = text.find(':');
  const std::string reason = colon != std::string::npos && colon < 48 ? text.substr(0, colon) : text;
  std::string out;
  for (std::size_t index = 0; index < reason.size();)
  {
    const auto digit = [&](std::size_t at) {
      return at < reason.size() && std::isdigit(static_cast<unsigned char>(reason[at]));
    };
    if (digit(index) || (reason[index] == '-' && digit(index + 1)))
    {
      ++index;
      while (digit(index) || (reason[index] == '.' && digit(index + 1)))
      {
        ++index;
      }
      out += '#';
      continue;
    }
    out += reason[index++];
  }
  return out.size() > 60 ? out.substr(0, 57) + "..." : out;
}

/// How a goal ended, as the table counts it. An invalid goal should be rejected; anything else it does is named.
std::string endOf(const actionlib::SimpleClientGoalState& state, bool invalid)
{
  const std::string& text = state.getText();
  std::string end;
  switch (state.state_)
  {
    case actionlib::SimpleClientGoalState::SUCCEEDED:
      end = "succeeded";
      break;
    case actionlib::SimpleClientGoalState::PREEMPTED:
      end = text.rfind("cancelled", 0) == 0    ? "cancelled" :
            text.rfind("preempted by", 0) == 0 ? "preempted by a new goal" :
                                                 "preempted: " + shortReason(text);
      break;
    case actionlib::SimpleClientGoalState::ABORTED:
      end = "aborted: " + shortReason(text);
      break;
    case actionlib::SimpleClientGoalState::REJECTED:
      if (invalid)
      {
        return "invalid, rejected";
      }
      end = text.rfind("superseded by", 0) == 0 ? "rejected: superseded while waiting for tf" :
                                                  "rejected: " + shortReason(text);
      break;
    case actionlib::SimpleClientGoalState::RECALLED:
      end = "recalled";
      break;
    default:
      end = "client state " + state.toString();
  }
  return invalid ? "INVALID GOAL NOT REJECTED, " + end : end;
}
}  // namespace

Ranges rangesOf(const PtzCapabilities& capabilities)
{
  Ranges ranges;
  auto inside = [](const PtzAxisCapability& axis, double& low, double& high) {
    if (axis.absolute && axis.max > axis.min)
    {
      const double margin = 0.2 * (axis.max - axis.min);
      low = std::max(low, axis.min + margin);
      high = std::min(high, axis.max - margin);
    }
  };
  inside(capabilities.pan, ranges.pan_min, ranges.pan_max);
  inside(capabilities.tilt, ranges.tilt_min, ranges.tilt_max);
  if (capabilities.zoom.absolute && capabilities.zoom.max > capabilities.zoom.min)
  {
    ranges.zoom_min = capabilities.zoom.min;
    ranges.zoom_max = capabilities.zoom.min + 0.3 * (capabilities.zoom.max - capabilities.zoom.min);
  }
  if (capabilities.zoom.velocity && capabilities.zoom.max_speed > 0.0)
  {
    ranges.zoom_speed = 0.3 * capabilities.zoom.max_speed;
  }
  ranges.pan_speed = capabilities.pan.velocity ? std::min(0.3, 0.5 * capabilities.pan.max_speed) : 0.0;
  ranges.tilt_speed = capabilities.tilt.velocity ? std::min(0.2, 0.5 * capabilities.tilt.max_speed) : 0.0;
  return ranges;
}

bool SoakClient::waitForServers(double seconds)
{
  return absolute_.waitForServer(ros::Duration(seconds)) && relative_.waitForServer(ros::Duration(seconds)) &&
         velocity_.waitForServer(ros::Duration(seconds)) && frame_.waitForServer(ros::Duration(seconds)) &&
         preset_.waitForServer(ros::Duration(seconds));
}

void SoakClient::run()
{
  while (!stop_)
  {
    oneGoal();
    ros::WallDuration(uniform(0.2, 2.5)).sleep();  // 4 clients: about 2 goals a second
  }
}

double SoakClient::uniform(double low, double high)
{
  return std::uniform_real_distribution<double>(low, high)(random_);
}

bool SoakClient::chance(double share)
{
  return uniform(0.0, 1.0) < share;
}

double SoakClient::zoom()
{
  return ranges_.zoom_max > ranges_.zoom_min ? uniform(ranges_.zoom_min, ranges_.zoom_max) : ranges_.zoom_min;
}

void SoakClient::oneGoal()
{
  const bool invalid = chance(0.05);
  const double kind_draw = uniform(0.0, 1.0);
  // A cancel 0 to 0.8 s after the goal, for a fifth of the goals; velocity goals always end by one.
  bool cancel = chance(0.2);
  double cancel_after = uniform(0.0, 0.8);
  std::string kind;
  std::function<actionlib::SimpleClientGoalState()> state;
  std::function<void()> cancel_goal;
  std::function<bool(double)> wait;
  auto use = [&](auto& client) {
    state = [&client] { return client.getState(); };
    cancel_goal = [&client] { client.cancelGoal(); };
    wait = [&client](double seconds) { return client.waitForResult(ros::Duration(seconds)); };
  };
  if (kind_draw < 0.3)
  {
    kind = "absolute";
    PtzGoal goal =
        makePtzGoal(uniform(ranges_.pan_min, ranges_.pan_max), uniform(ranges_.tilt_min, ranges_.tilt_max), zoom());
    if (invalid)
    {
      goal.tilt = chance(0.5) ? 5.0f : std::nanf("");  // outside any device's limits, or NaN
    }
    absolute_.sendGoal(goal);
    use(absolute_);
  }
  else if (kind_draw < 0.45)
  {
    kind = "relative";
    PtzGoal goal = makePtzGoal(uniform(-0.3, 0.3), uniform(-0.1, 0.1), 0.0);
    if (invalid)
    {
      goal.pan = std::numeric_limits<float>::infinity();
    }
    relative_.sendGoal(goal);
    use(relative_);
  }
  else if (kind_draw < 0.65)
  {
    kind = "velocity";
    PtzGoal goal = makePtzGoal(uniform(-1.0, 1.0) * ranges_.pan_speed, uniform(-1.0, 1.0) * ranges_.tilt_speed,
                               uniform(-1.0, 1.0) * ranges_.zoom_speed);
    if (invalid)
    {
      goal.pan = 1000.0f;  // above any device's top speed
    }
    cancel = true;
    cancel_after = uniform(0.2, 1.5);
    velocity_.sendGoal(goal);
    use(velocity_);
  }
  else if (kind_draw < 0.82)
  {
    kind = "frame";
    PtzFrameGoal goal;
    goal.frame_id = invalid ? "soak_no_such_frame" : FRAMES[chance(0.5) ? 0 : 1];
    goal.zoom = static_cast<float>(zoom());
    frame_.sendGoal(goal);
    use(frame_);
  }
  else
  {
    kind = "preset";
    PtzPresetGoal goal;
    goal.name = invalid ? "soak_no_such_preset" : (chance(0.5) ? PRESET : "home");
    preset_.sendGoal(goal);
    use(preset_);
  }
  const double sent_at = (ros::WallTime::now() - started_).toSec();
  {
    std::lock_guard<std::mutex> lock(tally_.mutex);
    ++tally_.goals_sent;
    ++tally_.sent[kind + (invalid ? " (invalid)" : "")];
  }
  bool ended = false;
  if (cancel)
  {
    ended = wait(cancel_after);
    if (!ended)
    {
      cancel_goal();
    }
  }
  if (!ended)
  {
    ended = wait(GOAL_DEADLINE);
  }
  const actionlib::SimpleClientGoalState final_state = state();
  std::lock_guard<std::mutex> lock(tally_.mutex);
  if (ended && final_state.isDone())
  {
    ++tally_.goals_ended;
    ++tally_.ends[endOf(final_state, invalid)];
  }
  else
  {
    char text[256];
    std::snprintf(text, sizeof(text), "%s goal sent at %.1f s: still %s after %.0f s", kind.c_str(), sent_at,
                  final_state.toString().c_str(), GOAL_DEADLINE);
    tally_.never_ended.push_back(text);
  }
}

StateRate::StateRate(ros::NodeHandle& node_handle)
{
  ros::SubscribeOptions options = ros::SubscribeOptions::create<PtzState>(
      "ptz_state", 100,
      [this](const PtzState::ConstPtr&) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (recording_)
        {
          arrivals_.push_back(monotonicNanoseconds() * 1e-9);
        }
      },
      ros::VoidPtr(), &queue_);
  subscriber_ = node_handle.subscribe(options);
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
}

void StateRate::record(bool on)
{
  std::lock_guard<std::mutex> lock(mutex_);
  recording_ = on;
}

void StateRate::figures(double& mean, double& worst, double& best) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  mean = worst = best = 0.0;
  if (arrivals_.size() < 2)
  {
    return;
  }
  mean = (arrivals_.size() - 1) / (arrivals_.back() - arrivals_.front());
  worst = 1e9;
  std::size_t end = 0;
  for (std::size_t begin = 0; begin < arrivals_.size() && arrivals_[begin] + WINDOW <= arrivals_.back(); ++begin)
  {
    while (end < arrivals_.size() && arrivals_[end] < arrivals_[begin] + WINDOW)
    {
      ++end;
    }
    const double rate = (end - begin) / WINDOW;
    worst = std::min(worst, rate);
    best = std::max(best, rate);
  }
  if (worst > 1e8)
  {
    worst = best = mean;  // shorter than one window
  }
}

}  // namespace ptz_bench

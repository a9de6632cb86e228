/**
 * \file
 * \brief bench_soak's goal clients (a goal mix, counted by how each goal ended) and its ptz_state rate meter.
 */
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzCapabilities.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzPresetAction.h"

namespace ptz_bench
{
using ptz_action_server::PtzAction;
using ptz_action_server::PtzFrameAction;
using ptz_action_server::PtzPresetAction;

constexpr double GOAL_DEADLINE = 120.0;  ///< s after which a goal that has not ended counts as never ended
constexpr double WINDOW = 10.0;          ///< s: the worst ptz_state window
constexpr const char* PRESET = "soak";   ///< saved at start
constexpr const char* FRAMES[] = { "soak_target_a", "soak_target_b" };

/// What the device's axes allow, from the node's latched capabilities, kept inside.
struct Ranges
{
  double pan_min = -1.0, pan_max = 1.0, tilt_min = -0.4, tilt_max = 0.4;
  double zoom_min = 1.0, zoom_max = 1.0;  ///< equal: the zoom takes no position goals
  double pan_speed = 0.3, tilt_speed = 0.2, zoom_speed = 0.0;
};

/// The goal ranges inside \p capabilities' axes.
Ranges rangesOf(const ptz_action_server::PtzCapabilities& capabilities);

/// What the clients counted, shared.
struct Tally
{
  std::mutex mutex;
  std::map<std::string, long> sent;  ///< by kind
  std::map<std::string, long> ends;  ///< by how they ended
  long goals_sent = 0;
  long goals_ended = 0;
  std::vector<std::string> never_ended;  ///< "kind sent at t s, last state ..."
};

/// One client: its own action clients (each with its spin thread), sending one goal at a time until \p stop.
class SoakClient
{
public:
  SoakClient(ros::NodeHandle node_handle, int index, const Ranges& ranges, Tally& tally, const std::atomic<bool>& stop,
             ros::WallTime started)
    : random_(1000 + index)
    , ranges_(ranges)
    , tally_(tally)
    , stop_(stop)
    , started_(started)
    , absolute_(node_handle, "move_ptz/position_abs", true)
    , relative_(node_handle, "move_ptz/position_rel", true)
    , velocity_(node_handle, "move_ptz/velocity", true)
    , frame_(node_handle, "move_ptz/frame", true)
    , preset_(node_handle, "move_ptz/preset", true)
  {
  }

  bool waitForServers(double seconds);

  void run();

private:
  double uniform(double low, double high);
  bool chance(double share);
  double zoom();

  /// Sends one goal of a kind drawn from the mix, cancels it or not, waits for its end and counts it.
  void oneGoal();

  std::mt19937 random_;
  const Ranges ranges_;
  Tally& tally_;
  const std::atomic<bool>& stop_;
  const ros::WallTime started_;
  actionlib::SimpleActionClient<PtzAction> absolute_;
  actionlib::SimpleActionClient<PtzAction> relative_;
  actionlib::SimpleActionClient<PtzAction> velocity_;
  actionlib::SimpleActionClient<PtzFrameAction> frame_;
  actionlib::SimpleActionClient<PtzPresetAction> preset_;
};

/// ptz_state arrivals on this process's steady clock (a subscriber of its own queue and thread).
class StateRate
{
public:
  explicit StateRate(ros::NodeHandle& node_handle);
  void record(bool on);
  /// Mean rate over the recording, and the lowest and highest count of any WINDOW s window, in Hz.
  void figures(double& mean, double& worst, double& best) const;

private:
  ros::CallbackQueue queue_;
  ros::Subscriber subscriber_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
  mutable std::mutex mutex_;
  bool recording_ = false;
  std::vector<double> arrivals_;
};

}  // namespace ptz_bench

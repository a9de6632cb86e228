/**
 * \file
 * \brief Demo client: moves the camera through a few goals (one preempted, one cancelled, one rejected), printing
 * feedback and state as it goes. Exits 0 when every goal ended as expected.
 */
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <string>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/ros/ptz_goal.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzState.h"

namespace
{
using ptz_action_server::makePtzGoal;
using ptz_action_server::PtzAction;
using ptz_action_server::PtzFrameAction;
using ptz_action_server::PtzGoal;
using ptz_action_server::PtzState;
using State = actionlib::SimpleClientGoalState;
using PtzClient = actionlib::SimpleActionClient<PtzAction>;
using FrameClient = actionlib::SimpleActionClient<PtzFrameAction>;

constexpr const char* TARGET_FRAME = "ptz_demo_target";

std::mutex print_mutex;
PtzState latest_state;

const char* modeName(int mode)
{
  switch (mode)
  {
    case PtzState::MODE_POSITION:
      return "POSITION";
    case PtzState::MODE_VELOCITY:
      return "VELOCITY";
    default:
      return "IDLE";
  }
}

void onState(const PtzState::ConstPtr& state)
{
  std::lock_guard<std::mutex> lock(print_mutex);
  latest_state = *state;
}

/// Prints every other feedback with the state published at that moment.
template <class FeedbackPtr>
void printFeedback(const char* label, const FeedbackPtr& feedback)
{
  static int count = 0;
  if (count++ % 2 != 0)
  {
    return;
  }
  std::lock_guard<std::mutex> lock(print_mutex);
  std::printf("    %-10s remaining pan %+7.3f tilt %+7.3f zoom %+6.2f | state %-8s pan %+7.3f tilt %+7.3f zoom %5.2f\n",
              label, feedback->pan_remaining, feedback->tilt_remaining, feedback->zoom_remaining,
              modeName(latest_state.mode), latest_state.pan, latest_state.tilt, latest_state.zoom);
  std::fflush(stdout);
}

/// Waits for the client's goal to end and reports whether it ended as \p expected.
template <class Client>
bool expectEnd(Client& client, const char* label, const State::StateEnum expected, double timeout = 15.0)
{
  if (!client.waitForResult(ros::Duration(timeout)))
  {
    std::printf("  FAIL %s: no result within %.0f s\n", label, timeout);
    return false;
  }
  const State state = client.getState();
  const bool ok = state == expected;
  std::printf("  %s %s ended %s%s%s\n", ok ? "ok  " : "FAIL", label, state.toString().c_str(),
              state.getText().empty() ? "" : ": ", state.getText().c_str());
  if (!ok)
  {
    std::printf("       (expected %s)\n", State(expected).toString().c_str());
  }
  std::fflush(stdout);
  return ok;
}

template <class Action>
void send(actionlib::SimpleActionClient<Action>& client, const typename Action::_action_goal_type::_goal_type& goal,
          const char* label)
{
  using Client = actionlib::SimpleActionClient<Action>;
  client.sendGoal(goal, typename Client::SimpleDoneCallback(), typename Client::SimpleActiveCallback(),
                  [label](const auto& feedback) { printFeedback(label, feedback); });
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_demo", ros::init_options::AnonymousName);
  ros::NodeHandle node_handle;
  std::string ns = "/ptz";
  ros::NodeHandle("~").getParam("ns", ns);
  for (int index = 1; index + 1 < argc; ++index)
  {
    if (std::string(argv[index]) == "--ns")
    {
      ns = argv[index + 1];
    }
  }
  ros::AsyncSpinner spinner(2);
  spinner.start();

  const ros::Subscriber state_subscriber = node_handle.subscribe(ns + "/ptz_state", 10, onState);
  PtzClient absolute(ns + "/move_ptz/position_abs", true);
  PtzClient preempting(ns + "/move_ptz/position_abs", true);
  PtzClient relative(ns + "/move_ptz/position_rel", true);
  PtzClient velocity(ns + "/move_ptz/velocity", true);
  FrameClient frame(ns + "/move_ptz/frame", true);
  std::printf("ptz_demo: waiting for the action servers under %s ...\n", ns.c_str());
  for (auto* client : { &absolute, &preempting, &relative, &velocity })
  {
    if (!client->waitForServer(ros::Duration(30.0)))
    {
      std::printf("ptz_demo: no action server under %s/move_ptz\n", ns.c_str());
      return 1;
    }
  }
  frame.waitForServer(ros::Duration(30.0));

  // A target for the frame goal: 2 m ahead, 1 m to the right, 0.5 m up from the camera's base.
  tf2_ros::StaticTransformBroadcaster static_broadcaster;
  geometry_msgs::TransformStamped target;
  target.header.stamp = ros::Time::now();
  target.header.frame_id = "ptz_base_link";
  target.child_frame_id = TARGET_FRAME;
  target.transform.translation.x = 2.0;
  target.transform.translation.y = -1.0;
  target.transform.translation.z = 0.5;
  target.transform.rotation.w = 1.0;
  static_broadcaster.sendTransform(target);

  bool all_ok = true;
  std::printf("\n[1/6] position_abs: pan 0.8 rad (right), tilt 0.3 rad (up), zoom 4x\n");
  send(absolute, makePtzGoal(0.8, 0.3, 4.0), "abs");
  all_ok &= expectEnd(absolute, "position_abs", State::SUCCEEDED);

  std::printf("\n[2/6] position_abs to pan -0.8, preempted after 0.6 s by position_abs to pan 0.3, tilt 0.1, 2x\n");
  send(absolute, makePtzGoal(-0.8, -0.2, 1.0), "first");
  ros::WallDuration(0.6).sleep();
  send(preempting, makePtzGoal(0.3, 0.1, 2.0), "second");
  all_ok &= expectEnd(absolute, "first goal", State::PREEMPTED);
  all_ok &= expectEnd(preempting, "second goal", State::SUCCEEDED);

  std::printf("\n[3/6] velocity: pan at -0.5 rad/s, cancelled after 1 s (the device decelerates to rest)\n");
  send(velocity, makePtzGoal(-0.5, 0.0, 0.0), "velocity");
  ros::WallDuration(1.0).sleep();
  velocity.cancelGoal();
  all_ok &= expectEnd(velocity, "velocity goal", State::PREEMPTED);

  std::printf("\n[4/6] position_rel: pan +0.3 rad, tilt -0.1 rad from where it stopped\n");
  send(relative, makePtzGoal(0.3, -0.1, 0.0), "rel");
  all_ok &= expectEnd(relative, "position_rel", State::SUCCEEDED);

  std::printf("\n[5/6] frame: point at '%s' (2 m ahead, 1 m right, 0.5 m up), zoom 3x\n", TARGET_FRAME);
  ptz_action_server::PtzFrameGoal frame_goal;
  frame_goal.frame_id = TARGET_FRAME;
  frame_goal.zoom = 3.0;
  ros::WallDuration(0.3).sleep();  // let the static transform reach the node
  send(frame, frame_goal, "frame");
  all_ok &= expectEnd(frame, "frame goal", State::SUCCEEDED);

  std::printf("\n[6/6] an invalid goal: pan NaN is rejected and nothing moves\n");
  send(absolute, makePtzGoal(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0), "nan");
  all_ok &= expectEnd(absolute, "NaN goal", State::REJECTED);

  ros::WallDuration(0.25).sleep();  // one more state tick
  {
    std::lock_guard<std::mutex> lock(print_mutex);
    std::printf("\nfinal state: %s pan %.3f rad, tilt %.3f rad, zoom %.2f X\n", modeName(latest_state.mode),
                latest_state.pan, latest_state.tilt, latest_state.zoom);
  }
  std::printf("ptz_demo: %s\n", all_ok ? "every goal ended as expected" : "SOME GOALS DID NOT END AS EXPECTED");
  return all_ok ? 0 : 1;
}

// The rviz panel's plain logic: namespace discovery, texts, jog velocities, greying, the tour line.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ptz_action_server/panel/panel_model.h"
#include "ptz_action_server/panel/tour_model.h"

using namespace ptz_action_server::panel;

TEST(PanelModel, OffersEveryNamespaceWithAPtzStateOfTheRightType)
{
  const std::vector<TopicInfo> topics = {
    { "/right/ptz_state", "ptz_action_server/PtzState" },
    { "/left/ptz_state", "ptz_action_server/PtzState" },
    { "/left/joint_states", "sensor_msgs/JointState" },
    { "/other/ptz_state", "std_msgs/String" },  // another type: not a camera
    { "/robot/arm/ptz_state", "ptz_action_server/PtzState" },
    { "/left/ptz_state", "ptz_action_server/PtzState" },  // listed twice
    { "/ptz_state", "ptz_action_server/PtzState" },       // a node at the root
    { "/left/not_ptz_state", "ptz_action_server/PtzState" },
  };
  EXPECT_EQ(cameraNamespaces(topics), (std::vector<std::string>{ "/", "/left", "/right", "/robot/arm" }));
  EXPECT_TRUE(cameraNamespaces({}).empty());
}

TEST(PanelModel, NamesInTheCamerasNamespace)
{
  EXPECT_EQ(inNamespace("/ptz", "move_ptz/velocity"), "/ptz/move_ptz/velocity");
  EXPECT_EQ(inNamespace("/", "ptz_state"), "/ptz_state");
  EXPECT_EQ(inNamespace("/a/b/", "ptz_state"), "/a/b/ptz_state");
}

TEST(PanelModel, DiagnosticsOfTheCamerasNode)
{
  EXPECT_TRUE(diagnosticsOfNamespace("/ptz", "ptz/ptz_action_server: Backend"));
  EXPECT_TRUE(diagnosticsOfNamespace("/robot/arm", "robot/arm/ptz_action_server: Backend"));
  EXPECT_TRUE(diagnosticsOfNamespace("/", "ptz_action_server: Backend"));
  EXPECT_FALSE(diagnosticsOfNamespace("/ptz", "left/ptz_action_server: Backend"));
  EXPECT_FALSE(diagnosticsOfNamespace("/ptz", "ptz/sub/ptz_action_server: Backend"));
  EXPECT_FALSE(diagnosticsOfNamespace("/", "left/ptz_action_server: Backend"));
  EXPECT_FALSE(diagnosticsOfNamespace("/ptz", "ptz/ptz_action_server"));
}

TEST(PanelModel, StateTexts)
{
  EXPECT_EQ(modeText(0), "idle");
  EXPECT_EQ(modeText(1), "position");
  EXPECT_EQ(modeText(2), "velocity");
  EXPECT_EQ(modeText(7), "mode 7");
  EXPECT_EQ(angleText(0.6), "34.4\u00b0 (0.600 rad)");
  EXPECT_EQ(angleText(-0.35), "-20.1\u00b0 (-0.350 rad)");
  EXPECT_EQ(angleText(std::numeric_limits<double>::quiet_NaN()), "n/a");
  EXPECT_EQ(zoomText(3.0), "3.00 x");
  EXPECT_EQ(zoomText(std::numeric_limits<double>::quiet_NaN()), "n/a");
  EXPECT_EQ(linkText(Link::UP), "up");
  EXPECT_EQ(linkText(Link::DOWN), "down");
  EXPECT_EQ(linkText(Link::UNKNOWN), "unknown");
}

TEST(PanelModel, StateIsFreshForTwoSeconds)
{
  StateWatch watch;
  EXPECT_FALSE(watch.fresh(0.0));
  EXPECT_EQ(watch.banner(0.0), "no ptz_state for 2 s");
  watch.received(10.0);
  EXPECT_TRUE(watch.fresh(11.9));
  EXPECT_EQ(watch.banner(11.9), "");
  EXPECT_FALSE(watch.fresh(12.1));
  EXPECT_EQ(watch.banner(12.1), "no ptz_state for 2 s");
  watch.received(20.0);  // the node came back
  EXPECT_TRUE(watch.fresh(20.5));
  watch.reset();  // another camera picked
  EXPECT_FALSE(watch.fresh(20.5));
}

TEST(PanelModel, GoalTextPrefersTheNewestActiveGoal)
{
  EXPECT_EQ(goalText({}), "no goal");
  std::vector<GoalStatusEntry> goals = {
    { "position_abs", 4, "stalled: tilt made no progress for 1.00 s", 5.0, "goal-1" },
    { "velocity", 1, "", 3.0, "goal-2" },
    { "preset", 3, "", 4.0, "goal-3" },
  };
  EXPECT_EQ(goalText(goals), "velocity: active");
  goals[1].status = 2;  // preempted: now the newest goal of any state wins
  EXPECT_EQ(goalText(goals), "position_abs: aborted: stalled: tilt made no progress for 1.00 s");
  EXPECT_EQ(goalStatusName(5), "rejected");
  EXPECT_EQ(goalStatusName(42), "status 42");
}

TEST(PanelModel, JogFollowsTheContractsSignsAtAFractionOfTheMaxSpeed)
{
  Abilities abilities;
  abilities.known = true;
  abilities.pan.max_speed = 2.0;
  abilities.tilt.max_speed = 1.0;
  abilities.zoom.max_speed = 4.0;
  const Velocity right = jogVelocity(Jog::RIGHT, 0.5, abilities);
  EXPECT_DOUBLE_EQ(right.pan, 1.0);
  EXPECT_DOUBLE_EQ(right.tilt, 0.0);
  EXPECT_DOUBLE_EQ(right.zoom, 0.0);
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::LEFT, 0.5, abilities).pan, -1.0);
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::UP, 0.5, abilities).tilt, 0.5);
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::DOWN, 0.5, abilities).tilt, -0.5);
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::ZOOM_IN, 0.5, abilities).zoom, 2.0);
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::ZOOM_OUT, 0.5, abilities).zoom, -2.0);
  // The fraction is clamped; unknown max speeds fall back to the defaults.
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::RIGHT, 3.0, abilities).pan, 2.0);
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::RIGHT, 0.0, abilities).pan, 0.1);
  abilities.pan.max_speed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::RIGHT, 1.0, abilities).pan, DEFAULT_PAN_TILT_SPEED);
  EXPECT_DOUBLE_EQ(jogVelocity(Jog::ZOOM_IN, 1.0, Abilities{}).zoom, DEFAULT_ZOOM_SPEED);
}

TEST(PanelModel, GreyingRules)
{
  EnableInputs inputs;
  inputs.look_available = true;
  Enables e = enables(inputs);  // no ptz_state: everything greyed, the switch too
  EXPECT_FALSE(e.jog_pan || e.jog_tilt || e.jog_zoom || e.absolute || e.presets || e.look_switch);

  inputs.fresh = true;
  e = enables(inputs);  // capabilities unknown: everything offered
  EXPECT_TRUE(e.jog_pan && e.jog_tilt && e.jog_zoom && e.absolute && e.presets && e.look_switch);

  inputs.link = Link::DOWN;  // the node rejects goals while the link is down
  e = enables(inputs);
  EXPECT_FALSE(e.jog_pan || e.jog_tilt || e.jog_zoom || e.absolute || e.presets);
  EXPECT_TRUE(e.look_switch);

  inputs.link = Link::UP;
  inputs.look_available = false;
  inputs.abilities.known = true;
  inputs.abilities.zoom.present = false;  // a pan-tilt unit
  inputs.abilities.pan.absolute = false;  // a velocity-only pan
  e = enables(inputs);
  EXPECT_TRUE(e.jog_pan && e.jog_tilt && e.absolute && e.presets);
  EXPECT_FALSE(e.jog_zoom || e.look_switch);
  inputs.abilities.tilt.absolute = false;  // nothing takes position goals: no pose, no presets
  e = enables(inputs);
  EXPECT_FALSE(e.absolute || e.presets);
}

TEST(PanelModel, AimMarkerOrientationFollowsTheUrdfConventions)
{
  // doc/urdf-and-tf.md: at pan +0.5 the optical axis is (cos 0.5, -sin 0.5, 0); at tilt +0.3 it is (cos 0.3, 0, sin
  // 0.3).
  const Quaternion q = orientationOfAim({ 0.5, 0.0 });
  const double dx = 1.0 - 2.0 * (q.y * q.y + q.z * q.z);
  const double dy = 2.0 * (q.x * q.y + q.w * q.z);
  EXPECT_NEAR(dx, std::cos(0.5), 1e-12);
  EXPECT_NEAR(dy, -std::sin(0.5), 1e-12);
  const Quaternion up = orientationOfAim({ 0.0, 0.3 });
  EXPECT_NEAR(2.0 * (up.x * up.z - up.w * up.y), std::sin(0.3), 1e-12);
  for (const Aim aim : { Aim{ 0.6, 0.35 }, Aim{ -2.5, -1.2 }, Aim{ 3.0, 0.0 }, Aim{ 0.0, -0.7 } })
  {
    const Aim back = aimOfOrientation(orientationOfAim(aim));
    EXPECT_NEAR(back.pan, aim.pan, 1e-9);
    EXPECT_NEAR(back.tilt, aim.tilt, 1e-9);
  }
  // Not normalised, and rolled about the optical axis: the same aim.
  Quaternion q2 = orientationOfAim({ 0.6, 0.35 });
  q2.x *= 3.0;
  q2.y *= 3.0;
  q2.z *= 3.0;
  q2.w *= 3.0;
  EXPECT_NEAR(aimOfOrientation(q2).pan, 0.6, 1e-9);
  const Quaternion roll{ std::sin(0.2), 0.0, 0.0, std::cos(0.2) };  // about x only
  EXPECT_NEAR(aimOfOrientation(roll).pan, 0.0, 1e-12);
  EXPECT_NEAR(aimOfOrientation(roll).tilt, 0.0, 1e-12);
  EXPECT_NEAR(aimOfOrientation(orientationOfAim({ 1.0, M_PI / 2.0 })).tilt, M_PI / 2.0, 1e-6);
}

TEST(PanelModel, RateLimiterLetsOneEventThroughPerPeriod)
{
  RateLimiter limiter(0.25);
  EXPECT_TRUE(limiter.allow(10.0));
  EXPECT_FALSE(limiter.allow(10.1));
  EXPECT_TRUE(limiter.allow(10.25));
  limiter.reset();
  EXPECT_TRUE(limiter.allow(10.3));
  RateLimiter never(0.0);
  EXPECT_FALSE(never.allow(1.0));
}

TEST(PanelModel, TourListLines)
{
  const TourListing tour{ "gate_round", { "gate", "yard", "home" }, { 10.0, 4.5, 0.0 } };
  EXPECT_EQ(tourListText(tour), "gate_round  (3 stops)");
  EXPECT_EQ(tourStopsText(tour), "gate 10 s, yard 4.5 s, home 0 s");
  EXPECT_EQ(tourListText({ "one", { "home" }, { 2.0 } }), "one  (1 stop)");
}

TEST(PanelModel, TourProgressSaysTheStopItsPresetAndTheTimeLeft)
{
  TourFeedback feedback;
  feedback.tour = "gate_round";
  feedback.stop = 1;
  feedback.preset = "yard";
  feedback.state = TOUR_DWELLING;
  feedback.time_left = 3.46;
  EXPECT_EQ(tourProgressText(feedback, 3, 2), "gate_round: stop 2 of 3 (yard), 3.5 s left, round 1 of 2");
  feedback.round = 4;  // looping (rounds 0), a tour the panel has not listed (0 stops)
  EXPECT_EQ(tourProgressText(feedback, 0, 0), "gate_round: stop 2 (yard), 3.5 s left, round 4");
  feedback.state = TOUR_MOVING;
  feedback.time_left = 10.0;
  EXPECT_EQ(tourProgressText(feedback, 3, 0), "gate_round: stop 2 of 3 (yard), moving there (dwell 10.0 s), round 4");
  feedback.state = TOUR_PAUSED;
  feedback.time_left = -1.0;
  EXPECT_EQ(tourProgressText(feedback, 3, 0), "gate_round: stop 2 of 3 (yard), paused while another goal runs, round "
                                              "4");
  feedback.time_left = 5.0;
  EXPECT_EQ(tourProgressText(feedback, 3, 0), "gate_round: stop 2 of 3 (yard), paused, resumes in 5.0 s, round 4");
}

TEST(PanelModel, TourEndSaysHowAndWhy)
{
  EXPECT_EQ(tourEndText("gate_round", 3, "", 6), "gate_round: succeeded (6 stops visited)");
  EXPECT_EQ(tourEndText("gate_round", 3, "visited 6 stops in 2 rounds", 6), "gate_round: succeeded: visited 6 stops in "
                                                                            "2 rounds");
  // The node's texts that start with the status are not said twice.
  EXPECT_EQ(
      tourEndText("gate_round", 2, "preempted at stop 2 of 3 (yard) of tour 'gate_round' by a new velocity goal", 1),
      "gate_round: preempted at stop 2 of 3 (yard) of tour 'gate_round' by a new velocity goal (1 stop visited)");
  EXPECT_EQ(tourEndText("gate_round", 2, "cancelled at stop 1 of 3 (gate) of tour 'gate_round'", 1), "gate_round: "
                                                                                                     "preempted: "
                                                                                                     "cancelled at "
                                                                                                     "stop 1 of 3 "
                                                                                                     "(gate) of tour "
                                                                                                     "'gate_round' (1 "
                                                                                                     "stop visited)");
  EXPECT_EQ(tourEndText("gate_round", 4, "stop 2 of 3 (yard) of tour 'gate_round': stalled: pan made no progress", 1),
            "gate_round: aborted: stop 2 of 3 (yard) of tour 'gate_round': stalled: pan made no progress (1 stop "
            "visited)");
  EXPECT_EQ(tourEndText("x", 5, "no tour named 'x'", 0), "x: rejected: no tour named 'x'");  // it never ran
  EXPECT_EQ(tourEndText("", 8, "", 0), "tour: recalled");
}

TEST(PanelModel, TourWatchShowsTheNewestRunningGoalElseHowTheLastEnded)
{
  const std::vector<TourListing> tours = { { "round_a", { "door", "home" }, { 5.0, 1.0 } } };
  TourWatch watch;
  EXPECT_EQ(watch.text(tours), "no tour");
  watch.goal("g1", "round_a", 0);
  EXPECT_EQ(watch.text(tours), "round_a: starting");
  TourFeedback feedback;
  feedback.tour = "round_a";
  feedback.preset = "door";
  feedback.state = TOUR_DWELLING;
  feedback.time_left = 4.0;
  watch.feedback("g1", feedback);
  EXPECT_EQ(watch.text(tours), "round_a: stop 1 of 2 (door), 4.0 s left, round 1");
  // A second goal replaces it: the node ends the first preempted, the line follows the second.
  watch.goal("g2", "round_a", 3);
  watch.result("g1", 2, "preempted by a new tour goal", 1);
  EXPECT_EQ(watch.text(tours), "round_a: starting");
  watch.feedback("g2", feedback);
  EXPECT_EQ(watch.text(tours), "round_a: stop 1 of 2 (door), 4.0 s left, round 1 of 3");
  watch.result("g2", 2, "cancelled at stop 1 of 2 (door) of tour 'round_a'", 1);
  watch.feedback("g2", feedback);  // a late feedback does not bring it back
  EXPECT_EQ(watch.text(tours), "round_a: preempted: cancelled at stop 1 of 2 (door) of tour 'round_a' (1 stop "
                               "visited)");
  // A goal heard first through its feedback (sent before the panel started) has its tour from there.
  feedback.tour = "unlisted";
  watch.feedback("g3", feedback);
  EXPECT_EQ(watch.text(tours), "unlisted: stop 1 (door), 4.0 s left, round 1");
  watch.result("g3", 4, "stop 1 of 4 (door) of tour 'unlisted': link down", 0);
  EXPECT_EQ(watch.text(tours), "unlisted: aborted: stop 1 of 4 (door) of tour 'unlisted': link down (0 stops visited)");
  watch.clear();
  EXPECT_EQ(watch.text(tours), "no tour");
  // Many goals: only the last few are kept, and the running one is still shown.
  for (int i = 0; i < 20; ++i)
  {
    watch.goal("many" + std::to_string(i), "round_a", 1);
    watch.result("many" + std::to_string(i), 3, "", 2);
  }
  watch.goal("last", "round_a", 1);
  EXPECT_EQ(watch.text(tours), "round_a: starting");
}

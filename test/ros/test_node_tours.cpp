/**
 * \file
 * \brief rostest client, tours on the sim (tours.test, with ~tour/resume_after): a tour visits its presets in order,
 * seen on ptz_state; it yields to an operator's goal and resumes once the operator lets go; the services check tours.
 */
#include "node_test.h"

#include <algorithm>
#include <cstddef>
#include <memory>

#include "ptz_action_server/DeletePreset.h"
#include "ptz_action_server/DeleteTour.h"
#include "ptz_action_server/ListTours.h"
#include "ptz_action_server/PtzTourAction.h"
#include "ptz_action_server/SavePreset.h"
#include "ptz_action_server/SaveTour.h"

namespace
{
using ptz_action_server::PtzTourAction;
using ptz_action_server::PtzTourFeedback;
using TourClient = actionlib::SimpleActionClient<PtzTourAction>;

struct TourPreset
{
  const char* name;
  double pan;
  double tilt;
};
const std::vector<TourPreset> TOUR_PRESETS{ { "tour_test_a", 0.5, 0.0 },
                                            { "tour_test_b", -0.5, 0.2 },
                                            { "tour_test_c", 0.0, -0.3 } };
constexpr const char* TOUR_NAME = "tour_test";
constexpr const char* SLOW_TOUR_NAME = "tour_test_slow";  // dwells long enough to be caught at a stop

bool atTourPose(const PtzState& state, double pan, double tilt)
{
  return std::abs(state.pan - pan) < 2 * TOLERANCE && std::abs(state.tilt - tilt) < 2 * TOLERANCE;
}

/// NodeTest with the tour action and the test's presets and tour saved (tours.test only: not NodeTest.*).
class TourTest : public NodeTest
{
protected:
  void SetUp() override
  {
    NodeTest::SetUp();
    ros::NodeHandle node_handle;
    ASSERT_TRUE(ros::service::waitForService(node_handle.resolveName("move_ptz/save_tour"), ros::Duration(GOAL_WAIT)));
    tour_ = std::make_unique<TourClient>("move_ptz/tour", true);
    ASSERT_TRUE(tour_->waitForServer(ros::Duration(GOAL_WAIT)));
    for (const TourPreset& preset : TOUR_PRESETS)
    {
      ASSERT_EQ(moveTo(preset.pan, preset.tilt, zoomOr1(1.0)), State::SUCCEEDED);
      ptz_action_server::SavePreset save;
      save.request.name = preset.name;
      ASSERT_TRUE(ros::service::call(node_handle.resolveName("move_ptz/save_preset"), save));
      ASSERT_TRUE(save.response.success) << save.response.message;
    }
    saveTour(TOUR_NAME, 0.5);
    ASSERT_EQ(moveTo(0.0, 0.0, zoomOr1(1.0)), State::SUCCEEDED);
  }

  void TearDown() override
  {
    ros::NodeHandle node_handle;
    if (tour_)
    {
      tour_->cancelAllGoals();
    }
    for (const char* name : { TOUR_NAME, SLOW_TOUR_NAME })
    {
      ptz_action_server::DeleteTour remove_tour;
      remove_tour.request.name = name;
      ros::service::call(node_handle.resolveName("move_ptz/delete_tour"), remove_tour);
    }
    for (const TourPreset& preset : TOUR_PRESETS)
    {
      ptz_action_server::DeletePreset remove;
      remove.request.name = preset.name;
      ros::service::call(node_handle.resolveName("move_ptz/delete_preset"), remove);
    }
  }

  /// Saves the tour \p name through the test's presets, \p dwell s at each (the first stop at half speed).
  static void saveTour(const std::string& name, double dwell)
  {
    ptz_action_server::SaveTour save;
    save.request.tour.name = name;
    for (const TourPreset& preset : TOUR_PRESETS)
    {
      ptz_action_server::PtzTourStop stop;
      stop.preset = preset.name;
      stop.dwell = dwell;
      stop.speed = save.request.tour.stops.empty() ? 0.5 : 0.0;
      save.request.tour.stops.push_back(stop);
    }
    ASSERT_TRUE(ros::service::call(ros::NodeHandle().resolveName("move_ptz/save_tour"), save));
    ASSERT_TRUE(save.response.success) << save.response.message;
  }

  /// Starts the tour \p name for \p rounds, its feedback into feedback_.
  void startTour(std::uint32_t rounds, const std::string& name = TOUR_NAME)
  {
    ptz_action_server::PtzTourGoal goal;
    goal.name = name;
    goal.rounds = rounds;
    tour_->sendGoal(goal, TourClient::SimpleDoneCallback(), TourClient::SimpleActiveCallback(),
                    [this](const ptz_action_server::PtzTourFeedbackConstPtr& feedback) { feedback_.add(*feedback); });
  }

  /// Waits until a feedback from the \p from th on satisfies \p predicate.
  bool waitForFeedback(const std::function<bool(const PtzTourFeedback&)>& predicate, double timeout,
                       std::size_t from = 0)
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::WallTime::now() < deadline)
    {
      const std::vector<PtzTourFeedback> all = feedback_.all();
      if (all.size() > from && std::any_of(all.begin() + static_cast<std::ptrdiff_t>(from), all.end(), predicate))
      {
        return true;
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }

  std::unique_ptr<TourClient> tour_;
  FeedbackLog<PtzTourFeedback> feedback_;
};

TEST_F(TourTest, VisitsItsPresetsInOrderWithTheirDwell)
{
  observer_->clear();
  startTour(1);
  ASSERT_TRUE(tour_->waitForResult(ros::Duration(3 * GOAL_WAIT)));
  ASSERT_EQ(tour_->getState(), State::SUCCEEDED) << tour_->getState().getText();
  EXPECT_TRUE(tour_->getResult()->success);
  EXPECT_EQ(tour_->getResult()->stops_visited, 3U);

  // On ptz_state: each preset reached, in the tour's order.
  const std::vector<PtzState> states = observer_->states();
  std::size_t from = 0;
  for (const TourPreset& preset : TOUR_PRESETS)
  {
    while (from < states.size() && !atTourPose(states[from], preset.pan, preset.tilt))
    {
      ++from;
    }
    EXPECT_LT(from, states.size()) << preset.name << " not reached after the stops before it";
  }
  // In the feedback: each stop moved to, then dwelt at, in order.
  std::vector<std::uint32_t> dwelt;
  for (const PtzTourFeedback& feedback : feedback_.all())
  {
    EXPECT_EQ(feedback.tour, TOUR_NAME);
    if (feedback.state == PtzTourFeedback::DWELLING && (dwelt.empty() || dwelt.back() != feedback.stop))
    {
      dwelt.push_back(feedback.stop);
      EXPECT_EQ(feedback.preset, TOUR_PRESETS[feedback.stop].name);
      EXPECT_LE(feedback.time_left, 0.5);
    }
  }
  EXPECT_EQ(dwelt, (std::vector<std::uint32_t>{ 0, 1, 2 }));
}

TEST_F(TourTest, YieldsToAnOperatorsGoalAndResumesAfterIdle)
{
  saveTour(SLOW_TOUR_NAME, 5.0);
  startTour(0, SLOW_TOUR_NAME);
  ASSERT_TRUE(waitForFeedback(
      [](const PtzTourFeedback& feedback) { return feedback.stop == 1 && feedback.state == PtzTourFeedback::DWELLING; },
      GOAL_WAIT));

  // The operator's goal preempts the tour's move: it runs to its end, and the tour waits (~tour/resume_after).
  ASSERT_EQ(moveTo(0.2, 0.1, zoomOr1(1.0)), State::SUCCEEDED) << absolute_->getState().getText();
  // (The tour may already be on its way back when this thread runs: the history shows where the operator put it.)
  EXPECT_TRUE(observer_->waitFor(
      [](const PtzState&) {
        const std::vector<PtzState> states = observer_->states();
        return std::any_of(states.begin(), states.end(),
                           [](const PtzState& state) { return atTourPose(state, 0.2, 0.1); });
      },
      5.0));
  EXPECT_EQ(tour_->getState(), State::ACTIVE) << tour_->getState().getText();
  EXPECT_TRUE(waitForFeedback([](const PtzTourFeedback& feedback) { return feedback.state == PtzTourFeedback::PAUSED; },
                              GOAL_WAIT));

  // Once the operator has let go, the tour resumes at the stop it was at, then goes on in order.
  EXPECT_TRUE(observer_->waitFor([](const PtzState& state) { return atTourPose(state, -0.5, 0.2); }, GOAL_WAIT))
      << "not back at " << TOUR_PRESETS[1].name;
  EXPECT_TRUE(observer_->waitFor([](const PtzState& state) { return atTourPose(state, 0.0, -0.3); }, GOAL_WAIT))
      << "not on to " << TOUR_PRESETS[2].name;
  EXPECT_EQ(tour_->getState(), State::ACTIVE);

  // A cancel stops the device and ends the tour.
  tour_->cancelGoal();
  ASSERT_TRUE(tour_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(tour_->getState(), State::PREEMPTED) << tour_->getState().getText();
  EXPECT_TRUE(observer_->waitFor([](const PtzState& state) { return state.mode == PtzState::MODE_IDLE; }, GOAL_WAIT));
}

TEST_F(TourTest, ServicesListToursAndRefuseBadOnes)
{
  ros::NodeHandle node_handle;
  ptz_action_server::ListTours list;
  ASSERT_TRUE(ros::service::call(node_handle.resolveName("move_ptz/list_tours"), list));
  bool listed = false;
  for (const auto& tour : list.response.tours)
  {
    if (tour.name == TOUR_NAME)
    {
      listed = true;
      ASSERT_EQ(tour.stops.size(), TOUR_PRESETS.size());
      EXPECT_EQ(tour.stops[0].preset, TOUR_PRESETS[0].name);
      EXPECT_DOUBLE_EQ(tour.stops[0].speed, 0.5);
      EXPECT_DOUBLE_EQ(tour.stops[2].dwell, 0.5);
    }
  }
  EXPECT_TRUE(listed);

  ptz_action_server::SaveTour save;
  save.request.tour.name = "tour_test_bad";
  save.request.tour.stops.resize(1);
  save.request.tour.stops[0].preset = "no_such_preset";
  ASSERT_TRUE(ros::service::call(node_handle.resolveName("move_ptz/save_tour"), save));
  EXPECT_FALSE(save.response.success);
  EXPECT_NE(save.response.message.find("no_such_preset"), std::string::npos) << save.response.message;

  // A goal for an unknown tour is rejected.
  ptz_action_server::PtzTourGoal goal;
  goal.name = "tour_test_bad";
  tour_->sendGoal(goal);
  ASSERT_TRUE(tour_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(tour_->getState(), State::REJECTED);
}

}  // namespace

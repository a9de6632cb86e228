// The panel's Tours box against the sim node, under Xvfb (main() is test_ptz_panel.cpp's): a tour saved through the
// node's service is listed, Start runs it (the camera reaches its first stop, the tour line says where the tour is),
// Stop and another goal end it (the line says how), a tour of one round succeeds; the goal line shows the goals of
// every action the node serves (the tour, position_abs_speed).
#include <gtest/gtest.h>

#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QtTest/QTest>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>

#include "panel_test.h"
#include "ptz_action_server/DeletePreset.h"
#include "ptz_action_server/DeleteTour.h"
#include "ptz_action_server/ListPresets.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzSpeedAction.h"
#include "ptz_action_server/SavePreset.h"
#include "ptz_action_server/SaveTour.h"

namespace
{
using ptz_action_server::PtzTourStop;

const char* const STOP_PRESET = "panel_tour_stop";
constexpr double NEAR = 0.01;  // rad: at the preset (the sim settles well within the goal tolerance)

class PanelToursTest : public PanelTest
{
protected:
  void TearDown() override
  {
    for (const char* tour : { "panel_round", "panel_once" })
    {
      ptz_action_server::DeleteTour remove;
      remove.request.name = tour;
      ros::service::call("/ptz/move_ptz/delete_tour", remove);
    }
    ptz_action_server::DeletePreset remove;
    remove.request.name = STOP_PRESET;
    ros::service::call("/ptz/move_ptz/delete_preset", remove);
    PanelTest::TearDown();
  }

  /// Moves the camera to (pan, tilt) with a position_abs goal and waits for its end; true if it succeeded.
  static bool moveTo(double pan, double tilt)
  {
    actionlib::SimpleActionClient<ptz_action_server::PtzAction> client("/ptz/move_ptz/position_abs", true);
    if (!client.waitForServer(ros::Duration(WAIT)))
    {
      return false;
    }
    ptz_action_server::PtzGoal goal;
    goal.pan = static_cast<float>(pan);
    goal.tilt = static_cast<float>(tilt);
    goal.zoom = 1.0f;
    client.sendGoal(goal);
    return client.waitForResult(ros::Duration(WAIT)) &&
           client.getState() == actionlib::SimpleClientGoalState::SUCCEEDED;
  }

  /// Saves STOP_PRESET at (pan, tilt) and returns the pose the node saved (its state then).
  static bool savePresetAt(double pan, double tilt, double& saved_pan, double& saved_tilt)
  {
    ptz_action_server::SavePreset save;
    save.request.name = STOP_PRESET;
    ptz_action_server::ListPresets list;
    if (!moveTo(pan, tilt) || !ros::service::call("/ptz/move_ptz/save_preset", save) || !save.response.success ||
        !ros::service::call("/ptz/move_ptz/list_presets", list))
    {
      return false;
    }
    for (std::size_t i = 0; i < list.response.names.size(); ++i)
    {
      if (list.response.names[i] == STOP_PRESET)
      {
        saved_pan = list.response.pan[i];
        saved_tilt = list.response.tilt[i];
        return true;
      }
    }
    return false;
  }

  static bool saveTour(const std::string& name, const std::vector<std::pair<std::string, double>>& stops)
  {
    ptz_action_server::SaveTour save;
    save.request.tour.name = name;
    for (const auto& [preset, dwell] : stops)
    {
      PtzTourStop stop;
      stop.preset = preset;
      stop.dwell = dwell;
      save.request.tour.stops.push_back(stop);
    }
    return ros::service::call("/ptz/move_ptz/save_tour", save) && save.response.success;
  }

  /// Refreshes the Tours box until `name` is listed and selects it; its row's text, "" if it never came.
  std::string listAndSelect(const QString& name)
  {
    QListWidget* tours = child<QListWidget>("tours");
    int row = -1;
    const auto listed = [&] {
      for (int i = 0; i < tours->count(); ++i)
      {
        if (tours->item(i)->data(Qt::UserRole).toString() == name)
        {
          row = i;
          return true;
        }
      }
      return false;
    };
    QTest::mouseClick(child<QPushButton>("tour_refresh"), Qt::LeftButton);
    if (!waitFor(listed))
    {
      return "";
    }
    tours->setCurrentRow(row);
    return tours->item(row)->text().toStdString();
  }

  /// Shows the Presets or the Tours tab ("presets_page", "tours_page"), as a click on it does.
  void showTab(const char* page)
  {
    child<QTabWidget>("preset_tabs")->setCurrentWidget(child<QWidget>(page));
  }

  bool at(double pan, double tilt)
  {
    std::lock_guard<std::mutex> lock(observer_.mutex);
    return observer_.has_state && std::abs(observer_.state.pan - pan) < NEAR &&
           std::abs(observer_.state.tilt - tilt) < NEAR;
  }

  bool lineStartsWith(const std::string& start)
  {
    return text("tour_progress").rfind(start, 0) == 0;
  }
};

TEST_F(PanelToursTest, ListsStartsAndStopsATourAndSaysHowItEnded)
{
  ASSERT_TRUE(waitFor([&] { return enabled("tour_start") && enabled("preset_home"); })) << text("banner");
  double pan = 0.0, tilt = 0.0;
  ASSERT_TRUE(savePresetAt(0.4, 0.15, pan, tilt));
  ASSERT_TRUE(moveTo(-0.2, 0.0));  // away from the first stop
  ASSERT_TRUE(saveTour("panel_round", { { STOP_PRESET, 60.0 }, { "home", 1.0 } }));
  showTab("tours_page");
  EXPECT_EQ(listAndSelect("panel_round"), "panel_round  (2 stops)");
  child<QSpinBox>("tour_rounds")->setValue(0);  // loop

  QTest::mouseClick(child<QPushButton>("tour_start"), Qt::LeftButton);
  EXPECT_TRUE(waitFor([&] { return at(pan, tilt); })) << text("tour_progress");
  EXPECT_TRUE(waitFor([&] { return lineStartsWith("panel_round: stop 1 of 2 (panel_tour_stop), "); })) << text("tour_"
                                                                                                               "progres"
                                                                                                               "s");
  EXPECT_TRUE(waitFor([&] { return text("tour_progress").find(" s left, round 1") != std::string::npos; }))
      << text("tour_progress");  // dwelling there
  EXPECT_TRUE(waitFor([&] { return text("state_goal") == "tour: active"; })) << text("state_goal");

  QTest::mouseClick(child<QPushButton>("tour_stop"), Qt::LeftButton);
  EXPECT_TRUE(waitFor([&] {
    return lineStartsWith("panel_round: preempted: cancelled at stop 1 of 2 (panel_tour_stop) of tour 'panel_round'");
  })) << text("tour_progress");

  // Started again, then another goal (the Presets box's Home) takes over: the tour ends preempted by it.
  QTest::mouseClick(child<QPushButton>("tour_start"), Qt::LeftButton);
  EXPECT_TRUE(waitFor([&] { return lineStartsWith("panel_round: stop 1 of 2 (panel_tour_stop), "); })) << text("tour_"
                                                                                                               "progres"
                                                                                                               "s");
  showTab("presets_page");
  QTest::mouseClick(child<QPushButton>("preset_home"), Qt::LeftButton);
  EXPECT_TRUE(waitFor([&] {
    return lineStartsWith("panel_round: preempted at stop 1 of 2 (panel_tour_stop) of tour 'panel_round' by a new "
                          "preset goal");
  })) << text("tour_progress");

  // Delete: the list loses it.
  showTab("tours_page");
  ASSERT_FALSE(listAndSelect("panel_round").empty());
  QTest::mouseClick(child<QPushButton>("tour_delete"), Qt::LeftButton);
  EXPECT_TRUE(waitFor([&] {
    return child<QListWidget>("tours")->findItems("panel_round", Qt::MatchStartsWith).empty();
  })) << text("message");
}

TEST_F(PanelToursTest, ATourOfOneRoundSucceeds)
{
  ASSERT_TRUE(waitFor([&] { return enabled("tour_start"); })) << text("banner");
  double pan = 0.0, tilt = 0.0;
  ASSERT_TRUE(savePresetAt(0.3, -0.1, pan, tilt));
  ASSERT_TRUE(saveTour("panel_once", { { "home", 0.2 }, { STOP_PRESET, 0.2 } }));
  showTab("tours_page");
  ASSERT_EQ(listAndSelect("panel_once"), "panel_once  (2 stops)");
  child<QSpinBox>("tour_rounds")->setValue(1);
  QTest::mouseClick(child<QPushButton>("tour_start"), Qt::LeftButton);
  EXPECT_TRUE(waitFor([&] { return text("tour_progress") == "panel_once: succeeded: visited 2 stops in 1 round"; }))
      << text("tou"
              "r_"
              "pro"
              "gre"
              "s"
              "s");
  EXPECT_TRUE(waitFor([&] { return at(pan, tilt); }));  // its last stop
}

TEST_F(PanelToursTest, TheGoalLineShowsAGoalOfEveryActionTheNodeServes)
{
  ASSERT_TRUE(waitFor([&] { return enabled("jog_right"); })) << text("banner");
  // position_abs_speed came after the panel's hand-written list of actions, which missed it.
  actionlib::SimpleActionClient<ptz_action_server::PtzSpeedAction> client("/ptz/move_ptz/position_abs_speed", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(WAIT)));
  ptz_action_server::PtzSpeedGoal goal;
  goal.pan = 0.1f;
  goal.tilt = 0.05f;
  goal.zoom = 1.0f;
  goal.speed = 0.5f;
  client.sendGoal(goal);
  EXPECT_TRUE(waitFor([&] { return text("state_goal").rfind("position_abs_speed: ", 0) == 0; })) << text("state_goal");
  EXPECT_TRUE(client.waitForResult(ros::Duration(WAIT)));
}

}  // namespace

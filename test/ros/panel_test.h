/**
 * \file
 * \brief The panel tests' fixture: PanelTest loads the rviz panel as rviz does and runs the Qt event loop while it
 * waits; Observer hears what the node received and published.
 */
#pragma once

#include <gtest/gtest.h>

#include <QApplication>
#include <QLabel>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <actionlib_msgs/GoalID.h>
#include <pluginlib/class_loader.hpp>
#include <ros/ros.h>
#include <rviz/panel.h>
#include <visualization_msgs/InteractiveMarkerInit.h>
#include <visualization_msgs/InteractiveMarkerUpdate.h>

#include "ptz_action_server/PtzActionGoal.h"
#include "ptz_action_server/PtzPresetActionGoal.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/panel/panel_model.h"
#include "ptz_action_server/panel/ptz_panel.h"

inline std::string g_no_display;      ///< why no X display could be had ("" when there is one); main() sets it
inline constexpr double WAIT = 20.0;  // s

/// What the node received and published, heard on the test's own spinner.
class Observer
{
public:
  Observer()
  {
    ros::NodeHandle node("/ptz");
    subscribers_.push_back(node.subscribe("ptz_state", 10, &Observer::onState, this));
    subscribers_.push_back(node.subscribe("move_ptz/velocity/goal", 10, &Observer::onVelocity, this));
    subscribers_.push_back(node.subscribe("move_ptz/velocity/cancel", 10, &Observer::onCancel, this));
    subscribers_.push_back(node.subscribe("move_ptz/preset/goal", 10, &Observer::onPreset, this));
    subscribers_.push_back(node.subscribe("move_ptz/position_abs/goal", 10, &Observer::onAbsolute, this));
    subscribers_.push_back(node.subscribe("aim_marker/update", 10, &Observer::onMarker, this));
    subscribers_.push_back(node.subscribe("aim_marker/update_full", 1, &Observer::onMarkerInit, this));
  }
  std::mutex mutex;
  ptz_action_server::PtzState state;
  bool has_state = false;
  std::vector<ptz_action_server::PtzGoal> velocity_goals;
  int cancels = 0;
  std::vector<std::string> preset_goals;
  std::vector<ptz_action_server::PtzGoal> absolute_goals;
  std::optional<ptz_action_server::panel::Aim> marker_aim;  ///< the aim marker's latest pose

private:
  void onAbsolute(const ptz_action_server::PtzActionGoal& message)
  {
    std::lock_guard<std::mutex> lock(mutex);
    absolute_goals.push_back(message.goal);
  }
  void onMarkerInit(const visualization_msgs::InteractiveMarkerInit& init)
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& marker : init.markers)
    {
      const geometry_msgs::Quaternion& q = marker.pose.orientation;
      marker_aim = ptz_action_server::panel::aimOfOrientation({ q.x, q.y, q.z, q.w });
    }
  }
  void onMarker(const visualization_msgs::InteractiveMarkerUpdate& update)
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto take = [this](const geometry_msgs::Quaternion& q) {
      marker_aim = ptz_action_server::panel::aimOfOrientation({ q.x, q.y, q.z, q.w });
    };
    for (const auto& marker : update.markers)
    {
      take(marker.pose.orientation);
    }
    for (const auto& pose : update.poses)
    {
      take(pose.pose.orientation);
    }
  }
  void onState(const ptz_action_server::PtzState& message)
  {
    std::lock_guard<std::mutex> lock(mutex);
    state = message;
    has_state = true;
  }
  void onVelocity(const ptz_action_server::PtzActionGoal& message)
  {
    std::lock_guard<std::mutex> lock(mutex);
    velocity_goals.push_back(message.goal);
  }
  void onCancel(const actionlib_msgs::GoalID&)
  {
    std::lock_guard<std::mutex> lock(mutex);
    ++cancels;
  }
  void onPreset(const ptz_action_server::PtzPresetActionGoal& message)
  {
    std::lock_guard<std::mutex> lock(mutex);
    preset_goals.push_back(message.goal.name);
  }
  std::vector<ros::Subscriber> subscribers_;
};

class PanelTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    if (!g_no_display.empty())
    {
      GTEST_SKIP() << "no X display for the panel: " << g_no_display;
    }
    // As rviz loads it: by its class name, through the package's rviz plugin export.
    loader_ = std::make_unique<pluginlib::ClassLoader<rviz::Panel>>("rviz", "rviz::Panel");
    panel_.reset(loader_->createUnmanagedInstance("ptz_action_server/PtzPanel"));
    ASSERT_NE(dynamic_cast<ptz_action_server::panel::PtzPanel*>(panel_.get()), nullptr);
    panel_->resize(360, 800);
    panel_->show();
  }
  void TearDown() override
  {
    panel_.reset();
  }

  ptz_action_server::panel::PtzPanel* panel() const
  {
    return static_cast<ptz_action_server::panel::PtzPanel*>(panel_.get());
  }
  template <typename T>
  T* child(const char* name) const
  {
    T* widget = panel_->findChild<T*>(name);
    EXPECT_NE(widget, nullptr) << name;
    return widget;
  }
  /// Runs the Qt event loop until `done` holds or WAIT passes.
  bool waitFor(const std::function<bool()>& done, double seconds = WAIT)
  {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline)
    {
      QApplication::processEvents();
      panel()->refresh();
      if (done())
      {
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return done();
  }
  std::string text(const char* label) const
  {
    QLabel* widget = child<QLabel>(label);
    return widget == nullptr ? "" : widget->text().toStdString();
  }
  bool enabled(const char* name) const
  {
    QWidget* widget = child<QWidget>(name);
    return widget != nullptr && widget->isEnabled();
  }

  Observer observer_;
  std::unique_ptr<pluginlib::ClassLoader<rviz::Panel>> loader_;
  std::unique_ptr<rviz::Panel> panel_;
};

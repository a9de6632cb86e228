// The panel's image view against the sim node's picture, under Xvfb (main() is test_ptz_panel.cpp's): a marker the
// simulated camera draws at a known direction is found by colour in the image the view shows, clicked and boxed with
// QTest; the test checks the move_ptz/pixel goals the node received (the pixel, the box, the header of the image shown)
// and that the camera then centred the marker (and zoomed), with the aim drawn while it moved.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QMouseEvent>
#include <QtTest/QTest>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <actionlib_msgs/GoalStatus.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/master.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "panel_test.h"
#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzPixelActionGoal.h"
#include "ptz_action_server/PtzPixelActionResult.h"
#include "ptz_action_server/panel/image_frame.h"
#include "ptz_action_server/panel/image_view.h"

namespace
{
using ptz_action_server::panel::ImageFrame;
using ptz_action_server::panel::ImageView;
using ptz_action_server::panel::Letterbox;
using ptz_action_server::panel::Pixel;
using ptz_action_server::panel::WidgetPoint;

// ptz_panel.test lists this frame first: the camera draws it magenta, 100 m away in the direction MARKER_PAN,
// MARKER_TILT from the tilt axis (0.12 m above the base).
const char* const MARKER = "panel_image_marker";
constexpr double MARKER_PAN = 0.25;  // rad, right
constexpr double MARKER_TILT = 0.1;  // rad, up
constexpr double CENTRED = 3.0;      // image px, beside the click's own rounding to a widget pixel
constexpr double CENTRE_U = 319.5;   // the sim's 640 x 360 picture's centre
constexpr double CENTRE_V = 179.5;

/// The marker's centroid in `frame`; false when fewer than 20 of its pixels are in view or it touches an edge.
bool markerIn(const ImageFrame& frame, double& u, double& v)
{
  double sum_u = 0.0, sum_v = 0.0;
  int count = 0;
  for (int row = 0; row < frame.height; ++row)
  {
    for (int column = 0; column < frame.width; ++column)
    {
      const std::uint8_t* p = frame.pixel(column, row);
      if (p[0] > 200 && p[1] < 80 && p[2] > 200)
      {
        if (row == 0 || column == 0 || row == frame.height - 1 || column == frame.width - 1)
        {
          return false;
        }
        sum_u += column;
        sum_v += row;
        ++count;
      }
    }
  }
  u = count > 0 ? sum_u / count : 0.0;
  v = count > 0 ? sum_v / count : 0.0;
  return count >= 20;
}

/// The pixel goals the node received and how they ended.
class PixelGoals
{
public:
  PixelGoals()
  {
    ros::NodeHandle node("/ptz");
    goals_ = node.subscribe("move_ptz/pixel/goal", 10, &PixelGoals::onGoal, this);
    results_ = node.subscribe("move_ptz/pixel/result", 10, &PixelGoals::onResult, this);
  }
  std::mutex mutex;
  std::vector<ptz_action_server::PtzPixelActionGoal> goals;
  std::vector<std::pair<std::string, int>> results;  ///< goal id, status
  /// The status the goal `id` ended with, or -1.
  int ended(const std::string& id)
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [goal, status] : results)
    {
      if (goal == id)
      {
        return status;
      }
    }
    return -1;
  }

private:
  void onGoal(const ptz_action_server::PtzPixelActionGoal& goal)
  {
    std::lock_guard<std::mutex> lock(mutex);
    goals.push_back(goal);
  }
  void onResult(const ptz_action_server::PtzPixelActionResult& result)
  {
    std::lock_guard<std::mutex> lock(mutex);
    results.emplace_back(result.status.goal_id.id, result.status.status);
  }
  ros::Subscriber goals_;
  ros::Subscriber results_;
};

/// Whether this process subscribes to `topic`, as the master has it.
bool subscribed(const std::string& topic)
{
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", request, response, payload, false))
  {
    return false;
  }
  XmlRpc::XmlRpcValue& subscribers = payload[1];
  for (int i = 0; i < subscribers.size(); ++i)
  {
    if (static_cast<std::string>(subscribers[i][0]) != topic)
    {
      continue;
    }
    for (int j = 0; j < subscribers[i][1].size(); ++j)
    {
      if (static_cast<std::string>(subscribers[i][1][j]) == ros::this_node::getName())
      {
        return true;
      }
    }
  }
  return false;
}

class PanelImageTest : public PanelTest
{
protected:
  void SetUp() override
  {
    PanelTest::SetUp();
    if (IsSkipped())
    {
      return;
    }
    panel_->resize(480, 1000);
    static tf2_ros::StaticTransformBroadcaster broadcaster;
    geometry_msgs::TransformStamped frame;
    frame.header.frame_id = "ptz_base_link";
    frame.header.stamp = ros::Time::now();
    frame.child_frame_id = MARKER;
    frame.transform.translation.x = 100.0 * std::cos(MARKER_TILT) * std::cos(MARKER_PAN);
    frame.transform.translation.y = -100.0 * std::cos(MARKER_TILT) * std::sin(MARKER_PAN);
    frame.transform.translation.z = 0.12 + 100.0 * std::sin(MARKER_TILT);
    frame.transform.rotation.w = 1.0;
    broadcaster.sendTransform(frame);
    view_ = child<ImageView>("image_view");
    ASSERT_NE(view_, nullptr);
    // Each case starts from the same pose, zoom 1.
    actionlib::SimpleActionClient<ptz_action_server::PtzAction> home("/ptz/move_ptz/position_abs", true);
    ASSERT_TRUE(home.waitForServer(ros::Duration(WAIT)));
    ptz_action_server::PtzGoal goal;
    goal.zoom = 1.0f;
    ASSERT_EQ(home.sendGoalAndWait(goal, ros::Duration(WAIT)).state_, actionlib::SimpleClientGoalState::SUCCEEDED);
    home_time_ = ros::Time::now().toSec();
  }

  /// Waits for the view to show an image taken after `after` (ROS time, s) with the marker in it.
  std::shared_ptr<const ImageFrame> markerShown(double after, double& u, double& v)
  {
    std::shared_ptr<const ImageFrame> shown;
    waitFor([&] {
      shown = view_->frame();
      return shown && shown->stamp() > after && markerIn(*shown, u, v);
    });
    return shown && shown->stamp() > after && markerIn(*shown, u, v) ? shown : nullptr;
  }

  /// The newest pixel goal once there are more than `before`.
  std::optional<ptz_action_server::PtzPixelActionGoal> nextGoal(std::size_t before)
  {
    std::optional<ptz_action_server::PtzPixelActionGoal> goal;
    waitFor([&] {
      std::lock_guard<std::mutex> lock(goals_.mutex);
      if (goals_.goals.size() > before)
      {
        goal = goals_.goals.back();
      }
      return goal.has_value();
    });
    return goal;
  }

  /// Runs the panel until the goal `id` ends; true if the view drew the aim (a box when `box`) while it ran.
  bool drawnUntilEnded(const std::string& id, bool box, int& status)
  {
    bool drawn = false;
    waitFor([&] {
      const auto aim = view_->aimDrawn();
      drawn = drawn || (aim && aim->box == box);
      status = goals_.ended(id);
      return status >= 0;
    });
    return drawn;
  }

  static QPoint widgetPoint(const Letterbox& box, const Pixel& pixel)
  {
    const WidgetPoint at = ptz_action_server::panel::widgetPointOf(box, pixel);
    return { static_cast<int>(std::lround(at.x)), static_cast<int>(std::lround(at.y)) };
  }

  PixelGoals goals_;
  ImageView* view_ = nullptr;
  double home_time_ = 0.0;
};

TEST_F(PanelImageTest, AClickCentresThePixelOfTheImageShown)
{
  double u = 0.0, v = 0.0;
  const std::shared_ptr<const ImageFrame> shown = markerShown(home_time_, u, v);
  ASSERT_NE(shown, nullptr) << "no image with the marker in the view: " << text("banner");
  ASSERT_GT(std::hypot(u - CENTRE_U, v - CENTRE_V), 50.0) << "the marker must start away from the centre";
  ASSERT_TRUE(waitFor([&] { return view_->cursor().shape() == Qt::CrossCursor; })) << "the view does not aim";
  // Where the image lies now: the panel's layout may have changed while events ran, none run until the click.
  const Letterbox box = view_->layout();
  ASSERT_GT(box.scale, 0.3) << "the view is too small to click in";
  std::size_t before = 0;
  {
    std::lock_guard<std::mutex> lock(goals_.mutex);
    before = goals_.goals.size();
  }
  const std::shared_ptr<const ImageFrame> clicked = view_->frame();  // no events run until the click
  QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier, widgetPoint(box, { u, v }));

  const auto goal = nextGoal(before);
  ASSERT_TRUE(goal) << "no move_ptz/pixel goal";
  // The image shown when clicked: its header and size; the marker's pixel, to the widget pixel clicked.
  EXPECT_EQ(goal->goal.image_header.stamp.sec, clicked->stamp_sec);
  EXPECT_EQ(goal->goal.image_header.stamp.nsec, clicked->stamp_nsec);
  EXPECT_EQ(goal->goal.image_header.frame_id, clicked->frame_id);
  EXPECT_EQ(goal->goal.image_width, 640u);
  EXPECT_EQ(goal->goal.image_height, 360u);
  EXPECT_NEAR(goal->goal.u, u, 0.5 / box.scale + 1e-6);
  EXPECT_NEAR(goal->goal.v, v, 0.5 / box.scale + 1e-6);
  EXPECT_EQ(goal->goal.box_width, 0.0);
  EXPECT_EQ(goal->goal.box_height, 0.0);

  int status = -1;
  EXPECT_TRUE(drawnUntilEnded(goal->goal_id.id, false, status)) << "the aim was not drawn while the camera moved";
  ASSERT_EQ(status, actionlib_msgs::GoalStatus::SUCCEEDED);
  double cu = 0.0, cv = 0.0;
  ASSERT_NE(markerShown(ros::Time::now().toSec(), cu, cv), nullptr) << "the marker left the picture";
  EXPECT_LE(std::hypot(cu - CENTRE_U, cv - CENTRE_V), CENTRED + 0.5 / box.scale)
      << "marker at (" << cu << ", " << cv << ")";
}

TEST_F(PanelImageTest, ADraggedBoxCentresAndZooms)
{
  double u = 0.0, v = 0.0;
  ASSERT_NE(markerShown(home_time_, u, v), nullptr) << "no image with the marker in the view";
  ASSERT_TRUE(waitFor([&] { return view_->cursor().shape() == Qt::CrossCursor; })) << "the view does not aim";
  std::size_t before = 0;
  {
    std::lock_guard<std::mutex> lock(goals_.mutex);
    before = goals_.goals.size();
  }
  const Letterbox box = view_->layout();  // as it lies now: no events run until the release
  const QPoint from = widgetPoint(box, { u - 40.0, v - 25.0 });
  const QPoint to = widgetPoint(box, { u + 40.0, v + 25.0 });
  const std::shared_ptr<const ImageFrame> pressed = view_->frame();
  QTest::mousePress(view_, Qt::LeftButton, Qt::NoModifier, from);
  // QTest::mouseMove moves the pointer only: the drag's move as Qt delivers it with the button held.
  QMouseEvent move(QEvent::MouseMove, to, view_->mapToGlobal(to), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(view_, &move);
  QTest::mouseRelease(view_, Qt::LeftButton, Qt::NoModifier, to);

  const auto goal = nextGoal(before);
  ASSERT_TRUE(goal) << "no move_ptz/pixel goal";
  EXPECT_EQ(goal->goal.image_header.stamp.sec, pressed->stamp_sec) << "the image shown when the button went down";
  EXPECT_EQ(goal->goal.image_header.stamp.nsec, pressed->stamp_nsec);
  EXPECT_NEAR(goal->goal.box_width, (to.x() - from.x()) / box.scale, 1e-6);
  EXPECT_NEAR(goal->goal.box_height, (to.y() - from.y()) / box.scale, 1e-6);
  EXPECT_NEAR(goal->goal.box_width, 80.0, 1.0 / box.scale + 1e-6);
  EXPECT_NEAR(goal->goal.u, u, 0.5 / box.scale + 1e-6);
  EXPECT_NEAR(goal->goal.v, v, 0.5 / box.scale + 1e-6);

  int status = -1;
  EXPECT_TRUE(drawnUntilEnded(goal->goal_id.id, true, status)) << "the box was not drawn while the camera moved";
  ASSERT_EQ(status, actionlib_msgs::GoalStatus::SUCCEEDED);
  double zoom = 0.0;
  {
    std::lock_guard<std::mutex> lock(observer_.mutex);
    zoom = observer_.state.zoom;
  }
  EXPECT_GT(zoom, 4.0) << "an 80 x 50 px box of 640 x 360 zooms about 7 X";
  double cu = 0.0, cv = 0.0;
  ASSERT_NE(markerShown(ros::Time::now().toSec(), cu, cv), nullptr) << "the marker left the picture";
  // The error of the centre clicked, in pixels of the picture at 1 X, grows with the zoom.
  EXPECT_LE(std::hypot(cu - CENTRE_U, cv - CENTRE_V) / zoom, CENTRED + 0.5 / box.scale)
      << "marker at (" << cu << ", " << cv << ") at " << zoom << " X";
}

TEST_F(PanelImageTest, SubscribesOnlyWhileTheViewIsShown)
{
  QCheckBox* on = child<QCheckBox>("image_on");
  ASSERT_NE(on, nullptr);
  const std::string topic = "/ptz/image_raw";
  ASSERT_TRUE(waitFor([&] { return subscribed(topic) && view_->frame() != nullptr; }));
  on->setChecked(false);
  EXPECT_TRUE(waitFor([&] { return !subscribed(topic); })) << "still subscribed with the view off";
  EXPECT_FALSE(view_->isVisible());
  on->setChecked(true);
  EXPECT_TRUE(waitFor([&] { return subscribed(topic) && view_->frame() != nullptr; }));
  panel_->hide();  // a closed panel (its dock hidden) shows nothing either
  EXPECT_TRUE(waitFor([&] { return !subscribed(topic); })) << "still subscribed with the panel hidden";
  panel_->show();
  EXPECT_TRUE(waitFor([&] { return subscribed(topic); }));
}

}  // namespace

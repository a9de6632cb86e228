/**
 * \file
 * \brief rostest client, field of view (field_of_view.test): the field_of_view topic and the zoomed camera_info.
 */
#include <set>

#include <sensor_msgs/CameraInfo.h>

#include "node_test.h"
#include "ptz_action_server/FieldOfView.h"

namespace
{
// As field_of_view.test sets them.
constexpr double WIDE_HORIZONTAL = 1.0;
constexpr double WIDE_VERTICAL = 0.6;
constexpr double CALIBRATION_ZOOM = 2.0;

/// The lens model: an ideal zoom lens, focal length proportional to X.
double angleAt(double wide_end, double zoom)
{
  return 2.0 * std::atan(std::tan(wide_end / 2.0) / zoom);
}

/// Records field_of_view messages, joint_states stamps and zoomed camera_info messages.
class ViewObserver
{
public:
  ViewObserver()
  {
    ros::NodeHandle node_handle;
    field_of_view_subscriber_ = node_handle.subscribe("field_of_view", 100, &ViewObserver::onFieldOfView, this);
    joints_subscriber_ = node_handle.subscribe("joint_states", 100, &ViewObserver::onJoints, this);
    zoomed_subscriber_ = node_handle.subscribe("/test_camera/camera_info_zoomed", 100, &ViewObserver::onZoomed, this);
  }

  /// Waits for a field_of_view message stamped as some joint_states message, and returns it.
  bool waitForMatchingFieldOfView(ptz_action_server::FieldOfView& matched)
  {
    return waitUntil(GOAL_WAIT, [&] {
      for (auto it = fields_.rbegin(); it != fields_.rend(); ++it)
      {
        if (joint_stamps_.count(it->header.stamp) > 0)
        {
          matched = *it;
          return true;
        }
      }
      return false;
    });
  }

  /// Waits a moment (0.2 s) for a zoomed camera_info stamped \p stamp.
  bool waitForZoomedBriefly(const ros::Time& stamp, sensor_msgs::CameraInfo& zoomed)
  {
    return waitUntil(0.2, [&] {
      for (const auto& info : zoomed_)
      {
        if (info.header.stamp == stamp)
        {
          zoomed = info;
          return true;
        }
      }
      return false;
    });
  }

private:
  bool waitUntil(double timeout, const std::function<bool()>& found)
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::WallTime::now() < deadline)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (found())
        {
          return true;
        }
      }
      ros::WallDuration(0.02).sleep();
    }
    return false;
  }
  void onFieldOfView(const ptz_action_server::FieldOfView::ConstPtr& message)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    fields_.push_back(*message);
  }
  void onJoints(const sensor_msgs::JointState::ConstPtr& message)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    joint_stamps_.insert(message->header.stamp);
  }
  void onZoomed(const sensor_msgs::CameraInfo::ConstPtr& message)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    zoomed_.push_back(*message);
  }

  ros::Subscriber field_of_view_subscriber_;
  ros::Subscriber joints_subscriber_;
  ros::Subscriber zoomed_subscriber_;
  std::mutex mutex_;
  std::vector<ptz_action_server::FieldOfView> fields_;
  std::set<ros::Time> joint_stamps_;
  std::vector<sensor_msgs::CameraInfo> zoomed_;
};

/// A 640 x 480 calibration, as an image driver would publish it.
sensor_msgs::CameraInfo calibration(const ros::Time& stamp)
{
  sensor_msgs::CameraInfo info;
  info.header.stamp = stamp;
  info.header.frame_id = "ptz_camera_optical_frame";
  info.width = 640;
  info.height = 480;
  info.distortion_model = "plumb_bob";
  info.D = { -0.1, 0.01, 0.0, 0.0, 0.0 };
  info.K = { 500.0, 0.0, 321.0, 0.0, 505.0, 239.0, 0.0, 0.0, 1.0 };
  info.R = { 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 };
  info.P = { 498.0, 0.0, 322.0, 0.0, 0.0, 503.0, 240.0, 0.0, 0.0, 0.0, 1.0, 0.0 };
  return info;
}

class FieldOfViewNodeTest : public NodeTest
{
};

TEST_F(FieldOfViewNodeTest, FieldOfViewFollowsTheZoomWithTheJointStatesStamp)
{
  ViewObserver view;
  ASSERT_EQ(moveTo(0.0, 0.0, 4.0), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
  ptz_action_server::FieldOfView field_of_view;
  ASSERT_TRUE(view.waitForMatchingFieldOfView(field_of_view)) << "no field_of_view stamped as a joint_states";
  ASSERT_TRUE(view.waitForMatchingFieldOfView(field_of_view));
  EXPECT_EQ(field_of_view.header.frame_id, "ptz_camera_link");
  EXPECT_NEAR(field_of_view.zoom, 4.0, 0.05);
  EXPECT_NEAR(field_of_view.horizontal, angleAt(WIDE_HORIZONTAL, field_of_view.zoom), 1e-9);
  EXPECT_NEAR(field_of_view.vertical, angleAt(WIDE_VERTICAL, field_of_view.zoom), 1e-9);
  EXPECT_LT(field_of_view.horizontal, WIDE_HORIZONTAL / 2.0 * 1.1);  // really narrower than the wide end
}

TEST_F(FieldOfViewNodeTest, CameraInfoIsRescaledForTheZoomWithItsHeaderKept)
{
  ViewObserver view;
  ros::Publisher camera_info = ros::NodeHandle().advertise<sensor_msgs::CameraInfo>("/test_camera/camera_info", 10);
  for (double zoom : { 6.0, 2.0, 1.0 })
  {
    ASSERT_EQ(moveTo(0.0, 0.0, zoom), State::SUCCEEDED) << absolute_->getState().getText();
    ASSERT_TRUE(observer_->waitTicks(2));
    const double reported_zoom = observer_->latest().zoom;
    EXPECT_NEAR(reported_zoom, zoom, 0.05);

    // The node may not have connected yet: publish until the zoomed copy of one stamp comes back.
    sensor_msgs::CameraInfo zoomed;
    const sensor_msgs::CameraInfo original = calibration(ros::Time(1000.0 + zoom));
    bool received = false;
    for (int attempt = 0; attempt < 100 && !received; ++attempt)
    {
      camera_info.publish(original);
      received = view.waitForZoomedBriefly(original.header.stamp, zoomed);
    }
    ASSERT_TRUE(received) << "no camera_info_zoomed at zoom " << zoom;
    EXPECT_EQ(zoomed.header.stamp, original.header.stamp);
    EXPECT_EQ(zoomed.header.frame_id, original.header.frame_id);
    EXPECT_EQ(zoomed.width, original.width);
    EXPECT_EQ(zoomed.D, original.D);

    const double scale_x = std::tan(angleAt(WIDE_HORIZONTAL, CALIBRATION_ZOOM) / 2.0) /
                           std::tan(angleAt(WIDE_HORIZONTAL, reported_zoom) / 2.0);
    const double scale_y = std::tan(angleAt(WIDE_VERTICAL, CALIBRATION_ZOOM) / 2.0) /
                           std::tan(angleAt(WIDE_VERTICAL, reported_zoom) / 2.0);
    EXPECT_NEAR(zoomed.K[0], 500.0 * scale_x, 1e-3) << "zoom " << reported_zoom;
    EXPECT_NEAR(zoomed.K[4], 505.0 * scale_y, 1e-3);
    EXPECT_NEAR(zoomed.P[0], 498.0 * scale_x, 1e-3);
    EXPECT_NEAR(zoomed.P[5], 503.0 * scale_y, 1e-3);
    EXPECT_DOUBLE_EQ(zoomed.K[2], 321.0);  // the principal point stays
    EXPECT_DOUBLE_EQ(zoomed.K[5], 239.0);
    EXPECT_DOUBLE_EQ(zoomed.P[2], 322.0);
    EXPECT_DOUBLE_EQ(zoomed.P[6], 240.0);
    EXPECT_DOUBLE_EQ(zoomed.K[8], 1.0);
    EXPECT_DOUBLE_EQ(zoomed.P[10], 1.0);
  }
}

}  // namespace

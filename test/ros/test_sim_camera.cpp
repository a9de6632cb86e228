/**
 * \file
 * \brief rostest client, the simulated camera's picture (sim_camera.test): image_raw and camera_info as a user sees
 * them, and a listed frame's marker where tf and camera_info say it is.
 */
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "../core/wait_until.h"
#include "node_test.h"
#include "ptz_action_server/FieldOfView.h"

namespace
{
// As sim_camera.test lists them, with the colours doc/backends/sim.md gives the first two frames.
const char* const TARGET = "sim_camera_target";
const char* const OTHER = "sim_camera_other";
constexpr std::uint8_t MAGENTA[3] = { 255, 0, 255 };
constexpr std::uint8_t YELLOW[3] = { 255, 255, 0 };
constexpr int WIDTH = 640;  // config/sim.yaml's
constexpr int HEIGHT = 360;
constexpr double PIXEL_TOLERANCE = 2.0;

/// Every image's stamp, the latest image, every camera_info and the latest field_of_view.
class CameraObserver
{
public:
  CameraObserver()
  {
    ros::NodeHandle node_handle;
    image_subscriber_ = node_handle.subscribe("image_raw", 5, &CameraObserver::onImage, this);
    info_subscriber_ = node_handle.subscribe("camera_info", 5, &CameraObserver::onInfo, this);
    view_subscriber_ = node_handle.subscribe("field_of_view", 5, &CameraObserver::onView, this);
  }

  /// Waits for an image stamped after \p after, and its camera_info (same stamp); false after the deadline.
  bool waitForImage(const ros::Time& after, sensor_msgs::Image& image, sensor_msgs::CameraInfo& info)
  {
    return ptz_action_server::waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          if (image_.header.stamp <= after)
          {
            return false;
          }
          for (const sensor_msgs::CameraInfo& candidate : infos_)
          {
            if (candidate.header.stamp == image_.header.stamp)
            {
              image = image_;
              info = candidate;
              return true;
            }
          }
          return false;
        },
        GOAL_WAIT);
  }
  std::vector<ros::Time> stamps() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return stamps_;
  }
  bool waitForView(ptz_action_server::FieldOfView& view)
  {
    return ptz_action_server::waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          view = view_;
          return view_.horizontal > 0.0;
        },
        GOAL_WAIT);
  }

private:
  void onImage(const sensor_msgs::Image::ConstPtr& image)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    image_ = *image;
    stamps_.push_back(image->header.stamp);
  }
  void onInfo(const sensor_msgs::CameraInfo::ConstPtr& info)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    infos_.push_back(*info);
    if (infos_.size() > 20)
    {
      infos_.erase(infos_.begin());
    }
  }
  void onView(const ptz_action_server::FieldOfView::ConstPtr& view)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    view_ = *view;
  }

  mutable std::mutex mutex_;
  sensor_msgs::Image image_;
  std::vector<ros::Time> stamps_;
  std::vector<sensor_msgs::CameraInfo> infos_;
  ptz_action_server::FieldOfView view_;
  ros::Subscriber image_subscriber_;
  ros::Subscriber info_subscriber_;
  ros::Subscriber view_subscriber_;
};

/// The centroid of \p image's pixels of exactly \p colour; false if there are none.
bool centroidOf(const sensor_msgs::Image& image, const std::uint8_t (&colour)[3], double& u, double& v)
{
  double sum_u = 0.0;
  double sum_v = 0.0;
  int pixels = 0;
  for (std::uint32_t row = 0; row < image.height; ++row)
  {
    const std::uint8_t* pixel = &image.data[row * image.step];
    for (std::uint32_t column = 0; column < image.width; ++column, pixel += 3)
    {
      if (pixel[0] == colour[0] && pixel[1] == colour[1] && pixel[2] == colour[2])
      {
        sum_u += column;
        sum_v += row;
        ++pixels;
      }
    }
  }
  if (pixels == 0)
  {
    return false;
  }
  u = sum_u / pixels;
  v = sum_v / pixels;
  return true;
}

class SimCameraTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    if (observer_ == nullptr)  // not yet set up by NodeTest's own cases in this run
    {
      NodeTest::SetUpTestSuite();
    }
    camera_ = new CameraObserver();
    static tf2_ros::StaticTransformBroadcaster broadcaster;
    std::vector<geometry_msgs::TransformStamped> frames(2);
    const double positions[2][3] = { { 3.0, -1.2, 0.8 }, { 4.0, 0.5, -0.4 } };
    const char* const names[2] = { TARGET, OTHER };
    for (int index = 0; index < 2; ++index)
    {
      frames[index].header.frame_id = "ptz_base_link";
      frames[index].header.stamp = ros::Time::now();
      frames[index].child_frame_id = names[index];
      frames[index].transform.translation.x = positions[index][0];
      frames[index].transform.translation.y = positions[index][1];
      frames[index].transform.translation.z = positions[index][2];
      frames[index].transform.rotation.w = 1.0;
    }
    broadcaster.sendTransform(frames);
  }

  /// Moves to the pose and returns an image (and its camera_info) taken after the goal succeeded.
  void lookAt(double pan, double tilt, double zoom, sensor_msgs::Image& image, sensor_msgs::CameraInfo& info)
  {
    ASSERT_EQ(moveTo(pan, tilt, zoom), State::SUCCEEDED);
    const ros::Time arrived = ros::Time::now();
    ASSERT_TRUE(camera_->waitForImage(arrived, image, info)) << "no image after the goal";
  }

  /// Where camera_info and tf put \p frame in the image stamped \p stamp; false if tf does not know.
  static bool projected(const std::string& frame, const sensor_msgs::CameraInfo& info, double& u, double& v)
  {
    if (!tf_buffer_->canTransform(info.header.frame_id, frame, info.header.stamp, ros::Duration(GOAL_WAIT)))
    {
      return false;
    }
    const auto transform = tf_buffer_->lookupTransform(info.header.frame_id, frame, info.header.stamp);
    const auto& point = transform.transform.translation;
    if (point.z <= 0.0)
    {
      return false;
    }
    u = info.K[0] * point.x / point.z + info.K[2];
    v = info.K[4] * point.y / point.z + info.K[5];
    return true;
  }

  static inline CameraObserver* camera_ = nullptr;
};

TEST_F(SimCameraTest, ImagesFollowTheLensAndTheirStampsAdvance)
{
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  lookAt(0.2, 0.1, zoomOr1(3.0), image, info);
  EXPECT_EQ(image.width, static_cast<std::uint32_t>(WIDTH));
  EXPECT_EQ(image.height, static_cast<std::uint32_t>(HEIGHT));
  EXPECT_EQ(image.encoding, "rgb8");
  EXPECT_EQ(image.step, image.width * 3);
  EXPECT_EQ(image.data.size(), static_cast<std::size_t>(image.step) * image.height);
  EXPECT_EQ(image.header.frame_id, "ptz_camera_optical_frame");
  EXPECT_EQ(info.header.frame_id, image.header.frame_id);
  EXPECT_EQ(info.width, image.width);
  EXPECT_EQ(info.height, image.height);

  // K from the field of view at the zoom the node reports: the angles span the image's outer edges.
  ptz_action_server::FieldOfView view;
  ASSERT_TRUE(camera_->waitForView(view));
  EXPECT_NEAR(view.zoom, zoomOr1(3.0), 0.05);
  EXPECT_NEAR(info.K[0], 0.5 * WIDTH / std::tan(view.horizontal / 2.0), 0.5);
  EXPECT_NEAR(info.K[4], 0.5 * HEIGHT / std::tan(view.vertical / 2.0), 0.5);
  EXPECT_DOUBLE_EQ(info.K[2], (WIDTH - 1) / 2.0);
  EXPECT_DOUBLE_EQ(info.K[5], (HEIGHT - 1) / 2.0);
  EXPECT_DOUBLE_EQ(info.P[0], info.K[0]);
  EXPECT_DOUBLE_EQ(info.P[5], info.K[4]);

  // The rate: images keep coming, each stamped later than the one before.
  const std::size_t before = camera_->stamps().size();
  ASSERT_TRUE(ptz_action_server::waitUntil([&] { return camera_->stamps().size() >= before + 5; }, GOAL_WAIT));
  const std::vector<ros::Time> stamps = camera_->stamps();
  for (std::size_t index = before + 1; index < stamps.size(); ++index)
  {
    EXPECT_GT(stamps[index], stamps[index - 1]);
  }
}

TEST_F(SimCameraTest, AListedFrameIsDrawnWhereTfAndCameraInfoPutIt)
{
  // Aimed a little beside the target (and zoomed, if the device can), so it is drawn off the image's centre.
  const double target_pan = std::atan2(1.2, 3.0);
  const double target_tilt = std::atan2(0.8 - 0.12, std::hypot(3.0, 1.2));
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  lookAt(target_pan - 0.08, target_tilt + 0.08, zoomOr1(2.0), image, info);
  double expected_u = 0.0;
  double expected_v = 0.0;
  ASSERT_TRUE(projected(TARGET, info, expected_u, expected_v));
  ASSERT_GT(expected_u, 20.0);
  ASSERT_LT(expected_u, WIDTH - 20.0);
  ASSERT_GT(expected_v, 20.0);
  ASSERT_LT(expected_v, HEIGHT - 20.0);
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(centroidOf(image, MAGENTA, u, v)) << "no magenta marker for " << TARGET;
  EXPECT_NEAR(u, expected_u, PIXEL_TOLERANCE);
  EXPECT_NEAR(v, expected_v, PIXEL_TOLERANCE);
  EXPECT_GT(u, WIDTH / 2.0 + 20.0) << "the camera looks left of the target: it is right of the centre";
  EXPECT_GT(v, HEIGHT / 2.0 + 20.0) << "the camera looks above the target: it is below the centre";

  // The second frame in the list, in the second colour.
  lookAt(std::atan2(-0.5, 4.0) + 0.05, std::atan2(-0.4 - 0.12, std::hypot(4.0, 0.5)), zoomOr1(1.0), image, info);
  ASSERT_TRUE(projected(OTHER, info, expected_u, expected_v));
  ASSERT_TRUE(centroidOf(image, YELLOW, u, v)) << "no yellow marker for " << OTHER;
  EXPECT_NEAR(u, expected_u, PIXEL_TOLERANCE);
  EXPECT_NEAR(v, expected_v, PIXEL_TOLERANCE);
}

TEST_F(SimCameraTest, PanningRightMovesTheMarkerLeft)
{
  const double target_pan = std::atan2(1.2, 3.0);
  const double target_tilt = std::atan2(0.8 - 0.12, std::hypot(3.0, 1.2));
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  double last_u = INFINITY;
  for (const double offset : { -0.1, 0.0, 0.1 })
  {
    lookAt(target_pan + offset, target_tilt, zoomOr1(1.0), image, info);
    double u = 0.0;
    double v = 0.0;
    ASSERT_TRUE(centroidOf(image, MAGENTA, u, v)) << "pan offset " << offset;
    // 0.1 rad at 60 degrees across 640 px is about 55 px.
    EXPECT_LT(u, last_u - 40.0) << "pan offset " << offset;
    EXPECT_NEAR(v, HEIGHT / 2.0, 40.0);
    last_u = u;
  }
}

}  // namespace

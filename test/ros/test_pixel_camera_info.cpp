/**
 * \file
 * \brief rostest client, aiming at pixels of a real camera's image (pixel_camera_info.test): the node has no picture of
 * its own; the client plays an image driver's camera_info (a calibration whose K is not the field of view's) on
 * /test_camera/camera_info, and pixel goals and clicks on /test_camera/image_raw_mouse_left aim along the rays its K
 * gives, carried to the zoom of the image by the field of view.
 */
#include <geometry_msgs/Point.h>
#include <sensor_msgs/CameraInfo.h>

#include "../core/wait_until.h"
#include "node_test.h"
#include "ptz_action_server/PtzPixelAction.h"

namespace pixel_camera_info_test
{
using ptz_action_server::PtzPixelAction;
using ptz_action_server::PtzPixelGoal;
using ptz_action_server::waitUntil;

// The driver's calibration at zoom 1 (pixel_camera_info.test's camera_info_zoom): 1280 x 720, its principal point off
// the centre and its focal lengths not the field of view's (1108.5 px across 60 degrees).
constexpr std::uint32_t WIDTH = 1280;
constexpr std::uint32_t HEIGHT = 720;
constexpr double FX = 1000.0;
constexpr double FY = 990.0;
constexpr double CX = 600.0;
constexpr double CY = 380.0;
constexpr double AIM_TOLERANCE = 0.001;  // rad: the device's 0.000897 rad steps, and float32

/// The pan and tilt that put the optical axis along the ray of pixel (\p u, \p v) of K scaled by \p zoom (an ideal
/// lens: config/sim.yaml's zoom law), seen from the camera at \p pan, \p tilt. The URDF's optical axes all pass
/// through one point, so these are the ray's own angles.
void expectedAim(double u, double v, double zoom, double pan, double tilt, double& aim_pan, double& aim_tilt)
{
  const Eigen::Vector3d optical((u - CX) / (FX * zoom), (v - CY) / (FY * zoom), 1.0);
  // Camera link axes in the base: x forward, y left, z up (the contract's pan turns right, tilt up).
  const Eigen::Vector3d forward(std::cos(tilt) * std::cos(pan), -std::cos(tilt) * std::sin(pan), std::sin(tilt));
  const Eigen::Vector3d left(std::sin(pan), std::cos(pan), 0.0);
  const Eigen::Vector3d up = forward.cross(left);
  const Eigen::Vector3d direction = optical.z() * forward - optical.x() * left - optical.y() * up;
  aim_pan = std::atan2(-direction.y(), direction.x());
  aim_tilt = std::atan2(direction.z(), std::hypot(direction.x(), direction.y()));
}

class PixelCameraInfoTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    if (observer_ == nullptr)  // not yet set up by another suite in this run
    {
      NodeTest::SetUpTestSuite();
    }
    pixel_ = new actionlib::SimpleActionClient<PtzPixelAction>("move_ptz/pixel", true);
    ros::NodeHandle node_handle;
    info_publisher_ =
        new ros::Publisher(node_handle.advertise<sensor_msgs::CameraInfo>("/test_camera/camera_info", 10));
    clicks_ = new ros::Publisher(node_handle.advertise<geometry_msgs::Point>("/test_camera/image_raw_mouse_left", 10));
    // The driver: a camera_info at 10 Hz, stamped with the time its image would have been taken.
    driver_ = new ros::WallTimer(node_handle.createWallTimer(ros::WallDuration(0.1), [](const ros::WallTimerEvent&) {
      sensor_msgs::CameraInfo info;
      info.header.stamp = ros::Time::now();
      info.header.frame_id = "ptz_camera_optical_frame";
      info.width = WIDTH;
      info.height = HEIGHT;
      info.distortion_model = "plumb_bob";
      info.D.assign(5, 0.0);
      info.K = { FX, 0.0, CX, 0.0, FY, CY, 0.0, 0.0, 1.0 };
      info.R = { 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 };
      info.P = { FX, 0.0, CX, 0.0, 0.0, FY, CY, 0.0, 0.0, 0.0, 1.0, 0.0 };
      info_publisher_->publish(info);
      std::lock_guard<std::mutex> lock(mutex_);
      latest_ = info.header;
    }));
  }

  void SetUp() override
  {
    NodeTest::SetUp();
    ASSERT_TRUE(pixel_->waitForServer(ros::Duration(30.0))) << "no move_ptz/pixel";
    // The node has heard the driver: its zoomed copy comes out.
    ASSERT_TRUE(ros::topic::waitForMessage<sensor_msgs::CameraInfo>("/test_camera/camera_info_zoomed",
                                                                    ros::Duration(GOAL_WAIT)));
  }

  /// The header of the driver's first camera_info (its image's) stamped after now: an image of the camera at rest.
  static std_msgs::Header nextImage()
  {
    const ros::Time now = ros::Time::now();
    std_msgs::Header header;
    EXPECT_TRUE(waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          header = latest_;
          return latest_.stamp > now;
        },
        GOAL_WAIT));
    return header;
  }

  /// Waits for the camera to rest at \p pan, \p tilt.
  static bool restsAt(double pan, double tilt)
  {
    return observer_->waitFor(
        [&](const PtzState& state) {
          return state.mode == PtzState::MODE_IDLE && std::abs(state.pan - pan) < TOLERANCE &&
                 std::abs(state.tilt - tilt) < TOLERANCE;
        },
        GOAL_WAIT);
  }

  static inline actionlib::SimpleActionClient<PtzPixelAction>* pixel_ = nullptr;
  static inline ros::Publisher* info_publisher_ = nullptr;
  static inline ros::Publisher* clicks_ = nullptr;
  static inline ros::WallTimer* driver_ = nullptr;
  static inline std::mutex mutex_;
  static inline std_msgs::Header latest_;
};

TEST_F(PixelCameraInfoTest, APixelAimsAlongItsRayOfTheCalibration)
{
  for (const double zoom : { 1.0, zoomOr1(2.0) })
  {
    ASSERT_EQ(moveTo(0.1, 0.05, zoom), State::SUCCEEDED);
    PtzPixelGoal goal;
    goal.image_header = nextImage();
    goal.u = 900.0;
    goal.v = 200.0;  // no size: the calibration's
    pixel_->sendGoal(goal);
    ASSERT_TRUE(pixel_->waitForResult(ros::Duration(GOAL_WAIT)));
    ASSERT_EQ(pixel_->getState(), State::SUCCEEDED) << pixel_->getState().getText();
    double pan = 0.0;
    double tilt = 0.0;
    expectedAim(goal.u, goal.v, zoom, 0.1, 0.05, pan, tilt);
    EXPECT_NEAR(pixel_->getResult()->pan, pan, AIM_TOLERANCE) << "at " << zoom << " X";
    EXPECT_NEAR(pixel_->getResult()->tilt, tilt, AIM_TOLERANCE) << "at " << zoom << " X";
    EXPECT_TRUE(restsAt(pan, tilt)) << "the camera is at pan " << observer_->latest().pan << ", tilt "
                                    << observer_->latest().tilt << " rad, not at the pixel's " << pan << ", " << tilt;
  }
}

TEST_F(PixelCameraInfoTest, AClickOnTheDriversImageAimsAtItsPixel)
{
  ASSERT_EQ(moveTo(-0.2, 0.1, 1.0), State::SUCCEEDED);
  ASSERT_TRUE(waitUntil([] { return clicks_->getNumSubscribers() > 0; }, GOAL_WAIT))
      << "the node does not listen to " << clicks_->getTopic();
  nextImage();                 // the node's latest image shows the camera at rest
  geometry_msgs::Point click;  // rqt_image_view's: whole pixels from the image's top-left outer corner
  click.x = 300.0;
  click.y = 500.0;
  clicks_->publish(click);
  double pan = 0.0;
  double tilt = 0.0;
  expectedAim(click.x - 0.5, click.y - 0.5, 1.0, -0.2, 0.1, pan, tilt);
  EXPECT_TRUE(restsAt(pan, tilt)) << "the camera is at pan " << observer_->latest().pan << ", tilt "
                                  << observer_->latest().tilt << " rad, not at the clicked pixel's " << pan << ", "
                                  << tilt;
}

}  // namespace pixel_camera_info_test

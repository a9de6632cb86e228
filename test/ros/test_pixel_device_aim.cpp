/**
 * \file
 * \brief rostest client, pixel goals the camera aims itself (axis_pixel_aim.test: the node on axis_camera_emulator,
 * ~pixel_aim auto, no field of view): the capabilities say so, a click right of the centre turns the pan by the angle
 * the camera's lens puts it at, a box zooms in by its magnification, the results give where the camera ended, and a
 * click on a picture the camera has left is refused (the node cannot compute it without a field of view).
 */
#include <cmath>

#include "node_test.h"
#include "ptz_action_server/PtzPixelAction.h"

namespace pixel_device_aim_test
{
using ptz_action_server::PtzPixelAction;
using ptz_action_server::PtzPixelGoal;
using PixelClient = actionlib::SimpleActionClient<PtzPixelAction>;

constexpr double DEGREE = M_PI / 180.0;
constexpr double ANGLE = 1e-3;  // rad: the camera reports degrees with four decimals, the result is a float32
constexpr int WIDTH = 640;
constexpr int HEIGHT = 360;
/// axis_camera_emulator's lens at 1X: 60 degrees across; x of the picture at its centre's right is atan(x tan 30 deg).
constexpr double HALF_WIDE = 30.0 * DEGREE;

class AxisPixelAimTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    NodeTest::SetUpTestSuite();
    pixel_ = new PixelClient("move_ptz/pixel", true);
  }

  void SetUp() override
  {
    NodeTest::SetUp();
    ASSERT_TRUE(pixel_->waitForServer(ros::Duration(30.0))) << "no move_ptz/pixel";
  }

  /// Moves there and waits until the camera's reported pose has rested a few ticks: its picture is that pose's.
  void restAt(double pan, double tilt, double zoom)
  {
    ASSERT_EQ(moveTo(pan, tilt, zoom), State::SUCCEEDED) << absolute_->getState().getText();
    ASSERT_TRUE(observer_->waitTicks(3));
  }

  /// A pixel goal on a WIDTH x HEIGHT picture stamped \p stamp; its final state.
  State aimAt(double u, double v, double box_width, double box_height, const ros::Time& stamp)
  {
    PtzPixelGoal goal;
    goal.image_header.stamp = stamp;
    goal.u = u;
    goal.v = v;
    goal.box_width = box_width;
    goal.box_height = box_height;
    goal.image_width = WIDTH;
    goal.image_height = HEIGHT;
    pixel_->sendGoal(goal);
    EXPECT_TRUE(pixel_->waitForResult(ros::Duration(GOAL_WAIT)));
    return pixel_->getState();
  }

  static inline PixelClient* pixel_ = nullptr;
};

TEST_F(AxisPixelAimTest, TheCapabilitiesSayTheCameraAimsItself)
{
  EXPECT_EQ(capabilities_->pixel_aim, "auto: device (VAPIX center, areazoom) on the picture the camera still shows, "
                                      "computed otherwise");
}

TEST_F(AxisPixelAimTest, AClickRightOfTheCentreTurnsThePanByItsAngleInTheLens)
{
  restAt(0.2, 0.0, zoomOr1(1.0));
  const double start = observer_->latest().pan;
  // Half way from the centre to the right edge (pixel 479.5 of 640: the outer edge of the last is 639.5).
  ASSERT_EQ(aimAt(0.75 * WIDTH - 0.5, 0.5 * HEIGHT - 0.5, 0.0, 0.0, ros::Time::now()), State::SUCCEEDED)
      << pixel_->getState().getText();
  EXPECT_NE(pixel_->getState().getText().find("aimed by the device's own command (VAPIX center, areazoom)"),
            std::string::npos)
      << pixel_->getState().getText();
  const double expected = start + std::atan(std::tan(HALF_WIDE) / 2.0);
  EXPECT_NEAR(pixel_->getResult()->pan, expected, ANGLE);
  EXPECT_NEAR(pixel_->getResult()->tilt, 0.0, ANGLE) << "not asked to move: where it stays";
  EXPECT_NEAR(observer_->latest().pan, expected, ANGLE) << "the result is where the camera settled";
}

TEST_F(AxisPixelAimTest, ABoxZoomsInByItsMagnification)
{
  if (!zoomable())
  {
    GTEST_SKIP() << "the camera's zoom takes no positions";
  }
  restAt(0.0, 0.0, 2.0);
  const double expected = 4.0 * observer_->latest().zoom;
  // A quarter of the picture each way: four times closer.
  ASSERT_EQ(aimAt(0.5 * WIDTH - 0.5, 0.5 * HEIGHT - 0.5, WIDTH / 4.0, HEIGHT / 4.0, ros::Time::now()), State::SUCCEEDED)
      << pixel_->getState().getText();
  EXPECT_NEAR(pixel_->getResult()->zoom, expected, 0.1);
  EXPECT_NEAR(pixel_->getResult()->pan, 0.0, ANGLE);
  EXPECT_NEAR(observer_->latest().zoom, expected, 0.1);
}

TEST_F(AxisPixelAimTest, AClickOnAPictureTheCameraHasLeftIsRefusedWithoutAFieldOfView)
{
  restAt(-0.1, 0.0, zoomOr1(1.0));
  const ros::Time then = ros::Time::now();
  restAt(0.3, 0.0, zoomOr1(1.0));
  EXPECT_EQ(aimAt(100.0, 100.0, 0.0, 0.0, then), State::REJECTED);
  const std::string text = pixel_->getState().getText();
  EXPECT_NE(text.find("since the image was taken"), std::string::npos) << text;
  EXPECT_NE(text.find("the node cannot aim from the image's pose"), std::string::npos) << text;
  EXPECT_NEAR(observer_->latest().pan, 0.3, ANGLE) << "nothing moved";
}

}  // namespace pixel_device_aim_test

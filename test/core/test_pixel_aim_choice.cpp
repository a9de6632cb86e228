/**
 * \file
 * \brief Who aims at a pixel (choosePixelAim): the device's own command on the picture the camera still shows, the node
 * on a picture it has left (or when asked), and never the device's command on a picture the camera has left.
 */
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "pixel_aim_test_support.h"
#include "ptz_action_server/core/motion/pixel_aim_choice.h"

using namespace ptz_action_server;
using namespace pixel_aim_test;

namespace
{
constexpr double NOT_KNOWN = std::numeric_limits<double>::quiet_NaN();

class PixelAimChoiceTest : public ::testing::Test
{
protected:
  PixelAimChoiceTest() : lens(FieldOfViewModel::fromWideEnd({ 60.0 * DEGREE, 34.0 * DEGREE }))
  {
    limits.view_centre = true;
    limits.view_box_zoom = true;
    limits.view_command = "VAPIX center, areazoom";
    current.link_up = true;
    current.position = { 0.3, -0.1, 2.0 };
    image.status = PoseLookupStatus::INTERPOLATED;
    image.pose = current.position;
  }

  static PixelGoal click(double u, double v, double box_width = 0.0, double box_height = 0.0)
  {
    PixelGoal goal;
    goal.u = u;
    goal.v = v;
    goal.box_width = box_width;
    goal.box_height = box_height;
    goal.image_width = WIDTH;
    goal.image_height = HEIGHT;
    return goal;
  }

  PixelAimChoice choose(PixelAimWay way, const PixelGoal& goal) const
  {
    return choosePixelAim(way, goal, image, current, camera, limits);
  }

  FieldOfViewModel lens;
  PixelCamera camera;  // no field of view: the node cannot compute
  Capabilities limits = zoomCamera();
  PtzSample current;
  PoseLookup image;
};

TEST_F(PixelAimChoiceTest, TheNamesOfTheWays)
{
  for (PixelAimWay way : { PixelAimWay::AUTO, PixelAimWay::COMPUTED, PixelAimWay::DEVICE })
  {
    PixelAimWay read = way == PixelAimWay::AUTO ? PixelAimWay::DEVICE : PixelAimWay::AUTO;
    ASSERT_TRUE(parsePixelAimWay(pixelAimWayName(way), read)) << pixelAimWayName(way);
    EXPECT_EQ(read, way);
  }
  PixelAimWay way = PixelAimWay::AUTO;
  EXPECT_FALSE(parsePixelAimWay("native", way));
  EXPECT_FALSE(parsePixelAimWay("", way));
}

TEST_F(PixelAimChoiceTest, AutoLeavesThePictureTheCameraStillShowsToTheDevice)
{
  camera.field_of_view = &lens;  // the node could compute: the camera knows its own lens better
  for (const PixelGoal& goal : { click(500.0, 100.0), click(320.0, 180.0, 64.0, 36.0) })
  {
    const PixelAimChoice choice = choose(PixelAimWay::AUTO, goal);
    EXPECT_EQ(choice.error, "");
    EXPECT_TRUE(choice.device);
    EXPECT_NE(choice.note.find("the camera still shows the image's picture"), std::string::npos) << choice.note;
  }
}

TEST_F(PixelAimChoiceTest, AutoComputesOnAPictureTheCameraHasLeft)
{
  camera.field_of_view = &lens;
  current.position[TILT] += 0.05;
  PixelAimChoice choice = choose(PixelAimWay::AUTO, click(500.0, 100.0));
  EXPECT_EQ(choice.error, "");
  EXPECT_FALSE(choice.device);
  current.position[TILT] = image.pose[TILT];
  current.moving = true;  // a frame of a moving camera: the pose history knows where it was
  choice = choose(PixelAimWay::AUTO, click(500.0, 100.0));
  EXPECT_EQ(choice.error, "");
  EXPECT_FALSE(choice.device);
}

TEST_F(PixelAimChoiceTest, AutoLeavesItToTheDeviceWithoutAFieldOfView)
{
  // Pixel (479.5, 89.5) is the point 3/4 across and 1/4 down: its outer edges count, as in camera_info's K.
  const PixelAimChoice choice = choose(PixelAimWay::AUTO, click(479.5, 89.5, 64.0, 90.0));
  ASSERT_EQ(choice.error, "");
  ASSERT_TRUE(choice.device);
  EXPECT_DOUBLE_EQ(choice.target.x, 0.75);
  EXPECT_DOUBLE_EQ(choice.target.y, 0.25);
  EXPECT_DOUBLE_EQ(choice.target.box_width, 0.1);
  EXPECT_DOUBLE_EQ(choice.target.box_height, 0.25);
  EXPECT_DOUBLE_EQ(choice.target.magnification(), 4.0);  // the box's taller share fills the view
  EXPECT_EQ(choice.target.image_width, WIDTH);
  EXPECT_EQ(choice.target.image_height, HEIGHT);
  EXPECT_NE(choice.note.find("(VAPIX center, areazoom)"), std::string::npos) << choice.note;
}

TEST_F(PixelAimChoiceTest, AutoLeavesItToTheDeviceWhenItsZoomIsNotReported)
{
  camera.field_of_view = &lens;
  limits.axes[ZOOM].feedback = false;
  image.pose[ZOOM] = NOT_KNOWN;
  const PixelAimChoice choice = choose(PixelAimWay::AUTO, click(100.0, 300.0));
  ASSERT_EQ(choice.error, "");
  ASSERT_TRUE(choice.device);
}

TEST_F(PixelAimChoiceTest, AutoComputesABoxTheDeviceWouldOnlyCentre)
{
  limits.view_box_zoom = false;
  camera.field_of_view = &lens;  // the node zooms to the box
  EXPECT_FALSE(choose(PixelAimWay::AUTO, click(100.0, 300.0, 20.0, 20.0)).device);
  EXPECT_TRUE(choose(PixelAimWay::AUTO, click(100.0, 300.0)).device);
  camera.field_of_view = nullptr;  // neither zooms to it: the device centres it, saying the zoom is left out
  const PixelAimChoice box = choose(PixelAimWay::AUTO, click(100.0, 300.0, 20.0, 20.0));
  EXPECT_TRUE(box.device);
  EXPECT_NE(box.note.find("the box's zoom is ignored"), std::string::npos) << box.note;
}

TEST_F(PixelAimChoiceTest, AutoComputesOnADeviceWithoutItsOwnCommand)
{
  limits.view_centre = false;
  const PixelAimChoice choice = choose(PixelAimWay::AUTO, click(100.0, 300.0));
  EXPECT_EQ(choice.error, "");  // the computed way refuses it, saying what to configure
  EXPECT_FALSE(choice.device);
}

TEST_F(PixelAimChoiceTest, ComputedNeverAsksTheDeviceAndDeviceAlwaysDoes)
{
  EXPECT_FALSE(choose(PixelAimWay::COMPUTED, click(100.0, 300.0)).device);
  camera.field_of_view = &lens;
  const PixelAimChoice forced = choose(PixelAimWay::DEVICE, click(100.0, 300.0));
  ASSERT_EQ(forced.error, "");
  EXPECT_TRUE(forced.device);
  EXPECT_NE(forced.note.find("pixel_aim is device"), std::string::npos) << forced.note;
  limits.view_centre = false;
  const PixelAimChoice refused = choose(PixelAimWay::DEVICE, click(100.0, 300.0));
  EXPECT_NE(refused.error.find("has no command of its own"), std::string::npos) << refused.error;
}

TEST_F(PixelAimChoiceTest, TheDevicesCommandIsRefusedOnAPictureTheCameraHasLeft)
{
  current.position[PAN] += 0.05;  // turned since the image
  PixelAimChoice choice = choose(PixelAimWay::AUTO, click(100.0, 300.0));
  EXPECT_FALSE(choice.device);
  EXPECT_NE(choice.error.find("the camera's pan went from 0.3000 to 0.3500 rad since the image was taken"),
            std::string::npos)
      << choice.error;
  EXPECT_NE(choice.error.find("no field of view is configured"), std::string::npos) << choice.error;
  current.position[PAN] = image.pose[PAN] + 0.001;  // a reading apart: still that picture
  EXPECT_TRUE(choose(PixelAimWay::AUTO, click(100.0, 300.0)).device);
  current.position[ZOOM] = 3.0;
  EXPECT_NE(choose(PixelAimWay::AUTO, click(100.0, 300.0)).error.find("zoom went from 2.00 to 3.00 X"),
            std::string::npos);
  current.position[ZOOM] = image.pose[ZOOM];
  current.moving = true;
  EXPECT_NE(choose(PixelAimWay::DEVICE, click(100.0, 300.0)).error.find("the camera is moving"), std::string::npos);
  current.moving = false;
  image.status = PoseLookupStatus::TOO_OLD;
  image.error = "the image is older than the history";
  EXPECT_EQ(choose(PixelAimWay::DEVICE, click(100.0, 300.0)).error, "the image is older than the history");
}

TEST_F(PixelAimChoiceTest, BadGoalsAreRefusedAsTheComputedWayRefusesThem)
{
  EXPECT_NE(choose(PixelAimWay::AUTO, click(700.0, 10.0)).error.find("is not on the 640 x 360 px image"),
            std::string::npos);
  EXPECT_NE(choose(PixelAimWay::AUTO, click(10.0, 10.0, 5.0, -1.0)).error.find("both sides must be positive"),
            std::string::npos);
  PixelGoal no_size = click(10.0, 10.0);
  no_size.image_width = 0;
  no_size.image_height = 0;
  // Without a size the device has no picture to point in either: the computed way gives the reason.
  const PixelAimChoice choice = choose(PixelAimWay::AUTO, no_size);
  EXPECT_FALSE(choice.device);
  EXPECT_EQ(choice.error, "");
  EXPECT_NE(choose(PixelAimWay::DEVICE, no_size).error.find("must be positive"), std::string::npos);
}

TEST_F(PixelAimChoiceTest, ABoxIsOnlyCentredByADeviceThatCannotZoomToIt)
{
  limits.view_box_zoom = false;
  PixelAimChoice choice = choose(PixelAimWay::AUTO, click(100.0, 300.0, 64.0, 36.0));
  ASSERT_TRUE(choice.device);
  EXPECT_FALSE(choice.target.box());
  EXPECT_NE(choice.note.find("the box's zoom is ignored (the device's own command only centres)"), std::string::npos)
      << choice.note;
  limits.view_box_zoom = true;
  limits.axes[ZOOM] = absentAxis();
  image.pose[ZOOM] = NOT_KNOWN;
  choice = choose(PixelAimWay::AUTO, click(100.0, 300.0, 64.0, 36.0));
  ASSERT_TRUE(choice.device);
  EXPECT_FALSE(choice.target.box());
  EXPECT_NE(choice.note.find("the device has no zoom"), std::string::npos) << choice.note;
}

}  // namespace

/**
 * \file
 * \brief rostest client, aiming in the simulated camera's picture (pixel_aim.test): a marker found by colour in one
 * image is centred by a pixel goal on that image (also one taken while the camera moved), a box around it fills the
 * view, bad goals are refused with their reason, and a click on image_raw_mouse_left centres it too.
 */
#include <geometry_msgs/Point.h>

#include "camera_observer.h"
#include "node_test.h"
#include "ptz_action_server/PtzPixelAction.h"

namespace pixel_aim_test
{
using ptz_action_server::boundingBoxOf;
using ptz_action_server::CameraObserver;
using ptz_action_server::centroidOf;
using ptz_action_server::PtzPixelAction;
using ptz_action_server::PtzPixelGoal;
using ptz_action_server::waitUntil;
using PixelClient = actionlib::SimpleActionClient<PtzPixelAction>;

// pixel_aim.test lists this frame first: its marker is magenta. It lies 100 m from the point every optical axis of
// the URDF passes through (the tilt axis, 0.12 m above the base), in the direction MARKER_PAN, MARKER_TILT.
const char* const MARKER = "pixel_aim_marker";
constexpr std::uint8_t MARKER_COLOUR[3] = { 255, 0, 255 };
constexpr double MARKER_PAN = 0.35;   // rad, the contract's: right of the base's x axis
constexpr double MARKER_TILT = 0.15;  // rad, up
constexpr double MARKER_DISTANCE = 100.0;
constexpr double AXES_HEIGHT = 0.12;  // m, urdf/ptz.urdf's tilt axis above the base
constexpr double CENTRED = 3.0;       // px: the marker's centroid from the principal point after a goal
constexpr double FILL_TOLERANCE = 0.1;

class PixelAimTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    if (observer_ == nullptr)  // not yet set up by another suite in this run
    {
      NodeTest::SetUpTestSuite();
    }
    camera_ = new CameraObserver();
    pixel_ = new PixelClient("move_ptz/pixel", true);
    ros::NodeHandle node_handle;
    clicks_ = new ros::Publisher(node_handle.advertise<geometry_msgs::Point>("image_raw_mouse_left", 10));
    // Sent after NodeTest's frames: the latched /tf_static of this process is this broadcaster's list.
    static tf2_ros::StaticTransformBroadcaster broadcaster;
    geometry_msgs::TransformStamped frame;
    frame.header.frame_id = "ptz_base_link";
    frame.header.stamp = ros::Time::now();
    frame.child_frame_id = MARKER;
    frame.transform.translation.x = MARKER_DISTANCE * std::cos(MARKER_TILT) * std::cos(MARKER_PAN);
    frame.transform.translation.y = -MARKER_DISTANCE * std::cos(MARKER_TILT) * std::sin(MARKER_PAN);
    frame.transform.translation.z = AXES_HEIGHT + MARKER_DISTANCE * std::sin(MARKER_TILT);
    frame.transform.rotation.w = 1.0;
    broadcaster.sendTransform(frame);
  }

  void SetUp() override
  {
    NodeTest::SetUp();
    ASSERT_TRUE(pixel_->waitForServer(ros::Duration(30.0))) << "no move_ptz/pixel";
  }

  /// Moves to the pose and returns an image (and its camera_info) taken after the goal succeeded that shows the
  /// marker whole.
  void lookAt(double pan, double tilt, double zoom, sensor_msgs::Image& image, sensor_msgs::CameraInfo& info)
  {
    ASSERT_EQ(moveTo(pan, tilt, zoom), State::SUCCEEDED) << absolute_->getState().getText();
    ASSERT_TRUE(camera_->waitForImage(ros::Time::now(), markerInside, image, info)) << "no image with the marker";
  }

  /// True if the marker is in \p image, clear of its edges.
  static bool markerInside(const sensor_msgs::Image& image)
  {
    int left = 0, right = 0, top = 0, bottom = 0;
    return boundingBoxOf(image, MARKER_COLOUR, left, right, top, bottom) && left > 0 && top > 0 &&
           right < static_cast<int>(image.width) - 1 && bottom < static_cast<int>(image.height) - 1;
  }

  /// A goal on pixel (\p u, \p v) of \p image, with a box if \p box_width and \p box_height are not 0.
  static PtzPixelGoal goalOn(const sensor_msgs::Image& image, double u, double v, double box_width = 0.0,
                             double box_height = 0.0)
  {
    PtzPixelGoal goal;
    goal.image_header = image.header;
    goal.image_width = image.width;
    goal.image_height = image.height;
    goal.u = u;
    goal.v = v;
    goal.box_width = box_width;
    goal.box_height = box_height;
    return goal;
  }

  State send(const PtzPixelGoal& goal)
  {
    pixel_->sendGoal(goal);
    EXPECT_TRUE(pixel_->waitForResult(ros::Duration(GOAL_WAIT)));
    return pixel_->getState();
  }

  /// The marker's centroid in an image taken after now, less the principal point; false if it is not in view.
  static bool markerOffset(double& du, double& dv, sensor_msgs::Image& image, sensor_msgs::CameraInfo& info)
  {
    double u = 0.0;
    double v = 0.0;
    if (!camera_->waitForImage(ros::Time::now(), image, info) || !centroidOf(image, MARKER_COLOUR, u, v))
    {
      return false;
    }
    du = u - info.K[2];
    dv = v - info.K[5];
    return true;
  }

  /// The camera's pan at \p stamp, from tf (the node's joint transforms, interpolated); false if tf cannot say.
  static bool panAt(const ros::Time& stamp, double& pan)
  {
    try
    {
      const auto transform =
          tf_buffer_->lookupTransform("ptz_base_link", "ptz_camera_link", stamp, ros::Duration(GOAL_WAIT));
      const Eigen::Vector3d axis = tf2::transformToEigen(transform).linear() * Eigen::Vector3d::UnitX();
      pan = std::atan2(-axis.y(), axis.x());
      return true;
    }
    catch (const tf2::TransformException& error)
    {
      ADD_FAILURE() << error.what();
      return false;
    }
  }

  static inline CameraObserver* camera_ = nullptr;
  static inline PixelClient* pixel_ = nullptr;
  static inline ros::Publisher* clicks_ = nullptr;
};

TEST_F(PixelAimTest, AClickedMarkerEndsUpInTheCentre)
{
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  lookAt(MARKER_PAN - 0.25, MARKER_TILT + 0.1, zoomOr1(1.0), image, info);
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(centroidOf(image, MARKER_COLOUR, u, v));
  ASSERT_GT(std::hypot(u - info.K[2], v - info.K[5]), 50.0) << "the marker must start away from the centre";

  ASSERT_EQ(send(goalOn(image, u, v)), State::SUCCEEDED) << pixel_->getState().getText();
  const auto result = pixel_->getResult();
  EXPECT_TRUE(result->success);
  EXPECT_NEAR(result->pan, MARKER_PAN, 0.002);  // rad: the marker's direction (its 0.5 px is 0.001 rad at 1 X)
  EXPECT_NEAR(result->tilt, MARKER_TILT, 0.002);
  EXPECT_NEAR(result->zoom, zoomOr1(1.0), 0.06) << "a click without a box keeps the zoom";

  double du = 0.0;
  double dv = 0.0;
  ASSERT_TRUE(markerOffset(du, dv, image, info)) << "the marker is not in the image after the goal";
  EXPECT_LE(std::hypot(du, dv), CENTRED) << "marker at (" << du << ", " << dv << ") px from the centre";
}

TEST_F(PixelAimTest, AClickOnAnImageTakenWhileMovingLandsOnTheMarker)
{
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  lookAt(MARKER_PAN - 0.4, MARKER_TILT, zoomOr1(1.0), image, info);
  double rest_u = 0.0;
  double rest_v = 0.0;
  ASSERT_TRUE(centroidOf(image, MARKER_COLOUR, rest_u, rest_v));

  // A long pan to the right: the marker slides left through the picture, and off it.
  absolute_->sendGoal(makePtzGoal(MARKER_PAN + 1.5, MARKER_TILT, zoomOr1(1.0)));
  const ros::Time sent = ros::Time::now();
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(camera_->waitForImage(
      sent,
      [&](const sensor_msgs::Image& candidate) {
        return markerInside(candidate) && centroidOf(candidate, MARKER_COLOUR, u, v) && u < rest_u - 30.0;
      },
      image, info))
      << "no image of the marker taken while the camera moved";
  double pan_at_image = 0.0;
  ASSERT_TRUE(panAt(image.header.stamp, pan_at_image));
  // The click comes late, as a user's does: the camera has moved on since the image.
  ASSERT_TRUE(observer_->waitFor([&](const PtzState& state) { return state.pan > pan_at_image + 0.1; }, GOAL_WAIT));
  const double pan_at_click = observer_->latest().pan;
  ASSERT_GT(pan_at_click - pan_at_image, 0.05) << "the pose at the image's stamp must differ from the pose now";

  ASSERT_EQ(send(goalOn(image, u, v)), State::SUCCEEDED) << pixel_->getState().getText();
  EXPECT_TRUE(waitUntil([] { return absolute_->getState() == State::PREEMPTED; }, GOAL_WAIT))
      << "the long goal ended " << absolute_->getState().toString();
  EXPECT_NEAR(pixel_->getResult()->pan, MARKER_PAN, 0.002);
  EXPECT_NEAR(pixel_->getResult()->tilt, MARKER_TILT, 0.002);
  double du = 0.0;
  double dv = 0.0;
  ASSERT_TRUE(markerOffset(du, dv, image, info)) << "the marker is not in the image after the goal";
  EXPECT_LE(std::hypot(du, dv), CENTRED) << "marker at (" << du << ", " << dv << ") px from the centre";
}

TEST_F(PixelAimTest, ABoxAroundTheMarkerFillsTheView)
{
  if (!zoomable())
  {
    GTEST_SKIP() << "the device's zoom takes no positions";
  }
  // The marker's disc spans 2 degrees: at 4 X about 78 px of 360; the view holds it exactly at about 18.6 X.
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  lookAt(MARKER_PAN + 0.02, MARKER_TILT - 0.015, 4.0, image, info);
  int left = 0, right = 0, top = 0, bottom = 0;
  ASSERT_TRUE(boundingBoxOf(image, MARKER_COLOUR, left, right, top, bottom));
  const PtzPixelGoal goal =
      goalOn(image, (left + right) / 2.0, (top + bottom) / 2.0, right - left + 1.0, bottom - top + 1.0);
  ASSERT_EQ(send(goal), State::SUCCEEDED) << pixel_->getState().getText();
  const double zoom = pixel_->getResult()->zoom;
  EXPECT_GT(zoom, 12.0);
  EXPECT_LT(zoom, capabilities_->zoom.max) << "the box is filled within the zoom range, not at its end";

  ASSERT_TRUE(camera_->waitForImage(ros::Time::now(), image, info));
  ASSERT_TRUE(boundingBoxOf(image, MARKER_COLOUR, left, right, top, bottom)) << "the marker left the view";
  const double width = right - left + 1.0;
  const double height = bottom - top + 1.0;
  // The larger relative side fills the view; the picture's edges cut it at 100 %, so the fill is also judged from
  // the side that is not cut: the disc is round in angle, so its height is its width scaled by fy / fx.
  const double larger_side = std::max(width / image.width, height / image.height);
  const double uncut_fill = std::max(width / image.width, width * info.K[4] / info.K[0] / image.height);
  EXPECT_GE(larger_side, 1.0 - FILL_TOLERANCE);
  EXPECT_NEAR(uncut_fill, 1.0, FILL_TOLERANCE);
  // Centred to the device's pan resolution: a step of 0.000897 rad is 9 px at 18.6 X.
  EXPECT_NEAR((left + right) / 2.0, info.K[2], 0.02 * image.width);
}

TEST_F(PixelAimTest, BadGoalsAreRefusedWithTheirReason)
{
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  lookAt(MARKER_PAN, MARKER_TILT, zoomOr1(1.0), image, info);

  PtzPixelGoal goal = goalOn(image, 100.0, 100.0);
  goal.image_header.stamp = ros::Time::now() - ros::Duration(60.0);
  EXPECT_EQ(send(goal), State::REJECTED);
  EXPECT_NE(pixel_->getState().getText().find("older than the camera's pose history"), std::string::npos)
      << pixel_->getState().getText();
  EXPECT_TRUE(std::isnan(pixel_->getResult()->pan)) << "a refused goal aimed nowhere";

  EXPECT_EQ(send(goalOn(image, image.width + 10.0, 100.0)), State::REJECTED);
  EXPECT_NE(pixel_->getState().getText().find("is not on the"), std::string::npos) << pixel_->getState().getText();

  EXPECT_EQ(send(goalOn(image, 100.0, 100.0, -20.0, 10.0)), State::REJECTED);
  EXPECT_NE(pixel_->getState().getText().find("both sides must be positive"), std::string::npos)
      << pixel_->getState().getText();

  goal = goalOn(image, 100.0, 100.0);
  goal.image_width = 0;  // no size, and no calibrated camera_info to take it from
  EXPECT_EQ(send(goal), State::REJECTED);
  EXPECT_NE(pixel_->getState().getText().find("must be positive"), std::string::npos) << pixel_->getState().getText();

  // Nothing moved.
  ASSERT_TRUE(observer_->waitTicks(2));
  EXPECT_NEAR(observer_->latest().pan, MARKER_PAN, TOLERANCE);
}

TEST_F(PixelAimTest, AClickOnTheMouseTopicCentresTheMarker)
{
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  lookAt(MARKER_PAN + 0.2, MARKER_TILT - 0.12, zoomOr1(1.0), image, info);
  double u = 0.0;
  double v = 0.0;
  ASSERT_TRUE(centroidOf(image, MARKER_COLOUR, u, v));
  ASSERT_TRUE(waitUntil([] { return clicks_->getNumSubscribers() > 0; }, GOAL_WAIT))
      << "the node does not listen to " << clicks_->getTopic();
  // As rqt_image_view publishes it: whole pixels from the image's top-left outer corner (the camera rests, so the
  // node's latest image is this one's twin).
  geometry_msgs::Point click;
  click.x = std::round(u + 0.5);
  click.y = std::round(v + 0.5);
  clicks_->publish(click);
  ASSERT_TRUE(observer_->waitFor(
      [](const PtzState& state) {
        return state.mode == PtzState::MODE_IDLE && std::abs(state.pan - MARKER_PAN) < 0.01 &&
               std::abs(state.tilt - MARKER_TILT) < 0.01;
      },
      GOAL_WAIT))
      << "the camera did not turn to the clicked marker";
  double du = 0.0;
  double dv = 0.0;
  ASSERT_TRUE(markerOffset(du, dv, image, info));
  // rqt_image_view's whole pixels: half a pixel more than a pixel goal's.
  EXPECT_LE(std::hypot(du, dv), CENTRED + 0.5) << "marker at (" << du << ", " << dv << ") px from the centre";
}

}  // namespace pixel_aim_test

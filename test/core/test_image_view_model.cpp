// The rviz panel's image view without Qt or ROS: image topics, the widget-to-image mapping (letterbox, scale,
// camera_info's pixel centres), dragged boxes, the camera's recent views, the aim re-projected, the goal drawn.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "ptz_action_server/panel/image_view_model.h"

using namespace ptz_action_server::panel;

namespace
{
constexpr double NAN_VALUE = std::numeric_limits<double>::quiet_NaN();

/// 60 degrees across, square pixels at 16:9 (config/sim.yaml's lens), looking at pan, tilt, with the zoom of an ideal
/// lens.
View simView(double pan, double tilt, double zoom = 1.0)
{
  const double horizontal = 2.0 * std::atan(std::tan(M_PI / 6.0) / zoom);
  const double vertical = 2.0 * std::atan(std::tan(0.5 * horizontal) * 360.0 / 640.0);
  return { pan, tilt, horizontal, vertical };
}
}  // namespace

TEST(PanelModelImage, OffersTheImageTopicsOfTheCamerasNamespace)
{
  const std::vector<TopicInfo> topics = {
    { "/ptz/image_raw", "sensor_msgs/Image" },
    { "/ptz/image_raw/compressed", "sensor_msgs/CompressedImage" },  // a transport of image_raw, not an image
    { "/ptz/camera_info", "sensor_msgs/CameraInfo" },
    { "/ptz/left/image", "sensor_msgs/Image" },
    { "/ptz2/image_raw", "sensor_msgs/Image" },  // another camera, whose name only starts alike
    { "/camera/image_raw", "sensor_msgs/Image" },
    { "/ptz/image_raw", "sensor_msgs/Image" },  // listed twice
  };
  EXPECT_EQ(imageTopics(topics, "/ptz"), (std::vector<std::string>{ "/ptz/image_raw", "/ptz/left/image" }));
  EXPECT_EQ(imageTopics(topics, "/").size(), 4u);
  EXPECT_TRUE(imageTopics(topics, "/none").empty());
  EXPECT_EQ(defaultImageTopic("/ptz"), "/ptz/image_raw");
  EXPECT_EQ(defaultImageTopic("/"), "/image_raw");
  EXPECT_EQ(defaultImageTopic(""), "") << "no camera: no image";
}

TEST(PanelModelImage, TheLetterboxKeepsTheAspectRatioAndCentres)
{
  // Wider than the image's 16:9: bars left and right.
  const Letterbox pillar = letterbox(640, 360, 800, 300);
  EXPECT_DOUBLE_EQ(pillar.scale, 300.0 / 360.0);
  EXPECT_DOUBLE_EQ(pillar.height(), 300.0);
  EXPECT_DOUBLE_EQ(pillar.width() / pillar.height(), 640.0 / 360.0);
  EXPECT_DOUBLE_EQ(pillar.left, 0.5 * (800.0 - pillar.width()));
  EXPECT_DOUBLE_EQ(pillar.top, 0.0);
  // Taller: bars above and below.
  const Letterbox letter = letterbox(640, 360, 360, 400);
  EXPECT_DOUBLE_EQ(letter.scale, 360.0 / 640.0);
  EXPECT_DOUBLE_EQ(letter.width(), 360.0);
  EXPECT_DOUBLE_EQ(letter.top, 0.5 * (400.0 - letter.height()));
  EXPECT_DOUBLE_EQ(letter.left, 0.0);
  // Nothing to draw.
  EXPECT_EQ(letterbox(0, 360, 360, 400).scale, 0.0);
  EXPECT_EQ(letterbox(640, 360, 0, 400).scale, 0.0);
  EXPECT_FALSE(pixelAt(letterbox(640, 360, 0, 0), { 0.0, 0.0 }));
}

TEST(PanelModelImage, AWidgetPositionIsThePixelItsCentreFallsOn)
{
  // One widget pixel per image pixel: the same indices, pixel (0, 0) the top-left pixel's centre.
  const Letterbox same = letterbox(640, 360, 640, 360);
  ASSERT_TRUE(pixelAt(same, { 0.0, 0.0 }));
  EXPECT_DOUBLE_EQ(pixelAt(same, { 0.0, 0.0 })->u, 0.0);
  EXPECT_DOUBLE_EQ(pixelAt(same, { 0.0, 0.0 })->v, 0.0);
  EXPECT_DOUBLE_EQ(pixelAt(same, { 639.0, 359.0 })->u, 639.0);
  EXPECT_DOUBLE_EQ(pixelAt(same, { 639.0, 359.0 })->v, 359.0);

  // Two widget pixels per image pixel: the top-left image pixel spans widget pixels 0 and 1, whose centres lie a
  // quarter of an image pixel either side of its centre.
  const Letterbox twice = letterbox(320, 180, 640, 360);
  EXPECT_DOUBLE_EQ(pixelAt(twice, { 0.0, 0.0 })->u, -0.25);
  EXPECT_DOUBLE_EQ(pixelAt(twice, { 1.0, 1.0 })->v, 0.25);

  // Letterboxed: the offset comes off first, then the scale; the bars are off the image.
  const Letterbox box = letterbox(640, 360, 400, 400);  // scale 0.625, 225 px tall, 87.5 px bars
  EXPECT_FALSE(pixelAt(box, { 10.0, 50.0 })) << "on the bar above";
  EXPECT_FALSE(pixelAt(box, { 10.0, 350.0 })) << "on the bar below";
  EXPECT_FALSE(pixelAt(box, { -3.0, 200.0 })) << "left of the widget";
  const std::optional<Pixel> pixel = pixelAt(box, { 10.0, 90.0 });
  ASSERT_TRUE(pixel);
  EXPECT_DOUBLE_EQ(pixel->u, (10.0 + 0.5) / box.scale - 0.5);
  EXPECT_DOUBLE_EQ(pixel->v, (90.0 + 0.5 - box.top) / box.scale - 0.5);

  // The image's centre ((width - 1) / 2, (height - 1) / 2) is the widget's centre, whatever the sizes.
  for (const Letterbox& any : { same, twice, box, letterbox(640, 360, 333, 517), letterbox(1920, 1080, 360, 202) })
  {
    const WidgetPoint centre = widgetPointOf(any, { 0.5 * (any.image_width - 1), 0.5 * (any.image_height - 1) });
    const double widget_width = any.width() + 2.0 * any.left;
    const double widget_height = any.height() + 2.0 * any.top;
    EXPECT_NEAR(centre.x + 0.5, 0.5 * widget_width, 1e-9);
    EXPECT_NEAR(centre.y + 0.5, 0.5 * widget_height, 1e-9);
  }
}

TEST(PanelModelImage, PixelsAndWidgetPositionsMapBothWays)
{
  const Letterbox box = letterbox(640, 360, 517, 611);
  for (const Pixel pixel : { Pixel{ 0.0, 0.0 }, Pixel{ 639.0, 359.0 }, Pixel{ 100.25, 17.5 }, Pixel{ 319.5, 179.5 } })
  {
    const WidgetPoint at = widgetPointOf(box, pixel);
    const std::optional<Pixel> back = pixelAt(box, at);
    ASSERT_TRUE(back) << pixel.u << ", " << pixel.v;
    EXPECT_NEAR(back->u, pixel.u, 1e-9);
    EXPECT_NEAR(back->v, pixel.v, 1e-9);
  }
  // A widget position rounded to a whole widget pixel (as a click has it) lands within half a widget pixel.
  const WidgetPoint at = widgetPointOf(box, { 400.3, 200.7 });
  const std::optional<Pixel> clicked = pixelAt(box, { std::round(at.x), std::round(at.y) });
  ASSERT_TRUE(clicked);
  EXPECT_LE(std::abs(clicked->u - 400.3), 0.5 / box.scale);
  EXPECT_LE(std::abs(clicked->v - 200.7), 0.5 / box.scale);
}

TEST(PanelModelImage, ADragIsABoxInImagePixelsClippedToTheImage)
{
  const Letterbox box = letterbox(640, 360, 320, 400);  // half size, 90 px tall, top 110
  // Corner to corner of the drawn image, either way round: the whole image.
  const WidgetPoint top_left{ 0.0 - 0.5, box.top - 0.5 };  // the positions whose centres are the outer corners
  const WidgetPoint bottom_right{ 320.0 - 0.5, box.top + box.height() - 0.5 };
  for (const auto& [from, to] : { std::pair{ top_left, bottom_right }, std::pair{ bottom_right, top_left } })
  {
    const std::optional<PixelBox> whole = draggedBox(box, from, to);
    ASSERT_TRUE(whole);
    EXPECT_DOUBLE_EQ(whole->width, 640.0);
    EXPECT_DOUBLE_EQ(whole->height, 360.0);
    EXPECT_DOUBLE_EQ(whole->u, 319.5);
    EXPECT_DOUBLE_EQ(whole->v, 179.5);
  }
  // 20 x 10 widget px inside: 40 x 20 image px, centred where the middle of the drag is.
  const std::optional<PixelBox> inside = draggedBox(box, { 100.0, 150.0 }, { 120.0, 160.0 });
  ASSERT_TRUE(inside);
  EXPECT_DOUBLE_EQ(inside->width, 40.0);
  EXPECT_DOUBLE_EQ(inside->height, 20.0);
  const std::optional<Pixel> middle = pixelAt(box, { 110.0, 155.0 });
  EXPECT_DOUBLE_EQ(inside->u, middle->u);
  EXPECT_DOUBLE_EQ(inside->v, middle->v);
  // From the bar above into the image: clipped at the image's top edge.
  const std::optional<PixelBox> clipped = draggedBox(box, { 100.0, 20.0 }, { 120.0, box.top + 9.5 });
  ASSERT_TRUE(clipped);
  EXPECT_DOUBLE_EQ(clipped->height, 20.0);
  EXPECT_DOUBLE_EQ(clipped->v, 9.5);
  // All on the bar: nothing.
  EXPECT_FALSE(draggedBox(box, { 10.0, 10.0 }, { 100.0, 60.0 }));
  // Drag or click: Qt's startDragDistance counts x plus y.
  EXPECT_FALSE(isDrag({ 10.0, 10.0 }, { 13.0, 15.0 }, 10.0));
  EXPECT_TRUE(isDrag({ 10.0, 10.0 }, { 16.0, 14.0 }, 10.0));
}

TEST(PanelModelImage, TheViewTrackInterpolatesPoseAndFieldOfView)
{
  ViewTrack track;
  EXPECT_FALSE(track.at(1.0));
  track.addPose(1.0, 0.2, 0.1);
  EXPECT_FALSE(track.at(1.0)) << "no field of view yet";
  track.addFieldOfView(0.95, 1.0, 0.6);
  track.addPose(1.1, 0.4, 0.0);
  track.addFieldOfView(1.05, 0.5, 0.3);
  const std::optional<View> between = track.at(1.05);
  ASSERT_TRUE(between);
  EXPECT_NEAR(between->pan, 0.3, 1e-12);
  EXPECT_NEAR(between->tilt, 0.05, 1e-12);
  EXPECT_NEAR(between->horizontal, 0.5, 1e-12);
  EXPECT_NEAR(track.at(1.0)->horizontal, 0.75, 1e-12);
  // Past the newest pose: carried on at the last speed (2 rad/s of pan), the field of view held, for MAX_AHEAD.
  const std::optional<View> ahead = track.at(1.15);
  ASSERT_TRUE(ahead);
  EXPECT_NEAR(ahead->pan, 0.5, 1e-12);
  EXPECT_NEAR(ahead->horizontal, 0.5, 1e-12);
  EXPECT_FALSE(track.at(1.1 + ViewTrack::MAX_AHEAD + 0.01));
  EXPECT_FALSE(track.at(0.99)) << "before the first pose";

  // Pan the shorter way round, across +-pi.
  ViewTrack wrap;
  wrap.addFieldOfView(0.0, 1.0, 0.6);
  wrap.addFieldOfView(1.0, 1.0, 0.6);
  wrap.addPose(0.0, M_PI - 0.1, 0.0);
  wrap.addPose(1.0, -M_PI + 0.1, 0.0);
  ASSERT_TRUE(wrap.at(0.5));
  EXPECT_NEAR(std::remainder(wrap.at(0.5)->pan - M_PI, 2.0 * M_PI), 0.0, 1e-12);

  // A NaN axis (a device that does not report it): no view.
  ViewTrack unknown;
  unknown.addFieldOfView(0.0, 1.0, 0.6);
  unknown.addPose(0.0, NAN_VALUE, 0.0);
  EXPECT_FALSE(unknown.at(0.0));

  // Time going back voids the past; TRACK_SPAN bounds it.
  track.addPose(0.5, -0.3, 0.0);
  track.addFieldOfView(0.5, 1.0, 0.6);
  ASSERT_TRUE(track.at(0.5));
  EXPECT_NEAR(track.at(0.5)->pan, -0.3, 1e-12);
  EXPECT_FALSE(track.at(1.05)) << "the samples of before the jump are gone";
  track.addPose(0.5 + ViewTrack::TRACK_SPAN + 1.0, 0.0, 0.0);
  track.addFieldOfView(0.5 + ViewTrack::TRACK_SPAN + 1.0, 1.0, 0.6);
  EXPECT_FALSE(track.at(0.6)) << "older than the span kept";
}

TEST(PanelModelImage, TheAimStaysOnWhatWasClickedAsTheCameraTurns)
{
  PixelAim aim;
  aim.target = { 500.0, 100.0, 0.0, 0.0 };
  aim.image_width = 640;
  aim.image_height = 360;
  const View before = simView(0.2, 0.1);

  // The same view: where it was clicked.
  std::optional<AimInImage> drawn = aimInImage(aim, before, 640, 360, before);
  ASSERT_TRUE(drawn);
  EXPECT_TRUE(drawn->tracked);
  EXPECT_FALSE(drawn->box);
  EXPECT_NEAR(drawn->centre.u, 500.0, 1e-9);
  EXPECT_NEAR(drawn->centre.v, 100.0, 1e-9);

  // A pixel on the middle row at tilt 0 lies atan((u - cx) / fx) right of the optical axis: turned there, it is at the
  // image's centre.
  PixelAim level = aim;
  level.target.v = 179.5;
  const View flat = simView(0.2, 0.0);
  const double fx = 320.0 / std::tan(0.5 * flat.horizontal);
  const View turned = simView(0.2 + std::atan((500.0 - 319.5) / fx), 0.0);
  drawn = aimInImage(level, flat, 640, 360, turned);
  ASSERT_TRUE(drawn);
  EXPECT_NEAR(drawn->centre.u, 319.5, 1e-6);
  EXPECT_NEAR(drawn->centre.v, 179.5, 1e-6);
  // Halfway there, it is on its way along the middle row.
  drawn = aimInImage(level, flat, 640, 360, simView(0.2 + 0.5 * std::atan((500.0 - 319.5) / fx), 0.0));
  EXPECT_GT(drawn->centre.u, 319.5 + 1.0);
  EXPECT_LT(drawn->centre.u, 500.0 - 1.0);
  EXPECT_NEAR(drawn->centre.v, 179.5, 1e-6);
  // Panning right moves it left; tilting up moves it down.
  EXPECT_LT(aimInImage(aim, before, 640, 360, simView(0.25, 0.1))->centre.u, 500.0 - 1.0);
  EXPECT_GT(aimInImage(aim, before, 640, 360, simView(0.2, 0.15))->centre.v, 100.0 + 1.0);
  // Half a turn away it is behind the camera: not drawn.
  EXPECT_FALSE(aimInImage(aim, before, 640, 360, simView(0.2 + M_PI, 0.1)));
}

TEST(PanelModelImage, ABoxCentredAndZoomedFillsTheView)
{
  // A 64 x 36 px box at the centre: zoomed 10 X (an ideal lens) it spans the whole 640 x 360 image.
  PixelAim aim;
  aim.target = { 319.5, 179.5, 64.0, 36.0 };
  aim.image_width = 640;
  aim.image_height = 360;
  const std::optional<AimInImage> drawn = aimInImage(aim, simView(0.0, 0.0), 640, 360, simView(0.0, 0.0, 10.0));
  ASSERT_TRUE(drawn);
  ASSERT_TRUE(drawn->box);
  // Corners at the outer edges: top-left (-0.5, -0.5), bottom-right (639.5, 359.5).
  EXPECT_NEAR(drawn->corners[0].u, -0.5, 1e-6);
  EXPECT_NEAR(drawn->corners[0].v, -0.5, 1e-6);
  EXPECT_NEAR(drawn->corners[2].u, 639.5, 1e-6);
  EXPECT_NEAR(drawn->corners[2].v, 359.5, 1e-6);
  EXPECT_NEAR(drawn->corners[1].u, drawn->corners[2].u, 1e-6) << "clockwise: top right above bottom right";
}

TEST(PanelModelImage, WithoutViewsTheAimStaysWhereItWasClickedScaledToTheImage)
{
  PixelAim aim;
  aim.target = { 100.0, 50.0, 20.0, 10.0 };
  aim.image_width = 640;
  aim.image_height = 360;
  // Drawn on an image twice the size: the same place of the picture.
  const std::optional<AimInImage> drawn = aimInImage(aim, std::nullopt, 1280, 720, simView(0.0, 0.0));
  ASSERT_TRUE(drawn);
  EXPECT_FALSE(drawn->tracked);
  EXPECT_DOUBLE_EQ(drawn->centre.u, (100.0 + 0.5) * 2.0 - 0.5);
  EXPECT_DOUBLE_EQ(drawn->centre.v, (50.0 + 0.5) * 2.0 - 0.5);
  EXPECT_DOUBLE_EQ(drawn->corners[2].u - drawn->corners[0].u, 40.0);
  // Re-projected between two image sizes of the same view: the same scaling.
  const View view = simView(0.3, -0.1);
  const std::optional<AimInImage> tracked = aimInImage(aim, view, 1280, 720, view);
  EXPECT_NEAR(tracked->centre.u, drawn->centre.u, 1e-6);
  EXPECT_NEAR(tracked->centre.v, drawn->centre.v, 1e-6);
  EXPECT_FALSE(aimInImage(aim, view, 0, 720, view));
}

TEST(PanelModelImage, ThePixelGoalIsDrawnWhilePendingOrActive)
{
  const auto entry = [](const std::string& id, std::uint8_t status) {
    GoalStatusEntry goal;
    goal.action = "pixel";
    goal.id = id;
    goal.status = status;
    return goal;
  };
  constexpr std::uint8_t PENDING = 0, ACTIVE = 1, PREEMPTED = 2, SUCCEEDED = 3, REJECTED = 5;
  PixelGoalWatch watch;
  EXPECT_FALSE(watch.active(0.0));
  PixelAim aim;
  aim.goal_id = "a";
  watch.goalSent(aim, 10.0);
  ASSERT_TRUE(watch.active(10.1)) << "heard, not yet listed";
  EXPECT_EQ(watch.active(10.1)->goal_id, "a");
  watch.status({ entry("older", SUCCEEDED) });
  EXPECT_TRUE(watch.active(10.2)) << "a list without it";
  watch.status({ entry("a", PENDING) });
  EXPECT_TRUE(watch.active(20.0)) << "listed: no timeout";
  watch.status({ entry("a", ACTIVE) });
  EXPECT_TRUE(watch.active(20.0));
  watch.status({ entry("a", SUCCEEDED) });
  EXPECT_FALSE(watch.active(20.0));

  // Listed, then dropped from the lists: it ended.
  aim.goal_id = "b";
  watch.goalSent(aim, 30.0);
  watch.status({ entry("b", ACTIVE) });
  watch.status({});
  EXPECT_FALSE(watch.active(30.5));
  // Rejected.
  aim.goal_id = "c";
  watch.goalSent(aim, 40.0);
  watch.status({ entry("c", REJECTED) });
  EXPECT_FALSE(watch.active(40.1));
  // Never listed (a node that is gone): dropped after UNLISTED_TIMEOUT.
  aim.goal_id = "d";
  watch.goalSent(aim, 50.0);
  EXPECT_TRUE(watch.active(50.0 + PixelGoalWatch::UNLISTED_TIMEOUT - 0.1));
  EXPECT_FALSE(watch.active(50.0 + PixelGoalWatch::UNLISTED_TIMEOUT + 0.1));
  // A newer goal replaces the one before (that one is preempted).
  aim.goal_id = "e";
  watch.goalSent(aim, 60.0);
  aim.goal_id = "f";
  watch.goalSent(aim, 60.1);
  watch.status({ entry("e", PREEMPTED), entry("f", ACTIVE) });
  ASSERT_TRUE(watch.active(60.2));
  EXPECT_EQ(watch.active(60.2)->goal_id, "f");
  watch.clear();
  EXPECT_FALSE(watch.active(60.2));
}

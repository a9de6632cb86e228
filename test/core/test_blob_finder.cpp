// BlobFinder (ptz_blob_detector's core) on the pictures the simulated camera draws.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "detection_tracker_test_support.h"
#include "ptz_action_server/render/camera_renderer.h"
#include "ptz_action_server/vision/blob_finder.h"

namespace ptz_action_server
{
namespace
{
using detection_tracker_test::HEIGHT;
using detection_tracker_test::WIDTH;

constexpr double MARKER_RADIUS = 0.0175;  ///< rad: the sim camera's default

/// The sim's camera at a pose, drawing markers where given pixels' rays go.
class BlobScene : public ::testing::Test
{
protected:
  BlobScene() : kinematics(pixel_aim_test::shippedKinematics())
  {
  }

  /// Renders, at \p pose, a marker for each of \p pixels 6 m away (markerColour(i) for the i-th); image_ gets it.
  void render(const AxisValues& pose, const std::vector<std::array<double, 2>>& pixels)
  {
    camera = kinematics.cameraInBase(pose[PAN], pose[TILT]);
    intrinsics = detection_tracker_test::viewAt(pose[ZOOM]);
    std::vector<SceneMarker> markers(pixels.size());
    for (std::size_t index = 0; index < pixels.size(); ++index)
    {
      markers[index].name = "marker_" + std::to_string(index);
      markers[index].position =
          camera * (6.0 * opticalToCameraLink(rayThroughPixel(intrinsics, pixels[index][0], pixels[index][1])));
      markers[index].present = true;
    }
    renderer.render(camera, intrinsics, markers, image);
  }
  /// The disc's diameter in pixels.
  double discSize() const
  {
    return 2.0 * intrinsics.fx * std::tan(MARKER_RADIUS);
  }

  PtzKinematics kinematics;
  CameraRenderer renderer;
  Eigen::Isometry3d camera;
  PinholeIntrinsics intrinsics;
  cv::Mat image;
};

BlobFinderSettings rgbSettings(std::size_t colour_index, int tolerance = 40)
{
  const Rgb colour = markerColour(colour_index);
  BlobFinderSettings settings;
  settings.colour.rgb = { colour.r, colour.g, colour.b };
  settings.colour.tolerance = tolerance;
  return settings;
}

TEST_F(BlobScene, TheMagentaMarkerIsFoundWhereItIsDrawnAndNothingElseIs)
{
  BlobFinder finder{ BlobFinderSettings() };  // magenta by default
  for (const AxisValues& pose : std::vector<AxisValues>{ { 0.0, 0.0, 1.0 }, { 0.7, 0.3, 4.0 }, { -2.0, -0.6, 1.5 } })
  {
    SCOPED_TRACE(::testing::Message() << "pan " << pose[PAN] << " tilt " << pose[TILT] << " zoom " << pose[ZOOM]);
    render(pose, { { 201.3, 97.8 }, { 455.6, 260.25 } });  // magenta, yellow
    const std::vector<Blob>& blobs = finder.find(image, ChannelOrder::RGB);
    ASSERT_EQ(blobs.size(), 1u) << "the backdrop, its marks, the labels and the yellow disc are not magenta";
    EXPECT_NEAR(blobs[0].u, 201.3, 0.1);
    EXPECT_NEAR(blobs[0].v, 97.8, 0.1);
    EXPECT_NEAR(blobs[0].width, discSize(), 2.0);
    EXPECT_NEAR(blobs[0].height, discSize(), 2.0);
    EXPECT_NEAR(blobs[0].area, M_PI * discSize() * discSize() / 4.0, 0.1 * blobs[0].area);
    // The box's centre is the disc's too.
    EXPECT_NEAR(blobs[0].left + (blobs[0].width - 1) / 2.0, 201.3, 0.6);
    EXPECT_NEAR(blobs[0].top + (blobs[0].height - 1) / 2.0, 97.8, 0.6);
  }
}

TEST_F(BlobScene, EveryMarkerColourIsFoundByItsOwnFinderOnly)
{
  std::vector<std::array<double, 2>> pixels;
  for (std::size_t index = 0; index < MARKER_COLOURS; ++index)
  {
    pixels.push_back({ 60.0 + 70.0 * index, 100.0 + 20.0 * index });
  }
  render({ 0.4, 0.2, 2.0 }, pixels);
  for (std::size_t index = 0; index < MARKER_COLOURS; ++index)
  {
    SCOPED_TRACE(::testing::Message() << "colour " << index);
    BlobFinder finder(rgbSettings(index));
    const std::vector<Blob>& blobs = finder.find(image, ChannelOrder::RGB);
    ASSERT_EQ(blobs.size(), 1u);
    EXPECT_NEAR(blobs[0].u, pixels[index][0], 0.1);
    EXPECT_NEAR(blobs[0].v, pixels[index][1], 0.1);
  }
}

TEST_F(BlobScene, BgrAndAlphaImagesGiveTheSameBlobs)
{
  render({ 0.0, 0.1, 1.0 }, { { 200.0, 150.0 }, { 320.0, 100.0 } });  // magenta, yellow
  BlobFinder finder(rgbSettings(1));                                  // yellow
  const Blob rgb = finder.find(image, ChannelOrder::RGB).at(0);
  EXPECT_NEAR(rgb.u, 320.0, 0.1);
  cv::Mat converted;
  cv::cvtColor(image, converted, cv::COLOR_RGB2BGR);
  ASSERT_EQ(finder.find(converted, ChannelOrder::BGR).size(), 1u);
  EXPECT_EQ(finder.find(converted, ChannelOrder::BGR).at(0).area, rgb.area);
  EXPECT_TRUE(finder.find(converted, ChannelOrder::RGB).empty()) << "read as RGB, the yellow disc is cyan";
  cv::cvtColor(image, converted, cv::COLOR_RGB2RGBA);
  ASSERT_EQ(finder.find(converted, ChannelOrder::RGB).size(), 1u);
  EXPECT_DOUBLE_EQ(finder.find(converted, ChannelOrder::RGB).at(0).u, rgb.u);
  cv::cvtColor(image, converted, cv::COLOR_RGB2BGRA);
  EXPECT_DOUBLE_EQ(finder.find(converted, ChannelOrder::BGR).at(0).v, rgb.v);
  cv::Mat gray(HEIGHT, WIDTH, CV_8UC1, cv::Scalar(0));
  EXPECT_THROW(finder.find(gray, ChannelOrder::RGB), std::invalid_argument);
}

TEST_F(BlobScene, AHueRangeFindsTheColourThroughShadesOfIt)
{
  // Magenta (hue 300 degrees) at full and at half brightness; red (hue 0) and yellow beside them.
  render({ 0.0, 0.0, 1.0 }, { { 100.0, 180.0 }, { 300.0, 180.0 }, { 400.0, 180.0 }, { 500.0, 180.0 } });
  cv::circle(image, cv::Point(200, 180), 8, cv::Scalar(128, 0, 128), cv::FILLED);  // dark magenta
  BlobFinderSettings settings;
  settings.colour.hsv = true;
  settings.colour.hue_min = 280.0;
  settings.colour.hue_max = 320.0;
  settings.colour.saturation_min = 0.6;
  settings.colour.value_min = 0.3;
  BlobFinder magenta(settings);
  const std::vector<Blob>& blobs = magenta.find(image, ChannelOrder::RGB);
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_NEAR(std::min(blobs[0].u, blobs[1].u), 100.0, 0.1);
  EXPECT_NEAR(std::max(blobs[0].u, blobs[1].u), 200.0, 0.1);
  // A range through 0 (340 to 20 degrees): the red disc (the fourth colour) only.
  settings.colour.hue_min = 340.0;
  settings.colour.hue_max = 20.0;
  BlobFinder red(settings);
  ASSERT_EQ(red.find(image, ChannelOrder::RGB).size(), 1u);
  EXPECT_NEAR(red.find(image, ChannelOrder::RGB).at(0).u, 500.0, 0.1);
}

TEST_F(BlobScene, SmallBlobsAreLeftOutAndTheLargestKeptFirst)
{
  render({ 0.0, 0.0, 1.0 }, {});
  const cv::Scalar magenta(255, 0, 255);
  cv::rectangle(image, cv::Rect(10, 10, 2, 1), magenta, cv::FILLED);    // 2 px: noise
  cv::rectangle(image, cv::Rect(100, 50, 5, 4), magenta, cv::FILLED);   // 20 px
  cv::rectangle(image, cv::Rect(300, 50, 10, 6), magenta, cv::FILLED);  // 60 px
  cv::rectangle(image, cv::Rect(500, 50, 6, 6), magenta, cv::FILLED);   // 36 px
  BlobFinderSettings settings;
  settings.min_area = 4;
  settings.max_blobs = 2;
  BlobFinder finder(settings);
  const std::vector<Blob>& blobs = finder.find(image, ChannelOrder::RGB);
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_EQ(blobs[0].area, 60);
  EXPECT_DOUBLE_EQ(blobs[0].u, 304.5);
  EXPECT_DOUBLE_EQ(blobs[0].v, 52.5);
  EXPECT_EQ(blobs[0].width, 10);
  EXPECT_EQ(blobs[1].area, 36);
  settings.max_blobs = 10;
  EXPECT_EQ(BlobFinder(settings).find(image, ChannelOrder::RGB).size(), 3u) << "the 2 px one is below min_area";
}

TEST(BlobFinder, BadSettingsAreNamed)
{
  BlobFinderSettings settings;
  EXPECT_EQ(findBadBlobSettings(settings), "");
  settings.colour.rgb = { 255, -1, 255 };
  EXPECT_EQ(findBadBlobSettings(settings), "the colour's channels must be in [0, 255], not -1");
  EXPECT_THROW(BlobFinder{ settings }, ConfigError);
  settings.colour.hsv = true;
  settings.colour.hue_max = 400.0;
  EXPECT_EQ(findBadBlobSettings(settings), "the hue range [0, 400] must be within [0, 360] degrees");
  settings.colour.hue_max = 20.0;
  settings.colour.value_min = 0.8;
  settings.colour.value_max = 0.5;
  EXPECT_NE(findBadBlobSettings(settings).find("must be rising within [0, 1]"), std::string::npos);
  settings.colour.value_min = 0.0;
  settings.min_area = 0;
  EXPECT_EQ(findBadBlobSettings(settings), "min_area must be at least 1 px, not 0");
}

}  // namespace
}  // namespace ptz_action_server

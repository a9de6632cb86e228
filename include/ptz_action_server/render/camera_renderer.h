/**
 * \file
 * \brief The simulated camera's picture: a backdrop of azimuth and elevation marks, and markers where frames are.
 *
 * Plain C++ and OpenCV, no ROS (the ROS side is SimCameraPublisher): one pinhole model for drawing and for aiming, so
 * what is drawn at pixel (u, v) is what rayThroughPixel(u, v), turned into the base frame, points at.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "ptz_action_server/core/motion/pinhole_view.h"
#include "ptz_action_server/render/direction_lookup.h"

namespace ptz_action_server
{
/// A point of the world drawn in the picture (a tf frame's origin).
struct SceneMarker
{
  std::string name;                                    ///< written beside its disc
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m, in the base frame (the frame pan and tilt turn in)
  bool present = false;                                ///< false: not drawn (its frame is not known yet)
};

/// An 8-bit RGB colour.
struct Rgb
{
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
};

/// How many marker colours there are; the list's marker i has markerColour(i), which repeats after this many.
constexpr std::size_t MARKER_COLOURS = 8;

/**
 * \brief The colour of the list's marker \p index: magenta, yellow, cyan, red, green, blue, orange, violet, then again.
 *
 * Each has a channel at 255 and one at 0, and nothing else in the picture has both (the backdrop, its marks and the
 * labels keep every channel within [20, 250]): a marker's disc is exactly the pixels of its colour.
 */
Rgb markerColour(std::size_t index);

/// What the picture shows besides the camera's pose.
struct RenderSettings
{
  double marker_radius = 0.0175;  ///< rad: a marker's disc spans fx * tan(marker_radius) pixels either side (1 degree)
};

/**
 * \brief Draws what the camera sees into an RGB image: sky, ground, the horizon, azimuth and elevation marks with their
 * degrees, and each present marker as a filled disc of its colour with its name.
 *
 * The world is a sphere of marks around the camera, infinitely far (only the camera's rotation moves it), in the
 * contract's angles: azimuth is the pan that looks there (clockwise from above, 0 along the base's x axis), elevation
 * the tilt. The marks' spacing follows the zoom (90 degrees down to 0.01, at least MIN_MARK_SPACING pixels apart);
 * the horizon and the four quarters of azimuth (0, 90, 180, -90) are drawn bolder. Markers are where they are (the
 * camera's offset from the pan axis counts), farther ones drawn first.
 *
 * Not thread-safe (one renderer per thread). The buffers are reused from one call to the next: rendering allocates
 * nothing of its own once the image size stays (OpenCV's resize, text and ellipse drawing take small temporary
 * buffers of their own).
 */
class CameraRenderer
{
public:
  /// Pixels the marks keep between them at least (at the image centre).
  static constexpr double MIN_MARK_SPACING = 48.0;

  explicit CameraRenderer(const RenderSettings& settings = RenderSettings());

  /// Draws into \p image (made CV_8UC3 of the intrinsics' size if it is not; RGB) what a camera link posed at
  /// \p camera_in_base (the base frame's pose of the link, as PtzKinematics::cameraInBase() gives it) sees through
  /// \p intrinsics.
  void render(const Eigen::Isometry3d& camera_in_base, const PinholeIntrinsics& intrinsics,
              const std::vector<SceneMarker>& markers, cv::Mat& image);

  /// The last render's per-pixel directions.
  const DirectionLookup& lookup() const
  {
    return lookup_;
  }
  /// The angle between two marks in the last render (rad).
  double markStep() const
  {
    return mark_step_;
  }

private:
  /// A marker projected into the image.
  struct Projected
  {
    std::size_t index = 0;  ///< in the markers' list: its colour
    double u = 0.0;
    double v = 0.0;
    double half_width = 0.0;   ///< px
    double half_height = 0.0;  ///< px
    double distance = 0.0;     ///< m from the camera
  };

  /// Sky and ground shaded by elevation, the marks blended over them (per pixel, from the lookup).
  void drawBackdrop(cv::Mat& image) const;
  /// The degrees of the marks in view, at their crossings with the marks nearest the image centre.
  void drawMarkLabels(cv::Mat& image);
  /// The markers in front of the camera, their names first and then their discs, the farthest first.
  void drawMarkers(const Eigen::Isometry3d& camera_in_base, const std::vector<SceneMarker>& markers, cv::Mat& image);
  /// Writes label_ with its top-left corner near (\p u, \p v), unless it would cover a label already written.
  void writeLabel(cv::Mat& image, double u, double v);
  /// The pixel of the direction \p azimuth, \p elevation (base frame, infinitely far); false if behind the camera.
  bool pixelOfDirection(double azimuth, double elevation, double& u, double& v) const;

  const RenderSettings settings_;
  DirectionLookup lookup_;
  PinholeIntrinsics intrinsics_;
  Eigen::Matrix3d base_to_optical_ = Eigen::Matrix3d::Identity();
  double mark_step_ = 0.0;
  std::string label_;                     ///< the label being written (its capacity reused)
  std::vector<cv::Rect> written_labels_;  ///< this render's label boxes, not to be covered
  std::vector<Projected> projected_;      ///< this render's markers in view
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief What each pixel of a pinhole image looks at: azimuth and elevation per pixel, interpolated from a coarse grid.
 *
 * Plain C++ and OpenCV, no ROS: the simulated camera's renderer shades its backdrop from it.
 */
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "ptz_action_server/core/motion/pinhole_view.h"

namespace ptz_action_server
{
/// The direction a pixel looks at, in the contract's angles (as directionOf() takes them), and how fast they change:
/// an angle's distance to a mark times its scale is the pixel's distance to that mark's line.
struct PixelDirection
{
  float azimuth = 0.0F;          ///< rad, relative to DirectionLookup::referenceAzimuth(), in (-pi, pi]
  float elevation = 0.0F;        ///< rad, up positive
  float azimuth_scale = 0.0F;    ///< pixels per rad of azimuth across its marks: 1 / |its gradient| (0 at a pole)
  float elevation_scale = 0.0F;  ///< pixels per rad of elevation across its marks: 1 / |its gradient|
};

/**
 * \brief Per pixel of an image, the azimuth and elevation (in the base frame, pan and tilt as the contract measures
 * them) of the ray the shared pinhole model (rayThroughPixel()) sends through it, and their scales in pixels.
 *
 * No trigonometry per pixel: the angles are computed exactly at the nodes of a grid GRID_STEP pixels apart and
 * cv::resize interpolates between them (bilinear: a mark lands within 0.05 px of its exact place, within 0.25 px with
 * the zenith or the nadir in view, where the elevation is a cone; the unit test measures it). Azimuths are taken
 * relative to the image centre's, so they only wrap opposite the view; the cells around a pole, where they wrap or
 * turn fast, are computed exactly per pixel instead. The buffers are allocated on
 * the first update() and reused while the image size stays.
 */
class DirectionLookup
{
public:
  /// Pixels between two grid nodes.
  static constexpr int GRID_STEP = 8;

  /// Fills the lookup for an image of \p intrinsics whose camera link has the axes \p camera_rotation (its columns:
  /// the link's x, y, z in the base frame; only the rotation matters, the backdrop being infinitely far).
  void update(const PinholeIntrinsics& intrinsics, const Eigen::Matrix3d& camera_rotation);

  /// The image-sized lookup: one PixelDirection (CV_32FC4) per pixel, valid after update().
  const cv::Mat& directions() const
  {
    return view_;
  }

  /// The azimuth of the image centre's ray (rad, contract pan): the directions' azimuths are relative to it.
  double referenceAzimuth() const
  {
    return reference_azimuth_;
  }

  /// The smallest and largest relative azimuth and elevation at the grid's nodes (rad): what the image may show.
  void range(double& min_azimuth, double& max_azimuth, double& min_elevation, double& max_elevation) const;

  /// Grid cells computed per pixel in the last update() (those around a pole).
  int exactCells() const
  {
    return exact_cells_;
  }

  /// The exact direction of pixel (\p u, \p v) (what the grid approximates), for the cells around a pole and the tests.
  PixelDirection exactAt(double u, double v) const;

private:
  /// Computes the pixels of the grid cell whose top-left node is (\p column, \p row) exactly.
  void computeCellExactly(int column, int row);

  PinholeIntrinsics intrinsics_;
  Eigen::Matrix3d optical_to_base_ = Eigen::Matrix3d::Identity();  ///< optical ray -> base-frame direction
  double reference_azimuth_ = 0.0;
  int exact_cells_ = 0;
  cv::Mat grid_;    ///< CV_32FC4 at the nodes: node (i, j) sits at pixel ((i - 0.5) s - 0.5, (j - 0.5) s - 0.5)
  cv::Mat padded_;  ///< CV_32FC4, the grid resized: GRID_STEP pixels per node, one cell of margin around the image
  cv::Mat view_;    ///< the image's part of padded_ (a view, no copy)
};

}  // namespace ptz_action_server

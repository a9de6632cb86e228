/**
 * \file
 * \brief Click to centre, drag to zoom: the pan, tilt and zoom that centre a pixel of an image, or fill the view with a
 * box of it, from the camera's pose when the image was taken.
 *
 * Works in the contract's angles, above the mount (MountedBackend): the pose history holds what the node reports
 * (contract angles for every mount), the URDF's chain and optical frame are the contract's, and the aim is a goal
 * like any other. The one thing a mount changes is the picture: a device hanging upside down whose image it does not
 * turn itself shows the world rotated by half a turn (PixelCamera::image_upside_down).
 */
#pragma once

#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/motion/pinhole_view.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// An image driver's calibration: its camera_info's K and image size, which hold at the zoom it was calibrated at.
struct CalibratedIntrinsics
{
  PinholeIntrinsics intrinsics;  ///< fx, fy, cx, cy of K (distortion is not modelled) and the calibrated size
  double zoom = 1.0;             ///< X the calibration holds at (the node's camera_info_zoom)
};

/// What the node knows of the camera's pixels.
struct PixelCamera
{
  /// The configured field of view (the node's FieldOfViewSettings::model); null: none. Needed for intrinsics at any
  /// zoom without a calibration, to carry a calibration to another zoom, and to find a box's zoom.
  const FieldOfViewModel* field_of_view = nullptr;
  /// A calibrated camera_info: intrinsics from its K, rescaled to the image's zoom (FieldOfViewModel::focalScale) and
  /// to the image's size. None: a centred principal point and the model's angles (intrinsicsFor).
  std::optional<CalibratedIntrinsics> calibration;
  /// The image shows the world turned by half a turn about the optical axis relative to the URDF's optical frame: a
  /// device mounted upside down (mount: inverted) that does not turn its picture itself.
  bool image_upside_down = false;
};

/// A click (or a box) on an image. Pixel coordinates as camera_info's K: (0, 0) is the centre of the top-left pixel.
struct PixelGoal
{
  double u = 0.0;           ///< px, column of the point to centre (a box: its centre)
  double v = 0.0;           ///< px, row
  double box_width = 0.0;   ///< px; 0 with box_height 0: centre only, the zoom stays. May reach past the image's edges
  double box_height = 0.0;  ///< px  (a box larger than the image zooms out)
  int image_width = 0;      ///< px of the image the pixel belongs to; 0: the calibration's
  int image_height = 0;     ///< px; 0: the calibration's
  /// m from the camera to what the pixel shows; 0 or infinity: far away, its direction alone. Known, it takes out the
  /// parallax of the URDF's camera offsets (the optical axis then passes through the point itself).
  double distance = 0.0;
};

/// Where to aim, or why not.
struct PixelAim
{
  std::string error;  ///< "" on success; else why not, for the goal's rejection (the rest means nothing)
  double pan = 0.0;   ///< rad, contract: the pixel's direction on the optical axis
  double tilt = 0.0;  ///< rad
  /// X, within the limits' zoom range: a box's zoom. NaN: leave the zoom alone (centre only, or a zoom the device
  /// cannot position, as notes says).
  double zoom = 0.0;
  /// How much of the view the box fills at \p zoom, as the larger of its relative width and height: 1 unless the zoom
  /// range (the device's, or a field-of-view table's) ended first; NaN without a box zoom.
  double box_fill = 0.0;
  std::string notes;                                    ///< "; " between them: a zoom clamped or ignored, an axis left
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< unit, URDF base frame: what the pixel shows, seen from the
                                                        ///< camera at the image's pose

  bool ok() const
  {
    return error.empty();
  }
};

/// The size of the image \p goal's pixel belongs to: the goal's, or where it gives none the calibration's (0 without).
void pixelGoalImageSize(const PixelGoal& goal, const PixelCamera& camera, int& width, int& height);

/// What \p goal cannot be on a \p width x \p height image (a size that is not positive, a pixel off the image, a box
/// with a side that is not positive, a negative distance), or "".
std::string findBadPixelGoal(const PixelGoal& goal, int width, int height);

/**
 * \brief The intrinsics of a \p width x \p height image taken at \p zoom: from the calibration (K rescaled from its
 * zoom to \p zoom and from its size to the image's) or from the field of view at \p zoom.
 *
 * Returns "" or why there are none: no field of view and no calibration, a calibration but no model to carry it to
 * another zoom, a size that is not positive.
 */
std::string intrinsicsAtZoom(const PixelCamera& camera, double zoom, int width, int height,
                             PinholeIntrinsics& intrinsics);

/**
 * \brief The aim that centres \p goal's pixel, and for a box the zoom that makes it fill the view.
 *
 * \p image_pose is the camera's contract pose when the image was taken (PoseHistory::at() of the image's stamp).
 * The pixel's ray at that pose (its intrinsics from intrinsicsAtZoom() at the pose's zoom) is aimed along
 * (PtzKinematics::aimAlong), or, with a distance, at the point it reaches (aimAt). For a box the rays through the
 * middles of its four sides are seen from the new aim, and the zoom is the largest whose view (the image's at the
 * new zoom) still holds them: the larger relative side fills it. The zoom is clamped into \p limits' zoom range, and
 * ignored (NaN, noted) on a device whose zoom cannot go to positions (findUnsupported()), as the contract says: "if
 * the camera does not support zoom ... the zoom field is ignored". Pan or tilt that cannot go to positions stays at
 * the image's (noted); both may lie outside \p limits: the goal's validation clamps or refuses them.
 *
 * An unknown image zoom (NaN) is taken as the wide end on a device without zoom (the calibration's zoom, or 1), and
 * is an error otherwise.
 */
PixelAim aimAtPixel(const PixelGoal& goal, const AxisValues& image_pose, const PixelCamera& camera,
                    const PtzKinematics& kinematics, const Capabilities& limits);

}  // namespace ptz_action_server

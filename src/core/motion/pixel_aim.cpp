#include "ptz_action_server/core/motion/pixel_aim.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace pixel_aim
{
constexpr double NOT_A_NUMBER = std::numeric_limits<double>::quiet_NaN();
constexpr double FILL_TOLERANCE = 1e-6;  ///< a box fill this close to 1 fills the view

void addNote(std::string& notes, const std::string& note)
{
  notes += (notes.empty() ? "" : "; ") + note;
}

}  // namespace pixel_aim

std::string findBadPixelGoal(const PixelGoal& goal, int width, int height)
{
  if (width <= 0 || height <= 0)
  {
    return formatText("the image size %d x %d px must be positive (give the image's width and height)", width, height);
  }
  // Pixel indices run from -0.5 (the outer edge of the first pixel) to size - 0.5 (of the last).
  if (!(goal.u >= -0.5 && goal.u <= width - 0.5 && goal.v >= -0.5 && goal.v <= height - 0.5))
  {
    return formatText("pixel (%g, %g) is not on the %d x %d px image", goal.u, goal.v, width, height);
  }
  const bool no_box = goal.box_width == 0.0 && goal.box_height == 0.0;
  if (!no_box && !(goal.box_width > 0.0 && goal.box_height > 0.0 && std::isfinite(goal.box_width) &&
                   std::isfinite(goal.box_height)))
  {
    return formatText("a box of %g x %g px cannot be filled: both sides must be positive (0 x 0: centre only)",
                      goal.box_width, goal.box_height);
  }
  if (!(goal.distance >= 0.0))  // also NaN
  {
    return formatText("the distance %g m must be positive, or 0 for far away", goal.distance);
  }
  return "";
}

namespace pixel_aim
{
/// The direction through pixel (\p u, \p v) of \p intrinsics in the camera link's axes.
Eigen::Vector3d linkRayThrough(const PinholeIntrinsics& intrinsics, bool upside_down, double u, double v)
{
  Eigen::Vector3d ray = rayThroughPixel(intrinsics, u, v);
  if (upside_down)
  {
    ray.x() = -ray.x();  // half a turn about the optical axis
    ray.y() = -ray.y();
  }
  return opticalToCameraLink(ray);
}

/**
 * \brief The angles a box spans, in the field-of-view model's terms, once the camera is at \p aimed: a view of the
 * model's at least this wide and tall holds the box.
 *
 * \p sides are the directions of the middles of the box's left, right, top and bottom sides in the camera link's
 * axes at \p camera_at_image; \p intrinsics the image's, at \p image_zoom. Returns "" or the error.
 */
std::string boxSpan(const std::array<Eigen::Vector3d, 4>& sides, const Eigen::Isometry3d& camera_at_image,
                    const Eigen::Isometry3d& aimed, double distance, const PinholeIntrinsics& intrinsics,
                    const FieldOfViewModel& field_of_view, double image_zoom, FieldOfViewAngles& span)
{
  // Half the box's extent as tangents off the new optical axis: horizontal from sides 0 and 1, vertical from 2 and 3.
  std::array<double, 2> half_tangent{ 0.0, 0.0 };
  for (std::size_t side = 0; side < sides.size(); ++side)
  {
    const Eigen::Vector3d in_base = camera_at_image.linear() * sides[side];
    const Eigen::Vector3d in_aimed_link =
        distance > 0.0 ? Eigen::Vector3d(aimed.inverse() * (camera_at_image.translation() + distance * in_base)) :
                         Eigen::Vector3d(aimed.linear().transpose() * in_base);
    const Eigen::Vector3d optical = cameraLinkToOptical(in_aimed_link);
    if (!(optical.z() > 0.0))
    {
      return "the box reaches behind the camera";
    }
    const double tangent = std::abs((side < 2 ? optical.x() : optical.y()) / optical.z());
    half_tangent[side / 2] = std::max(half_tangent[side / 2], tangent);
  }
  // The image reaches (size / 2) / f off its axis (as tangents), and f scales with the model's focal length from zoom
  // to zoom: the box fills a view whose model half-angle tangent is the image zoom's times half_tangent f / (size / 2).
  const FieldOfViewAngles at_image = field_of_view.at(image_zoom);
  span.horizontal =
      2.0 * std::atan(std::tan(at_image.horizontal / 2.0) * half_tangent[0] * intrinsics.fx / (0.5 * intrinsics.width));
  span.vertical =
      2.0 * std::atan(std::tan(at_image.vertical / 2.0) * half_tangent[1] * intrinsics.fy / (0.5 * intrinsics.height));
  return "";
}

/// How much of the view at \p zoom a box spanning \p span fills: the larger of its relative width and height.
double boxFill(const FieldOfViewModel& field_of_view, const FieldOfViewAngles& span, double zoom)
{
  const FieldOfViewAngles view = field_of_view.at(zoom);
  return std::max(std::tan(span.horizontal / 2.0) / std::tan(view.horizontal / 2.0),
                  std::tan(span.vertical / 2.0) / std::tan(view.vertical / 2.0));
}

/// The zoom (clamped into \p range) that fills the view with a box spanning \p span; \p aim's zoom, box_fill, notes.
void fillWithBox(const FieldOfViewModel& field_of_view, const FieldOfViewAngles& span, const AxisRange& range,
                 PixelAim& aim)
{
  const double ideal = field_of_view.zoomShowing(span);
  if (!std::isfinite(ideal))  // a span has angles in (0, pi) by construction; kept for a clear word all the same
  {
    addNote(aim.notes, "the box's zoom is ignored (no zoom of the field of view frames it)");
    return;
  }
  aim.zoom = std::min(std::max(ideal, range.min), range.max);
  aim.box_fill = boxFill(field_of_view, span, aim.zoom);
  if (std::abs(aim.box_fill - 1.0) <= FILL_TOLERANCE)
  {
    return;
  }
  const bool larger = aim.box_fill > 1.0;
  addNote(aim.notes,
          formatText("the box is %s than the %s view (zoom %g X, where %s ends): it fills %.0f %% of it",
                     larger ? "larger" : "smaller", larger ? "widest" : "narrowest", aim.zoom,
                     aim.zoom != ideal ? "the device's zoom range" : "the field of view model", 100.0 * aim.box_fill));
}
}  // namespace pixel_aim

void pixelGoalImageSize(const PixelGoal& goal, const PixelCamera& camera, int& width, int& height)
{
  width = goal.image_width > 0 || !camera.calibration ? goal.image_width : camera.calibration->intrinsics.width;
  height = goal.image_height > 0 || !camera.calibration ? goal.image_height : camera.calibration->intrinsics.height;
}

std::string intrinsicsAtZoom(const PixelCamera& camera, double zoom, int width, int height,
                             PinholeIntrinsics& intrinsics)
{
  if (width <= 0 || height <= 0)
  {
    return formatText("the image size %d x %d px must be positive", width, height);
  }
  if (!camera.calibration)
  {
    if (camera.field_of_view == nullptr)
    {
      return "no field of view is configured (field_of_view/horizontal and vertical, or field_of_view/table), so "
             "the pixel's direction is unknown";
    }
    intrinsics = intrinsicsFor(camera.field_of_view->at(zoom), width, height);
    return "";
  }
  const CalibratedIntrinsics& calibration = *camera.calibration;
  FocalScale scale;
  if (zoom != calibration.zoom)
  {
    if (camera.field_of_view == nullptr)
    {
      return formatText("the camera_info holds at zoom %g X and no field of view is configured to carry it to zoom "
                        "%g X",
                        calibration.zoom, zoom);
    }
    scale = camera.field_of_view->focalScale(calibration.zoom, zoom);
  }
  const PinholeIntrinsics& calibrated = calibration.intrinsics;
  if (calibrated.width <= 0 || calibrated.height <= 0 || !(calibrated.fx > 0.0) || !(calibrated.fy > 0.0))
  {
    return formatText("the camera_info's %d x %d px image or its focal lengths (%g, %g px) are not positive",
                      calibrated.width, calibrated.height, calibrated.fx, calibrated.fy);
  }
  // A resized image scales K about the outer corner of the first pixel, (-0.5, -0.5) in pixel indices.
  const double size_x = static_cast<double>(width) / calibrated.width;
  const double size_y = static_cast<double>(height) / calibrated.height;
  intrinsics.width = width;
  intrinsics.height = height;
  intrinsics.fx = calibrated.fx * size_x * scale.x;
  intrinsics.fy = calibrated.fy * size_y * scale.y;
  intrinsics.cx = (calibrated.cx + 0.5) * size_x - 0.5;
  intrinsics.cy = (calibrated.cy + 0.5) * size_y - 0.5;
  return "";
}

PixelAim aimAtPixel(const PixelGoal& goal, const AxisValues& image_pose, const PixelCamera& camera,
                    const PtzKinematics& kinematics, const Capabilities& limits)
{
  using pixel_aim::addNote;
  PixelAim aim;
  aim.zoom = pixel_aim::NOT_A_NUMBER;
  aim.box_fill = pixel_aim::NOT_A_NUMBER;
  int width = 0;
  int height = 0;
  pixelGoalImageSize(goal, camera, width, height);
  aim.error = findBadPixelGoal(goal, width, height);
  if (!aim.ok())
  {
    return aim;
  }
  for (const Axis axis : { PAN, TILT })
  {
    if (!std::isfinite(image_pose[axis]))
    {
      aim.error = formatText("the camera's %s when the image was taken is unknown", axisName(axis));
      return aim;
    }
  }
  // A device without zoom has a fixed lens: the view the calibration (or the wide end) describes, whatever it reports.
  double image_zoom = image_pose[ZOOM];
  if (!limits.axes[ZOOM].present)
  {
    image_zoom = camera.calibration ? camera.calibration->zoom : 1.0;
  }
  else if (!std::isfinite(image_zoom))
  {
    aim.error = "the camera's zoom when the image was taken is unknown, and with it the pixel's direction";
    return aim;
  }
  PinholeIntrinsics intrinsics;
  aim.error = intrinsicsAtZoom(camera, image_zoom, width, height, intrinsics);
  if (!aim.ok())
  {
    return aim;
  }

  const Eigen::Isometry3d camera_at_image = kinematics.cameraInBase(image_pose[PAN], image_pose[TILT]);
  aim.direction =
      camera_at_image.linear() * pixel_aim::linkRayThrough(intrinsics, camera.image_upside_down, goal.u, goal.v);
  const double distance = std::isfinite(goal.distance) ? goal.distance : 0.0;
  const bool aimed = distance > 0.0 ?
                         kinematics.aimAt(camera_at_image.translation() + distance * aim.direction, aim.pan, aim.tilt) :
                         kinematics.aimAlong(aim.direction, aim.pan, aim.tilt);
  if (!aimed)
  {
    aim.error = "no pan and tilt aim the camera at the pixel";
    return aim;
  }
  for (const Axis axis : { PAN, TILT })
  {
    const std::string unsupported = findUnsupported(limits, axis, AxisRequest::POSITION);
    if (!unsupported.empty())
    {
      (axis == PAN ? aim.pan : aim.tilt) = image_pose[axis];
      addNote(aim.notes, formatText("the %s stays (%s)", axisName(axis), unsupported.c_str()));
    }
  }

  if (goal.box_width == 0.0 && goal.box_height == 0.0)
  {
    return aim;
  }
  const std::string zoom_unsupported = findUnsupported(limits, ZOOM, AxisRequest::POSITION);
  if (!zoom_unsupported.empty())
  {
    addNote(aim.notes, "the box's zoom is ignored (" + zoom_unsupported + ")");
    return aim;
  }
  if (camera.field_of_view == nullptr)
  {
    addNote(aim.notes, "the box's zoom is ignored (no field of view is configured)");
    return aim;
  }
  const double half_width = goal.box_width / 2.0;
  const double half_height = goal.box_height / 2.0;
  const std::array<Eigen::Vector3d, 4> sides{
    pixel_aim::linkRayThrough(intrinsics, camera.image_upside_down, goal.u - half_width, goal.v),
    pixel_aim::linkRayThrough(intrinsics, camera.image_upside_down, goal.u + half_width, goal.v),
    pixel_aim::linkRayThrough(intrinsics, camera.image_upside_down, goal.u, goal.v - half_height),
    pixel_aim::linkRayThrough(intrinsics, camera.image_upside_down, goal.u, goal.v + half_height),
  };
  FieldOfViewAngles span;
  aim.error = pixel_aim::boxSpan(sides, camera_at_image, kinematics.cameraInBase(aim.pan, aim.tilt), distance,
                                 intrinsics, *camera.field_of_view, image_zoom, span);
  if (!aim.ok())
  {
    return aim;
  }
  pixel_aim::fillWithBox(*camera.field_of_view, span, limits.axes[ZOOM].range, aim);
  return aim;
}

}  // namespace ptz_action_server

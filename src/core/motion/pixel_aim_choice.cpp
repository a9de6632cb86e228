#include "ptz_action_server/core/motion/pixel_aim_choice.h"

#include <cmath>

#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// A camera whose pan and tilt are this close to the image's (rad, a fifth of a degree) still shows that picture.
constexpr double STILL_ANGLE = 0.0035;
/// ... and whose zoom is within this share of the image's.
constexpr double STILL_ZOOM = 0.02;

/// Why the node cannot compute the aim at \p goal on a \p width x \p height image whose pose was found, or "".
std::string whyNotComputed(const PixelGoal& goal, const AxisValues& image_pose, const PixelCamera& camera,
                           const Capabilities& limits, int width, int height)
{
  const AxisCapability& zoom = limits.axes[ZOOM];
  if (zoom.present && !std::isfinite(image_pose[ZOOM]))
  {
    return "the camera does not report its zoom, so the field of view of the image is unknown";
  }
  const double image_zoom = zoom.present ? image_pose[ZOOM] : camera.calibration ? camera.calibration->zoom : 1.0;
  PinholeIntrinsics intrinsics;
  const std::string no_intrinsics = intrinsicsAtZoom(camera, image_zoom, width, height, intrinsics);
  if (!no_intrinsics.empty())
  {
    return no_intrinsics;
  }
  const bool box = goal.box_width != 0.0 || goal.box_height != 0.0;
  if (box && zoom.present)
  {
    const std::string unsupported = findUnsupported(limits, ZOOM, AxisRequest::POSITION);
    if (!unsupported.empty())
    {
      return "the box's zoom cannot be computed (" + unsupported + ")";
    }
    if (camera.field_of_view == nullptr)
    {
      return "the box's zoom cannot be computed (no field of view is configured)";
    }
  }
  return "";
}

/// Why the camera no longer shows the picture of \p image_pose now (\p current), or "".
std::string findMovedSince(const AxisValues& image_pose, const PtzSample& current, const Capabilities& limits)
{
  if (current.moving)
  {
    return "the camera is moving";
  }
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = limits.axes[axis];
    const double then = image_pose[axis];
    const double now = current.position[axis];
    if (!capability.present || !capability.feedback || !std::isfinite(then))
    {
      continue;
    }
    const bool moved = axis == ZOOM ? std::abs(now / then - 1.0) > STILL_ZOOM :
                                      std::abs(std::remainder(now - then, 2.0 * M_PI)) > STILL_ANGLE;
    if (moved)
    {
      return formatText(axis == ZOOM ? "the camera's %s went from %.2f to %.2f %s since the image was taken" :
                                       "the camera's %s went from %.4f to %.4f %s since the image was taken",
                        axisName(axis), then, now, unitOf(axis));
    }
  }
  return "";
}
}  // namespace

const char* pixelAimWayName(PixelAimWay way)
{
  switch (way)
  {
    case PixelAimWay::COMPUTED:
      return "computed";
    case PixelAimWay::DEVICE:
      return "device";
    default:
      return "auto";
  }
}

bool parsePixelAimWay(const std::string& text, PixelAimWay& way)
{
  for (PixelAimWay candidate : { PixelAimWay::AUTO, PixelAimWay::COMPUTED, PixelAimWay::DEVICE })
  {
    if (text == pixelAimWayName(candidate))
    {
      way = candidate;
      return true;
    }
  }
  return false;
}

std::string describePixelAim(PixelAimWay way, const Capabilities& limits)
{
  const std::string device = "device (" + (limits.view_command.empty() ? "its own command" : limits.view_command) + ")";
  if (way == PixelAimWay::COMPUTED || !limits.view_centre)
  {
    return way == PixelAimWay::DEVICE ? "device, which this device has not: pixel goals are refused" : "computed";
  }
  return way == PixelAimWay::DEVICE ? device :
                                      "auto: " + device + " on the picture the camera still shows, computed otherwise";
}

PixelAimChoice choosePixelAim(PixelAimWay way, const PixelGoal& goal, const PoseLookup& image_pose,
                              const PtzSample& current, const PixelCamera& camera, const Capabilities& limits)
{
  PixelAimChoice choice;
  if (way == PixelAimWay::COMPUTED)
  {
    return choice;
  }
  if (!limits.view_centre)
  {
    if (way == PixelAimWay::DEVICE)
    {
      choice.error = "pixel_aim is device, and this device has no command of its own to centre a point of its "
                     "picture (set pixel_aim: auto or computed)";
    }
    return choice;
  }
  int width = 0;
  int height = 0;
  pixelGoalImageSize(goal, camera, width, height);
  const bool auto_way = way == PixelAimWay::AUTO;
  if (auto_way && (!image_pose.found() || width <= 0 || height <= 0))
  {
    return choice;  // the device has no better picture to point in: the computed way says why not
  }
  choice.error = findBadPixelGoal(goal, width, height);
  if (!choice.error.empty())
  {
    return choice;
  }
  if (!image_pose.found())
  {
    choice.error = image_pose.error;
    return choice;
  }
  const bool box = goal.box_width != 0.0 || goal.box_height != 0.0;
  const bool device_zooms = limits.view_box_zoom && limits.axes[ZOOM].present;
  const std::string why_not_computed =
      auto_way ? whyNotComputed(goal, image_pose.pose, camera, limits, width, height) : std::string();
  const std::string moved = findMovedSince(image_pose.pose, current, limits);
  if (!moved.empty())
  {
    if (auto_way && why_not_computed.empty())
    {
      choice.error.clear();
      return choice;  // the pose history aims right from a picture the camera has left
    }
    choice.error = moved + ": the device's own command aims in the picture it shows now, not in the image's" +
                   (why_not_computed.empty() ? std::string() :
                                               ", and the node cannot aim from the image's pose: " + why_not_computed);
    return choice;
  }
  if (auto_way && box && !device_zooms && why_not_computed.empty())
  {
    return choice;  // the device would only centre the box: the node also zooms to it
  }
  choice.device = true;
  ViewTarget& target = choice.target;
  // Pixel indices run from -0.5 (the outer edge of the first pixel) to size - 0.5 (of the last).
  target.x = (goal.u + 0.5) / width;
  target.y = (goal.v + 0.5) / height;
  target.image_width = width;
  target.image_height = height;
  choice.note = "aimed by the device's own command" +
                (limits.view_command.empty() ? std::string() : " (" + limits.view_command + ")") +
                (!auto_way ? std::string(": pixel_aim is device") : ": the camera still shows the image's picture");
  if (box)
  {
    if (device_zooms)
    {
      target.box_width = goal.box_width / width;
      target.box_height = goal.box_height / height;
    }
    else
    {
      choice.note += limits.axes[ZOOM].present ? "; the box's zoom is ignored (the device's own command only centres)" :
                                                 "; the box's zoom is ignored (the device has no zoom)";
    }
  }
  return choice;
}

}  // namespace ptz_action_server

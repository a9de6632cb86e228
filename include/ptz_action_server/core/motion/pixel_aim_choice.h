/**
 * \file
 * \brief Who aims at a pixel: the node, computing the aim from the pose history and the camera model (aimAtPixel), or
 * the device, with a command of its own on its current picture (VAPIX center / areazoom, ONVIF RelativeMove in
 * TranslationSpaceFov).
 *
 * The computed way needs the picture's field of view at the image's zoom (a field of view, or a calibrated camera_info
 * at that zoom) and the pose at the image's time; it then aims right from any image in the history, also one taken
 * while the camera moved. The device's command needs neither (the camera knows its lens, and its zoom even when it does
 * not report it), but it works on the picture the camera shows now: a click on an image the camera has moved away from
 * since would be off. So by default (PixelAimWay::AUTO) the node computes whenever it can, and leaves it to a device
 * that can only when it cannot.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/motion/pixel_aim.h"
#include "ptz_action_server/core/motion/pose_history.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// Which way pixel goals go (the node's ~pixel_aim).
enum class PixelAimWay
{
  AUTO,      ///< computed when the node can, else the device's own command where it has one
  COMPUTED,  ///< always computed (refused when the node cannot)
  DEVICE,    ///< always the device's own command (refused on a device without one)
};

/// "auto", "computed" or "device".
const char* pixelAimWayName(PixelAimWay way);
/// Reads "auto", "computed" or "device"; false for anything else.
bool parsePixelAimWay(const std::string& text, PixelAimWay& way);

/// How a pixel goal is aimed.
struct PixelAimChoice
{
  std::string error;    ///< "" unless the goal is refused (then the rest means nothing)
  bool device = false;  ///< the device's own command on \p target; false: the computed way (aimAtPixel)
  ViewTarget target;    ///< the pixel and box in the picture's normalised coordinates, for the device
  std::string note;     ///< why the device's command, and what it leaves out (the box's zoom), for the goal's texts
};

/**
 * \brief Decides who aims at \p goal's pixel, as \p way says.
 *
 * The node can compute when the image's pose was found (\p image_pose), its size is known and its intrinsics are at
 * the image's zoom (intrinsicsAtZoom(): a field of view, or a calibration at that zoom; a zoom the device does not
 * report is unknown), and, for a box, a field of view gives the box's zoom on a zoom that goes to positions. Under
 * AUTO the device aims when the node cannot and \p limits say it can (Capabilities::view_centre); the computed way
 * otherwise (which then refuses with its reason).
 *
 * The device's command is refused (error) when the goal is bad (findBadPixelGoal()), the image's pose is not found, or
 * the camera no longer shows that picture: it moves now (\p current), or it has moved since the image was taken (its
 * reported pan, tilt or zoom differ from the image's). A box on a device that cannot zoom to one is only centred
 * (noted). The image is the device's own picture, as it sends it: the device knows how it is turned, so
 * PixelCamera::image_upside_down does not apply.
 */
PixelAimChoice choosePixelAim(PixelAimWay way, const PixelGoal& goal, const PoseLookup& image_pose,
                              const PtzSample& current, const PixelCamera& camera, const Capabilities& limits);

}  // namespace ptz_action_server

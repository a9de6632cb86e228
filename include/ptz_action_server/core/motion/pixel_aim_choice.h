/**
 * \file
 * \brief Who aims at a pixel: the node, computing the aim from the pose history and the camera model (aimAtPixel), or
 * the device, with a command of its own on its current picture (VAPIX center / areazoom, ONVIF RelativeMove in
 * TranslationSpaceFov).
 *
 * The computed way needs the picture's field of view at the image's zoom (a field of view, or a calibrated camera_info
 * at that zoom) and the pose at the image's time; it then aims right from any image in the history, also one taken
 * while the camera moved. The device's command needs neither (the camera knows its own lens, and its zoom even when it
 * does not report it), but it works on the picture the camera shows now. So by default (PixelAimWay::AUTO) the device
 * aims when it has a command for it and the image is its own current picture (the camera rests where it was when the
 * image was taken), and the node computes otherwise.
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
  AUTO,      ///< the device's own command on the picture it still shows, computed otherwise
  COMPUTED,  ///< always computed (refused when the node cannot)
  DEVICE,    ///< always the device's own command (refused on a device without one)
};

/// "auto", "computed" or "device".
const char* pixelAimWayName(PixelAimWay way);
/// Reads "auto", "computed" or "device"; false for anything else.
bool parsePixelAimWay(const std::string& text, PixelAimWay& way);

/// How pixel goals are aimed on a device with \p limits under \p way, for the capabilities message: "computed",
/// "device (VAPIX center, areazoom)", "auto: device (...) on the picture the camera still shows, computed otherwise".
std::string describePixelAim(PixelAimWay way, const Capabilities& limits);

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
 * AUTO: the device (its own command, Capabilities::view_centre) when the image's pose was found and the camera still
 * shows that picture (at rest in \p current, its reported pan, tilt and zoom those of \p image_pose); a box the device
 * would only centre (no Capabilities::view_box_zoom) goes the computed way when the node can zoom to it. Otherwise the
 * computed way (aimAtPixel, which refuses with its reason), unless the node cannot compute (no intrinsics at the
 * image's zoom, a zoom the device does not report): then the goal is refused, naming both reasons.
 *
 * DEVICE: always the device's command; refused on a device without one, for a bad goal (findBadPixelGoal()), when the
 * image's pose is not found, or when the camera no longer shows that picture. COMPUTED: never the device.
 *
 * A box on a device that cannot zoom to one is only centred (noted). The image is the device's own picture, as it
 * sends it: the device knows how it is turned, so PixelCamera::image_upside_down does not apply.
 */
PixelAimChoice choosePixelAim(PixelAimWay way, const PixelGoal& goal, const PoseLookup& image_pose,
                              const PtzSample& current, const PixelCamera& camera, const Capabilities& limits);

}  // namespace ptz_action_server

/**
 * \file
 * \brief OnvifProtocol's aim in the camera's own picture: RelativeMove in the TranslationSpaceFov its PTZ configuration
 * options list (the PTZ specification's annex of additional spaces; what Frigate's click to centre sends).
 */
#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/onvif/onvif_protocol.h"

namespace ptz_action_server
{
void OnvifProtocol::planView()
{
  view_ = ViewPlan();
  const onvif::Space* pan_tilt = onvif::findSpace(option_spaces_.relative_pan_tilt, onvif::FOV_PAN_TILT_TRANSLATION);
  if (pan_tilt == nullptr || !pan_tilt_.feedback)
  {
    return;  // without a reported pan-tilt the goal could not tell that the camera moved: the node computes
  }
  view_.centre = true;
  view_.x = pan_tilt->x;
  view_.y = pan_tilt->y;
  if (!zoom_.present)
  {
    return;
  }
  if (const onvif::Space* fov = onvif::findSpace(option_spaces_.relative_zoom, onvif::FOV_ZOOM_TRANSLATION))
  {
    view_.zoom = ViewPlan::Zoom::FOV;
    view_.z = fov->x;
  }
  else if (const onvif::Space* generic =
               onvif::findSpace(option_spaces_.relative_zoom, onvif::GENERIC_ZOOM_TRANSLATION))
  {
    view_.zoom = ViewPlan::Zoom::GENERIC;
    view_.z = generic->x;
  }
}

void OnvifProtocol::aimInView(const ViewTarget& target)
{
  if (!view_.centre)
  {
    return;  // not declared: the supervisor never asks
  }
  velocity_body_.clear();
  motion_check_.clear();
  onvif::Vector translation;
  translation.pan_tilt = true;
  translation.pan_tilt_space = onvif::FOV_PAN_TILT_TRANSLATION;
  // The picture's centre is (0, 0), its upper right corner (1, 1).
  translation.x = std::clamp(2.0 * target.x - 1.0, view_.x.min, view_.x.max);
  translation.y = std::clamp(1.0 - 2.0 * target.y, view_.y.min, view_.y.max);
  if (target.box() && view_.zoom != ViewPlan::Zoom::NONE)
  {
    translation.zoom = true;
    const double magnification = target.magnification();
    if (view_.zoom == ViewPlan::Zoom::FOV)
    {
      translation.zoom_space = onvif::FOV_ZOOM_TRANSLATION;
      translation.z = std::clamp(magnification, std::max(view_.z.min, 0.0), view_.z.max);
    }
    else
    {
      // X = zoom_max ^ z: a magnification m adds log(m) / log(zoom_max) to the generic zoom.
      translation.zoom_space = onvif::GENERIC_ZOOM_TRANSLATION;
      translation.z = std::clamp(std::log(magnification) / std::log(settings_.zoom_max), view_.z.min, view_.z.max);
    }
  }
  command(paths_.ptz, onvif::relativeMove(profile_.token, translation), "RelativeMove");
}

}  // namespace ptz_action_server

/**
 * \file
 * \brief The node's mount and field-of-view settings, read once from its parameters.
 */
#pragma once

#include <optional>
#include <string>

#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/mounted_backend.h"
#include "ptz_action_server/ros/param_reader.h"

namespace ptz_action_server
{
/// Reads ~mount ("upright" or "inverted") and ~pan_offset (rad, in [-2 pi, 2 pi]).
MountConfig loadMountConfig(const ParamReader& params);

/// What the node publishes about the camera's field of view.
struct FieldOfViewSettings
{
  std::optional<FieldOfViewModel> model;  ///< none: no field_of_view topic and no camera_info rescale
  std::string camera_info_topic;          ///< "": no camera_info rescale; else republished as <topic>_zoomed
  double camera_info_zoom = 1.0;          ///< X the incoming camera_info was calibrated at

  /// Reads ~field_of_view/horizontal and ~field_of_view/vertical (wide end, rad, with ~field_of_view/zoom_law) or
  /// ~field_of_view/table (a list of [zoom, horizontal, vertical] rows), ~camera_info_topic and ~camera_info_zoom. A
  /// camera_info topic needs a field of view. Throws ConfigError naming the parameter.
  static FieldOfViewSettings load(const ParamReader& params);
};

}  // namespace ptz_action_server

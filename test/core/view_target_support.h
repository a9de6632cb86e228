/**
 * \file
 * \brief A point of a 640 x 360 picture, and a square box around it, as the view-aim tests give a device.
 */
#pragma once

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// (\p x, \p y) of the picture (0..1), with a box of \p box of its width and height (0: centre only).
inline ViewTarget viewTargetAt(double x, double y, double box = 0.0)
{
  ViewTarget target;
  target.x = x;
  target.y = y;
  target.box_width = box;
  target.box_height = box;
  target.image_width = 640;
  target.image_height = 360;
  return target;
}

}  // namespace ptz_action_server

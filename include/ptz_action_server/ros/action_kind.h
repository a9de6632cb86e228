/**
 * \file
 * \brief The node's actions, for names and messages.
 */
#pragma once

namespace ptz_action_server
{
/// One of the actions, for names and messages; each action has its row, in this order, in NODE_ACTIONS
/// (action_servers.h), the table of the node's actions.
enum class ActionKind
{
  POSITION_ABS,
  POSITION_REL,
  VELOCITY,
  POSITION_ABS_TF,
  FRAME,
  TRACK_FRAME,
  PRESET,
  PIXEL,
  TRACK_DETECTIONS,
  TOUR,
  POSITION_ABS_SPEED,
  CLICKED_POINT,  ///< not an action: a point on the clicked point topic (LookAtClickedPoint)
  IMAGE_CLICK,    ///< not an action: a click on <image_topic>_mouse_left (ImageClicks)
};

/// "position_abs", ..., the name under move_ptz/ (NODE_ACTIONS); "look_at_clicked_point" for a clicked point,
/// "image_click" for a click on an image.
const char* actionName(ActionKind kind);

}  // namespace ptz_action_server

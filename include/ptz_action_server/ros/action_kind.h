/**
 * \file
 * \brief The node's actions, for names and messages.
 */
#pragma once

namespace ptz_action_server
{
/// One of the actions, for names and messages.
enum class ActionKind
{
  POSITION_ABS,
  POSITION_REL,
  VELOCITY,
  POSITION_ABS_TF,
  FRAME,
  TRACK_FRAME,
  PRESET,
  CLICKED_POINT,  ///< not an action: a point on the clicked point topic (LookAtClickedPoint)
};

/// "position_abs", ..., the name under move_ptz/.
const char* actionName(ActionKind kind);

}  // namespace ptz_action_server

/**
 * \file
 * \brief Checks a goal against the device's limits before anything moves.
 */
#pragma once

#include <array>
#include <string>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// Goals this far outside a limit are taken as the limit itself: float32 goals cannot hold pi exactly.
constexpr double LIMIT_EPSILON = 1e-5;

/// The outcome of a validation: what to command, or why not.
struct ValidatedGoal
{
  bool accepted = false;
  /// The values to command (clamped where allowed). An absent axis holds its range minimum; a zoom the goal leaves
  /// alone on a device that cannot position it holds NaN ("leave it where it is", see PtzBackend::goTo()).
  AxisValues values{};
  /// The axes the goal asks for: only these are judged (a goal is never reported reached on an axis it did not ask
  /// for, nor on one the device cannot move).
  std::array<bool, AXIS_COUNT> judged{};
  bool clamped = false;
  /// The rejection reason; or the notes of an accepted goal (what was clamped, a zoom ignored or left alone, "; "
  /// between them); empty otherwise.
  std::string message;
};

/// Returns "" if every value is finite, else the reason naming the first axis that is NaN or Inf.
std::string findNonFinite(const AxisValues& values, const char* quantity);

/// What a goal asks of an axis, for findUnsupported()'s words.
enum class AxisRequest
{
  POSITION,  ///< go to a position (absolute, relative, preset, frame goals)
  OFFSET,    ///< move by an offset from where it is (the node's position_rel)
  VELOCITY,  ///< move at a speed
};

/**
 * \brief Why \p axis cannot do \p request on a device with \p capabilities, or "" when it can.
 *
 * The text names what the device lacks and what to set, e.g. "this camera reports no zoom position: zoom goals are
 * not supported; set axis/zoom_table". A position needs `absolute` and `feedback` (a goal the node cannot see
 * reached is never reported reached), an offset `feedback`, a velocity `velocity`; every request needs `present`.
 */
std::string findUnsupported(const Capabilities& capabilities, Axis axis, AxisRequest request);

/// The zoom a position goal of zoom \p value commands on \p zoom, by validatePositionGoal()'s rule (for the aims a
/// goal is steered to after its validation, as track_frame's): the range minimum on a device without zoom; \p value
/// clamped into the range on a zoom that goes to positions; else 1 (the widest view) where the device can go there
/// and \p value is 1, and NaN ("leave it where it is") otherwise.
double commandedZoom(const AxisCapability& zoom, double value);

/// True when a position goal's \p value leaves pan or tilt alone on a device without the axis: 0, as clients of
/// pan-only devices send. (Zoom follows the seed's rule instead, see validatePositionGoal().)
bool leavesAxisAlone(const Capabilities& capabilities, Axis axis, double value);

/**
 * \brief Validates an absolute position goal (pan, tilt in rad, zoom as X) against \p limits.
 *
 * NaN or Inf anywhere rejects the goal, as does a pan or tilt the device cannot position or report (see
 * findUnsupported(); leavesAxisAlone() values are accepted and not judged). A value outside its range rejects it,
 * or, with \p clamp, is clamped and noted in the message.
 *
 * Zoom follows the seed: "if the camera does not support zoom (e.g. the Flir D46 PTU), the zoom field is ignored".
 * On a device without zoom any zoom is accepted, commanded as the axis' range minimum and not judged, and the message
 * says it was ignored (unless it was 0 or 1, which ask nothing). On a device with a zoom it cannot position, zoom 0
 * leaves it alone (NaN) and zoom 1, the widest view, is always accepted: sent as 1 where the axis has `widest_view`,
 * else left alone, judged only with feedback, and noted; any other zoom is refused naming the remedy.
 */
ValidatedGoal validatePositionGoal(const AxisValues& target, const Capabilities& limits, bool clamp);

/// Validates a velocity goal (rad/s, X/s) against each axis' max speed, with the same rules: a non-zero velocity on
/// an axis that cannot move at a speed is refused (but a zoom velocity on a device without zoom is ignored, and
/// noted), zero is accepted everywhere.
ValidatedGoal validateVelocityGoal(const AxisValues& velocity, const Capabilities& limits, bool clamp);

}  // namespace ptz_action_server

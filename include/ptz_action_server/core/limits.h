/**
 * \file
 * \brief The limits goals are checked against: the URDF's joint limits, narrowed by what the device can do.
 */
#pragma once

#include <string>
#include <vector>

#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Pan and tilt limits and speeds from the URDF joints, inside the contract's [-pi, pi] and [-pi/2, pi/2].
 *
 * Zoom gets the range [1, 1]: the URDF knows nothing of it. Throws ConfigError when a joint's range is empty inside
 * the contract's.
 */
Capabilities urdfLimits(const PtzKinematics& kinematics);

/// The device's capabilities narrowed by the URDF's limits, and what the node should warn about.
struct LimitIntersection
{
  Capabilities limits;                ///< what goals are checked against
  std::vector<std::string> warnings;  ///< one line per axis whose device range is narrower than the URDF's
};

/**
 * \brief Narrows \p device to \p urdf on pan and tilt: the tighter range and the lower max speed win (a URDF
 * speed of 0 means none). Zoom is the device's.
 *
 * Throws ConfigError when the device's and the URDF's ranges of an axis do not overlap.
 */
LimitIntersection intersectLimits(const Capabilities& device, const Capabilities& urdf);

}  // namespace ptz_action_server

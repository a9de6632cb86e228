/**
 * \file
 * \brief The parameter values behind the published PanTilt golden frames (published-wire-facts.md 2.2, 2.3), shared
 * by the PanTilt codec tests.
 */
#pragma once

#include "ptz_action_server/core/pantilt/pantilt_codec.h"

namespace pantilt_test
{
/// Positions 100/200, angles 10/-5, speeds 1/2, the seed's combined fields 300 / 45.5 / 3, the v1.x flags set and the
/// customs 0.
inline cr::pantilt::PanTiltParams goldenParams()
{
  cr::pantilt::PanTiltParams params;
  params.panMotorPosition = 100;
  params.tiltMotorPosition = 200;
  params.panAngle = 10.0f;
  params.tiltAngle = -5.0f;
  params.panTiltMotorPosition = 300;
  params.panTiltAngle = 45.5f;
  params.panMotorSpeed = 1.0f;
  params.tiltMotorSpeed = 2.0f;
  params.panTiltMotorSpeed = 3.0f;
  params.isConnected = true;
  params.isOpen = true;
  return params;
}
}  // namespace pantilt_test

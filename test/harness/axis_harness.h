/**
 * \file
 * \brief The Axis (VAPIX) harness: AxisCameraEmulator behind its HTTP server (Digest, or https with its certificate
 * pinned), the axis backend with the camera's credentials.
 */
#pragma once

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
class AxisHarness : public HttpCameraHarness<AxisCameraEmulator, AxisCameraEmulatorConfig, AxisProtocol>
{
public:
  explicit AxisHarness(const AxisCameraEmulatorConfig& camera = AxisCameraEmulatorConfig(),
                       DeviceConfig<AxisProtocol> backend = {})
    : HttpCameraHarness(camera, std::move(backend), camera.http.username, camera.http.password)
  {
  }
};

}  // namespace ptz_action_server

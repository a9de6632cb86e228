/**
 * \file
 * \brief The ONVIF harness: OnvifCameraEmulator behind its HTTP server (http, or https with its certificate pinned),
 * the onvif backend with the camera's credentials for WS-Security and, where the camera demands it, HTTP Digest.
 */
#pragma once

#include "harness/emulator_harness.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
class OnvifHarness : public HttpCameraHarness<OnvifCameraEmulator, OnvifCameraEmulatorConfig, OnvifProtocol>
{
public:
  explicit OnvifHarness(const OnvifCameraEmulatorConfig& camera = OnvifCameraEmulatorConfig(),
                        DeviceConfig<OnvifProtocol> backend = {})
    : HttpCameraHarness(camera, std::move(backend), camera.username, camera.password)
  {
    config_.settings.username = camera.username;
    config_.settings.password = camera.password;
  }
};

}  // namespace ptz_action_server

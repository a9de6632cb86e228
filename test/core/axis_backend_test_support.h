/**
 * \file
 * \brief What the Axis backend's tests share: a backend config for a camera on 127.0.0.1, the requests the camera
 * received, the field camera of issue 21.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
namespace axis_backend_test
{
inline constexpr double WAIT = 15.0;

inline DeviceConfig<AxisProtocol> configFor(std::uint16_t port, const std::string& password = "pass")
{
  DeviceConfig<AxisProtocol> config;
  config.link.port = port;
  config.link.http.username = "root";
  config.link.http.password = password;
  config.session.startup_timeout = 5.0;
  config.session.state_timeout = 1.0;
  return config;
}

/// The targets of the requests \p server received that contain \p containing, in order.
inline std::vector<std::string> targets(HttpCameraServer& server, const std::string& containing)
{
  std::vector<std::string> found;
  for (const HttpExchange& exchange : server.received().items())
  {
    if (exchange.target.find(containing) != std::string::npos)
    {
      found.push_back(exchange.target);
    }
  }
  return found;
}

/// The camera of issue 21: firmware without the zoom attributes, a 30X lens (VAPIX zoom 1..9999, linear), \p model.
inline AxisCameraEmulatorConfig fieldCamera(const std::string& model)
{
  AxisCameraEmulatorConfig camera;
  camera.attributes = false;
  camera.zoom_table = AxisCameraEmulatorConfig::linearZoomTable(30.0);
  camera.model = model;
  return camera;
}

}  // namespace axis_backend_test
}  // namespace ptz_action_server

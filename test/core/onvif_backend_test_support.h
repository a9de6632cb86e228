/**
 * \file
 * \brief What the ONVIF backend's tests share: an emulated camera's backend config, the start-up error, the requests
 * the camera received, the warnings told.
 */
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
namespace onvif_backend_test
{
inline constexpr double WAIT = 15.0;

inline DeviceConfig<OnvifProtocol> configFor(const OnvifCameraEmulator& camera, const std::string& password = "admin")
{
  DeviceConfig<OnvifProtocol> config;
  config.link.port = camera.port();
  config.link.http.username = "admin";
  config.link.http.password = password;
  config.settings.username = "admin";
  config.settings.password = password;
  config.session.startup_timeout = 5.0;
  config.session.state_timeout = 1.0;
  return config;
}

inline std::string startupError(const DeviceConfig<OnvifProtocol>& config)
{
  try
  {
    makeDeviceBackend<OnvifProtocol>(config)->start();
  }
  catch (const BackendError& error)
  {
    return error.what();
  }
  return {};
}

inline std::size_t countOf(HttpCameraServer& server, const std::string& text)
{
  std::size_t count = 0;
  for (const HttpExchange& exchange : server.received().items())
  {
    count += exchange.body.find(text) != std::string::npos ? 1 : 0;
  }
  return count;
}

inline std::string lastBodyOf(HttpCameraServer& server, const std::string& operation)
{
  std::string body;
  for (const HttpExchange& exchange : server.received().items())
  {
    body = exchange.body.find("<tptz:" + operation) != std::string::npos ? exchange.body : body;
  }
  return body;
}

inline DeviceConfig<OnvifProtocol> configForMode(const std::string& mode, std::unique_ptr<OnvifCameraEmulator>& camera)
{
  OnvifCameraEmulatorConfig camera_config;
  EXPECT_TRUE(camera_config.applyMode(mode)) << mode;
  camera = std::make_unique<OnvifCameraEmulator>(camera_config);
  return configFor(*camera);
}

/// What \p backend's camera was told once, as the node takes it.
inline std::vector<std::string> toldOnce(DeviceBackend& backend)
{
  std::vector<std::string> told = backend.takeWarnings();
  EXPECT_TRUE(backend.takeWarnings().empty());
  return told;
}

}  // namespace onvif_backend_test
}  // namespace ptz_action_server

/**
 * \file
 * \brief What only the ONVIF backend does, against onvif_camera_emulator's camera on 127.0.0.1: the bring-up (clock
 * offset, configured host kept, profile, node), ContinuousMove re-sent before its timeout, and the start-up failures
 * named (a wrong password, a missing profile, a timeout the camera does not take).
 */
#include <gtest/gtest.h>

#include <cmath>

#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
constexpr double WAIT = 15.0;

OnvifConfig configFor(const OnvifCameraEmulator& camera, const std::string& password = "admin")
{
  OnvifConfig config;
  config.link.port = camera.port();
  config.link.http.username = "admin";
  config.link.http.password = password;
  config.onvif.username = "admin";
  config.onvif.password = password;
  config.session.startup_timeout = 5.0;
  config.session.state_timeout = 1.0;
  return config;
}

std::string startupError(const OnvifConfig& config)
{
  try
  {
    makeOnvifBackend(config)->start();
  }
  catch (const BackendError& error)
  {
    return error.what();
  }
  return {};
}

std::size_t countOf(HttpCameraServer& server, const std::string& text)
{
  std::size_t count = 0;
  for (const HttpExchange& exchange : server.received().items())
  {
    count += exchange.body.find(text) != std::string::npos ? 1 : 0;
  }
  return count;
}

TEST(OnvifBackend, BringsUpInTheCamerasClockAndKeepsTheConfiguredHost)
{
  OnvifCameraEmulatorConfig camera_config;
  camera_config.clock_offset = 3600.0;  // tokens stamped in our clock would be an hour off and refused
  OnvifCameraEmulator camera(camera_config);
  auto backend = makeOnvifBackend(configFor(camera));
  backend->start();
  EXPECT_EQ(camera.refusedTokens(), 0u);
  const Capabilities capabilities = backend->capabilities();
  EXPECT_NEAR(capabilities.axes[PAN].range.max, M_PI, 1e-9);  // from the degree space's XRange
  EXPECT_NEAR(capabilities.axes[TILT].range.min, -M_PI / 2.0, 1e-9);
  EXPECT_TRUE(capabilities.axes[ZOOM].present);
  EXPECT_NEAR(capabilities.axes[ZOOM].range.max, 18.0, 1e-9);
  for (const char* operation :
       { "GetSystemDateAndTime", "GetCapabilities", "GetProfiles", "GetNodes", "GetConfigurationOptions", "GetStatus" })
  {
    EXPECT_GE(countOf(camera.server(), operation), 1u) << operation;
  }
  // The camera advertised 192.0.2.1; every request still reached it at the configured 127.0.0.1.
  backend->goTo({ 0.4, -0.1, 3.0 });
  ASSERT_TRUE(waitUntil(
      [&] { return std::abs(backend->sample().position[PAN] - 0.4) < 1e-3 && !backend->sample().moving; }, WAIT));
  EXPECT_NEAR(camera.sample().position[ZOOM], 3.0, 1e-3);
  EXPECT_NEAR(backend->sample().position[ZOOM], 3.0, 1e-3);
  EXPECT_EQ(camera.server().counters().connections, 1u);
}

TEST(OnvifBackend, AContinuousMoveIsResentBeforeItsTimeout)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  OnvifConfig config = configFor(camera);
  config.onvif.velocity_timeout = 1;
  auto backend = makeOnvifBackend(config);
  backend->start();
  backend->moveAtVelocity({ 0.3, 0.0, 0.0 });
  const auto& protocol = backend->protocol<OnvifProtocol>();
  // Three refreshes take 1.5 s: without them the camera would have stopped after its 1 s timeout.
  ASSERT_TRUE(waitUntil([&] { return protocol.counters().velocity_refreshes >= 3; }, WAIT));
  EXPECT_NEAR(camera.sample().velocity[PAN], 0.3, 0.02);
  EXPECT_NE(countOf(camera.server(), "<tptz:Timeout>PT1S</tptz:Timeout>"), 0u);
  backend->stop();
  ASSERT_TRUE(waitUntil([&] { return !camera.sample().moving; }, WAIT));
  EXPECT_EQ(countOf(camera.server(), "<tptz:Stop>"), 1u);
}

TEST(OnvifBackendStartup, AWrongPasswordIsTheCamerasFaultWithoutThePassword)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  const std::string error = startupError(configFor(camera, "hunter2"));
  EXPECT_EQ(error, "an ONVIF camera on http://127.0.0.1:" + std::to_string(camera.port()) +
                       ": the ONVIF camera refused GetCapabilities: ter:NotAuthorized: Sender not Authorized: a wrong "
                       "username or password");
  EXPECT_EQ(error.find("hunter2"), std::string::npos);
}

TEST(OnvifBackendStartup, AMissingProfileAndAnUnacceptableTimeoutAreNamed)
{
  OnvifCameraEmulator camera{ OnvifCameraEmulatorConfig() };
  OnvifConfig config = configFor(camera);
  config.onvif.profile = "nope";
  EXPECT_EQ(startupError(config), "an ONVIF camera on http://127.0.0.1:" + std::to_string(camera.port()) +
                                      ": GetProfiles: no profile 'nope' with a PTZConfiguration (profiles: profile_0, "
                                      "profile_1)");
  config.onvif.profile.clear();
  config.onvif.velocity_timeout = 100;
  EXPECT_EQ(startupError(config), "an ONVIF camera on http://127.0.0.1:" + std::to_string(camera.port()) +
                                      ": velocity_timeout 100 s is outside the camera's PTZTimeout range [1, 60] s");
}

TEST(OnvifBackendStartup, ACameraThatDemandsHttpDigestTooIsServed)
{
  OnvifCameraEmulatorConfig camera_config;
  camera_config.http.auth = HttpAuth::DIGEST;
  camera_config.http.username = "admin";
  camera_config.http.password = "admin";
  OnvifCameraEmulator camera(camera_config);
  auto backend = makeOnvifBackend(configFor(camera));
  backend->start();
  EXPECT_TRUE(backend->sample().link_up);
  // The first POST goes without HTTP authentication (a camera may want none) and meets the one challenge; its
  // nonce serves the rest of the bring-up and every poll.
  EXPECT_EQ(camera.server().counters().challenges, 1u);
  EXPECT_EQ(camera.server().counters().refused_credentials, 0u);
}

}  // namespace
}  // namespace ptz_action_server

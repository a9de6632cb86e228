/**
 * \file
 * \brief An emulated ONVIF PTZ camera: device, media and PTZ services (SOAP 1.2) behind WS-Security UsernameToken
 * (and HTTP Digest if asked), over the shared sim motion model.
 */
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/sim_device_model.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
namespace onvif
{
struct SoapMessage;
}

/// The camera the emulator plays.
struct OnvifCameraEmulatorConfig
{
  OnvifCameraEmulatorConfig()
  {
    http.auth = HttpAuth::NONE;  // ONVIF authenticates in the message; HttpAuth::DIGEST makes it demand both
    http.realm = "onvif_camera";
  }
  HttpCameraServerConfig http;
  std::string username = "admin";  ///< WS-Security user
  std::string password = "admin";
  /// Pan -180..180 deg, tilt -90..90 deg (generic x = pan / 180 deg, y = tilt / 90 deg), zoom 1..18X.
  SimDeviceConfig device = defaultDevice();
  bool degree_space = true;    ///< lists SphericalPositionSpaceDegrees (Profile T); false: generic spaces only
  double clock_offset = 0.0;   ///< s the camera's clock runs ahead of the system's (tokens are judged by it)
  double max_token_age = 5.0;  ///< s a UsernameToken's Created may differ from the camera's clock
  std::string advertised_host = "192.0.2.1";  ///< the host GetCapabilities' XAddrs name (wrong, as some firmware's)

  static SimDeviceConfig defaultDevice();
};

/**
 * \brief An ONVIF camera on 127.0.0.1: `/onvif/device_service` (GetSystemDateAndTime without authentication,
 * GetCapabilities), `/onvif/media_service` (GetProfiles: `profile_0` without PTZ, `profile_1` with `ptz0` on node
 * `node0`), `/onvif/ptz_service` (GetNodes, GetConfigurationOptions, AbsoluteMove, ContinuousMove with its Timeout,
 * Stop, GetStatus). Faults as cameras send them: ter:NotAuthorized (HTTP 400), ter:InvalidArgVal,
 * ter:ActionNotSupported. Answers use prefixes of their own (`env:`, a default namespace), as cameras differ.
 */
class OnvifCameraEmulator
{
public:
  explicit OnvifCameraEmulator(const OnvifCameraEmulatorConfig& config,
                               std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~OnvifCameraEmulator();

  std::uint16_t port() const
  {
    return server_->port();
  }
  HttpCameraServer& server()
  {
    return *server_;
  }
  PtzSample sample() const;
  /// Refuses every move with a fault carrying REFUSAL.
  void setRefuse(bool refuse);
  /// Fault hooks of the motion model: a stalled axis accepts every command and silently stays where it is.
  void setFaults(const SimFaults& faults);
  static constexpr const char* REFUSAL = "PTZ is locked by another user";

  /// Tokens the camera refused (a wrong password, a stale Created).
  std::uint64_t refusedTokens() const;

private:
  HttpAnswer handle(const std::string& target, const std::string& body);
  HttpAnswer operate(const std::string& operation, const onvif::SoapMessage& message, TimePoint now);
  /// The reason a token is refused, or "".
  std::string checkToken(const onvif::SoapMessage& message) const;
  void expireVelocity(TimePoint now) const;
  double cameraUtc() const;

  const OnvifCameraEmulatorConfig config_;
  const std::shared_ptr<const Clock> clock_;
  mutable std::mutex mutex_;  ///< guards everything below
  mutable SimDeviceModel model_;
  bool refuse_ = false;
  mutable bool velocity_active_ = false;
  TimePoint velocity_until_{};
  std::uint64_t refused_tokens_ = 0;
  std::unique_ptr<HttpCameraServer> server_;  ///< last: its thread calls handle()
};

}  // namespace ptz_action_server

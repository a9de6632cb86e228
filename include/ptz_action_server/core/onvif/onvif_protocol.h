/**
 * \file
 * \brief ONVIF PTZ cameras (SOAP 1.2 over HTTP POST): bring-up of the clock, services, profile and node; AbsoluteMove,
 * ContinuousMove, Stop and GetStatus, stamped with WS-Security UsernameToken digests in the camera's clock.
 */
#pragma once

#include <memory>
#include <random>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"

namespace ptz_action_server
{
/// How a generic-space coordinate maps to an angle: angle = sign * scale * x + offset.
struct GenericAxisMapping
{
  double scale = M_PI;  ///< rad of x = 1
  double offset = 0.0;  ///< rad at x = 0
  double sign = 1.0;    ///< -1 for cameras that turn left for a positive pan
};

/// What only the ONVIF protocol needs to know.
struct OnvifSettings
{
  std::string device_path = "/onvif/device_service";  ///< where GetSystemDateAndTime and GetCapabilities go
  std::string profile;                                ///< profile token; "" = the first with a PTZConfiguration
  std::string username;                               ///< WS-Security user ("" = no WS-Security)
  std::string password;                               ///< never printed
  bool prefer_degrees = true;                         ///< use SphericalPositionSpaceDegrees when the node lists it
  GenericAxisMapping pan{ M_PI, 0.0, 1.0 };
  GenericAxisMapping tilt{ M_PI / 2.0, 0.0, 1.0 };
  double velocity_sign_pan = 1.0;  ///< a camera may turn its velocities otherwise than its positions
  double velocity_sign_tilt = 1.0;
  double zoom_max = 18.0;       ///< X at generic zoom 1 (zoom 0 is 1X; X = zoom_max ^ z, never linear)
  double pan_max_speed = 1.5;   ///< rad/s at generic velocity 1
  double tilt_max_speed = 1.0;  ///< rad/s
  double zoom_max_rate = 8.0;   ///< X/s at generic zoom velocity 1
  double acceleration = 3.0;    ///< rad/s^2, for goal timeouts
  int velocity_timeout = 2;     ///< s of a ContinuousMove's Timeout (whole seconds); re-sent at half of it
};

/// Everything an ONVIF backend is built from.
struct OnvifConfig
{
  LinkConfig link = defaultLink();
  DeviceSessionConfig session{ 0.5, 0.1, 10.0, 0.15, 0.5 };
  OnvifSettings onvif;

  static LinkConfig defaultLink();
};

struct OnvifCounters
{
  Counter statuses;  ///< GetStatus replies read
  Counter faults;    ///< SOAP faults to commands
  Counter error_answers;
  Counter malformed;
  Counter velocity_refreshes;  ///< ContinuousMoves re-sent before their timeout
};

/**
 * \brief ONVIF PTZ over a DeviceSession's HTTP link.
 *
 * Bring-up at every (re)connection: GetSystemDateAndTime (no authentication; the clock offset), GetCapabilities (the
 * service paths; the configured host is kept), GetProfiles, GetNodes, GetConfigurationOptions. Goals are AbsoluteMove
 * in the degree space when the node lists it, otherwise in the generic space through the per-axis mappings; velocity
 * goals ContinuousMove (re-sent before its timeout), cancel Stop, state GetStatus at the poll period. A SOAP fault to a
 * command is a device fault with the camera's words; during the bring-up it fails the start.
 */
class OnvifProtocol : public DeviceProtocol
{
public:
  OnvifProtocol(const OnvifSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "onvif";
  }
  std::string deviceName() const override
  {
    return "an ONVIF camera";
  }
  Capabilities capabilities() const override;
  void onConnected() override;
  void onReceived(const std::uint8_t*, std::size_t) override
  {
  }
  void poll() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const OnvifCounters& counters() const
  {
    return counters_;
  }

private:
  /// POSTs \p body (an operation) to \p path; true with message_.content the response, else \p problem ("" when
  /// the link was lost).
  bool call(const std::string& path, const std::string& body, bool secure, std::string& problem);
  void command(const std::string& path, const std::string& body, const char* operation);
  void setupFailed(const std::string& problem);
  bool bringUp(std::string& problem);
  Capabilities cameraCapabilities() const;
  double angleOf(const GenericAxisMapping& mapping, double x) const;
  double genericOf(const GenericAxisMapping& mapping, double angle) const;
  double cameraTime() const;

  const OnvifSettings settings_;
  DeviceSession& session_;
  HttpLink& http_;
  OnvifCounters counters_;

  // I/O thread only.
  std::mt19937_64 random_;
  double clock_offset_ = 0.0;  ///< camera UTC - our UTC, s
  onvif::ServicePaths paths_;
  onvif::Profile profile_;
  onvif::Node node_;
  bool use_degrees_ = false;
  HttpRequest request_;
  onvif::SoapMessage message_;
  std::string velocity_body_;  ///< the ContinuousMove in force ("" when none)
  TimePoint velocity_sent_at_{};
};

std::unique_ptr<DeviceBackend> makeOnvifBackend(const OnvifConfig& config,
                                                std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());

}  // namespace ptz_action_server

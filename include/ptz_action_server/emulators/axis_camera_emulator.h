/**
 * \file
 * \brief An emulated Axis PTZ camera: VAPIX ptz.cgi on a real HTTP server (Digest by default), over the shared sim
 * motion model.
 */
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/sim_device_model.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
/// The camera the emulator plays.
struct AxisCameraEmulatorConfig
{
  HttpCameraServerConfig http;
  /// Pan -170..170 deg, tilt -20..90 deg, zoom 1..18X; speeds as SimDeviceConfig::defaults().
  SimDeviceConfig device = defaultDevice();
  /// VAPIX zoom value -> X (`VALUE:X,...`); "" = a camera without the zoom attributes (answers `Error:`)
  std::string zoom_table = DEFAULT_ZOOM_TABLE;
  int cameras = 1;  ///< video channels: `camera=` beyond them is refused

  static SimDeviceConfig defaultDevice();
  /// An 18X optical zoom: the magnification grows faster towards tele, as optics do.
  static constexpr const char* DEFAULT_ZOOM_TABLE = "1:1,1000:1.35,2000:1.8,3000:2.4,4000:3.2,5000:4.3,6000:5.8,7000:7."
                                                    "7,8000:10.3,9000:13.7,9999:18";
};

/**
 * \brief A VAPIX PTZ camera on 127.0.0.1.
 *
 * `/axis-cgi/com/ptz.cgi` (GET query or POST form): `pan`, `tilt` (fractional degrees), `zoom` (1..9999), `speed`
 * (1..100), `rpan`, `rtilt`, `rzoom`, `continuouspantiltmove=P,T`, `continuouszoommove=Z`, `move=stop|home` answer
 * 204; `query=position|limits|speed|attributes` (with `group=zoom`) answer `key=value` lines; anything else an
 * `Error:` body as the camera words it. Other paths: 404. Thread-safe.
 */
class AxisCameraEmulator
{
public:
  explicit AxisCameraEmulator(const AxisCameraEmulatorConfig& config,
                              std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());

  std::uint16_t port() const
  {
    return server_->port();
  }
  HttpCameraServer& server()
  {
    return *server_;
  }
  /// The model's state now (rad, X).
  PtzSample sample() const;
  /// Answers every move with `Error:` (as a camera whose PTZ control another user holds).
  void setRefuse(bool refuse);
  /// Fault hooks of the motion model: a stalled axis accepts every command and silently stays where it is.
  void setFaults(const SimFaults& faults);

  /// The camera's words when it refuses a move under setRefuse().
  static constexpr const char* REFUSAL = "PTZ control is locked by another user";

private:
  HttpAnswer handle(const std::string& method, const std::string& target, const std::string& body);
  HttpAnswer query(const std::string& what, const std::string& group, TimePoint now);

  const AxisCameraEmulatorConfig config_;
  const std::shared_ptr<const Clock> clock_;
  vapix::ZoomTable zoom_table_;
  mutable std::mutex mutex_;  ///< guards the model and refuse_
  mutable SimDeviceModel model_;
  bool refuse_ = false;
  int speed_ = 100;
  std::unique_ptr<HttpCameraServer> server_;  ///< last: its thread calls handle()
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief An emulated Axis PTZ camera: VAPIX ptz.cgi on a real HTTP server (Digest by default), over the shared sim
 * motion model.
 */
#pragma once

#include <map>
#include <optional>
#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/axis/vapix_queue.h"
#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/core/sim/sim_lens_model.h"
#include "ptz_action_server/emulators/http_camera_emulator.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
/// The camera the emulator plays.
struct AxisCameraEmulatorConfig
{
  HttpCameraServerConfig http;
  /// Pan -170..170 deg, tilt -20..90 deg; speeds as SimDeviceConfig::defaults(). The zoom range follows the lens.
  SimDeviceConfig device = defaultDevice();
  /// The lens: VAPIX zoom value -> X (`VALUE:X,...`); "" = no zoom at all (no MinZoom/MaxZoom in the limits, no
  /// zoom= in the position).
  std::string zoom_table = DEFAULT_ZOOM_TABLE;
  /// The firmware answers `query=attributes&group=zoom` (zoomSteps: the lens's points, maxOpticalZoomMag) and lists
  /// it in `info=1`. false: a firmware without it, as a field camera: `info=1` lists
  /// `query={ speed | position | limits | presetposcam | presetposall }` and asking answers
  /// `Error:` / `query: unknown value: attributes`.
  bool attributes = true;
  /// `root.Brand.ProdNbr` of param.cgi (`ProdFullName` "AXIS <model> PTZ Network Camera").
  std::string model = DEFAULT_MODEL;
  int cameras = 1;  ///< video channels: `camera=` beyond them is refused
  /// PTZ control queue on (`root.PTZ.Various.V1.CtlQueueing=true`), as the VAPIX Queuing API describes it with the
  /// Administrator group's defaults (UseCookie=yes, TimeoutType=activity): every client gets a cookie with its first
  /// ptz.cgi or ptzqueue.cgi request and is told apart by it; `ptzqueue.cgi?control=request|query|drop` answers
  /// `<a name="pos"></a><a name="seconds"></a><a name="period"></a>`; a move from a client that does not hold control
  /// is answered as any (204) and moves nothing (the queue documents no answer for it: the worst case). Queries are
  /// everyone's. false: `CtlQueueing=false`, no cookies, and ptzqueue.cgi answers `Error:`.
  bool control_queue = false;
  double control_time = 60.0;     ///< TimeoutTime: s of control after the holder's last move or request
  double queue_period = 5.0;      ///< the period ptzqueue.cgi recommends, s
  double queue_poll_time = 20.0;  ///< CtlQueuePollTime, s
  /// Its focus and iris (SimLensAxisConfig::present: whether it has them; values 1..9999, 1 near and closed).
  SimLensConfig lens;
  /// The driver takes `center=x,y` and `areazoom=x,y,z` (with `imagewidth`, `imageheight`) and info=1 lists them, as
  /// the VAPIX documentation's and the field camera's do; false: a driver without them (`Error:` unknown argument).
  bool area_zoom = true;
  /// The lens at zoom 1 (full angles, rad), narrowing as an ideal zoom lens with the zoom's X: what `center` and
  /// `areazoom` aim with.
  FieldOfViewAngles field_of_view = HttpCameraEmulator::defaultFieldOfView();
  int image_width = 1280;  ///< px of the picture `center` and `areazoom` count in without `imagewidth` (720p)
  int image_height = 720;  ///< px, without `imageheight`

  static SimDeviceConfig defaultDevice();
  /// An 18X optical zoom listed per X as Axis cameras list their zoomSteps: VAPIX values step evenly per X.
  static constexpr const char* DEFAULT_ZOOM_TABLE = "1:1,589:2,1177:3,1765:4,2353:5,2941:6,3529:7,4117:8,4705:9,5294:"
                                                    "10,5882:11,6470:12,7058:13,7646:14,8234:15,"
                                                    "8822:16,9410:17,9999:18";
  /// An 18X model (P55 family).
  static constexpr const char* DEFAULT_MODEL = "P5534-E";
  /// The lens of a camera with \p max_optical X at VAPIX zoom 9999, linear (ZoomTable::linear()), as text.
  static std::string linearZoomTable(double max_optical);
};

/**
 * \brief A VAPIX PTZ camera on 127.0.0.1.
 *
 * `/axis-cgi/com/ptz.cgi` (GET query or POST form): `pan`, `tilt` (fractional degrees), `zoom` (1..9999), `speed`
 * (1..100), `rpan`, `rtilt`, `rzoom`, `continuouspantiltmove=P,T`, `continuouszoommove=Z`, `move=stop|home`, and
 * `center=X,Y`, `areazoom=X,Y,Z` (whole pixels of an `imagewidth` x `imageheight` picture, turned into angles with the
 * lens at the current zoom; Z / 100 multiplies the zoom's X) answer 204;
 * `query=position|limits|speed|presetposcam|presetposall` answer `key=value` lines (a position carries pan, tilt, zoom,
 * iris, focus, brightness, autofocus, autoiris), `query=attributes&group=zoom` the documented sections (unless
 * AxisCameraEmulatorConfig::attributes is off), `info=1` the commands it takes; anything else an `Error:` body as the
 * camera words it. `/axis-cgi/param.cgi?action=list&group=root.Brand` answers the brand parameters. Other paths: 404.
 * Thread-safe.
 */
class AxisCameraEmulator : public HttpCameraEmulator
{
public:
  explicit AxisCameraEmulator(const AxisCameraEmulatorConfig& config,
                              std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());

  std::uint16_t port() const
  {
    return server_->port();
  }
  HttpCameraServer& server() override
  {
    return *server_;
  }
  // sample(), setFaults() and setRefuse() are HttpCameraEmulator's: under setRefuse() every move is answered with
  // `Error:` REFUSAL.
  /// What the camera was asked, classified (axis_camera_classify.cpp); challenged requests left out.
  std::vector<ClassifiedCommand> classify() const;
  /// control_queue: another client (a browser, a guard tour) holds PTZ control for \p seconds from now (-1: for good,
  /// as a client with TimeoutType infinity); 0 lets it go.
  void holdControlElsewhere(double seconds);
  /// control_queue: the client (cookie value) that holds control now; "" for none, "other" for holdControlElsewhere().
  std::string controlHolder() const;
  /// The lens now: focus and iris modes and positions (shares 0..1), for tests.
  LensState lensState() const;

  /// The camera's words when it refuses a move under setRefuse().
  static constexpr const char* REFUSAL = "PTZ control is locked by another user";

private:
  HttpAnswer handle(const std::string& method, const std::string& target, const std::string& body);
  /// A ptz.cgi or ptzqueue.cgi request of \p client; mutex_ held.
  HttpAnswer command(const std::string& path, std::map<std::string, std::string>& values, const std::string& client,
                     TimePoint now);
  HttpAnswer query(const std::string& what, const std::string& group, TimePoint now);
  /// `center` / `areazoom` in \p values, checked: "" and the move made, or the `Error:` words; mutex_ held.
  std::string aimInPicture(std::map<std::string, std::string>& values, bool act, TimePoint now);
  HttpAnswer info() const;
  // Focus and iris (axis_camera_emulator_lens.cpp); mutex_ held.
  /// A request with a lens argument: its answer (only lens arguments and camera= may come with it); else nothing.
  std::optional<HttpAnswer> lensCommand(const std::map<std::string, std::string>& values, const std::string& client,
                                        TimePoint now);
  /// The lens lines of a position answer (`iris=`, `focus=`, `brightness=`, `autofocus=`, `autoiris=`; those of the
  /// functions it has), in the field camera's order.
  std::string lensLines(TimePoint now) const;
  HttpAnswer parameters(const std::string& action, const std::string& group) const;
  // PTZ control queue (axis_camera_emulator_queue.cpp); mutex_ held.
  /// The client the request's cookie names; a new one (and \p set_cookie) when it names none.
  std::string clientOf(const std::string& cookie, std::string& set_cookie);
  HttpAnswer queueAnswer(const std::string& control, const std::string& client, TimePoint now);
  /// \p client may move the camera now (no queue, or it holds control: its time starts again).
  bool mayMove(const std::string& client, TimePoint now);
  std::string queueParameters(const std::string& group) const;

  const AxisCameraEmulatorConfig config_;
  vapix::ZoomTable zoom_table_;
  FieldOfViewModel optics_;  ///< what `center` and `areazoom` aim with
  // Guarded by mutex_, with the model.
  std::string holder_;  ///< the client that holds PTZ control ("" none)
  TimePoint held_until_{};
  bool held_for_good_ = false;
  unsigned clients_ = 0;  ///< cookies handed out
  int speed_ = 100;
  SimLensModel lens_;
  std::unique_ptr<HttpCameraServer> server_;  ///< last: its thread calls handle()
};

}  // namespace ptz_action_server

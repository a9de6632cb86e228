/**
 * \file
 * \brief Axis PTZ cameras over VAPIX (HTTP): absolute moves in fractional degrees, continuous moves for velocity
 * goals, `move=stop` for a cancel, `query=position` polled at 10 Hz; limits, offered commands and the zoom X-factor
 * found out at start.
 */
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/axis/vapix_lens.h"
#include "ptz_action_server/core/axis/vapix_queue.h"
#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/http/http_device_protocol.h"

namespace ptz_action_server
{
/// Whether the backend asks for PTZ control before it moves the camera (VAPIX PTZ control queue).
enum class AxisControlQueue
{
  AUTO,  ///< as the camera's `root.PTZ.Various.V<camera>.CtlQueueing` says, read at every set-up
  ON,    ///< always (a camera whose parameters this user may not read)
  OFF,   ///< never
};

/// What only the Axis protocol needs to know.
struct AxisSettings
{
  int camera = 1;               ///< the `camera=` of every request (video channel of multi-sensor units)
  int speed = 100;              ///< `speed=` of absolute moves, 1..100
  double pan_max_speed = 1.5;   ///< rad/s of `continuouspantiltmove=100,..` (and of speed=100)
  double tilt_max_speed = 1.0;  ///< rad/s
  double zoom_max_rate = 8.0;   ///< X/s of `continuouszoommove=100`
  double acceleration = 3.0;    ///< rad/s^2, for goal timeouts
  /// `VALUE:X,...` (VAPIX zoom -> X): wins over whatever the camera says; "" = find out (see AxisProtocol)
  std::string zoom_table;
  /// X at VAPIX zoom 9999 (the camera's optical zoom, from its data sheet), linear from 1X at 1: wins over the
  /// camera's table; 0 = find out. Not together with zoom_table.
  double zoom_max_factor = 0.0;
  /// A camera that gives no table: assume its model family's optical zoom (modelFamilyZoom()), with a warning; false:
  /// its zoom X stays unknown (zoom goals are refused, velocity goals work).
  bool zoom_guess = true;
  AxisControlQueue control_queue = AxisControlQueue::AUTO;
};

/// Counters for diagnostics.
struct AxisCounters
{
  Counter positions;         ///< position replies read
  Counter refusals;          ///< `Error:` answers to commands
  Counter error_answers;     ///< HTTP statuses >= 400 to commands or polls
  Counter malformed;         ///< bodies that were neither `key=value` lines nor `Error:`
  Counter control_requests;  ///< ptzqueue.cgi control=request sent (the queue's renewals included)
  Counter without_control;   ///< commands not sent: another client held PTZ control
};

/// Where the zoom X-factor comes from, best first.
enum class AxisZoomSource
{
  NO_ZOOM,             ///< `query=limits` gives no MinZoom / MaxZoom: the camera has no zoom
  CONFIGURED_TABLE,    ///< the zoom_table setting
  CONFIGURED_MAXIMUM,  ///< the zoom_max_factor setting, linear
  CAMERA_TABLE,        ///< the camera's zoomSteps
  CAMERA_MAXIMUM,      ///< the camera's maxOpticalZoomMag (and maxDigitalZoomMag), linear
  MODEL_GUESS,         ///< the model family's usual optical zoom, linear: a guess, with a warning
  UNKNOWN,             ///< none of the above: zoom X unknown (zoom goals refused), with a warning
};

/**
 * \brief VAPIX PTZ over a DeviceSession's HTTP link.
 *
 * At every (re)connection: `query=limits` (limits in degrees, the node intersects them with the URDF's), `info=1`
 * (what the camera offers: absolute and continuous moves, rpan/rtilt, presets, home), `query=position` (does it
 * report its zoom), then, when the limits give a zoom, its X-factor from the first that has one: zoom_table,
 * zoom_max_factor, the camera's `query=attributes&group=zoom` (zoomSteps, or maxOpticalZoomMag: firmware without
 * them answers `Error:`), the model family's usual optical zoom (param.cgi `root.Brand.ProdNbr`; a guess, warned
 * about). Without any, zoom is declared present without `absolute` and `feedback` (velocity goals, and zoom 1 goals:
 * `widest_view`, sent as `zoom=` the limits' MinZoom), never reported as a silent 1X.
 *
 * PTZ control queue (VAPIX Queuing API): a channel with `CtlQueueing=true` moves only for the client that holds
 * control (told apart by the cookie the camera sets; the HTTP link keeps it). The backend then asks for control at
 * set-up (`ptzqueue.cgi?control=request`), renews it before the camera's timer runs out (every answer's period, at
 * most half the time left and half CtlQueuePollTime), asks again before a command when it does not hold it, drops it
 * at shutdown, and fails a command another client holds control for, naming its queue position and wait.
 *
 * Pixel goals the node leaves to the camera (PtzBackend::aimInView()) are `center` and `areazoom`, declared
 * (Capabilities::view_centre, view_box_zoom) when info=1 lists them.
 *
 * 401, 403, 404, `Error:` bodies and malformed replies to limits or position, and an unreadable zoom table, fail the
 * start with the reason (later: the connection is dropped and set up again after the backoff); `info=1`, the
 * attributes and param.cgi only inform. A command answered with `Error:` or an HTTP error is a device fault with the
 * camera's words.
 */
class AxisProtocol : public HttpDeviceProtocol
{
public:
  /// DeviceConfig<AxisProtocol> (device_backend.h): these settings, and the defaults of the link and the session
  /// (HttpDeviceProtocol's: state is `query=position` every 100 ms).
  using Settings = AxisSettings;
  /// Throws ConfigError for a config this protocol cannot run (not over HTTP, ...).
  static void validate(const DeviceConfig<AxisProtocol>& config);

  AxisProtocol(const AxisSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "axis";
  }
  std::string deviceName() const override
  {
    return "an Axis camera";
  }
  /// Pan, tilt within +-180 / +-90 deg until the camera's limits are read; zoom as the settings say.
  Capabilities capabilities() const override;
  void onConnected() override;
  /// `query=position`.
  void poll() override;
  /// `pan tilt zoom speed`, fractional degrees, the zoom through the table (left out as NaN); without a table or zoom
  /// feedback a zoom of 1 is `zoom=` MinZoom (the widest view), any other left out.
  void goTo(const AxisValues& position) override;
  /// The absolute move's `speed=` (one for pan and tilt): the slower of the two axes' shares of their top speeds.
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  /// `continuouspantiltmove` and `continuouszoommove`, scaled by the max speeds.
  void moveAtVelocity(const AxisValues& velocity) override;
  /// `move=stop` (the camera decelerates).
  void stop() override;
  /// Focus and iris (vapix::lensArguments()), as a request of its own: a refusal is a lens fault, never the goal's.
  void lens(const LensCommand& command) override;
  /// `center=X,Y` (a box: `areazoom=X,Y,Z`, Z = 100 x its magnification) with the picture's `imagewidth` and
  /// `imageheight`: the camera centres that pixel of its picture with its own lens, whatever its zoom X is known as.
  void aimInView(const ViewTarget& target) override;
  /// Drops PTZ control when it held it (control queue).
  void shutdown() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const AxisCounters& counters() const
  {
    return counters_;
  }

  /// Where the zoom X-factor came from at the last set-up. Any thread.
  AxisZoomSource zoomSource() const;

private:
  /// GETs \p path; true and \p body filled on a 200 or 204, otherwise \p problem says why ("" when the link was
  /// lost: the session has its reason). \p what names the request in the problem. Every request goes through it.
  bool exchange(const std::string& path, const std::string& what, std::string& body, std::string& problem);
  /// Sends `ptz.cgi?camera=N&` + \p arguments; true and \p reply filled when the camera answered usably, otherwise
  /// \p problem says why ("" when the link was lost: the session has its reason).
  bool request(const std::string& arguments, vapix::Reply& reply, std::string& problem);
  /// A command: a refusal or error answer is a fault of the current command.
  void command(const std::string& arguments);
  /// Finds the zoom X-factor (zoom_table_, zoom_source_); false when the set-up cannot go on (it said why).
  bool findZoomTable(const vapix::Limits& limits);
  Capabilities cameraCapabilities(const vapix::Limits& limits, const vapix::CommandList& commands) const;
  /// `speed=` of the absolute move, 1..100 of the top speeds of pan and tilt; the zoom moves at its own speed.
  MoveSpeedCapability moveSpeed() const;
  // PTZ control queue (axis_control_queue.cpp).
  /// Whether the channel queues PTZ control (control_queue_, queue_poll_time_), as the settings or the camera say.
  void findControlQueue();
  /// control=request: true when control is ours (for its holder the camera's timer starts again).
  bool requestControl();
  /// True when commands may go: no queue, or control is ours (asked for or renewed first when due).
  bool haveControl();
  /// Why a command cannot go: who holds control, our place and wait.
  std::string withoutControl() const;
  /// The X-factor of a position reply (1 when it cannot be known: the zoom's feedback is false then).
  double zoomFactor(const vapix::Position& position) const;
  /// The lens modes and positions of a position answer, to the session's LensReport.
  void reportLens(const vapix::LensReading& reading);

  const AxisSettings settings_;
  AxisCounters counters_;
  vapix::ZoomTable configured_table_;  ///< from zoom_table or zoom_max_factor; empty: find out

  // I/O thread only.
  vapix::ZoomTable zoom_table_;  ///< empty: zoom X unknown (or no zoom)
  vapix::LensLimits lens_limits_;
  AxisZoomSource zoom_source_ = AxisZoomSource::NO_ZOOM;
  bool zoom_feedback_ = false;  ///< the position reply carries zoom= and zoom_table_ maps it
  bool zoom_velocity_ = false;  ///< the camera has a zoom it moves with continuouszoommove
  /// Without zoom feedback: `zoom=` at widest_zoom_value_ (the limits' MinZoom) still goes to the widest view.
  bool widest_view_ = false;
  double widest_zoom_value_ = vapix::ZOOM_VALUE_MIN;
  bool control_queue_ = false;  ///< the channel queues PTZ control: commands need it
  bool control_held_ = false;
  double queue_poll_time_ = 0.0;  ///< CtlQueuePollTime, s (0: not known)
  double renew_after_ = 5.0;      ///< s after a request before control is asked for again
  TimePoint control_asked_at_{};
  vapix::QueueStatus queue_status_;
  std::string queue_problem_;  ///< why the last request gave no status ("" when it did)
  HttpRequest request_;        ///< reused: the 10 Hz poll allocates nothing once warm
  vapix::Reply reply_;
  std::string arguments_;
  std::string arguments_path_;
  std::string body_;

  // Shared with diagnostics() and zoomSource(); guarded by facts_mutex_.
  mutable std::mutex facts_mutex_;
  AxisZoomSource shared_zoom_source_ = AxisZoomSource::NO_ZOOM;
  std::string zoom_text_;   ///< where the X-factor came from, for diagnostics
  std::string model_text_;  ///< the product, when it was read
  std::string queue_text_;  ///< the control queue, for diagnostics
};

/// "camera table", "model guess", ... for messages and diagnostics.
const char* zoomSourceName(AxisZoomSource source);

}  // namespace ptz_action_server

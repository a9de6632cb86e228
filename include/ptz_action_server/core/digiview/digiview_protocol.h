/**
 * \file
 * \brief The digiview backend: Ptz goals aim a DigiView (Synclair Vision) user-controllable virtual camera.
 */
#pragma once

#include <array>
#include <atomic>
#include <deque>
#include <memory>

#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/digiview/digiview_codec.h"

namespace ptz_action_server
{
/// What only the DigiView protocol needs to know.
struct DigiViewSettings
{
  /// The format DigiView speaks ("0.5" by default), the unit of its angles (the format's documented one unless set)
  /// and whether it fills the checksum.
  digiview::Wire wire;
  std::string stream_name = "main";  ///< 1 to nameSizeOf(format) characters
  std::uint8_t cam_id = 0;
  double fov_wide = 1.2;         ///< rad: the field of view that zoom 1x maps to (fov = fov_wide / X)
  double zoom_max = 0.0;         ///< X; 0: fov_wide / 0.1 (DigiView's narrowest field of view)
  std::uint8_t lock_flags = 0;   ///< 0: the view follows the vehicle on every axis, so yaw and pitch are the base's
  std::uint8_t crop_mode = 1;    ///< not in 1.2
  double slew_rate = 1.0;        ///< rad/s DigiView turns a view at (for velocity goals and goal timeouts)
  double acceleration = 0.0;     ///< rad/s^2 of that turn; 0: unknown (instant)
  double velocity_period = 0.1;  ///< s between the targets of a velocity goal

  /// fov_wide / 0.1 unless zoom_max says otherwise.
  double zoomMax() const;
  digiview::CameraId camera() const
  {
    return digiview::CameraId{ stream_name, cam_id };
  }
  /// What a configuration of \p format that names no angle unit must be told: for "1.1", whose angles this package
  /// sent in radians before it followed 1.1's own documentation (degrees), a deprecation line naming the setting
  /// (\p setting, as the node resolves it); empty for the others (their unit never changed).
  static std::string angleUnitNotice(digiview::Format format, const std::string& setting = "~digiview/angle_unit");
};

struct DigiViewCounters
{
  Counter messages;
  Counter states;  ///< CURRENT_PARAMETERS of our camera
  Counter acknowledged;
  Counter refused;             ///< CHECKSUM_ERROR, DATA_ERROR, FORBIDDEN, UNKNOWN replies
  Counter unverified;          ///< accepted with a checksum byte of 0 (checksum rule zero_accepted)
  std::array<Counter, 7> bad;  ///< messages dropped, by UnpackError
};

/**
 * \brief Aims one DigiView user view (stream_name, cam_id) like a pan-tilt-zoom camera, over a DeviceSession.
 *
 * Goals become SET CAM_TARGETING in directional mode (yaw = pan, pitch = tilt: DigiView's Tait-Bryan yaw is
 * clockwise from north and its pitch positive up, the same signs as the contract) and SET CAM_OPTICS_AND_CONTROL
 * (fov = fov_wide / zoom), angles in the wire's unit. DigiView has no velocity command: a velocity goal is a target
 * moved every velocity_period. State comes from subscriptions (100 ms) to CAM_TARGETING and CAM_OPTICS_AND_CONTROL:
 * GET_INTERVAL in format 0.5, a GET with interval_ms from 1.0 on (1.1's CAM_TARGETING carries detection_id -1, 1.2's
 * view_id -1: no detection). Every format is cut from a TCP stream by its own size. A SET that DigiView refuses is a
 * device fault with DigiView's reason. From 1.1 on SYSTEM_STATUS is subscribed too: a halted DigiView (HALT) keeps
 * the link (its status reports keep it alive), holds the view where it stopped, and makes every goal a device fault
 * until it runs again. After a loss the view is held where it is; at shutdown the subscriptions are cancelled and QUIT
 * is sent.
 */
class DigiViewProtocol : public DeviceProtocol
{
public:
  /// DeviceConfig<DigiViewProtocol> (device_backend.h): these settings, and the defaults of the link and the session.
  using Settings = DigiViewSettings;
  /// tcp (the default: a connection, which QUIT closes) or udp (one message per datagram)
  static LinkConfig defaultLink()
  {
    LinkConfig link;
    link.kind = LinkKind::TCP;
    link.port = 5500;
    link.reconnect_min = 0.1;
    return link;
  }
  /// No CURRENT_PARAMETERS of the view for 0.5 s drops the link (they come every 100 ms).
  static DeviceSessionConfig defaultSession()
  {
    return { 0.5, 0.1, 10.0, 0.25, 0.5 };
  }

  DigiViewProtocol(const DigiViewSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "digiview";
  }
  std::string deviceName() const override;
  /// From the settings: pan +-pi, tilt +-pi/2 at the slew rate; zoom 1x to fov_wide / narrowest field of view.
  Capabilities capabilities() const override;
  /// GET VIDEO_OUTPUT (the number of views), SYSTEM_STATUS, and the view's state, then every 100 ms.
  void onConnected() override;
  /// Messages of the configured format's size: cut from the stream on TCP, one per datagram on UDP. When nothing
  /// unpacked yet and the first messages are of a format of another size, start() fails saying so.
  void onReceived(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected() override;
  void onClosing() override;
  /// Subscribes again after three missed states (over UDP nothing else tells that DigiView restarted), and asks
  /// again for a stream description that did not come (a datagram may be lost).
  void poll() override;
  /// SET CAM_TARGETING (directional, absolute) and SET CAM_OPTICS_AND_CONTROL (fov = fov_wide / zoom).
  void goTo(const AxisValues& position) override;
  /// DigiView has none: a target moved on every velocity_period.
  void moveAtVelocity(const AxisValues& velocity) override;
  /// A target where the view comes to rest (its braking distance at the configured acceleration).
  void stop() override;
  /// A target where the view is.
  void hold() override;
  /// Cancels both subscriptions (interval 0), then QUIT.
  void shutdown() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const DigiViewCounters& counters() const
  {
    return counters_;
  }
  /// The user views of the stream, as its VIDEO_OUTPUT said (0 before it came).
  std::uint8_t numUserViews() const
  {
    return num_user_views_;
  }
  /// DigiView's last SYSTEM_STATUS said HALT (1.1 on): goals are refused until it runs again.
  bool halted() const
  {
    return halted_;
  }

private:
  /// A SET awaiting DigiView's answer, and the command it served.
  struct PendingSet
  {
    digiview::ParamType param;
    std::uint64_t command;
  };

  /// Describe the stream, report the view every 100 ms.
  void subscribe();
  void handle(const std::uint8_t* bytes, std::size_t size);
  /// Nothing unpacked on this connection: if what came is of a format of another size, start() fails saying so.
  void checkOtherFormat(const std::uint8_t* bytes, std::size_t size);
  void handleState(const digiview::Message& message);
  void handleStatus(const digiview::Message& message);
  void handleAnswer(const digiview::Message& message);
  /// Halted (from 1.1 on, SYSTEM_STATUS HALT) or running again: a halt ends the goal in flight.
  void setHalted(bool halted);
  /// Halted: the command is reported as a fault instead of being sent.
  bool refusedWhileHalted();
  void send(const digiview::Message& message);
  void sendTargets(const AxisValues& target);
  void velocityTick();

  const DigiViewSettings settings_;
  DeviceSession& session_;
  boost::asio::steady_timer velocity_timer_;
  DigiViewCounters counters_;
  std::atomic<std::uint8_t> num_user_views_{ 0 };
  std::atomic<std::uint8_t> system_status_{ 0 };
  std::atomic<bool> halted_{ false };

  // I/O thread only.
  bool described_ = false;   ///< VIDEO_OUTPUT of the stream arrived on this connection
  bool targeted_ = false;    ///< CAM_TARGETING of the view arrived on this connection
  bool understood_ = false;  ///< a message unpacked on this connection
  const std::size_t message_size_;
  std::array<std::uint8_t, digiview::MAX_MESSAGE_SIZE> stream_buffer_{};
  std::size_t buffered_ = 0;
  std::size_t bad_in_a_row_ = 0;  ///< stream: messages that did not unpack since the last that did
  std::array<std::uint8_t, 2 * digiview::MAX_MESSAGE_SIZE> opening_{};  ///< TCP: the first bytes of the connection
  std::size_t opening_size_ = 0;
  std::deque<PendingSet> pending_sets_;  ///< oldest first
  TimePoint heard_at_{};                 ///< the last state of the view, or the last subscription
  TimePoint subscribed_at_{};
  AxisValues reported_{ { 0.0, 0.0, 1.0 } };
  AxisValues velocity_{};
  AxisValues velocity_origin_{};
  TimePoint velocity_started_{};
};

}  // namespace ptz_action_server

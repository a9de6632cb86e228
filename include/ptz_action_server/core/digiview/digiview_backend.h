/**
 * \file
 * \brief The digiview backend: Ptz goals aim a DigiView (Synclair Vision) user-controllable virtual camera.
 */
#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/digiview/messages.h"
#include "ptz_action_server/core/motion_estimator.h"

namespace ptz_action_server
{
enum class DigiViewTransport
{
  TCP,  ///< the default: a connection, which QUIT closes
  UDP,  ///< one message per datagram
};

struct DigiViewConfig
{
  std::string host = "127.0.0.1";
  std::uint16_t port = 5500;
  DigiViewTransport transport = DigiViewTransport::TCP;
  std::string stream_name = "main";
  std::uint8_t cam_id = 0;
  double fov_wide = 1.2;        ///< rad: the field of view that zoom 1x maps to (fov = fov_wide / X)
  double zoom_max = 0.0;        ///< X; 0: fov_wide / 0.1 (DigiView's narrowest field of view)
  std::uint8_t lock_flags = 0;  ///< 0: the view follows the vehicle on every axis, so yaw and pitch are the base's
  std::uint8_t crop_mode = 1;
  double slew_rate = 1.0;         ///< rad/s DigiView turns a view at (for velocity goals and goal timeouts)
  double acceleration = 0.0;      ///< rad/s^2 of that turn; 0: unknown (instant)
  double state_timeout = 0.5;     ///< s without CURRENT_PARAMETERS before the link is down
  double velocity_period = 0.1;   ///< s between the targets of a velocity goal
  double settle_window = 0.25;    ///< s the reported direction must stay still to count as settled
  double startup_timeout = 10.0;  ///< s start() waits for DigiView to describe the stream
  double reconnect_min = 0.1;     ///< s before reconnecting; doubles up to reconnect_max
  double reconnect_max = 2.0;
};

struct DigiViewCounters
{
  std::uint64_t messages = 0;
  std::uint64_t states = 0;  ///< CURRENT_PARAMETERS of our camera
  std::uint64_t acknowledged = 0;
  std::uint64_t refused = 0;           ///< CHECKSUM_ERROR, DATA_ERROR, FORBIDDEN, UNKNOWN replies
  std::array<std::uint64_t, 7> bad{};  ///< messages dropped, by UnpackError
  std::uint64_t connections = 0;
  std::uint64_t link_losses = 0;
};

/**
 * \brief Aims one DigiView user view (stream_name, cam_id) like a pan-tilt-zoom camera.
 *
 * Goals become SET CAM_TARGETING in directional mode (yaw = pan, pitch = tilt: DigiView's Tait-Bryan yaw is
 * clockwise from north and its pitch positive up, the same signs as the contract) and SET CAM_OPTICS_AND_CONTROL
 * (fov = fov_wide / zoom). DigiView has no velocity command: a velocity goal is a target moved every
 * velocity_period. State comes from GET_INTERVAL subscriptions (100 ms) to CAM_TARGETING and
 * CAM_OPTICS_AND_CONTROL. A SET that DigiView refuses is a device fault with DigiView's reason. The connection is
 * kept up with backoff; after a loss the view is held where it is. The destructor sends QUIT.
 */
class DigiViewBackend : public PtzBackend
{
public:
  explicit DigiViewBackend(const DigiViewConfig& config,
                           std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~DigiViewBackend() override;

  std::string name() const override
  {
    return "digiview";
  }
  Capabilities capabilities() const override;
  /// Connects and waits until DigiView has described the stream (VIDEO_OUTPUT) and reported the view.
  void start() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  PtzSample sample() const override;
  std::string lastFault() const override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  DigiViewCounters counters() const;
  double zoomMax() const;

private:
  void connect();
  void onConnected();
  void onDisconnected(const std::string& reason);
  void startRead();
  void handle(const std::uint8_t* bytes, std::size_t size);
  void send(const digiview::Message& message);
  void startWrite();
  void sendTargets(double pan, double tilt, double zoom);
  void velocityTick();
  void superviseLink();
  digiview::CameraId camera() const;
  bool linkUpLocked(TimePoint now) const;

  const DigiViewConfig config_;
  const std::shared_ptr<const Clock> clock_;

  boost::asio::io_context context_;
  boost::asio::ip::tcp::socket tcp_;
  boost::asio::ip::udp::socket udp_;
  boost::asio::steady_timer reconnect_timer_;
  boost::asio::steady_timer velocity_timer_;
  boost::asio::steady_timer link_timer_;

  // I/O thread only.
  bool connected_ = false;
  bool ever_connected_ = false;
  bool hold_on_state_ = false;  ///< after a reconnection: hold the view where it is once it reports
  bool quitting_ = false;       ///< QUIT is on its way: stop the loop once it is written
  double backoff_ = 0.0;
  std::array<std::uint8_t, 2048> read_buffer_{};
  std::size_t read_size_ = 0;
  std::deque<digiview::Bytes> write_queue_;
  std::deque<digiview::ParamType> outstanding_sets_;  ///< SETs awaiting their reply, oldest first
  AxisValues velocity_{};
  AxisValues velocity_origin_{};
  TimePoint velocity_started_{};

  mutable std::mutex mutex_;  ///< guards everything below
  std::condition_variable described_;
  bool stream_described_ = false;
  bool state_seen_ = false;
  std::string startup_problem_;
  std::uint8_t num_user_views_ = 0;
  std::uint8_t system_status_ = 0;
  AxisValues reported_{ { 0.0, 0.0, 1.0 } };
  TimePoint last_state_at_{};
  bool link_was_up_ = false;
  MotionEstimator motion_;
  std::uint64_t fault_count_ = 0;
  std::string last_fault_;
  DigiViewCounters counters_;
  std::string last_error_;

  std::thread thread_;
};

}  // namespace ptz_action_server

/**
 * \file
 * \brief The pantilt_udp backend: the node is the control system, a PanTilt device controller sits across UDP.
 */
#pragma once

#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/motion_estimator.h"
#include "ptz_action_server/core/pantilt/pantilt.h"
#include "ptz_action_server/core/transport/udp_socket.h"

namespace ptz_action_server
{
struct PanTiltUdpConfig
{
  std::string device_host = "127.0.0.1";
  std::uint16_t device_port = 5000;
  std::string local_host = "0.0.0.0";
  std::uint16_t local_port = 0;  ///< 0: ephemeral
  cr::pantilt::WireVersion version = cr::pantilt::WireVersion::V1_0;
  double state_timeout = 0.5;         ///< s without a valid params frame before the link counts as down
  double state_request_period = 0.2;  ///< s between state requests while no frames arrive
  double settle_window = 0.05;        ///< s over which a still position means "settled"
  double pan_speed = 100.0;           ///< % of the max speed for position goals
  double tilt_speed = 100.0;          ///< %
  /// Pan and tilt ranges (rad), max speeds at 100 % (rad/s) and accelerations (rad/s^2). Zoom: none.
  std::array<AxisCapability, 2> axes{ { { true, { -M_PI, M_PI }, 1.5, 3.0 },
                                        { true, { -M_PI / 2.0, M_PI / 2.0 }, 1.0, 3.0 } } };
};

/// Why datagrams were dropped; each dropped datagram is counted under exactly one.
struct PanTiltUdpCounters
{
  std::uint64_t frames_ok = 0;
  std::uint64_t foreign_sender = 0;  ///< not from the configured device address and port
  std::uint64_t bad_size = 0;        ///< includes datagrams longer than any params frame
  std::uint64_t bad_header = 0;
  std::uint64_t bad_version = 0;
  std::uint64_t bad_mask = 0;
  std::uint64_t datagrams_sent = 0;
  std::uint64_t send_failures = 0;
  std::uint64_t link_losses = 0;

  std::uint64_t dropped() const
  {
    return foreign_sender + bad_size + bad_header + bad_version + bad_mask;
  }
};

/**
 * \brief Talks PanTilt to a device controller over UDP.
 *
 * Goals become SET_PARAM (speeds, angles in degrees) + COMMAND GO_TO_PAN_TILT_ANGLE frames (1.1: one COMMAND with
 * the angles as arguments); velocity goals become MOVE_PAN_TILT in 1.1 and, in 1.0, which has no velocity command,
 * a speed setting plus a move towards the limit; cancel becomes STOP. State comes from the device's params frames
 * (see PanTiltUdpDevice for the reporting rules): the link is up only while valid frames from the device's address
 * arrive. When the link comes back after a loss, the backend sends STOP (the old goal is not resumed) and the speeds.
 * Commands are sent from the caller's thread without blocking; the I/O thread receives and supervises the link.
 */
class PanTiltUdpBackend : public PtzBackend
{
public:
  explicit PanTiltUdpBackend(const PanTiltUdpConfig& config,
                             std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~PanTiltUdpBackend() override;

  std::string name() const override
  {
    return "pantilt_udp";
  }
  Capabilities capabilities() const override;
  void start() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  void stop() override;
  PtzSample sample() const override;
  std::string lastFault() const override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  PanTiltUdpCounters counters() const;
  /// The local endpoint (with the ephemeral port), valid after start().
  UdpEndpoint localEndpoint() const;

private:
  void run();
  void handleDatagram(const std::uint8_t* data, std::size_t size, bool truncated, const UdpEndpoint& from);
  void superviseLink(TimePoint now);
  void sendSetParam(cr::pantilt::PanTiltParam id, double value);
  void sendCommand(cr::pantilt::PanTiltCommand id, double arg1 = 0.0, double arg2 = 0.0);
  void sendSpeeds();
  void sendStateRequest();
  void send(const std::uint8_t* data, int size);
  bool linkUp(TimePoint now) const;

  const PanTiltUdpConfig config_;
  const std::shared_ptr<const Clock> clock_;
  UdpSocket socket_;
  UdpEndpoint device_;
  std::mutex send_mutex_;  ///< keeps a goal's SET_PARAM + COMMAND sequence together

  mutable std::mutex state_mutex_;  ///< guards everything below
  MotionEstimator motion_;          ///< positions of recent frames: velocity and settling
  TimePoint last_frame_at_{};
  bool ever_received_ = false;
  bool link_was_up_ = false;
  TimePoint last_request_at_{};
  PanTiltUdpCounters counters_;

  std::atomic<bool> running_{ false };
  std::thread thread_;
};

}  // namespace ptz_action_server
